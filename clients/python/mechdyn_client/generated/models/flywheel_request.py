from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.flywheel_dto import FlywheelDto
  from ..models.flywheel_request_constants_type_0 import FlywheelRequestConstantsType0
  from ..models.function_spec import FunctionSpec
  from ..models.machine_dto import MachineDto
  from ..models.torque_dto import TorqueDto





T = TypeVar("T", bound="FlywheelRequest")



@_attrs_define
class FlywheelRequest:
    """ A flywheel design problem. Give the speeds as exactly one of:
    `mean_speed` + `irregularity`, `mean_speed` + `min_speed`, or `min_speed` + `max_speed`.

        Example:
            {'irregularity': 0.04, 'mean_speed': '60 rpm', 'reduced_inertia': {'expr': '5*sin(phi)^2'}, 'torques': [{'name':
                'slider load', 'value': {'segments': [{'expr': '-500*sin(phi)', 'from': 0, 'to': 'pi'}]}}, {'balance': True,
                'name': 'motor'}]}

        Attributes:
            check (bool | None | Unset): Run the independent time-simulation check (default true).
            constants (FlywheelRequestConstantsType0 | None | Unset): Named values every expression of this request may
                read, e.g.
                `{"F": "1200 N", "r": "0.1 m"}`: each a number (SI) or a quantity,
                read in SI. A constant no expression reads is a warning.
            existing_inertia (float | None | str | Unset):
            flywheel (FlywheelDto | None | Unset):
            irregularity (float | None | str | Unset):
            machine (MachineDto | None | Unset):
            max_speed (float | None | str | Unset):
            mean_speed (float | None | str | Unset):
            min_speed (float | None | str | Unset):
            period (float | None | str | Unset):
            reduced_inertia (float | FunctionSpec | None | str | Unset):
            samples (int | None | Unset): Rows of the sampled table in the result and its CSV (default 361; 0 for none).
            tolerance (float | None | Unset): Requested relative accuracy (default 1e-9).
            torques (list[TorqueDto] | None | Unset): Torques on the machine, positive when they drive it (at least one
                item, or a `machine`).
     """

    check: bool | None | Unset = UNSET
    constants: FlywheelRequestConstantsType0 | None | Unset = UNSET
    existing_inertia: float | None | str | Unset = UNSET
    flywheel: FlywheelDto | None | Unset = UNSET
    irregularity: float | None | str | Unset = UNSET
    machine: MachineDto | None | Unset = UNSET
    max_speed: float | None | str | Unset = UNSET
    mean_speed: float | None | str | Unset = UNSET
    min_speed: float | None | str | Unset = UNSET
    period: float | None | str | Unset = UNSET
    reduced_inertia: float | FunctionSpec | None | str | Unset = UNSET
    samples: int | None | Unset = UNSET
    tolerance: float | None | Unset = UNSET
    torques: list[TorqueDto] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.flywheel_dto import FlywheelDto # noqa: PLC0415
        from ..models.flywheel_request_constants_type_0 import FlywheelRequestConstantsType0 # noqa: PLC0415
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        from ..models.machine_dto import MachineDto # noqa: PLC0415
        from ..models.torque_dto import TorqueDto # noqa: PLC0415
        check: bool | None | Unset
        if isinstance(self.check, Unset):
            check = UNSET
        else:
            check = self.check

        constants: dict[str, Any] | None | Unset
        if isinstance(self.constants, Unset):
            constants = UNSET
        elif isinstance(self.constants, FlywheelRequestConstantsType0):
            constants = self.constants.to_dict()
        else:
            constants = self.constants

        existing_inertia: float | None | str | Unset
        if isinstance(self.existing_inertia, Unset):
            existing_inertia = UNSET
        else:
            existing_inertia = self.existing_inertia

        flywheel: dict[str, Any] | None | Unset
        if isinstance(self.flywheel, Unset):
            flywheel = UNSET
        elif isinstance(self.flywheel, FlywheelDto):
            flywheel = self.flywheel.to_dict()
        else:
            flywheel = self.flywheel

        irregularity: float | None | str | Unset
        if isinstance(self.irregularity, Unset):
            irregularity = UNSET
        else:
            irregularity = self.irregularity

        machine: dict[str, Any] | None | Unset
        if isinstance(self.machine, Unset):
            machine = UNSET
        elif isinstance(self.machine, MachineDto):
            machine = self.machine.to_dict()
        else:
            machine = self.machine

        max_speed: float | None | str | Unset
        if isinstance(self.max_speed, Unset):
            max_speed = UNSET
        else:
            max_speed = self.max_speed

        mean_speed: float | None | str | Unset
        if isinstance(self.mean_speed, Unset):
            mean_speed = UNSET
        else:
            mean_speed = self.mean_speed

        min_speed: float | None | str | Unset
        if isinstance(self.min_speed, Unset):
            min_speed = UNSET
        else:
            min_speed = self.min_speed

        period: float | None | str | Unset
        if isinstance(self.period, Unset):
            period = UNSET
        else:
            period = self.period

        reduced_inertia: dict[str, Any] | float | None | str | Unset
        if isinstance(self.reduced_inertia, Unset):
            reduced_inertia = UNSET
        elif isinstance(self.reduced_inertia, FunctionSpec):
            reduced_inertia = self.reduced_inertia.to_dict()
        else:
            reduced_inertia = self.reduced_inertia

        samples: int | None | Unset
        if isinstance(self.samples, Unset):
            samples = UNSET
        else:
            samples = self.samples

        tolerance: float | None | Unset
        if isinstance(self.tolerance, Unset):
            tolerance = UNSET
        else:
            tolerance = self.tolerance

        torques: list[dict[str, Any]] | None | Unset
        if isinstance(self.torques, Unset):
            torques = UNSET
        elif isinstance(self.torques, list):
            torques = []
            for torques_item_data in self.torques:
                torques_item = torques_item_data.to_dict()
                torques.append(torques_item)


        else:
            torques = self.torques


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
        })
        if check is not UNSET:
            field_dict["check"] = check
        if constants is not UNSET:
            field_dict["constants"] = constants
        if existing_inertia is not UNSET:
            field_dict["existing_inertia"] = existing_inertia
        if flywheel is not UNSET:
            field_dict["flywheel"] = flywheel
        if irregularity is not UNSET:
            field_dict["irregularity"] = irregularity
        if machine is not UNSET:
            field_dict["machine"] = machine
        if max_speed is not UNSET:
            field_dict["max_speed"] = max_speed
        if mean_speed is not UNSET:
            field_dict["mean_speed"] = mean_speed
        if min_speed is not UNSET:
            field_dict["min_speed"] = min_speed
        if period is not UNSET:
            field_dict["period"] = period
        if reduced_inertia is not UNSET:
            field_dict["reduced_inertia"] = reduced_inertia
        if samples is not UNSET:
            field_dict["samples"] = samples
        if tolerance is not UNSET:
            field_dict["tolerance"] = tolerance
        if torques is not UNSET:
            field_dict["torques"] = torques

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.flywheel_dto import FlywheelDto # noqa: PLC0415
        from ..models.flywheel_request_constants_type_0 import FlywheelRequestConstantsType0 # noqa: PLC0415
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        from ..models.machine_dto import MachineDto # noqa: PLC0415
        from ..models.torque_dto import TorqueDto # noqa: PLC0415
        d = dict(src_dict)
        def _parse_check(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        check = _parse_check(d.pop("check", UNSET))


        def _parse_constants(data: object) -> FlywheelRequestConstantsType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                constants_type_0 = FlywheelRequestConstantsType0.from_dict(data)



                return constants_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(FlywheelRequestConstantsType0 | None | Unset, data)

        constants = _parse_constants(d.pop("constants", UNSET))


        def _parse_existing_inertia(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        existing_inertia = _parse_existing_inertia(d.pop("existing_inertia", UNSET))


        def _parse_flywheel(data: object) -> FlywheelDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                flywheel_type_0 = FlywheelDto.from_dict(data)



                return flywheel_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(FlywheelDto | None | Unset, data)

        flywheel = _parse_flywheel(d.pop("flywheel", UNSET))


        def _parse_irregularity(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        irregularity = _parse_irregularity(d.pop("irregularity", UNSET))


        def _parse_machine(data: object) -> MachineDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                machine_type_0 = MachineDto.from_dict(data)



                return machine_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(MachineDto | None | Unset, data)

        machine = _parse_machine(d.pop("machine", UNSET))


        def _parse_max_speed(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        max_speed = _parse_max_speed(d.pop("max_speed", UNSET))


        def _parse_mean_speed(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        mean_speed = _parse_mean_speed(d.pop("mean_speed", UNSET))


        def _parse_min_speed(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        min_speed = _parse_min_speed(d.pop("min_speed", UNSET))


        def _parse_period(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        period = _parse_period(d.pop("period", UNSET))


        def _parse_reduced_inertia(data: object) -> float | FunctionSpec | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_function_dto_type_1 = FunctionSpec.from_dict(data)



                return componentsschemas_function_dto_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | FunctionSpec | None | str | Unset, data)

        reduced_inertia = _parse_reduced_inertia(d.pop("reduced_inertia", UNSET))


        def _parse_samples(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        samples = _parse_samples(d.pop("samples", UNSET))


        def _parse_tolerance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tolerance = _parse_tolerance(d.pop("tolerance", UNSET))


        def _parse_torques(data: object) -> list[TorqueDto] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                torques_type_0 = []
                _torques_type_0 = data
                for torques_type_0_item_data in (_torques_type_0):
                    torques_type_0_item = TorqueDto.from_dict(torques_type_0_item_data)



                    torques_type_0.append(torques_type_0_item)

                return torques_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[TorqueDto] | None | Unset, data)

        torques = _parse_torques(d.pop("torques", UNSET))


        instance_ = cls(
            check=check,
            constants=constants,
            existing_inertia=existing_inertia,
            flywheel=flywheel,
            irregularity=irregularity,
            machine=machine,
            max_speed=max_speed,
            mean_speed=mean_speed,
            min_speed=min_speed,
            period=period,
            reduced_inertia=reduced_inertia,
            samples=samples,
            tolerance=tolerance,
            torques=torques,
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
