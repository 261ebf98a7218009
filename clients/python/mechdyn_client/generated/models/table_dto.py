from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast






T = TypeVar("T", bound="TableDto")



@_attrs_define
class TableDto:
    """ 
        Attributes:
            angle (list[float | str]): Angles (rad, or angle quantities), strictly increasing in [0, period).
            value (list[float]):
     """

    angle: list[float | str]
    value: list[float]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        angle = []
        for angle_item_data in self.angle:
            angle_item: float | str
            angle_item = angle_item_data
            angle.append(angle_item)



        value = self.value




        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "angle": angle,
            "value": value,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        angle = []
        _angle = d.pop("angle")
        for angle_item_data in (_angle):
            def _parse_angle_item(data: object) -> float | str:
                return cast(float | str, data)

            angle_item = _parse_angle_item(angle_item_data)

            angle.append(angle_item)


        value = cast(list[float], d.pop("value"))


        instance_ = cls(
            angle=angle,
            value=value,
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
