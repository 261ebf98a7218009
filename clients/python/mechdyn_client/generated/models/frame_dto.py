from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="FrameDto")



@_attrs_define
class FrameDto:
    """ The frame's motion about x: speed Ω₀ and angle φ₀ at t = 0, constant acceleration γ.

        Attributes:
            speed (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            acceleration (float | None | str | Unset):
            angle (float | None | str | Unset):
     """

    speed: float | str
    acceleration: float | None | str | Unset = UNSET
    angle: float | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        speed: float | str
        speed = self.speed

        acceleration: float | None | str | Unset
        if isinstance(self.acceleration, Unset):
            acceleration = UNSET
        else:
            acceleration = self.acceleration

        angle: float | None | str | Unset
        if isinstance(self.angle, Unset):
            angle = UNSET
        else:
            angle = self.angle


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "speed": speed,
        })
        if acceleration is not UNSET:
            field_dict["acceleration"] = acceleration
        if angle is not UNSET:
            field_dict["angle"] = angle

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        def _parse_speed(data: object) -> float | str:
            return cast(float | str, data)

        speed = _parse_speed(d.pop("speed"))


        def _parse_acceleration(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        acceleration = _parse_acceleration(d.pop("acceleration", UNSET))


        def _parse_angle(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        angle = _parse_angle(d.pop("angle", UNSET))


        instance_ = cls(
            speed=speed,
            acceleration=acceleration,
            angle=angle,
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
