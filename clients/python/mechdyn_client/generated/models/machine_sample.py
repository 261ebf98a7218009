from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.body_position import BodyPosition
  from ..models.contact_dto import ContactDto
  from ..models.energy_dto import EnergyDto
  from ..models.input_state import InputState
  from ..models.point_state import PointState
  from ..models.reaction_dto import ReactionDto





T = TypeVar("T", bound="MachineSample")



@_attrs_define
class MachineSample:
    """ The mechanism at one sample (the same instants as `samples`).

        Attributes:
            bodies (list[BodyPosition]): Every moving body's position (the paths and drawings of the plots).
            constraint_residual (float): Largest |Φ| of the joint constraints at the sample, m or rad.
            energy (EnergyDto): The mechanism's energies, J.
            inputs (list[InputState]): Every input, in the order given.
            reactions (list[ReactionDto]): Joint reactions (the force body `by` exerts on body `on`), when asked.
            t (float):
            contacts (list[ContactDto] | None | Unset): Every contact joint's state, with the reactions.
            points (list[PointState] | None | Unset): The points of `track`, where given.
     """

    bodies: list[BodyPosition]
    constraint_residual: float
    energy: EnergyDto
    inputs: list[InputState]
    reactions: list[ReactionDto]
    t: float
    contacts: list[ContactDto] | None | Unset = UNSET
    points: list[PointState] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.body_position import BodyPosition # noqa: PLC0415
        from ..models.contact_dto import ContactDto # noqa: PLC0415
        from ..models.energy_dto import EnergyDto # noqa: PLC0415
        from ..models.input_state import InputState # noqa: PLC0415
        from ..models.point_state import PointState # noqa: PLC0415
        from ..models.reaction_dto import ReactionDto # noqa: PLC0415
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



        reactions = []
        for reactions_item_data in self.reactions:
            reactions_item = reactions_item_data.to_dict()
            reactions.append(reactions_item)



        t = self.t

        contacts: list[dict[str, Any]] | None | Unset
        if isinstance(self.contacts, Unset):
            contacts = UNSET
        elif isinstance(self.contacts, list):
            contacts = []
            for contacts_item_data in self.contacts:
                contacts_item = contacts_item_data.to_dict()
                contacts.append(contacts_item)


        else:
            contacts = self.contacts

        points: list[dict[str, Any]] | None | Unset
        if isinstance(self.points, Unset):
            points = UNSET
        elif isinstance(self.points, list):
            points = []
            for points_item_data in self.points:
                points_item = points_item_data.to_dict()
                points.append(points_item)


        else:
            points = self.points


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "bodies": bodies,
            "constraint_residual": constraint_residual,
            "energy": energy,
            "inputs": inputs,
            "reactions": reactions,
            "t": t,
        })
        if contacts is not UNSET:
            field_dict["contacts"] = contacts
        if points is not UNSET:
            field_dict["points"] = points

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.body_position import BodyPosition # noqa: PLC0415
        from ..models.contact_dto import ContactDto # noqa: PLC0415
        from ..models.energy_dto import EnergyDto # noqa: PLC0415
        from ..models.input_state import InputState # noqa: PLC0415
        from ..models.point_state import PointState # noqa: PLC0415
        from ..models.reaction_dto import ReactionDto # noqa: PLC0415
        d = dict(src_dict)
        bodies = []
        _bodies = d.pop("bodies")
        for bodies_item_data in (_bodies):
            bodies_item = BodyPosition.from_dict(bodies_item_data)



            bodies.append(bodies_item)


        constraint_residual = d.pop("constraint_residual")

        energy = EnergyDto.from_dict(d.pop("energy"))




        inputs = []
        _inputs = d.pop("inputs")
        for inputs_item_data in (_inputs):
            inputs_item = InputState.from_dict(inputs_item_data)



            inputs.append(inputs_item)


        reactions = []
        _reactions = d.pop("reactions")
        for reactions_item_data in (_reactions):
            reactions_item = ReactionDto.from_dict(reactions_item_data)



            reactions.append(reactions_item)


        t = d.pop("t")

        def _parse_contacts(data: object) -> list[ContactDto] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                contacts_type_0 = []
                _contacts_type_0 = data
                for contacts_type_0_item_data in (_contacts_type_0):
                    contacts_type_0_item = ContactDto.from_dict(contacts_type_0_item_data)



                    contacts_type_0.append(contacts_type_0_item)

                return contacts_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[ContactDto] | None | Unset, data)

        contacts = _parse_contacts(d.pop("contacts", UNSET))


        def _parse_points(data: object) -> list[PointState] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                points_type_0 = []
                _points_type_0 = data
                for points_type_0_item_data in (_points_type_0):
                    points_type_0_item = PointState.from_dict(points_type_0_item_data)



                    points_type_0.append(points_type_0_item)

                return points_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[PointState] | None | Unset, data)

        points = _parse_points(d.pop("points", UNSET))


        instance_ = cls(
            bodies=bodies,
            constraint_residual=constraint_residual,
            energy=energy,
            inputs=inputs,
            reactions=reactions,
            t=t,
            contacts=contacts,
            points=points,
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
