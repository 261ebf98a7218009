from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.kinetic_energy import KineticEnergy
  from ..models.potential_energy import PotentialEnergy





T = TypeVar("T", bound="EnergyDto")



@_attrs_define
class EnergyDto:
    """ The mechanism's energies, J.

        Attributes:
            kinetic (KineticEnergy): T = Σ ½(m v_G² + I_G ω²), and each moving body's share.
            potential (PotentialEnergy): Gravity's −Σ m g·r_G (r_G from the drawing's origin) and the springs' Σ ½k(l −
                l₀)².
     """

    kinetic: KineticEnergy
    potential: PotentialEnergy
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.kinetic_energy import KineticEnergy # noqa: PLC0415
        from ..models.potential_energy import PotentialEnergy # noqa: PLC0415
        kinetic = self.kinetic.to_dict()

        potential = self.potential.to_dict()


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "kinetic": kinetic,
            "potential": potential,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.kinetic_energy import KineticEnergy # noqa: PLC0415
        from ..models.potential_energy import PotentialEnergy # noqa: PLC0415
        d = dict(src_dict)
        kinetic = KineticEnergy.from_dict(d.pop("kinetic"))




        potential = PotentialEnergy.from_dict(d.pop("potential"))




        instance_ = cls(
            kinetic=kinetic,
            potential=potential,
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
