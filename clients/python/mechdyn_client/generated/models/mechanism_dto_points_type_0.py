from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast






T = TypeVar("T", bound="MechanismDtoPointsType0")



@_attrs_define
class MechanismDtoPointsType0:
    """ Named points in the drawn configuration: `{NAME: [x, y]}` (in space
    `[x, y, z]`), each coordinate in m or a length with its unit (`"8 cm"`).

     """

    additional_properties: dict[str, list[float | str]] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        
        field_dict: dict[str, Any] = {}
        for prop_name, prop in self.additional_properties.items():
            field_dict[prop_name] = []
            for componentsschemas_drawn_coords_item_data in prop:
                componentsschemas_drawn_coords_item: float | str
                componentsschemas_drawn_coords_item = componentsschemas_drawn_coords_item_data
                field_dict[prop_name].append(componentsschemas_drawn_coords_item)




        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        instance_ = cls(
        )


        additional_properties = {}
        for prop_name, prop_dict in d.items():
            additional_property = []
            _additional_property = prop_dict
            for componentsschemas_drawn_coords_item_data in (_additional_property):
                def _parse_componentsschemas_drawn_coords_item(data: object) -> float | str:
                    return cast(float | str, data)

                componentsschemas_drawn_coords_item = _parse_componentsschemas_drawn_coords_item(componentsschemas_drawn_coords_item_data)

                additional_property.append(componentsschemas_drawn_coords_item)

            additional_properties[prop_name] = additional_property

        instance_.additional_properties = additional_properties
        return instance_

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> list[float | str]:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: list[float | str]) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
