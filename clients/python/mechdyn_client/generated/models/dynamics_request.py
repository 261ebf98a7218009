from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.integrator_choice import IntegratorChoice
from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.dynamics_machine import DynamicsMachine
  from ..models.dynamics_request_constants_type_0 import DynamicsRequestConstantsType0
  from ..models.dynamics_torque import DynamicsTorque
  from ..models.function_spec import FunctionSpec
  from ..models.initial import Initial





T = TypeVar("T", bound="DynamicsRequest")



@_attrs_define
class DynamicsRequest:
    """ A machine — in reduced form (`torques` and `reduced_inertia`) or as a
    mechanism (`machine`) — and its start: exactly one of `duration` and `until_angle`.

        Example:
            {'initial': {'angle': 0, 'speed': 0}, 'reduced_inertia': {'expr': '0.07 + 0.05*sin(phi)^2'}, 'torques':
                [{'name': 'motor and yoke', 'value': {'expr': '15 - 20*sin(phi)^2'}}], 'until_angle': '720 deg'}

        Attributes:
            constants (DynamicsRequestConstantsType0 | None | Unset): Named values every expression of this request may
                read, e.g.
                `{"F": "1200 N", "r": "0.1 m"}`: each a number (SI) or a quantity,
                read in SI. A constant no expression reads is a warning.
            duration (float | None | str | Unset):
            initial (Initial | None | Unset):
            integrator (IntegratorChoice | None | Unset):
            machine (DynamicsMachine | None | Unset):
            max_duration (float | None | str | Unset):
            period (float | None | str | Unset):
            reduced_inertia (float | FunctionSpec | None | str | Unset):
            samples (int | None | Unset): Output points, evenly spaced in time, both ends included (default 201).
            tolerance (float | None | Unset): Requested relative accuracy (default 1e-9). With a `machine`, positions
                are held to it relative to the mechanism's size.
            torques (list[DynamicsTorque] | Unset): Reduced form: torques on the machine, positive when they drive it:
                Functions whose expressions may read `phi` (reduced to the period),
                `omega` and `t`.
            until_angle (float | None | str | Unset):
     """

    constants: DynamicsRequestConstantsType0 | None | Unset = UNSET
    duration: float | None | str | Unset = UNSET
    initial: Initial | None | Unset = UNSET
    integrator: IntegratorChoice | None | Unset = UNSET
    machine: DynamicsMachine | None | Unset = UNSET
    max_duration: float | None | str | Unset = UNSET
    period: float | None | str | Unset = UNSET
    reduced_inertia: float | FunctionSpec | None | str | Unset = UNSET
    samples: int | None | Unset = UNSET
    tolerance: float | None | Unset = UNSET
    torques: list[DynamicsTorque] | Unset = UNSET
    until_angle: float | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.dynamics_machine import DynamicsMachine # noqa: PLC0415
        from ..models.dynamics_request_constants_type_0 import DynamicsRequestConstantsType0 # noqa: PLC0415
        from ..models.dynamics_torque import DynamicsTorque # noqa: PLC0415
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        from ..models.initial import Initial # noqa: PLC0415
        constants: dict[str, Any] | None | Unset
        if isinstance(self.constants, Unset):
            constants = UNSET
        elif isinstance(self.constants, DynamicsRequestConstantsType0):
            constants = self.constants.to_dict()
        else:
            constants = self.constants

        duration: float | None | str | Unset
        if isinstance(self.duration, Unset):
            duration = UNSET
        else:
            duration = self.duration

        initial: dict[str, Any] | None | Unset
        if isinstance(self.initial, Unset):
            initial = UNSET
        elif isinstance(self.initial, Initial):
            initial = self.initial.to_dict()
        else:
            initial = self.initial

        integrator: None | str | Unset
        if isinstance(self.integrator, Unset):
            integrator = UNSET
        elif isinstance(self.integrator, IntegratorChoice):
            integrator = self.integrator.value
        else:
            integrator = self.integrator

        machine: dict[str, Any] | None | Unset
        if isinstance(self.machine, Unset):
            machine = UNSET
        elif isinstance(self.machine, DynamicsMachine):
            machine = self.machine.to_dict()
        else:
            machine = self.machine

        max_duration: float | None | str | Unset
        if isinstance(self.max_duration, Unset):
            max_duration = UNSET
        else:
            max_duration = self.max_duration

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

        torques: list[dict[str, Any]] | Unset = UNSET
        if not isinstance(self.torques, Unset):
            torques = []
            for torques_item_data in self.torques:
                torques_item = torques_item_data.to_dict()
                torques.append(torques_item)



        until_angle: float | None | str | Unset
        if isinstance(self.until_angle, Unset):
            until_angle = UNSET
        else:
            until_angle = self.until_angle


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
        })
        if constants is not UNSET:
            field_dict["constants"] = constants
        if duration is not UNSET:
            field_dict["duration"] = duration
        if initial is not UNSET:
            field_dict["initial"] = initial
        if integrator is not UNSET:
            field_dict["integrator"] = integrator
        if machine is not UNSET:
            field_dict["machine"] = machine
        if max_duration is not UNSET:
            field_dict["max_duration"] = max_duration
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
        if until_angle is not UNSET:
            field_dict["until_angle"] = until_angle

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.dynamics_machine import DynamicsMachine # noqa: PLC0415
        from ..models.dynamics_request_constants_type_0 import DynamicsRequestConstantsType0 # noqa: PLC0415
        from ..models.dynamics_torque import DynamicsTorque # noqa: PLC0415
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        from ..models.initial import Initial # noqa: PLC0415
        d = dict(src_dict)
        def _parse_constants(data: object) -> DynamicsRequestConstantsType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                constants_type_0 = DynamicsRequestConstantsType0.from_dict(data)



                return constants_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(DynamicsRequestConstantsType0 | None | Unset, data)

        constants = _parse_constants(d.pop("constants", UNSET))


        def _parse_duration(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        duration = _parse_duration(d.pop("duration", UNSET))


        def _parse_initial(data: object) -> Initial | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                initial_type_0 = Initial.from_dict(data)



                return initial_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(Initial | None | Unset, data)

        initial = _parse_initial(d.pop("initial", UNSET))


        def _parse_integrator(data: object) -> IntegratorChoice | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                integrator_type_0 = IntegratorChoice(data)



                return integrator_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(IntegratorChoice | None | Unset, data)

        integrator = _parse_integrator(d.pop("integrator", UNSET))


        def _parse_machine(data: object) -> DynamicsMachine | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                machine_type_0 = DynamicsMachine.from_dict(data)



                return machine_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(DynamicsMachine | None | Unset, data)

        machine = _parse_machine(d.pop("machine", UNSET))


        def _parse_max_duration(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        max_duration = _parse_max_duration(d.pop("max_duration", UNSET))


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


        _torques = d.pop("torques", UNSET)
        torques: list[DynamicsTorque] | Unset = UNSET
        if _torques is not UNSET:
            torques = []
            for torques_item_data in _torques:
                torques_item = DynamicsTorque.from_dict(torques_item_data)



                torques.append(torques_item)


        def _parse_until_angle(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        until_angle = _parse_until_angle(d.pop("until_angle", UNSET))


        instance_ = cls(
            constants=constants,
            duration=duration,
            initial=initial,
            integrator=integrator,
            machine=machine,
            max_duration=max_duration,
            period=period,
            reduced_inertia=reduced_inertia,
            samples=samples,
            tolerance=tolerance,
            torques=torques,
            until_angle=until_angle,
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
