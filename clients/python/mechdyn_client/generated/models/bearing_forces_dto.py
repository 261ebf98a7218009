from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast






T = TypeVar("T", bound="BearingForcesDto")



@_attrs_define
class BearingForcesDto:
    """ The forces bearings A and B put on the rotor turning at `speed` with no
    other load, [[Fx, Fy], [Fx, Fy]] in the rotor's frame at angle 0, before
    and after the corrections.

        Attributes:
            after (list[list[float]]):
            bearings (list[float]):
            before (list[list[float]]):
            speed (float):
     """

    after: list[list[float]]
    bearings: list[float]
    before: list[list[float]]
    speed: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        after = []
        for after_item_data in self.after:
            after_item = after_item_data


            after.append(after_item)



        bearings = self.bearings



        before = []
        for before_item_data in self.before:
            before_item = before_item_data


            before.append(before_item)



        speed = self.speed


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "after": after,
            "bearings": bearings,
            "before": before,
            "speed": speed,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        after = []
        _after = d.pop("after")
        for after_item_data in (_after):
            after_item = cast(list[float], after_item_data)

            after.append(after_item)


        bearings = cast(list[float], d.pop("bearings"))


        before = []
        _before = d.pop("before")
        for before_item_data in (_before):
            before_item = cast(list[float], before_item_data)

            before.append(before_item)


        speed = d.pop("speed")

        instance_ = cls(
            after=after,
            bearings=bearings,
            before=before,
            speed=speed,
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
