from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset







T = TypeVar("T", bound="DynamicsSample")



@_attrs_define
class DynamicsSample:
    """ One sample of the motion.

        Attributes:
            acceleration (float):
            angle (float):
            energy_residual (float): (W − ΔT)/max(|W|, |ΔT|, T₀, T, T_peak) from the start to this sample, W the
                work of the actions (mechanism form: −ΔV where they have a
                potential and no contact has friction; else their integrated power),
                T_peak the largest T sampled so far: the energy balance's drift.
            speed (float):
            t (float):
     """

    acceleration: float
    angle: float
    energy_residual: float
    speed: float
    t: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        acceleration = self.acceleration

        angle = self.angle

        energy_residual = self.energy_residual

        speed = self.speed

        t = self.t


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "acceleration": acceleration,
            "angle": angle,
            "energy_residual": energy_residual,
            "speed": speed,
            "t": t,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        acceleration = d.pop("acceleration")

        angle = d.pop("angle")

        energy_residual = d.pop("energy_residual")

        speed = d.pop("speed")

        t = d.pop("t")

        instance_ = cls(
            acceleration=acceleration,
            angle=angle,
            energy_residual=energy_residual,
            speed=speed,
            t=t,
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
