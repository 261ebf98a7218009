from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="DiskDto")



@_attrs_define
class DiskDto:
    """ A solid disk holding `flywheel_inertia.exact` (I = ½MR²): exactly one
    of `rim_speed`, `radius`, `thickness`, and its `density` (needed with a
    thickness; without one, a disk sized by its radius or rim speed has its
    mass M = 2I/R² and no thickness).

        Attributes:
            density (float | None | str | Unset):
            radius (float | None | str | Unset):
            rim_speed (float | None | str | Unset):
            thickness (float | None | str | Unset):
     """

    density: float | None | str | Unset = UNSET
    radius: float | None | str | Unset = UNSET
    rim_speed: float | None | str | Unset = UNSET
    thickness: float | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        density: float | None | str | Unset
        if isinstance(self.density, Unset):
            density = UNSET
        else:
            density = self.density

        radius: float | None | str | Unset
        if isinstance(self.radius, Unset):
            radius = UNSET
        else:
            radius = self.radius

        rim_speed: float | None | str | Unset
        if isinstance(self.rim_speed, Unset):
            rim_speed = UNSET
        else:
            rim_speed = self.rim_speed

        thickness: float | None | str | Unset
        if isinstance(self.thickness, Unset):
            thickness = UNSET
        else:
            thickness = self.thickness


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
        })
        if density is not UNSET:
            field_dict["density"] = density
        if radius is not UNSET:
            field_dict["radius"] = radius
        if rim_speed is not UNSET:
            field_dict["rim_speed"] = rim_speed
        if thickness is not UNSET:
            field_dict["thickness"] = thickness

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        def _parse_density(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        density = _parse_density(d.pop("density", UNSET))


        def _parse_radius(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        radius = _parse_radius(d.pop("radius", UNSET))


        def _parse_rim_speed(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        rim_speed = _parse_rim_speed(d.pop("rim_speed", UNSET))


        def _parse_thickness(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        thickness = _parse_thickness(d.pop("thickness", UNSET))


        instance_ = cls(
            density=density,
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
