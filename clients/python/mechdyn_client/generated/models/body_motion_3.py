from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast






T = TypeVar("T", bound="BodyMotion3")



@_attrs_define
class BodyMotion3:
    """ A body in space: its centre of mass's position, velocity and
    acceleration, its rotation from the drawing, its angular velocity and
    acceleration (ground axes, SI).

        Attributes:
            acceleration (list[float]):
            angular_acceleration (list[float]):
            angular_velocity (list[float]):
            body (str):
            position (list[float]):
            rotation (list[list[float]]): R, the rotation from the drawn body to the body now (rows).
            velocity (list[float]):
     """

    acceleration: list[float]
    angular_acceleration: list[float]
    angular_velocity: list[float]
    body: str
    position: list[float]
    rotation: list[list[float]]
    velocity: list[float]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        acceleration = self.acceleration



        angular_acceleration = self.angular_acceleration



        angular_velocity = self.angular_velocity



        body = self.body

        position = self.position



        rotation = []
        for rotation_item_data in self.rotation:
            rotation_item = rotation_item_data


            rotation.append(rotation_item)



        velocity = self.velocity




        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "acceleration": acceleration,
            "angular_acceleration": angular_acceleration,
            "angular_velocity": angular_velocity,
            "body": body,
            "position": position,
            "rotation": rotation,
            "velocity": velocity,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        acceleration = cast(list[float], d.pop("acceleration"))


        angular_acceleration = cast(list[float], d.pop("angular_acceleration"))


        angular_velocity = cast(list[float], d.pop("angular_velocity"))


        body = d.pop("body")

        position = cast(list[float], d.pop("position"))


        rotation = []
        _rotation = d.pop("rotation")
        for rotation_item_data in (_rotation):
            rotation_item = cast(list[float], rotation_item_data)

            rotation.append(rotation_item)


        velocity = cast(list[float], d.pop("velocity"))


        instance_ = cls(
            acceleration=acceleration,
            angular_acceleration=angular_acceleration,
            angular_velocity=angular_velocity,
            body=body,
            position=position,
            rotation=rotation,
            velocity=velocity,
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
