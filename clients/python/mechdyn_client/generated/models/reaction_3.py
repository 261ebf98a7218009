from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast






T = TypeVar("T", bound="Reaction3")



@_attrs_define
class Reaction3:
    """ A joint's reaction on its second body (`on`) by its first (`by`): the
    force, and the moment about the joint's point as `on` carries it.

        Attributes:
            by (str):
            determinate (bool): False where the joint's rows are redundant: equilibrium cannot
                tell its share (this is the share of least norm).
            force (list[float]):
            joint (str):
            magnitude (float): |force|, N.
            moment (list[float]):
            on (str):
     """

    by: str
    determinate: bool
    force: list[float]
    joint: str
    magnitude: float
    moment: list[float]
    on: str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        by = self.by

        determinate = self.determinate

        force = self.force



        joint = self.joint

        magnitude = self.magnitude

        moment = self.moment



        on = self.on


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "by": by,
            "determinate": determinate,
            "force": force,
            "joint": joint,
            "magnitude": magnitude,
            "moment": moment,
            "on": on,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        by = d.pop("by")

        determinate = d.pop("determinate")

        force = cast(list[float], d.pop("force"))


        joint = d.pop("joint")

        magnitude = d.pop("magnitude")

        moment = cast(list[float], d.pop("moment"))


        on = d.pop("on")

        instance_ = cls(
            by=by,
            determinate=determinate,
            force=force,
            joint=joint,
            magnitude=magnitude,
            moment=moment,
            on=on,
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
