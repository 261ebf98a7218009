from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.support_dto import SupportDto





T = TypeVar("T", bound="ReactionsDto")



@_attrs_define
class ReactionsDto:
    """ The bearing forces in one set of axes: due to the motion, to the weight, and both.

        Attributes:
            dynamic (SupportDto): Forces on D and E (N) and the driving moment about the axis (N·m).
            static (SupportDto): Forces on D and E (N) and the driving moment about the axis (N·m).
            total (SupportDto): Forces on D and E (N) and the driving moment about the axis (N·m).
     """

    dynamic: SupportDto
    static: SupportDto
    total: SupportDto
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.support_dto import SupportDto # noqa: PLC0415
        dynamic = self.dynamic.to_dict()

        static = self.static.to_dict()

        total = self.total.to_dict()


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "dynamic": dynamic,
            "static": static,
            "total": total,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.support_dto import SupportDto # noqa: PLC0415
        d = dict(src_dict)
        dynamic = SupportDto.from_dict(d.pop("dynamic"))




        static = SupportDto.from_dict(d.pop("static"))




        total = SupportDto.from_dict(d.pop("total"))




        instance_ = cls(
            dynamic=dynamic,
            static=static,
            total=total,
        )


        instance_.additional_properties = d
        return instance_

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> Any:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
