from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="InputInfo")



@_attrs_define
class InputInfo:
    """ A driven input: its joint and the units of its coordinate and driving action.

        Attributes:
            coordinate_unit (str): "rad" (a revolute joint, a body) or "m" (a prismatic joint, a point).
            driving_unit (str): "N*m" (a torque: at a revolute joint, on a body) or "N" (a force:
                along a prismatic joint, on a point).
            actuator (None | str | Unset): The joint where the driving effort acts (the input's own joint by default).
            body (None | str | Unset): The body the input's point belongs to, or whose rotation is the input.
            joint (None | str | Unset): The input joint (absent for an input on a point or a body).
            point (None | str | Unset): The point whose displacement along a direction is the input.
     """

    coordinate_unit: str
    driving_unit: str
    actuator: None | str | Unset = UNSET
    body: None | str | Unset = UNSET
    joint: None | str | Unset = UNSET
    point: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        coordinate_unit = self.coordinate_unit

        driving_unit = self.driving_unit

        actuator: None | str | Unset
        if isinstance(self.actuator, Unset):
            actuator = UNSET
        else:
            actuator = self.actuator

        body: None | str | Unset
        if isinstance(self.body, Unset):
            body = UNSET
        else:
            body = self.body

        joint: None | str | Unset
        if isinstance(self.joint, Unset):
            joint = UNSET
        else:
            joint = self.joint

        point: None | str | Unset
        if isinstance(self.point, Unset):
            point = UNSET
        else:
            point = self.point


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "coordinate_unit": coordinate_unit,
            "driving_unit": driving_unit,
        })
        if actuator is not UNSET:
            field_dict["actuator"] = actuator
        if body is not UNSET:
            field_dict["body"] = body
        if joint is not UNSET:
            field_dict["joint"] = joint
        if point is not UNSET:
            field_dict["point"] = point

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        coordinate_unit = d.pop("coordinate_unit")

        driving_unit = d.pop("driving_unit")

        def _parse_actuator(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        actuator = _parse_actuator(d.pop("actuator", UNSET))


        def _parse_body(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        body = _parse_body(d.pop("body", UNSET))


        def _parse_joint(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        joint = _parse_joint(d.pop("joint", UNSET))


        def _parse_point(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        point = _parse_point(d.pop("point", UNSET))


        instance_ = cls(
            coordinate_unit=coordinate_unit,
            driving_unit=driving_unit,
            actuator=actuator,
            body=body,
            joint=joint,
            point=point,
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
