from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.counterweight_dto import CounterweightDto
  from ..models.grubler_dto import GrublerDto
  from ..models.input_info import InputInfo
  from ..models.kinetostatics_accuracy import KinetostaticsAccuracy
  from ..models.kinetostatics_result_assembled_points_type_0 import KinetostaticsResultAssembledPointsType0
  from ..models.notes_messages import NotesMessages
  from ..models.step_dto import StepDto
  from ..models.summary_dto import SummaryDto





T = TypeVar("T", bound="KinetostaticsResult")



@_attrs_define
class KinetostaticsResult:
    """ Result of a kinetostatics job (SI units).

        Attributes:
            warnings (list[str]): What to know before trusting the numbers: a condition met on the
                way (a tolerance nearly spent, a geometry nearly singular, a law
                of design broken), in the asker's language.
            accuracy (KinetostaticsAccuracy):
            dof (int): Degrees of freedom from the rank of the constraint Jacobian.
            grubler (GrublerDto):
            inputs (list[InputInfo]):
            redundant_constraints (int):
            steps (list[StepDto]):
            summary (SummaryDto):
            messages (NotesMessages | Unset): The catalogue's message each text of this result was written from,
                by JSON pointer into the result (`/warnings/0`, `/accuracy/method`):
                match a warning by its `id`; the texts themselves are in the
                language asked for (`Accept-Language`, `?lang=`).
            assembled_points (KinetostaticsResultAssembledPointsType0 | None | Unset): Where the points went, for a
                mechanism given by its `dimensions` (m).
            counterweights (list[CounterweightDto] | None | Unset): The counterweights of `balance`, in its order.
     """

    warnings: list[str]
    accuracy: KinetostaticsAccuracy
    dof: int
    grubler: GrublerDto
    inputs: list[InputInfo]
    redundant_constraints: int
    steps: list[StepDto]
    summary: SummaryDto
    messages: NotesMessages | Unset = UNSET
    assembled_points: KinetostaticsResultAssembledPointsType0 | None | Unset = UNSET
    counterweights: list[CounterweightDto] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.counterweight_dto import CounterweightDto # noqa: PLC0415
        from ..models.grubler_dto import GrublerDto # noqa: PLC0415
        from ..models.input_info import InputInfo # noqa: PLC0415
        from ..models.kinetostatics_accuracy import KinetostaticsAccuracy # noqa: PLC0415
        from ..models.kinetostatics_result_assembled_points_type_0 import KinetostaticsResultAssembledPointsType0 # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        from ..models.step_dto import StepDto # noqa: PLC0415
        from ..models.summary_dto import SummaryDto # noqa: PLC0415
        warnings = self.warnings



        accuracy = self.accuracy.to_dict()

        dof = self.dof

        grubler = self.grubler.to_dict()

        inputs = []
        for inputs_item_data in self.inputs:
            inputs_item = inputs_item_data.to_dict()
            inputs.append(inputs_item)



        redundant_constraints = self.redundant_constraints

        steps = []
        for steps_item_data in self.steps:
            steps_item = steps_item_data.to_dict()
            steps.append(steps_item)



        summary = self.summary.to_dict()

        messages: dict[str, Any] | Unset = UNSET
        if not isinstance(self.messages, Unset):
            messages = self.messages.to_dict()

        assembled_points: dict[str, Any] | None | Unset
        if isinstance(self.assembled_points, Unset):
            assembled_points = UNSET
        elif isinstance(self.assembled_points, KinetostaticsResultAssembledPointsType0):
            assembled_points = self.assembled_points.to_dict()
        else:
            assembled_points = self.assembled_points

        counterweights: list[dict[str, Any]] | None | Unset
        if isinstance(self.counterweights, Unset):
            counterweights = UNSET
        elif isinstance(self.counterweights, list):
            counterweights = []
            for counterweights_item_data in self.counterweights:
                counterweights_item = counterweights_item_data.to_dict()
                counterweights.append(counterweights_item)


        else:
            counterweights = self.counterweights


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "warnings": warnings,
            "accuracy": accuracy,
            "dof": dof,
            "grubler": grubler,
            "inputs": inputs,
            "redundant_constraints": redundant_constraints,
            "steps": steps,
            "summary": summary,
        })
        if messages is not UNSET:
            field_dict["messages"] = messages
        if assembled_points is not UNSET:
            field_dict["assembled_points"] = assembled_points
        if counterweights is not UNSET:
            field_dict["counterweights"] = counterweights

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.counterweight_dto import CounterweightDto # noqa: PLC0415
        from ..models.grubler_dto import GrublerDto # noqa: PLC0415
        from ..models.input_info import InputInfo # noqa: PLC0415
        from ..models.kinetostatics_accuracy import KinetostaticsAccuracy # noqa: PLC0415
        from ..models.kinetostatics_result_assembled_points_type_0 import KinetostaticsResultAssembledPointsType0 # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        from ..models.step_dto import StepDto # noqa: PLC0415
        from ..models.summary_dto import SummaryDto # noqa: PLC0415
        d = dict(src_dict)
        warnings = cast(list[str], d.pop("warnings"))


        accuracy = KinetostaticsAccuracy.from_dict(d.pop("accuracy"))




        dof = d.pop("dof")

        grubler = GrublerDto.from_dict(d.pop("grubler"))




        inputs = []
        _inputs = d.pop("inputs")
        for inputs_item_data in (_inputs):
            inputs_item = InputInfo.from_dict(inputs_item_data)



            inputs.append(inputs_item)


        redundant_constraints = d.pop("redundant_constraints")

        steps = []
        _steps = d.pop("steps")
        for steps_item_data in (_steps):
            steps_item = StepDto.from_dict(steps_item_data)



            steps.append(steps_item)


        summary = SummaryDto.from_dict(d.pop("summary"))




        _messages = d.pop("messages", UNSET)
        messages: NotesMessages | Unset
        if isinstance(_messages,  Unset):
            messages = UNSET
        else:
            messages = NotesMessages.from_dict(_messages)




        def _parse_assembled_points(data: object) -> KinetostaticsResultAssembledPointsType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                assembled_points_type_0 = KinetostaticsResultAssembledPointsType0.from_dict(data)



                return assembled_points_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(KinetostaticsResultAssembledPointsType0 | None | Unset, data)

        assembled_points = _parse_assembled_points(d.pop("assembled_points", UNSET))


        def _parse_counterweights(data: object) -> list[CounterweightDto] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                counterweights_type_0 = []
                _counterweights_type_0 = data
                for counterweights_type_0_item_data in (_counterweights_type_0):
                    counterweights_type_0_item = CounterweightDto.from_dict(counterweights_type_0_item_data)



                    counterweights_type_0.append(counterweights_type_0_item)

                return counterweights_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[CounterweightDto] | None | Unset, data)

        counterweights = _parse_counterweights(d.pop("counterweights", UNSET))


        instance_ = cls(
            warnings=warnings,
            accuracy=accuracy,
            dof=dof,
            grubler=grubler,
            inputs=inputs,
            redundant_constraints=redundant_constraints,
            steps=steps,
            summary=summary,
            messages=messages,
            assembled_points=assembled_points,
            counterweights=counterweights,
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
