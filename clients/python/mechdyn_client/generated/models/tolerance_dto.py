from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="ToleranceDto")



@_attrs_define
class ToleranceDto:
    """ How close an answer must be (every field optional).

    Passes when |given − expected| ≤ `absolute`, or ≤ `relative`·|expected|;
    with `sigfigs` = n, the relative rule is replaced by PrairieLearn's
    |given − expected| ≤ 0.51·10^(⌊log10|expected|⌋ − n + 1); when
    |expected| ≤ `zero_level` (SI), passes iff |given − expected| ≤ `zero_level`.

        Attributes:
            absolute (float | None | Unset): In the answer's SI unit, e.g. 0.5 (N·m).
            relative (float | None | Unset): E.g. 0.01: within 1 % (353.52 accepts 349.98 to 357.06).
            sigfigs (int | None | Unset): Significant figures, 1 to 15: 3 figures of 0.0004567 accept 0.000457, not
                0.000456.
            zero_level (float | None | Unset): SI; an expected value this small is compared absolutely (a reaction passing
                through zero).
     """

    absolute: float | None | Unset = UNSET
    relative: float | None | Unset = UNSET
    sigfigs: int | None | Unset = UNSET
    zero_level: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        absolute: float | None | Unset
        if isinstance(self.absolute, Unset):
            absolute = UNSET
        else:
            absolute = self.absolute

        relative: float | None | Unset
        if isinstance(self.relative, Unset):
            relative = UNSET
        else:
            relative = self.relative

        sigfigs: int | None | Unset
        if isinstance(self.sigfigs, Unset):
            sigfigs = UNSET
        else:
            sigfigs = self.sigfigs

        zero_level: float | None | Unset
        if isinstance(self.zero_level, Unset):
            zero_level = UNSET
        else:
            zero_level = self.zero_level


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
        })
        if absolute is not UNSET:
            field_dict["absolute"] = absolute
        if relative is not UNSET:
            field_dict["relative"] = relative
        if sigfigs is not UNSET:
            field_dict["sigfigs"] = sigfigs
        if zero_level is not UNSET:
            field_dict["zero_level"] = zero_level

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        def _parse_absolute(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        absolute = _parse_absolute(d.pop("absolute", UNSET))


        def _parse_relative(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        relative = _parse_relative(d.pop("relative", UNSET))


        def _parse_sigfigs(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        sigfigs = _parse_sigfigs(d.pop("sigfigs", UNSET))


        def _parse_zero_level(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        zero_level = _parse_zero_level(d.pop("zero_level", UNSET))


        instance_ = cls(
            absolute=absolute,
            relative=relative,
            sigfigs=sigfigs,
            zero_level=zero_level,
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
