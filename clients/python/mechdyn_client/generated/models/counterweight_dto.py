from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset







T = TypeVar("T", bound="CounterweightDto")



@_attrs_define
class CounterweightDto:
    """ A counterweight on a link pivoted to the frame.

        Attributes:
            angle (float): In the link's frame, from the line joining its joint with the frame
                to its other joint, CCW, rad.
            body (str):
            mass_radius (float): m·r, measured from the link's joint with the frame, kg·m.
     """

    angle: float
    body: str
    mass_radius: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        angle = self.angle

        body = self.body

        mass_radius = self.mass_radius


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "angle": angle,
            "body": body,
            "mass_radius": mass_radius,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        angle = d.pop("angle")

        body = d.pop("body")

        mass_radius = d.pop("mass_radius")

        instance_ = cls(
            angle=angle,
            body=body,
            mass_radius=mass_radius,
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
