from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="BalanceDto")



@_attrs_define
class BalanceDto:
    """ Which links get counterweights, and how much of a slider-crank's
    reciprocating mass they balance.

        Example:
            {'counterweights': ['crank', 'rocker']}

        Attributes:
            counterweights (list[str]): The links pivoted to the frame that carry them, by name: a
                four-bar's crank and rocker, a slider-crank's crank.
            reciprocating_fraction (float | None | str | Unset):
     """

    counterweights: list[str]
    reciprocating_fraction: float | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        counterweights = self.counterweights



        reciprocating_fraction: float | None | str | Unset
        if isinstance(self.reciprocating_fraction, Unset):
            reciprocating_fraction = UNSET
        else:
            reciprocating_fraction = self.reciprocating_fraction


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "counterweights": counterweights,
        })
        if reciprocating_fraction is not UNSET:
            field_dict["reciprocating_fraction"] = reciprocating_fraction

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        counterweights = cast(list[str], d.pop("counterweights"))


        def _parse_reciprocating_fraction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        reciprocating_fraction = _parse_reciprocating_fraction(d.pop("reciprocating_fraction", UNSET))


        instance_ = cls(
            counterweights=counterweights,
            reciprocating_fraction=reciprocating_fraction,
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
