from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset







T = TypeVar("T", bound="ItemWork")



@_attrs_define
class ItemWork:
    """ Work of one torque item over a cycle, reduced to the reference shaft.

        Attributes:
            mean_torque (float): The item's mean torque on the reference shaft, work over the period
                (C* = W/λ, N·m): a constant motor's reduced torque (the balance
                torque) or a load's mean.
            name (str):
            work (float): J
     """

    mean_torque: float
    name: str
    work: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        mean_torque = self.mean_torque

        name = self.name

        work = self.work


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "mean_torque": mean_torque,
            "name": name,
            "work": work,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        mean_torque = d.pop("mean_torque")

        name = d.pop("name")

        work = d.pop("work")

        instance_ = cls(
            mean_torque=mean_torque,
            name=name,
            work=work,
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
