from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset







T = TypeVar("T", bound="MemberResult")



@_attrs_define
class MemberResult:
    """ One member's motion and load (SI: rad/s, N·m, W).

        Attributes:
            member (str):
            power (float):
            speed (float):
            torque (float): The external torque on it (given, found, or 0).
     """

    member: str
    power: float
    speed: float
    torque: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        member = self.member

        power = self.power

        speed = self.speed

        torque = self.torque


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "member": member,
            "power": power,
            "speed": speed,
            "torque": torque,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        member = d.pop("member")

        power = d.pop("power")

        speed = d.pop("speed")

        torque = d.pop("torque")

        instance_ = cls(
            member=member,
            power=power,
            speed=speed,
            torque=torque,
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
