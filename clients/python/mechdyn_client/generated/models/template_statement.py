from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.stated import Stated





T = TypeVar("T", bound="TemplateStatement")



@_attrs_define
class TemplateStatement:
    """ The statement's quantities, by name: where the statement prints a
    magnitude (a resisting torque C_r), the field it comes from and its
    sign, so that `/statement/NAME` of the template's job is that number
    as printed (see [`Stated`]).

     """

    additional_properties: dict[str, Stated] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.stated import Stated # noqa: PLC0415
        
        field_dict: dict[str, Any] = {}
        for prop_name, prop in self.additional_properties.items():
            field_dict[prop_name] = prop.to_dict()


        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.stated import Stated # noqa: PLC0415
        d = dict(src_dict)
        instance_ = cls(
        )


        additional_properties = {}
        for prop_name, prop_dict in d.items():
            additional_property = Stated.from_dict(prop_dict)



            additional_properties[prop_name] = additional_property

        instance_.additional_properties = additional_properties
        return instance_

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> Stated:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: Stated) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
