from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.equivalent_result_masses import EquivalentResultMasses
  from ..models.notes_messages import NotesMessages





T = TypeVar("T", bound="EquivalentResult")



@_attrs_define
class EquivalentResult:
    """ 
        Attributes:
            warnings (list[str]): What to know before trusting the numbers: a condition met on the
                way (a tolerance nearly spent, a geometry nearly singular, a law
                of design broken), in the asker's language.
            complete (bool): Mass, centre of mass and inertia all match (completely equivalent).
            masses (EquivalentResultMasses): Mass at each point, kg.
            residual (float): Largest relative residual of the four conditions.
            unique (bool): The points determine the masses (otherwise a minimum-norm set is given).
            messages (NotesMessages | Unset): The catalogue's message each text of this result was written from,
                by JSON pointer into the result (`/warnings/0`, `/accuracy/method`):
                match a warning by its `id`; the texts themselves are in the
                language asked for (`Accept-Language`, `?lang=`).
     """

    warnings: list[str]
    complete: bool
    masses: EquivalentResultMasses
    residual: float
    unique: bool
    messages: NotesMessages | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.equivalent_result_masses import EquivalentResultMasses # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        warnings = self.warnings



        complete = self.complete

        masses = self.masses.to_dict()

        residual = self.residual

        unique = self.unique

        messages: dict[str, Any] | Unset = UNSET
        if not isinstance(self.messages, Unset):
            messages = self.messages.to_dict()


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "warnings": warnings,
            "complete": complete,
            "masses": masses,
            "residual": residual,
            "unique": unique,
        })
        if messages is not UNSET:
            field_dict["messages"] = messages

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.equivalent_result_masses import EquivalentResultMasses # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        d = dict(src_dict)
        warnings = cast(list[str], d.pop("warnings"))


        complete = d.pop("complete")

        masses = EquivalentResultMasses.from_dict(d.pop("masses"))




        residual = d.pop("residual")

        unique = d.pop("unique")

        _messages = d.pop("messages", UNSET)
        messages: NotesMessages | Unset
        if isinstance(_messages,  Unset):
            messages = UNSET
        else:
            messages = NotesMessages.from_dict(_messages)




        instance_ = cls(
            warnings=warnings,
            complete=complete,
            masses=masses,
            residual=residual,
            unique=unique,
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
