from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.member_result import MemberResult
  from ..models.notes_messages import NotesMessages





T = TypeVar("T", bound="TrainResult")



@_attrs_define
class TrainResult:
    """ 
        Attributes:
            warnings (list[str]): What to know before trusting the numbers: a condition met on the
                way (a tolerance nearly spent, a geometry nearly singular, a law
                of design broken), in the asker's language.
            dof (int): Moving members minus independent mesh equations.
            members (list[MemberResult]):
            method (str):
            power_residual (float): Σ T·ω / max |T·ω| over the members (0 in exact arithmetic).
            messages (NotesMessages | Unset): The catalogue's message each text of this result was written from,
                by JSON pointer into the result (`/warnings/0`, `/accuracy/method`):
                match a warning by its `id`; the texts themselves are in the
                language asked for (`Accept-Language`, `?lang=`).
     """

    warnings: list[str]
    dof: int
    members: list[MemberResult]
    method: str
    power_residual: float
    messages: NotesMessages | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.member_result import MemberResult # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        warnings = self.warnings



        dof = self.dof

        members = []
        for members_item_data in self.members:
            members_item = members_item_data.to_dict()
            members.append(members_item)



        method = self.method

        power_residual = self.power_residual

        messages: dict[str, Any] | Unset = UNSET
        if not isinstance(self.messages, Unset):
            messages = self.messages.to_dict()


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "warnings": warnings,
            "dof": dof,
            "members": members,
            "method": method,
            "power_residual": power_residual,
        })
        if messages is not UNSET:
            field_dict["messages"] = messages

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.member_result import MemberResult # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        d = dict(src_dict)
        warnings = cast(list[str], d.pop("warnings"))


        dof = d.pop("dof")

        members = []
        _members = d.pop("members")
        for members_item_data in (_members):
            members_item = MemberResult.from_dict(members_item_data)



            members.append(members_item)


        method = d.pop("method")

        power_residual = d.pop("power_residual")

        _messages = d.pop("messages", UNSET)
        messages: NotesMessages | Unset
        if isinstance(_messages,  Unset):
            messages = UNSET
        else:
            messages = NotesMessages.from_dict(_messages)




        instance_ = cls(
            warnings=warnings,
            dof=dof,
            members=members,
            method=method,
            power_residual=power_residual,
            messages=messages,
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
