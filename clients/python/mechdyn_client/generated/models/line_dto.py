from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast






T = TypeVar("T", bound="LineDto")



@_attrs_define
class LineDto:
    """ 
        Attributes:
            direction (list[float]): Its direction as drawn, [x, y] (any length but 0).
            through (list[float | str] | str):
     """

    direction: list[float]
    through: list[float | str] | str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        direction = self.direction



        through: list[float | str] | str
        if isinstance(self.through, list):
            through = []
            for through_item_data in self.through:
                through_item: float | str
                through_item = through_item_data
                through.append(through_item)


        else:
            through = self.through


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "direction": direction,
            "through": through,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        direction = cast(list[float], d.pop("direction"))


        def _parse_through(data: object) -> list[float | str] | str:
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

        through = _parse_through(d.pop("through"))


        instance_ = cls(
            direction=direction,
            through=through,
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
