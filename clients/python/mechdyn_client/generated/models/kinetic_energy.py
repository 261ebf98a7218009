from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.kinetic_energy_bodies import KineticEnergyBodies





T = TypeVar("T", bound="KineticEnergy")



@_attrs_define
class KineticEnergy:
    """ T = Σ ½(m v_G² + I_G ω²), and each moving body's share.

        Attributes:
            bodies (KineticEnergyBodies):
            total (float):
     """

    bodies: KineticEnergyBodies
    total: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.kinetic_energy_bodies import KineticEnergyBodies # noqa: PLC0415
        bodies = self.bodies.to_dict()

        total = self.total


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "bodies": bodies,
            "total": total,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.kinetic_energy_bodies import KineticEnergyBodies # noqa: PLC0415
        d = dict(src_dict)
        bodies = KineticEnergyBodies.from_dict(d.pop("bodies"))




        total = d.pop("total")

        instance_ = cls(
            bodies=bodies,
            total=total,
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
