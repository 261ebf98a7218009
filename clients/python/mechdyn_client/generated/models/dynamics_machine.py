from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.input_dto import InputDto
  from ..models.load_dto import LoadDto
  from ..models.mechanism_dto import MechanismDto
  from ..models.track_dto_type_1 import TrackDtoType1





T = TypeVar("T", bound="DynamicsMachine")



@_attrs_define
class DynamicsMachine:
    """ A mechanism with free input joints, and its loads. A spatial one
    (`"space": "spatial"`) has joints' rotations or slides for inputs, and
    its result `machine` says `"space": "spatial"`, each body's motion and
    each reaction as vectors.

        Attributes:
            input_ (InputDto | list[InputDto]):
            mechanism (MechanismDto): A mechanism drawn in one assembled configuration, planar (see the
                example of KinetostaticsRequest) or, with `"space": "spatial"`, in
                three dimensions.
            conserve_energy (bool | None | Unset): Hold the energy T + V to its initial value after every step (the
                velocities scaled onto it): a long conservative run's error then
                grows linearly with time instead of quadratically. Default: wherever
                every load has a potential (springs, constant forces and torques;
                gravity always has one);
                `false` integrates without it; `true` requires it.
            loads (list[LoadDto] | None | Unset): Loads as in kinetostatics; their Functions may read `phi` (the first
                input's angle reduced to the period), `omega` (its speed) and `t`.
                Joint friction is not supported in dynamics, but at a rolling contact
                (it rolls while |tangential| ≤ μ·normal, and slips otherwise).
            reactions (bool | None | Unset): Report the joint reactions at every sample (default true).
            track (list[str | TrackDtoType1] | None | Unset): Points to follow, as in kinetostatics: each sample then has
                their
                `points` (position, velocity, acceleration).
     """

    input_: InputDto | list[InputDto]
    mechanism: MechanismDto
    conserve_energy: bool | None | Unset = UNSET
    loads: list[LoadDto] | None | Unset = UNSET
    reactions: bool | None | Unset = UNSET
    track: list[str | TrackDtoType1] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.input_dto import InputDto # noqa: PLC0415
        from ..models.load_dto import LoadDto # noqa: PLC0415
        from ..models.mechanism_dto import MechanismDto # noqa: PLC0415
        from ..models.track_dto_type_1 import TrackDtoType1 # noqa: PLC0415
        input_: dict[str, Any] | list[dict[str, Any]]
        if isinstance(self.input_, InputDto):
            input_ = self.input_.to_dict()
        else:
            input_ = []
            for input__item_data in self.input_:
                input__item = input__item_data.to_dict()
                input_.append(input__item)




        mechanism = self.mechanism.to_dict()

        conserve_energy: bool | None | Unset
        if isinstance(self.conserve_energy, Unset):
            conserve_energy = UNSET
        else:
            conserve_energy = self.conserve_energy

        loads: list[dict[str, Any]] | None | Unset
        if isinstance(self.loads, Unset):
            loads = UNSET
        elif isinstance(self.loads, list):
            loads = []
            for loads_item_data in self.loads:
                loads_item = loads_item_data.to_dict()
                loads.append(loads_item)


        else:
            loads = self.loads

        reactions: bool | None | Unset
        if isinstance(self.reactions, Unset):
            reactions = UNSET
        else:
            reactions = self.reactions

        track: list[dict[str, Any] | str] | None | Unset
        if isinstance(self.track, Unset):
            track = UNSET
        elif isinstance(self.track, list):
            track = []
            for track_item_data in self.track:
                track_item: dict[str, Any] | str
                if isinstance(track_item_data, TrackDtoType1):
                    track_item = track_item_data.to_dict()
                else:
                    track_item = track_item_data
                track.append(track_item)


        else:
            track = self.track


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "input": input_,
            "mechanism": mechanism,
        })
        if conserve_energy is not UNSET:
            field_dict["conserve_energy"] = conserve_energy
        if loads is not UNSET:
            field_dict["loads"] = loads
        if reactions is not UNSET:
            field_dict["reactions"] = reactions
        if track is not UNSET:
            field_dict["track"] = track

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.input_dto import InputDto # noqa: PLC0415
        from ..models.load_dto import LoadDto # noqa: PLC0415
        from ..models.mechanism_dto import MechanismDto # noqa: PLC0415
        from ..models.track_dto_type_1 import TrackDtoType1 # noqa: PLC0415
        d = dict(src_dict)
        def _parse_input_(data: object) -> InputDto | list[InputDto]:
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_inputs_type_0 = InputDto.from_dict(data)



                return componentsschemas_inputs_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, list):
                raise TypeError()
            componentsschemas_inputs_type_1 = []
            _componentsschemas_inputs_type_1 = data
            for componentsschemas_inputs_type_1_item_data in (_componentsschemas_inputs_type_1):
                componentsschemas_inputs_type_1_item = InputDto.from_dict(componentsschemas_inputs_type_1_item_data)



                componentsschemas_inputs_type_1.append(componentsschemas_inputs_type_1_item)

            return componentsschemas_inputs_type_1

        input_ = _parse_input_(d.pop("input"))


        mechanism = MechanismDto.from_dict(d.pop("mechanism"))




        def _parse_conserve_energy(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        conserve_energy = _parse_conserve_energy(d.pop("conserve_energy", UNSET))


        def _parse_loads(data: object) -> list[LoadDto] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                loads_type_0 = []
                _loads_type_0 = data
                for loads_type_0_item_data in (_loads_type_0):
                    loads_type_0_item = LoadDto.from_dict(loads_type_0_item_data)



                    loads_type_0.append(loads_type_0_item)

                return loads_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[LoadDto] | None | Unset, data)

        loads = _parse_loads(d.pop("loads", UNSET))


        def _parse_reactions(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        reactions = _parse_reactions(d.pop("reactions", UNSET))


        def _parse_track(data: object) -> list[str | TrackDtoType1] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                track_type_0 = []
                _track_type_0 = data
                for track_type_0_item_data in (_track_type_0):
                    def _parse_track_type_0_item(data: object) -> str | TrackDtoType1:
                        try:
                            if not isinstance(data, dict):
                                raise TypeError()
                            componentsschemas_track_dto_type_1 = TrackDtoType1.from_dict(data)



                            return componentsschemas_track_dto_type_1
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        return cast(str | TrackDtoType1, data)

                    track_type_0_item = _parse_track_type_0_item(track_type_0_item_data)

                    track_type_0.append(track_type_0_item)

                return track_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[str | TrackDtoType1] | None | Unset, data)

        track = _parse_track(d.pop("track", UNSET))


        instance_ = cls(
            input_=input_,
            mechanism=mechanism,
            conserve_energy=conserve_energy,
            loads=loads,
            reactions=reactions,
            track=track,
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
