from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.machine_dynamics_assembled_points_type_0 import MachineDynamicsAssembledPointsType0
  from ..models.machine_sample import MachineSample





T = TypeVar("T", bound="MachineDynamics")



@_attrs_define
class MachineDynamics:
    """ What the mechanism form adds to a dynamics result.

        Attributes:
            dof (int): Degrees of freedom at the start (one input each).
            input_units (list[str]): Each input's coordinate unit: "rad" (a revolute joint, a body) or
                "m" (a prismatic joint, a point); speeds and accelerations per second.
            near_singular (list[float]): Times (s) at which the integration met the joint Jacobian within 1e-5
                (relative singular value) of losing rank — a singular position, such
                as a parallelogram lying flat, passed at close range. There the motion
                along the fold was held (the mechanism stays on its branch) and the
                reactions of the joints involved are not determinate. Singular
                positions the steps passed over at a distance are not listed.
            redundant_constraints (int): Constraints that repeat others (their reactions are then not determinate).
            samples (list[MachineSample]):
            assembled_points (MachineDynamicsAssembledPointsType0 | None | Unset): Where the points went, for a mechanism
                given by its `dimensions` (m).
     """

    dof: int
    input_units: list[str]
    near_singular: list[float]
    redundant_constraints: int
    samples: list[MachineSample]
    assembled_points: MachineDynamicsAssembledPointsType0 | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.machine_dynamics_assembled_points_type_0 import MachineDynamicsAssembledPointsType0 # noqa: PLC0415
        from ..models.machine_sample import MachineSample # noqa: PLC0415
        dof = self.dof

        input_units = self.input_units



        near_singular = self.near_singular



        redundant_constraints = self.redundant_constraints

        samples = []
        for samples_item_data in self.samples:
            samples_item = samples_item_data.to_dict()
            samples.append(samples_item)



        assembled_points: dict[str, Any] | None | Unset
        if isinstance(self.assembled_points, Unset):
            assembled_points = UNSET
        elif isinstance(self.assembled_points, MachineDynamicsAssembledPointsType0):
            assembled_points = self.assembled_points.to_dict()
        else:
            assembled_points = self.assembled_points


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "dof": dof,
            "input_units": input_units,
            "near_singular": near_singular,
            "redundant_constraints": redundant_constraints,
            "samples": samples,
        })
        if assembled_points is not UNSET:
            field_dict["assembled_points"] = assembled_points

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.machine_dynamics_assembled_points_type_0 import MachineDynamicsAssembledPointsType0 # noqa: PLC0415
        from ..models.machine_sample import MachineSample # noqa: PLC0415
        d = dict(src_dict)
        dof = d.pop("dof")

        input_units = cast(list[str], d.pop("input_units"))


        near_singular = cast(list[float], d.pop("near_singular"))


        redundant_constraints = d.pop("redundant_constraints")

        samples = []
        _samples = d.pop("samples")
        for samples_item_data in (_samples):
            samples_item = MachineSample.from_dict(samples_item_data)



            samples.append(samples_item)


        def _parse_assembled_points(data: object) -> MachineDynamicsAssembledPointsType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                assembled_points_type_0 = MachineDynamicsAssembledPointsType0.from_dict(data)



                return assembled_points_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(MachineDynamicsAssembledPointsType0 | None | Unset, data)

        assembled_points = _parse_assembled_points(d.pop("assembled_points", UNSET))


        instance_ = cls(
            dof=dof,
            input_units=input_units,
            near_singular=near_singular,
            redundant_constraints=redundant_constraints,
            samples=samples,
            assembled_points=assembled_points,
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
