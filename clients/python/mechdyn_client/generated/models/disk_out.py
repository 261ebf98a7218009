from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="DiskOut")



@_attrs_define
class DiskOut:
    """ 
        Attributes:
            mass (float): kg
            radius (float): m
            rim_speed (float): m/s, R·k·ω_a: the rim's mean speed (k the flywheel shaft's `ratio`).
            thickness (float | None | Unset): m; null without a `density`.
     """

    mass: float
    radius: float
    rim_speed: float
    thickness: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        mass = self.mass

        radius = self.radius

        rim_speed = self.rim_speed

        thickness: float | None | Unset
        if isinstance(self.thickness, Unset):
            thickness = UNSET
        else:
            thickness = self.thickness


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "mass": mass,
            "radius": radius,
            "rim_speed": rim_speed,
        })
        if thickness is not UNSET:
            field_dict["thickness"] = thickness

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        mass = d.pop("mass")

        radius = d.pop("radius")

        rim_speed = d.pop("rim_speed")

        def _parse_thickness(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thickness = _parse_thickness(d.pop("thickness", UNSET))


        instance_ = cls(
            mass=mass,
            radius=radius,
            rim_speed=rim_speed,
            thickness=thickness,
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
