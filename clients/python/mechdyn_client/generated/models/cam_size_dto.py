from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="CamSizeDto")



@_attrs_define
class CamSizeDto:
    """ 
        Attributes:
            max_pressure_angle (float | None | str | Unset):
            min_curvature_radius (float | None | str | Unset):
     """

    max_pressure_angle: float | None | str | Unset = UNSET
    min_curvature_radius: float | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        max_pressure_angle: float | None | str | Unset
        if isinstance(self.max_pressure_angle, Unset):
            max_pressure_angle = UNSET
        else:
            max_pressure_angle = self.max_pressure_angle

        min_curvature_radius: float | None | str | Unset
        if isinstance(self.min_curvature_radius, Unset):
            min_curvature_radius = UNSET
        else:
            min_curvature_radius = self.min_curvature_radius


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
        })
        if max_pressure_angle is not UNSET:
            field_dict["max_pressure_angle"] = max_pressure_angle
        if min_curvature_radius is not UNSET:
            field_dict["min_curvature_radius"] = min_curvature_radius

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        def _parse_max_pressure_angle(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        max_pressure_angle = _parse_max_pressure_angle(d.pop("max_pressure_angle", UNSET))


        def _parse_min_curvature_radius(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        min_curvature_radius = _parse_min_curvature_radius(d.pop("min_curvature_radius", UNSET))


        instance_ = cls(
            max_pressure_angle=max_pressure_angle,
            min_curvature_radius=min_curvature_radius,
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
