from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.body_motion import BodyMotion
  from ..models.body_motion_3 import BodyMotion3
  from ..models.contact_dto import ContactDto
  from ..models.energy_dto import EnergyDto
  from ..models.point_state import PointState
  from ..models.reaction_3 import Reaction3
  from ..models.reaction_dto import ReactionDto
  from ..models.shaking_dto import ShakingDto
  from ..models.step_dto_energy_contribution_type_0 import StepDtoEnergyContributionType0





T = TypeVar("T", bound="StepDto")



@_attrs_define
class StepDto:
    """ 
        Attributes:
            input_ (float | list[float]): A number for one input, a list (in input order) for several.
            jacobian_condition (float): Condition number of Φ_q (joints and inputs). The exact 2-norm κ₂ (an
                SVD) where `outputs` has "condition", or where the estimate below
                exceeds 100 (so every near-singular position is measured exactly);
                elsewhere the 1-norm κ₁ from Φ_q's LU: exact (Φ_q⁻¹ formed) up to
                12 coordinates, estimated by Hager's method (LAPACK's xGECON) beyond;
                within a factor of the coordinates' number of κ₂.
            scaled_condition (float): The same of Φ_q scaled by the mechanism's size (each length
                coordinate in units of the drawing's size L, each row divided by its
                largest entry): free of the units and of the size of the drawing,
                it decides the singular (above 1e6) and near-singular (1e4) positions.
            singular (bool): A singular position (toggle, change point): nothing but the input is computed here.
            contacts (list[ContactDto] | None | Unset): Every contact joint's state, with the reactions.
            driving (float | list[float] | None | Unset):
            energy (EnergyDto | None | Unset):
            energy_contribution (None | StepDtoEnergyContributionType0 | Unset): Quinn's energy-contribution coefficient
                T_body/T of each moving body (one input).
            kinematics (list[BodyMotion3] | list[BodyMotion] | None | Unset):
            points (list[PointState] | None | Unset): The points of `track`, where given.
            reactions (list[Reaction3] | list[ReactionDto] | None | Unset):
            reduced_inertia (float | None | Unset): I*(φ), one input only.
            reduced_torque (float | None | Unset): M*(φ) of every load, driver excluded.
            shaking (None | ShakingDto | Unset):
     """

    input_: float | list[float]
    jacobian_condition: float
    scaled_condition: float
    singular: bool
    contacts: list[ContactDto] | None | Unset = UNSET
    driving: float | list[float] | None | Unset = UNSET
    energy: EnergyDto | None | Unset = UNSET
    energy_contribution: None | StepDtoEnergyContributionType0 | Unset = UNSET
    kinematics: list[BodyMotion3] | list[BodyMotion] | None | Unset = UNSET
    points: list[PointState] | None | Unset = UNSET
    reactions: list[Reaction3] | list[ReactionDto] | None | Unset = UNSET
    reduced_inertia: float | None | Unset = UNSET
    reduced_torque: float | None | Unset = UNSET
    shaking: None | ShakingDto | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.body_motion import BodyMotion # noqa: PLC0415
        from ..models.body_motion_3 import BodyMotion3 # noqa: PLC0415
        from ..models.contact_dto import ContactDto # noqa: PLC0415
        from ..models.energy_dto import EnergyDto # noqa: PLC0415
        from ..models.point_state import PointState # noqa: PLC0415
        from ..models.reaction_3 import Reaction3 # noqa: PLC0415
        from ..models.reaction_dto import ReactionDto # noqa: PLC0415
        from ..models.shaking_dto import ShakingDto # noqa: PLC0415
        from ..models.step_dto_energy_contribution_type_0 import StepDtoEnergyContributionType0 # noqa: PLC0415
        input_: float | list[float]
        if isinstance(self.input_, list):
            input_ = self.input_


        else:
            input_ = self.input_

        jacobian_condition = self.jacobian_condition

        scaled_condition = self.scaled_condition

        singular = self.singular

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

        driving: float | list[float] | None | Unset
        if isinstance(self.driving, Unset):
            driving = UNSET
        elif isinstance(self.driving, list):
            driving = self.driving


        else:
            driving = self.driving

        energy: dict[str, Any] | None | Unset
        if isinstance(self.energy, Unset):
            energy = UNSET
        elif isinstance(self.energy, EnergyDto):
            energy = self.energy.to_dict()
        else:
            energy = self.energy

        energy_contribution: dict[str, Any] | None | Unset
        if isinstance(self.energy_contribution, Unset):
            energy_contribution = UNSET
        elif isinstance(self.energy_contribution, StepDtoEnergyContributionType0):
            energy_contribution = self.energy_contribution.to_dict()
        else:
            energy_contribution = self.energy_contribution

        kinematics: list[dict[str, Any]] | None | Unset
        if isinstance(self.kinematics, Unset):
            kinematics = UNSET
        elif isinstance(self.kinematics, list):
            kinematics = []
            for kinematics_item_data in self.kinematics:
                kinematics_item = kinematics_item_data.to_dict()
                kinematics.append(kinematics_item)


        elif isinstance(self.kinematics, list):
            kinematics = []
            for kinematics_item_data in self.kinematics:
                kinematics_item = kinematics_item_data.to_dict()
                kinematics.append(kinematics_item)


        else:
            kinematics = self.kinematics

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

        reactions: list[dict[str, Any]] | None | Unset
        if isinstance(self.reactions, Unset):
            reactions = UNSET
        elif isinstance(self.reactions, list):
            reactions = []
            for reactions_item_data in self.reactions:
                reactions_item = reactions_item_data.to_dict()
                reactions.append(reactions_item)


        elif isinstance(self.reactions, list):
            reactions = []
            for reactions_item_data in self.reactions:
                reactions_item = reactions_item_data.to_dict()
                reactions.append(reactions_item)


        else:
            reactions = self.reactions

        reduced_inertia: float | None | Unset
        if isinstance(self.reduced_inertia, Unset):
            reduced_inertia = UNSET
        else:
            reduced_inertia = self.reduced_inertia

        reduced_torque: float | None | Unset
        if isinstance(self.reduced_torque, Unset):
            reduced_torque = UNSET
        else:
            reduced_torque = self.reduced_torque

        shaking: dict[str, Any] | None | Unset
        if isinstance(self.shaking, Unset):
            shaking = UNSET
        elif isinstance(self.shaking, ShakingDto):
            shaking = self.shaking.to_dict()
        else:
            shaking = self.shaking


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "input": input_,
            "jacobian_condition": jacobian_condition,
            "scaled_condition": scaled_condition,
            "singular": singular,
        })
        if contacts is not UNSET:
            field_dict["contacts"] = contacts
        if driving is not UNSET:
            field_dict["driving"] = driving
        if energy is not UNSET:
            field_dict["energy"] = energy
        if energy_contribution is not UNSET:
            field_dict["energy_contribution"] = energy_contribution
        if kinematics is not UNSET:
            field_dict["kinematics"] = kinematics
        if points is not UNSET:
            field_dict["points"] = points
        if reactions is not UNSET:
            field_dict["reactions"] = reactions
        if reduced_inertia is not UNSET:
            field_dict["reduced_inertia"] = reduced_inertia
        if reduced_torque is not UNSET:
            field_dict["reduced_torque"] = reduced_torque
        if shaking is not UNSET:
            field_dict["shaking"] = shaking

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.body_motion import BodyMotion # noqa: PLC0415
        from ..models.body_motion_3 import BodyMotion3 # noqa: PLC0415
        from ..models.contact_dto import ContactDto # noqa: PLC0415
        from ..models.energy_dto import EnergyDto # noqa: PLC0415
        from ..models.point_state import PointState # noqa: PLC0415
        from ..models.reaction_3 import Reaction3 # noqa: PLC0415
        from ..models.reaction_dto import ReactionDto # noqa: PLC0415
        from ..models.shaking_dto import ShakingDto # noqa: PLC0415
        from ..models.step_dto_energy_contribution_type_0 import StepDtoEnergyContributionType0 # noqa: PLC0415
        d = dict(src_dict)
        def _parse_input_(data: object) -> float | list[float]:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_scalars_type_1 = list(data)

                return componentsschemas_scalars_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float], data)

        input_ = _parse_input_(d.pop("input"))


        jacobian_condition = d.pop("jacobian_condition")

        scaled_condition = d.pop("scaled_condition")

        singular = d.pop("singular")

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


        def _parse_driving(data: object) -> float | list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_scalars_type_1 = list(data)

                return componentsschemas_scalars_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float] | None | Unset, data)

        driving = _parse_driving(d.pop("driving", UNSET))


        def _parse_energy(data: object) -> EnergyDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                energy_type_0 = EnergyDto.from_dict(data)



                return energy_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(EnergyDto | None | Unset, data)

        energy = _parse_energy(d.pop("energy", UNSET))


        def _parse_energy_contribution(data: object) -> None | StepDtoEnergyContributionType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                energy_contribution_type_0 = StepDtoEnergyContributionType0.from_dict(data)



                return energy_contribution_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | StepDtoEnergyContributionType0 | Unset, data)

        energy_contribution = _parse_energy_contribution(d.pop("energy_contribution", UNSET))


        def _parse_kinematics(data: object) -> list[BodyMotion3] | list[BodyMotion] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_kinematics_type_0 = []
                _componentsschemas_kinematics_type_0 = data
                for componentsschemas_kinematics_type_0_item_data in (_componentsschemas_kinematics_type_0):
                    componentsschemas_kinematics_type_0_item = BodyMotion.from_dict(componentsschemas_kinematics_type_0_item_data)



                    componentsschemas_kinematics_type_0.append(componentsschemas_kinematics_type_0_item)

                return componentsschemas_kinematics_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_kinematics_type_1 = []
                _componentsschemas_kinematics_type_1 = data
                for componentsschemas_kinematics_type_1_item_data in (_componentsschemas_kinematics_type_1):
                    componentsschemas_kinematics_type_1_item = BodyMotion3.from_dict(componentsschemas_kinematics_type_1_item_data)



                    componentsschemas_kinematics_type_1.append(componentsschemas_kinematics_type_1_item)

                return componentsschemas_kinematics_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[BodyMotion3] | list[BodyMotion] | None | Unset, data)

        kinematics = _parse_kinematics(d.pop("kinematics", UNSET))


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


        def _parse_reactions(data: object) -> list[Reaction3] | list[ReactionDto] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_step_reactions_schema_type_0 = []
                _componentsschemas_step_reactions_schema_type_0 = data
                for componentsschemas_step_reactions_schema_type_0_item_data in (_componentsschemas_step_reactions_schema_type_0):
                    componentsschemas_step_reactions_schema_type_0_item = ReactionDto.from_dict(componentsschemas_step_reactions_schema_type_0_item_data)



                    componentsschemas_step_reactions_schema_type_0.append(componentsschemas_step_reactions_schema_type_0_item)

                return componentsschemas_step_reactions_schema_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_step_reactions_schema_type_1 = []
                _componentsschemas_step_reactions_schema_type_1 = data
                for componentsschemas_step_reactions_schema_type_1_item_data in (_componentsschemas_step_reactions_schema_type_1):
                    componentsschemas_step_reactions_schema_type_1_item = Reaction3.from_dict(componentsschemas_step_reactions_schema_type_1_item_data)



                    componentsschemas_step_reactions_schema_type_1.append(componentsschemas_step_reactions_schema_type_1_item)

                return componentsschemas_step_reactions_schema_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[Reaction3] | list[ReactionDto] | None | Unset, data)

        reactions = _parse_reactions(d.pop("reactions", UNSET))


        def _parse_reduced_inertia(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        reduced_inertia = _parse_reduced_inertia(d.pop("reduced_inertia", UNSET))


        def _parse_reduced_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        reduced_torque = _parse_reduced_torque(d.pop("reduced_torque", UNSET))


        def _parse_shaking(data: object) -> None | ShakingDto | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                shaking_type_0 = ShakingDto.from_dict(data)



                return shaking_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | ShakingDto | Unset, data)

        shaking = _parse_shaking(d.pop("shaking", UNSET))


        instance_ = cls(
            input_=input_,
            jacobian_condition=jacobian_condition,
            scaled_condition=scaled_condition,
            singular=singular,
            contacts=contacts,
            driving=driving,
            energy=energy,
            energy_contribution=energy_contribution,
            kinematics=kinematics,
            points=points,
            reactions=reactions,
            reduced_inertia=reduced_inertia,
            reduced_torque=reduced_torque,
            shaking=shaking,
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
