from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="CheckItem")



@_attrs_define
class CheckItem:
    """ One answer judged.

        Attributes:
            answer (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            feedback (str): For the student: which quantity, how far off, the slip (in the
                asker's language; its message in the result's `messages`).
            pass_ (bool):
            pointer (str): JSON pointer into the reference result. Example: /inertia_exact.
            unit (str): SI unit of `given` and `expected` (`1`: dimensionless). Example: kg*m^2.
            expected (float | None | Unset): The reference value in SI; null when `reveal` is false.
            given (float | None | Unset): The answer in SI (`unit`); null when it could not be read.
            relative_error (float | None | Unset): |given − expected| / |expected|; null when not revealed or expected is 0.
            slip (None | str | Unset): The slip a wrong answer matches: `other_value:/POINTER`, `opposite_sign`,
                `degrees`, `rpm`, `times_2pi`, `over_2pi`, `power_of_ten:K`.
     """

    answer: float | str
    feedback: str
    pass_: bool
    pointer: str
    unit: str
    expected: float | None | Unset = UNSET
    given: float | None | Unset = UNSET
    relative_error: float | None | Unset = UNSET
    slip: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        answer: float | str
        answer = self.answer

        feedback = self.feedback

        pass_ = self.pass_

        pointer = self.pointer

        unit = self.unit

        expected: float | None | Unset
        if isinstance(self.expected, Unset):
            expected = UNSET
        else:
            expected = self.expected

        given: float | None | Unset
        if isinstance(self.given, Unset):
            given = UNSET
        else:
            given = self.given

        relative_error: float | None | Unset
        if isinstance(self.relative_error, Unset):
            relative_error = UNSET
        else:
            relative_error = self.relative_error

        slip: None | str | Unset
        if isinstance(self.slip, Unset):
            slip = UNSET
        else:
            slip = self.slip


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "answer": answer,
            "feedback": feedback,
            "pass": pass_,
            "pointer": pointer,
            "unit": unit,
        })
        if expected is not UNSET:
            field_dict["expected"] = expected
        if given is not UNSET:
            field_dict["given"] = given
        if relative_error is not UNSET:
            field_dict["relative_error"] = relative_error
        if slip is not UNSET:
            field_dict["slip"] = slip

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        def _parse_answer(data: object) -> float | str:
            return cast(float | str, data)

        answer = _parse_answer(d.pop("answer"))


        feedback = d.pop("feedback")

        pass_ = d.pop("pass")

        pointer = d.pop("pointer")

        unit = d.pop("unit")

        def _parse_expected(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        expected = _parse_expected(d.pop("expected", UNSET))


        def _parse_given(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        given = _parse_given(d.pop("given", UNSET))


        def _parse_relative_error(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        relative_error = _parse_relative_error(d.pop("relative_error", UNSET))


        def _parse_slip(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        slip = _parse_slip(d.pop("slip", UNSET))


        instance_ = cls(
            answer=answer,
            feedback=feedback,
            pass_=pass_,
            pointer=pointer,
            unit=unit,
            expected=expected,
            given=given,
            relative_error=relative_error,
            slip=slip,
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
