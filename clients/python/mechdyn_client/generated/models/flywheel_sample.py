from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset







T = TypeVar("T", bound="FlywheelSample")



@_attrs_define
class FlywheelSample:
    """ One row of the sampled cycle (also the rows of the CSV export).

        Attributes:
            angle (float): φ, rad
            reduced_inertia (float): I*(φ), kg·m²
            reduced_torque (float): M*(φ), N·m
            speed (float): ω(φ) with the exact inertia, rad/s
            work (float): W(φ) = ∫₀^φ M*, J
     """

    angle: float
    reduced_inertia: float
    reduced_torque: float
    speed: float
    work: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        angle = self.angle

        reduced_inertia = self.reduced_inertia

        reduced_torque = self.reduced_torque

        speed = self.speed

        work = self.work


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "angle": angle,
            "reduced_inertia": reduced_inertia,
            "reduced_torque": reduced_torque,
            "speed": speed,
            "work": work,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        angle = d.pop("angle")

        reduced_inertia = d.pop("reduced_inertia")

        reduced_torque = d.pop("reduced_torque")

        speed = d.pop("speed")

        work = d.pop("work")

        instance_ = cls(
            angle=angle,
            reduced_inertia=reduced_inertia,
            reduced_torque=reduced_torque,
            speed=speed,
            work=work,
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
