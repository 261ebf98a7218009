from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="CamSegmentDto")



@_attrs_define
class CamSegmentDto:
    """ A segment ending at `to` with the follower at `lift` by `law`.

        Attributes:
            law (str): dwell, harmonic, cycloidal, polynomial-345, polynomial-4567, modified-sine or modified-trapezoid
                (in any case, or in Spanish: "cicloidal", "reposo", "armónico"…).
            to (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            lift (float | None | str | Unset):
     """

    law: str
    to: float | str
    lift: float | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        law = self.law

        to: float | str
        to = self.to

        lift: float | None | str | Unset
        if isinstance(self.lift, Unset):
            lift = UNSET
        else:
            lift = self.lift


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "law": law,
            "to": to,
        })
        if lift is not UNSET:
            field_dict["lift"] = lift

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        law = d.pop("law")

        def _parse_to(data: object) -> float | str:
            return cast(float | str, data)

        to = _parse_to(d.pop("to"))


        def _parse_lift(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        lift = _parse_lift(d.pop("lift", UNSET))


        instance_ = cls(
            law=law,
            to=to,
            lift=lift,
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
