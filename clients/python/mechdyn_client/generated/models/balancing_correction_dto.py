from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset







T = TypeVar("T", bound="BalancingCorrectionDto")



@_attrs_define
class BalancingCorrectionDto:
    """ The mass to add in a plane: at the plane's radius and angle; m·R.

        Attributes:
            angle (float):
            mass (float):
            mass_radius (float):
            plane (float): z of the plane.
            radius (float):
     """

    angle: float
    mass: float
    mass_radius: float
    plane: float
    radius: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        angle = self.angle

        mass = self.mass

        mass_radius = self.mass_radius

        plane = self.plane

        radius = self.radius


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "angle": angle,
            "mass": mass,
            "mass_radius": mass_radius,
            "plane": plane,
            "radius": radius,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        angle = d.pop("angle")

        mass = d.pop("mass")

        mass_radius = d.pop("mass_radius")

        plane = d.pop("plane")

        radius = d.pop("radius")

        instance_ = cls(
            angle=angle,
            mass=mass,
            mass_radius=mass_radius,
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
