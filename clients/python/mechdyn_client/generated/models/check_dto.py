from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset







T = TypeVar("T", bound="CheckDto")



@_attrs_define
class CheckDto:
    """ Measured on an independent time simulation of the steady state with `inertia_exact`.

        Attributes:
            cycle_time (float): Duration of one cycle, s.
            irregularity (float):
            mean_speed (float): (ω_max + ω_min)/2 of the simulation, rad/s.
            omega_max (float):
            omega_min (float):
            periodicity_error (float): |ω(period) − ω(0)|/ω_a of the simulated motion.
            steps (int):
     """

    cycle_time: float
    irregularity: float
    mean_speed: float
    omega_max: float
    omega_min: float
    periodicity_error: float
    steps: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        cycle_time = self.cycle_time

        irregularity = self.irregularity

        mean_speed = self.mean_speed

        omega_max = self.omega_max

        omega_min = self.omega_min

        periodicity_error = self.periodicity_error

        steps = self.steps


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "cycle_time": cycle_time,
            "irregularity": irregularity,
            "mean_speed": mean_speed,
            "omega_max": omega_max,
            "omega_min": omega_min,
            "periodicity_error": periodicity_error,
            "steps": steps,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        cycle_time = d.pop("cycle_time")

        irregularity = d.pop("irregularity")

        mean_speed = d.pop("mean_speed")

        omega_max = d.pop("omega_max")

        omega_min = d.pop("omega_min")

        periodicity_error = d.pop("periodicity_error")

        steps = d.pop("steps")

        instance_ = cls(
            cycle_time=cycle_time,
            irregularity=irregularity,
            mean_speed=mean_speed,
            omega_max=omega_max,
            omega_min=omega_min,
            periodicity_error=periodicity_error,
            steps=steps,
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
