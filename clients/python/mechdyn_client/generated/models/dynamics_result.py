from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.dynamics_accuracy import DynamicsAccuracy
  from ..models.dynamics_sample import DynamicsSample
  from ..models.event_dto import EventDto
  from ..models.machine_dynamics import MachineDynamics
  from ..models.notes_messages import NotesMessages
  from ..models.spatial_machine_dynamics import SpatialMachineDynamics





T = TypeVar("T", bound="DynamicsResult")



@_attrs_define
class DynamicsResult:
    """ Result of a dynamics job (SI units).

        Attributes:
            warnings (list[str]): What to know before trusting the numbers: a condition met on the
                way (a tolerance nearly spent, a geometry nearly singular, a law
                of design broken), in the asker's language.
            accuracy (DynamicsAccuracy):
            energy_residual (float):
            events (list[EventDto]):
            samples (list[DynamicsSample]):
            messages (NotesMessages | Unset): The catalogue's message each text of this result was written from,
                by JSON pointer into the result (`/warnings/0`, `/accuracy/method`):
                match a warning by its `id`; the texts themselves are in the
                language asked for (`Accept-Language`, `?lang=`).
            end (EventDto | None | Unset):
            machine (MachineDynamics | None | SpatialMachineDynamics | Unset):
            stopped (None | str | Unset): Why the run stopped before its end, where it did: "separation" (a
                contact's normal force fell to 0: the bodies part), "not_reached"
                (the end angle was not reached within the longest duration),
                "chatter" (contacts switched between rolling and slipping without
                end); a warning says more.
     """

    warnings: list[str]
    accuracy: DynamicsAccuracy
    energy_residual: float
    events: list[EventDto]
    samples: list[DynamicsSample]
    messages: NotesMessages | Unset = UNSET
    end: EventDto | None | Unset = UNSET
    machine: MachineDynamics | None | SpatialMachineDynamics | Unset = UNSET
    stopped: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.dynamics_accuracy import DynamicsAccuracy # noqa: PLC0415
        from ..models.dynamics_sample import DynamicsSample # noqa: PLC0415
        from ..models.event_dto import EventDto # noqa: PLC0415
        from ..models.machine_dynamics import MachineDynamics # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        from ..models.spatial_machine_dynamics import SpatialMachineDynamics # noqa: PLC0415
        warnings = self.warnings



        accuracy = self.accuracy.to_dict()

        energy_residual = self.energy_residual

        events = []
        for events_item_data in self.events:
            events_item = events_item_data.to_dict()
            events.append(events_item)



        samples = []
        for samples_item_data in self.samples:
            samples_item = samples_item_data.to_dict()
            samples.append(samples_item)



        messages: dict[str, Any] | Unset = UNSET
        if not isinstance(self.messages, Unset):
            messages = self.messages.to_dict()

        end: dict[str, Any] | None | Unset
        if isinstance(self.end, Unset):
            end = UNSET
        elif isinstance(self.end, EventDto):
            end = self.end.to_dict()
        else:
            end = self.end

        machine: dict[str, Any] | None | Unset
        if isinstance(self.machine, Unset):
            machine = UNSET
        elif isinstance(self.machine, MachineDynamics):
            machine = self.machine.to_dict()
        elif isinstance(self.machine, SpatialMachineDynamics):
            machine = self.machine.to_dict()
        else:
            machine = self.machine

        stopped: None | str | Unset
        if isinstance(self.stopped, Unset):
            stopped = UNSET
        else:
            stopped = self.stopped


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "warnings": warnings,
            "accuracy": accuracy,
            "energy_residual": energy_residual,
            "events": events,
            "samples": samples,
        })
        if messages is not UNSET:
            field_dict["messages"] = messages
        if end is not UNSET:
            field_dict["end"] = end
        if machine is not UNSET:
            field_dict["machine"] = machine
        if stopped is not UNSET:
            field_dict["stopped"] = stopped

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.dynamics_accuracy import DynamicsAccuracy # noqa: PLC0415
        from ..models.dynamics_sample import DynamicsSample # noqa: PLC0415
        from ..models.event_dto import EventDto # noqa: PLC0415
        from ..models.machine_dynamics import MachineDynamics # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        from ..models.spatial_machine_dynamics import SpatialMachineDynamics # noqa: PLC0415
        d = dict(src_dict)
        warnings = cast(list[str], d.pop("warnings"))


        accuracy = DynamicsAccuracy.from_dict(d.pop("accuracy"))




        energy_residual = d.pop("energy_residual")

        events = []
        _events = d.pop("events")
        for events_item_data in (_events):
            events_item = EventDto.from_dict(events_item_data)



            events.append(events_item)


        samples = []
        _samples = d.pop("samples")
        for samples_item_data in (_samples):
            samples_item = DynamicsSample.from_dict(samples_item_data)



            samples.append(samples_item)


        _messages = d.pop("messages", UNSET)
        messages: NotesMessages | Unset
        if isinstance(_messages,  Unset):
            messages = UNSET
        else:
            messages = NotesMessages.from_dict(_messages)




        def _parse_end(data: object) -> EventDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                end_type_0 = EventDto.from_dict(data)



                return end_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(EventDto | None | Unset, data)

        end = _parse_end(d.pop("end", UNSET))


        def _parse_machine(data: object) -> MachineDynamics | None | SpatialMachineDynamics | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_machine_result_type_0 = MachineDynamics.from_dict(data)



                return componentsschemas_machine_result_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_machine_result_type_1 = SpatialMachineDynamics.from_dict(data)



                return componentsschemas_machine_result_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(MachineDynamics | None | SpatialMachineDynamics | Unset, data)

        machine = _parse_machine(d.pop("machine", UNSET))


        def _parse_stopped(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        stopped = _parse_stopped(d.pop("stopped", UNSET))


        instance_ = cls(
            warnings=warnings,
            accuracy=accuracy,
            energy_residual=energy_residual,
            events=events,
            samples=samples,
            messages=messages,
            end=end,
            machine=machine,
            stopped=stopped,
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
