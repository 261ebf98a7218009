from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast






T = TypeVar("T", bound="Group")



@_attrs_define
class Group:
    """ An Assur group (or an input's body with its effort): bodies whose
    equations, once the groups before are solved, give their unknowns.

        Attributes:
            bodies (list[str]):
            unknowns (list[str]): The reactions and efforts its equations give (`R34`, `M_m`).
     """

    bodies: list[str]
    unknowns: list[str]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        bodies = self.bodies



        unknowns = self.unknowns




        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "bodies": bodies,
            "unknowns": unknowns,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        bodies = cast(list[str], d.pop("bodies"))


        unknowns = cast(list[str], d.pop("unknowns"))


        instance_ = cls(
            bodies=bodies,
            unknowns=unknowns,
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
