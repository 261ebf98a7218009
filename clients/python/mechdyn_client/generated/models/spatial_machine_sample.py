from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.body_motion_3 import BodyMotion3
  from ..models.energy_dto import EnergyDto
  from ..models.input_state import InputState
  from ..models.reaction_3 import Reaction3





T = TypeVar("T", bound="SpatialMachineSample")



@_attrs_define
class SpatialMachineSample:
    """ The spatial mechanism at one sample (the same instants as `samples`).

        Attributes:
            bodies (list[BodyMotion3]): Every moving body's motion, vectors in ground axes.
            constraint_residual (float): Largest |Φ| of the joints at the sample, m (an angle's row times the
                drawing's size).
            energy (EnergyDto): The mechanism's energies, J.
            inputs (list[InputState]): Every input, in the order given: the first's coordinate runs on past
                ±π (it is integrated), the others' are read from the position.
            t (float):
            work (float): W, the work of every applied action since t = 0, gravity's and the
                springs' and dampers' included (J): W − (T − T₀) is the energy
                balance's residual.
            reactions (list[Reaction3] | None | Unset): Every joint's reaction on its second body, when asked.
     """

    bodies: list[BodyMotion3]
    constraint_residual: float
    energy: EnergyDto
    inputs: list[InputState]
    t: float
    work: float
    reactions: list[Reaction3] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.body_motion_3 import BodyMotion3 # noqa: PLC0415
        from ..models.energy_dto import EnergyDto # noqa: PLC0415
        from ..models.input_state import InputState # noqa: PLC0415
        from ..models.reaction_3 import Reaction3 # noqa: PLC0415
        bodies = []
        for bodies_item_data in self.bodies:
            bodies_item = bodies_item_data.to_dict()
            bodies.append(bodies_item)



        constraint_residual = self.constraint_residual

        energy = self.energy.to_dict()

        inputs = []
        for inputs_item_data in self.inputs:
            inputs_item = inputs_item_data.to_dict()
            inputs.append(inputs_item)



        t = self.t

        work = self.work

        reactions: list[dict[str, Any]] | None | Unset
        if isinstance(self.reactions, Unset):
            reactions = UNSET
        elif isinstance(self.reactions, list):
            reactions = []
            for reactions_item_data in self.reactions:
                reactions_item = reactions_item_data.to_dict()
                reactions.append(reactions_item)


        else:
            reactions = self.reactions


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "bodies": bodies,
            "constraint_residual": constraint_residual,
            "energy": energy,
            "inputs": inputs,
            "t": t,
            "work": work,
        })
        if reactions is not UNSET:
            field_dict["reactions"] = reactions

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.body_motion_3 import BodyMotion3 # noqa: PLC0415
        from ..models.energy_dto import EnergyDto # noqa: PLC0415
        from ..models.input_state import InputState # noqa: PLC0415
        from ..models.reaction_3 import Reaction3 # noqa: PLC0415
        d = dict(src_dict)
        bodies = []
        _bodies = d.pop("bodies")
        for bodies_item_data in (_bodies):
            bodies_item = BodyMotion3.from_dict(bodies_item_data)



            bodies.append(bodies_item)


        constraint_residual = d.pop("constraint_residual")

        energy = EnergyDto.from_dict(d.pop("energy"))




        inputs = []
        _inputs = d.pop("inputs")
        for inputs_item_data in (_inputs):
            inputs_item = InputState.from_dict(inputs_item_data)



            inputs.append(inputs_item)


        t = d.pop("t")

        work = d.pop("work")

        def _parse_reactions(data: object) -> list[Reaction3] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                reactions_type_0 = []
                _reactions_type_0 = data
                for reactions_type_0_item_data in (_reactions_type_0):
                    reactions_type_0_item = Reaction3.from_dict(reactions_type_0_item_data)



                    reactions_type_0.append(reactions_type_0_item)

                return reactions_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[Reaction3] | None | Unset, data)

        reactions = _parse_reactions(d.pop("reactions", UNSET))


        instance_ = cls(
            bodies=bodies,
            constraint_residual=constraint_residual,
            energy=energy,
            inputs=inputs,
            t=t,
            work=work,
            reactions=reactions,
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
