from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.output_kind import OutputKind
from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.balance_dto import BalanceDto
  from ..models.input_dto import InputDto
  from ..models.kinetostatics_request_constants_type_0 import KinetostaticsRequestConstantsType0
  from ..models.load_dto import LoadDto
  from ..models.mechanism_dto import MechanismDto
  from ..models.track_dto_type_1 import TrackDtoType1





T = TypeVar("T", bound="KinetostaticsRequest")



@_attrs_define
class KinetostaticsRequest:
    """ A kinetostatic (inverse dynamics) problem: a mechanism, its driven input(s) and its loads.

        Example:
            {'input': {'end': '360 deg', 'joint': 'O', 'speed': '1500 rpm', 'start': 0, 'steps': 36}, 'loads': [{'at': 'B',
                'body': 'piston', 'direction': [1, 0], 'magnitude': {'expr': '-8000*exp(3*(cos(phi - 0.35) - 1))'}, 'type':
                'force'}], 'mechanism': {'bodies': [{'cg': [0.02, 0], 'inertia': 0.004, 'mass': '2 kg', 'name': 'crank'}, {'cg':
                [0.1698, 0.006], 'inertia': 0.012, 'mass': 1.2, 'name': 'rod'}, {'cg': 'B', 'inertia': 0.001, 'mass': 0.9,
                'name': 'piston'}], 'gravity': [0, -9.81], 'joints': [{'at': 'O', 'bodies': ['ground', 'crank'], 'name': 'O',
                'type': 'revolute'}, {'at': 'A', 'bodies': ['crank', 'rod'], 'name': 'A', 'type': 'revolute'}, {'at': 'B',
                'bodies': ['rod', 'piston'], 'name': 'B', 'type': 'revolute'}, {'at': 'B', 'axis': [1, 0], 'bodies': ['ground',
                'piston'], 'name': 'guide', 'type': 'prismatic'}], 'points': {'A': [0.08, 0], 'B': [0.37933, 0.02], 'O': [0,
                0]}}}

        Attributes:
            input_ (InputDto | list[InputDto]):
            mechanism (MechanismDto): A mechanism drawn in one assembled configuration, planar (see the
                example of KinetostaticsRequest) or, with `"space": "spatial"`, in
                three dimensions.
            actuators (list[str] | None | Unset): Where each input's driving effort acts, one joint per input in
                order: a revolute joint (a torque) or a prismatic one (a force along
                its axis); `driving` is then the actuators' efforts. Default: each
                input's own joint; for an input on a point, a force on the point
                along its direction; on a body, a torque on the body.
            balance (BalanceDto | None | Unset):
            constants (KinetostaticsRequestConstantsType0 | None | Unset): Named values every expression of this request may
                read, e.g.
                `{"F": "1200 N", "r": "0.1 m"}`: each a number (SI) or a quantity,
                read in SI. A constant no expression reads is a warning.
            loads (list[LoadDto] | None | Unset):
            outputs (list[OutputKind] | None | Unset): Compute only these (default: driving, reactions, kinematics and
                reduced; "condition" is asked for by name).
            track (list[str | TrackDtoType1] | None | Unset): Points to follow: each step then has their `points` (position,
                velocity, acceleration). A name from `points` moves with the body its
                joints or centre of mass put it on; `{"name", "body", "at"}` is a
                point of one body (a pin in a slot must say which).
     """

    input_: InputDto | list[InputDto]
    mechanism: MechanismDto
    actuators: list[str] | None | Unset = UNSET
    balance: BalanceDto | None | Unset = UNSET
    constants: KinetostaticsRequestConstantsType0 | None | Unset = UNSET
    loads: list[LoadDto] | None | Unset = UNSET
    outputs: list[OutputKind] | None | Unset = UNSET
    track: list[str | TrackDtoType1] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.balance_dto import BalanceDto # noqa: PLC0415
        from ..models.input_dto import InputDto # noqa: PLC0415
        from ..models.kinetostatics_request_constants_type_0 import KinetostaticsRequestConstantsType0 # noqa: PLC0415
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

        actuators: list[str] | None | Unset
        if isinstance(self.actuators, Unset):
            actuators = UNSET
        elif isinstance(self.actuators, list):
            actuators = self.actuators


        else:
            actuators = self.actuators

        balance: dict[str, Any] | None | Unset
        if isinstance(self.balance, Unset):
            balance = UNSET
        elif isinstance(self.balance, BalanceDto):
            balance = self.balance.to_dict()
        else:
            balance = self.balance

        constants: dict[str, Any] | None | Unset
        if isinstance(self.constants, Unset):
            constants = UNSET
        elif isinstance(self.constants, KinetostaticsRequestConstantsType0):
            constants = self.constants.to_dict()
        else:
            constants = self.constants

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

        outputs: list[str] | None | Unset
        if isinstance(self.outputs, Unset):
            outputs = UNSET
        elif isinstance(self.outputs, list):
            outputs = []
            for outputs_item_data in self.outputs:
                outputs_item = outputs_item_data.value
                outputs.append(outputs_item)


        else:
            outputs = self.outputs

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
        if actuators is not UNSET:
            field_dict["actuators"] = actuators
        if balance is not UNSET:
            field_dict["balance"] = balance
        if constants is not UNSET:
            field_dict["constants"] = constants
        if loads is not UNSET:
            field_dict["loads"] = loads
        if outputs is not UNSET:
            field_dict["outputs"] = outputs
        if track is not UNSET:
            field_dict["track"] = track

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.balance_dto import BalanceDto # noqa: PLC0415
        from ..models.input_dto import InputDto # noqa: PLC0415
        from ..models.kinetostatics_request_constants_type_0 import KinetostaticsRequestConstantsType0 # noqa: PLC0415
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




        def _parse_actuators(data: object) -> list[str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                actuators_type_0 = list(data)

                return actuators_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[str] | None | Unset, data)

        actuators = _parse_actuators(d.pop("actuators", UNSET))


        def _parse_balance(data: object) -> BalanceDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                balance_type_0 = BalanceDto.from_dict(data)



                return balance_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(BalanceDto | None | Unset, data)

        balance = _parse_balance(d.pop("balance", UNSET))


        def _parse_constants(data: object) -> KinetostaticsRequestConstantsType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                constants_type_0 = KinetostaticsRequestConstantsType0.from_dict(data)



                return constants_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(KinetostaticsRequestConstantsType0 | None | Unset, data)

        constants = _parse_constants(d.pop("constants", UNSET))


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


        def _parse_outputs(data: object) -> list[OutputKind] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                outputs_type_0 = []
                _outputs_type_0 = data
                for outputs_type_0_item_data in (_outputs_type_0):
                    outputs_type_0_item = OutputKind(outputs_type_0_item_data)



                    outputs_type_0.append(outputs_type_0_item)

                return outputs_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[OutputKind] | None | Unset, data)

        outputs = _parse_outputs(d.pop("outputs", UNSET))


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
            actuators=actuators,
            balance=balance,
            constants=constants,
            loads=loads,
            outputs=outputs,
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
