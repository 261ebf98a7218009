from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.count import Count
  from ..models.notes_messages import NotesMessages





T = TypeVar("T", bound="MobilityResult")



@_attrs_define
class MobilityResult:
    """ 
        Attributes:
            warnings (list[str]): What to know before trusting the numbers: a condition met on the
                way (a tolerance nearly spent, a geometry nearly singular, a law
                of design broken), in the asker's language.
            candidate_inputs (list[str]): Joints whose coordinates can serve together as the inputs.
            grubler (Count): Grübler's (Kutzbach's) count.
            indeterminate_joints (list[str]): Joints whose reactions equilibrium cannot determine (redundant constraints).
            locked (bool): No freedom: dof 0 (for counts, a mobility of 0 or less).
            messages (NotesMessages | Unset): The catalogue's message each text of this result was written from,
                by JSON pointer into the result (`/warnings/0`, `/accuracy/method`):
                match a warning by its `id`; the texts themselves are in the
                language asked for (`Accept-Language`, `?lang=`).
            dof (int | None | Unset): Degrees of freedom from the Jacobian's rank at the drawn position
                (null for counts).
            input_coordinates (None | str | Unset): For counts: how many input coordinates describe the motion, and what
                counts alone cannot tell of which (null for a drawing: see `candidate_inputs`).
            redundant_constraints (int | None | Unset): Constraints the others already impose (rows − rank; null for
                counts).
     """

    warnings: list[str]
    candidate_inputs: list[str]
    grubler: Count
    indeterminate_joints: list[str]
    locked: bool
    messages: NotesMessages | Unset = UNSET
    dof: int | None | Unset = UNSET
    input_coordinates: None | str | Unset = UNSET
    redundant_constraints: int | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.count import Count # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        warnings = self.warnings



        candidate_inputs = self.candidate_inputs



        grubler = self.grubler.to_dict()

        indeterminate_joints = self.indeterminate_joints



        locked = self.locked

        messages: dict[str, Any] | Unset = UNSET
        if not isinstance(self.messages, Unset):
            messages = self.messages.to_dict()

        dof: int | None | Unset
        if isinstance(self.dof, Unset):
            dof = UNSET
        else:
            dof = self.dof

        input_coordinates: None | str | Unset
        if isinstance(self.input_coordinates, Unset):
            input_coordinates = UNSET
        else:
            input_coordinates = self.input_coordinates

        redundant_constraints: int | None | Unset
        if isinstance(self.redundant_constraints, Unset):
            redundant_constraints = UNSET
        else:
            redundant_constraints = self.redundant_constraints


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "warnings": warnings,
            "candidate_inputs": candidate_inputs,
            "grubler": grubler,
            "indeterminate_joints": indeterminate_joints,
            "locked": locked,
        })
        if messages is not UNSET:
            field_dict["messages"] = messages
        if dof is not UNSET:
            field_dict["dof"] = dof
        if input_coordinates is not UNSET:
            field_dict["input_coordinates"] = input_coordinates
        if redundant_constraints is not UNSET:
            field_dict["redundant_constraints"] = redundant_constraints

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.count import Count # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        d = dict(src_dict)
        warnings = cast(list[str], d.pop("warnings"))


        candidate_inputs = cast(list[str], d.pop("candidate_inputs"))


        grubler = Count.from_dict(d.pop("grubler"))




        indeterminate_joints = cast(list[str], d.pop("indeterminate_joints"))


        locked = d.pop("locked")

        _messages = d.pop("messages", UNSET)
        messages: NotesMessages | Unset
        if isinstance(_messages,  Unset):
            messages = UNSET
        else:
            messages = NotesMessages.from_dict(_messages)




        def _parse_dof(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        dof = _parse_dof(d.pop("dof", UNSET))


        def _parse_input_coordinates(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        input_coordinates = _parse_input_coordinates(d.pop("input_coordinates", UNSET))


        def _parse_redundant_constraints(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        redundant_constraints = _parse_redundant_constraints(d.pop("redundant_constraints", UNSET))


        instance_ = cls(
            warnings=warnings,
            candidate_inputs=candidate_inputs,
            grubler=grubler,
            indeterminate_joints=indeterminate_joints,
            locked=locked,
            messages=messages,
            dof=dof,
            input_coordinates=input_coordinates,
            redundant_constraints=redundant_constraints,
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
