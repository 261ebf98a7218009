from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast






T = TypeVar("T", bound="PointMassDto")



@_attrs_define
class PointMassDto:
    """ A point mass: its mass, radius and angle (CCW from the rotor's x axis) in the plane at z = `plane`.

        Attributes:
            angle (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            mass (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            plane (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            radius (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
     """

    angle: float | str
    mass: float | str
    plane: float | str
    radius: float | str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        angle: float | str
        angle = self.angle

        mass: float | str
        mass = self.mass

        plane: float | str
        plane = self.plane

        radius: float | str
        radius = self.radius


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "angle": angle,
            "mass": mass,
            "plane": plane,
            "radius": radius,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        def _parse_angle(data: object) -> float | str:
            return cast(float | str, data)

        angle = _parse_angle(d.pop("angle"))


        def _parse_mass(data: object) -> float | str:
            return cast(float | str, data)

        mass = _parse_mass(d.pop("mass"))


        def _parse_plane(data: object) -> float | str:
            return cast(float | str, data)

        plane = _parse_plane(d.pop("plane"))


        def _parse_radius(data: object) -> float | str:
            return cast(float | str, data)

        radius = _parse_radius(d.pop("radius"))


        instance_ = cls(
            angle=angle,
            mass=mass,
            plane=plane,
            radius=radius,
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
