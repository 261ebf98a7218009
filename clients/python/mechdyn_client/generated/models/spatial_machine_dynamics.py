from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.mechanism_space import MechanismSpace
from typing import cast

if TYPE_CHECKING:
  from ..models.spatial_machine_sample import SpatialMachineSample





T = TypeVar("T", bound="SpatialMachineDynamics")



@_attrs_define
class SpatialMachineDynamics:
    """ What a spatial machine adds to a dynamics result.

        Attributes:
            dof (int): Degrees of freedom at the start (one input each).
            input_units (list[str]): Each input's coordinate unit: "rad" (a rotation) or "m" (a slide);
                speeds and accelerations per second.
            redundant_constraints (int): Constraint rows that repeat others at the start (Bricard's linkage
                has one), left out of the equations; the reactions they share are
                then not determinate.
            samples (list[SpatialMachineSample]):
            space (MechanismSpace): The plane or space.
     """

    dof: int
    input_units: list[str]
    redundant_constraints: int
    samples: list[SpatialMachineSample]
    space: MechanismSpace
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.spatial_machine_sample import SpatialMachineSample # noqa: PLC0415
        dof = self.dof

        input_units = self.input_units



        redundant_constraints = self.redundant_constraints

        samples = []
        for samples_item_data in self.samples:
            samples_item = samples_item_data.to_dict()
            samples.append(samples_item)



        space = self.space.value


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "dof": dof,
            "input_units": input_units,
            "redundant_constraints": redundant_constraints,
            "samples": samples,
            "space": space,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.spatial_machine_sample import SpatialMachineSample # noqa: PLC0415
        d = dict(src_dict)
        dof = d.pop("dof")

        input_units = cast(list[str], d.pop("input_units"))


        redundant_constraints = d.pop("redundant_constraints")

        samples = []
        _samples = d.pop("samples")
        for samples_item_data in (_samples):
            samples_item = SpatialMachineSample.from_dict(samples_item_data)



            samples.append(samples_item)


        space = MechanismSpace(d.pop("space"))




        instance_ = cls(
            dof=dof,
            input_units=input_units,
            redundant_constraints=redundant_constraints,
            samples=samples,
            space=space,
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
