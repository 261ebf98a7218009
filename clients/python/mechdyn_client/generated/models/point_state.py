from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset







T = TypeVar("T", bound="PointState")



@_attrs_define
class PointState:
    """ A tracked point's motion at a step (m, m/s, m/s²).

        Attributes:
            ax (float):
            ay (float):
            body (str):
            name (str):
            vx (float):
            vy (float):
            x (float):
            y (float):
     """

    ax: float
    ay: float
    body: str
    name: str
    vx: float
    vy: float
    x: float
    y: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        ax = self.ax

        ay = self.ay

        body = self.body

        name = self.name

        vx = self.vx

        vy = self.vy

        x = self.x

        y = self.y


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "ax": ax,
            "ay": ay,
            "body": body,
            "name": name,
            "vx": vx,
            "vy": vy,
            "x": x,
            "y": y,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        ax = d.pop("ax")

        ay = d.pop("ay")

        body = d.pop("body")

        name = d.pop("name")

        vx = d.pop("vx")

        vy = d.pop("vy")

        x = d.pop("x")

        y = d.pop("y")

        instance_ = cls(
            ax=ax,
            ay=ay,
            body=body,
            name=name,
            vx=vx,
            vy=vy,
            x=x,
            y=y,
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
