from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast






T = TypeVar("T", bound="CorrectionPlaneDto")



@_attrs_define
class CorrectionPlaneDto:
    """ A correction plane: its axial position and the radius where its mass is put.

        Attributes:
            radius (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            z (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
     """

    radius: float | str
    z: float | str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        radius: float | str
        radius = self.radius

        z: float | str
        z = self.z


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "radius": radius,
            "z": z,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        def _parse_radius(data: object) -> float | str:
            return cast(float | str, data)

        radius = _parse_radius(d.pop("radius"))


        def _parse_z(data: object) -> float | str:
            return cast(float | str, data)

        z = _parse_z(d.pop("z"))


        instance_ = cls(
            radius=radius,
            z=z,
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
