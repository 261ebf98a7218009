from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="Stated")



@_attrs_define
class Stated:
    """ One of a statement's quantities: `sign` × the result's number at `of`.

        Attributes:
            of (str): JSON pointer into the job's result, e.g. `/balance_torque`. Example: /balance_torque.
            description (None | str | Unset):
            printed (float | None | Unset): The value the statement's solution prints, in the field's SI unit
                (built-in templates: graded against the job by the tests).
            sign (float | None | Unset): +1 (default) or −1: a resisting torque is −`balance_torque`. Example: -1.
            wrong (None | str | Unset): Why the printed number is wrong, where it is (it then fails a check).
     """

    of: str
    description: None | str | Unset = UNSET
    printed: float | None | Unset = UNSET
    sign: float | None | Unset = UNSET
    wrong: None | str | Unset = UNSET





    def to_dict(self) -> dict[str, Any]:
        of = self.of

        description: None | str | Unset
        if isinstance(self.description, Unset):
            description = UNSET
        else:
            description = self.description

        printed: float | None | Unset
        if isinstance(self.printed, Unset):
            printed = UNSET
        else:
            printed = self.printed

        sign: float | None | Unset
        if isinstance(self.sign, Unset):
            sign = UNSET
        else:
            sign = self.sign

        wrong: None | str | Unset
        if isinstance(self.wrong, Unset):
            wrong = UNSET
        else:
            wrong = self.wrong


        field_dict: dict[str, Any] = {}

        field_dict.update({
            "of": of,
        })
        if description is not UNSET:
            field_dict["description"] = description
        if printed is not UNSET:
            field_dict["printed"] = printed
        if sign is not UNSET:
            field_dict["sign"] = sign
        if wrong is not UNSET:
            field_dict["wrong"] = wrong

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        of = d.pop("of")

        def _parse_description(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        description = _parse_description(d.pop("description", UNSET))


        def _parse_printed(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        printed = _parse_printed(d.pop("printed", UNSET))


        def _parse_sign(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        sign = _parse_sign(d.pop("sign", UNSET))


        def _parse_wrong(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        wrong = _parse_wrong(d.pop("wrong", UNSET))


        instance_ = cls(
            of=of,
            description=description,
            printed=printed,
            sign=sign,
            wrong=wrong,
        )

        return instance_

