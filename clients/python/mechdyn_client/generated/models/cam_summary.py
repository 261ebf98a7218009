from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.at_angle import AtAngle





T = TypeVar("T", bound="CamSummary")



@_attrs_define
class CamSummary:
    """ 
        Attributes:
            base_radius (float): m (given, or the smallest meeting `size`).
            lift_unit (str): The lift's unit: "m" (translating), or "rad" (oscillating: then
                its velocity is rad/s, its acceleration rad/s², the preload N·m).
            max_pressure_angle (AtAngle): A value and the cam angle where it is.
            min_curvature_radius (AtAngle): A value and the cam angle where it is.
            undercut (bool): The profile folds on itself (a roller larger than the pitch curve's
                convex radius; a flat face on a concave stretch).
            critical_speed (float | None | Unset): With `dynamics`: the cam speed above which the follower leaves the cam
                (rad/s; null: none).
            face_width (float | None | Unset): A flat face: the smallest width that keeps contact (m).
            min_preload (float | None | Unset): With `dynamics`: the least spring preload that keeps contact at `speed` (N).
            separation (list[list[float]] | None | Unset): With `dynamics`: the angle ranges [from, to] (rad) where the
                contact force is negative (null: none).
     """

    base_radius: float
    lift_unit: str
    max_pressure_angle: AtAngle
    min_curvature_radius: AtAngle
    undercut: bool
    critical_speed: float | None | Unset = UNSET
    face_width: float | None | Unset = UNSET
    min_preload: float | None | Unset = UNSET
    separation: list[list[float]] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.at_angle import AtAngle # noqa: PLC0415
        base_radius = self.base_radius

        lift_unit = self.lift_unit

        max_pressure_angle = self.max_pressure_angle.to_dict()

        min_curvature_radius = self.min_curvature_radius.to_dict()

        undercut = self.undercut

        critical_speed: float | None | Unset
        if isinstance(self.critical_speed, Unset):
            critical_speed = UNSET
        else:
            critical_speed = self.critical_speed

        face_width: float | None | Unset
        if isinstance(self.face_width, Unset):
            face_width = UNSET
        else:
            face_width = self.face_width

        min_preload: float | None | Unset
        if isinstance(self.min_preload, Unset):
            min_preload = UNSET
        else:
            min_preload = self.min_preload

        separation: list[list[float]] | None | Unset
        if isinstance(self.separation, Unset):
            separation = UNSET
        elif isinstance(self.separation, list):
            separation = []
            for separation_item_data in self.separation:
                separation_item = separation_item_data


                separation.append(separation_item)


        else:
            separation = self.separation


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "base_radius": base_radius,
            "lift_unit": lift_unit,
            "max_pressure_angle": max_pressure_angle,
            "min_curvature_radius": min_curvature_radius,
            "undercut": undercut,
        })
        if critical_speed is not UNSET:
            field_dict["critical_speed"] = critical_speed
        if face_width is not UNSET:
            field_dict["face_width"] = face_width
        if min_preload is not UNSET:
            field_dict["min_preload"] = min_preload
        if separation is not UNSET:
            field_dict["separation"] = separation

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.at_angle import AtAngle # noqa: PLC0415
        d = dict(src_dict)
        base_radius = d.pop("base_radius")

        lift_unit = d.pop("lift_unit")

        max_pressure_angle = AtAngle.from_dict(d.pop("max_pressure_angle"))




        min_curvature_radius = AtAngle.from_dict(d.pop("min_curvature_radius"))




        undercut = d.pop("undercut")

        def _parse_critical_speed(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        critical_speed = _parse_critical_speed(d.pop("critical_speed", UNSET))


        def _parse_face_width(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        face_width = _parse_face_width(d.pop("face_width", UNSET))


        def _parse_min_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        min_preload = _parse_min_preload(d.pop("min_preload", UNSET))


        def _parse_separation(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                separation_type_0 = []
                _separation_type_0 = data
                for separation_type_0_item_data in (_separation_type_0):
                    separation_type_0_item = cast(list[float], separation_type_0_item_data)

                    separation_type_0.append(separation_type_0_item)

                return separation_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        separation = _parse_separation(d.pop("separation", UNSET))


        instance_ = cls(
            base_radius=base_radius,
            lift_unit=lift_unit,
            max_pressure_angle=max_pressure_angle,
            min_curvature_radius=min_curvature_radius,
            undercut=undercut,
            critical_speed=critical_speed,
            face_width=face_width,
            min_preload=min_preload,
            separation=separation,
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
