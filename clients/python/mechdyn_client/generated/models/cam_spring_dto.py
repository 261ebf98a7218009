from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="CamSpringDto")



@_attrs_define
class CamSpringDto:
    """ 
        Attributes:
            stiffness (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            preload (float | None | str | Unset):
     """

    stiffness: float | str
    preload: float | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        stiffness: float | str
        stiffness = self.stiffness

        preload: float | None | str | Unset
        if isinstance(self.preload, Unset):
            preload = UNSET
        else:
            preload = self.preload


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "stiffness": stiffness,
        })
        if preload is not UNSET:
            field_dict["preload"] = preload

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        def _parse_stiffness(data: object) -> float | str:
            return cast(float | str, data)

        stiffness = _parse_stiffness(d.pop("stiffness"))


        def _parse_preload(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        preload = _parse_preload(d.pop("preload", UNSET))


        instance_ = cls(
            stiffness=stiffness,
            preload=preload,
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
