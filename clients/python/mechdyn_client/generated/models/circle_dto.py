from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="CircleDto")



@_attrs_define
class CircleDto:
    """ 
        Attributes:
            center (list[float | str] | str):
            radius (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            inside (bool | None | Unset): The other curve touches it from within (a track, a ring's inside); default false.
     """

    center: list[float | str] | str
    radius: float | str
    inside: bool | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        center: list[float | str] | str
        if isinstance(self.center, list):
            center = []
            for center_item_data in self.center:
                center_item: float | str
                center_item = center_item_data
                center.append(center_item)


        else:
            center = self.center

        radius: float | str
        radius = self.radius

        inside: bool | None | Unset
        if isinstance(self.inside, Unset):
            inside = UNSET
        else:
            inside = self.inside


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "center": center,
            "radius": radius,
        })
        if inside is not UNSET:
            field_dict["inside"] = inside

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        def _parse_center(data: object) -> list[float | str] | str:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_point_ref_type_1 = []
                _componentsschemas_point_ref_type_1 = data
                for componentsschemas_point_ref_type_1_item_data in (_componentsschemas_point_ref_type_1):
                    def _parse_componentsschemas_point_ref_type_1_item(data: object) -> float | str:
                        return cast(float | str, data)

                    componentsschemas_point_ref_type_1_item = _parse_componentsschemas_point_ref_type_1_item(componentsschemas_point_ref_type_1_item_data)

                    componentsschemas_point_ref_type_1.append(componentsschemas_point_ref_type_1_item)

                return componentsschemas_point_ref_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | str] | str, data)

        center = _parse_center(d.pop("center"))


        def _parse_radius(data: object) -> float | str:
            return cast(float | str, data)

        radius = _parse_radius(d.pop("radius"))


        def _parse_inside(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        inside = _parse_inside(d.pop("inside", UNSET))


        instance_ = cls(
            center=center,
            radius=radius,
            inside=inside,
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
