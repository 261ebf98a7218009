from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="TrackDtoType1")



@_attrs_define
class TrackDtoType1:
    """ a point of one body; `at` defaults to the point called `name`

        Attributes:
            body (str):
            name (str):
            at (list[float | str] | str | Unset):
     """

    body: str
    name: str
    at: list[float | str] | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        body = self.body

        name = self.name

        at: list[float | str] | str | Unset
        if isinstance(self.at, Unset):
            at = UNSET
        elif isinstance(self.at, list):
            at = []
            for at_item_data in self.at:
                at_item: float | str
                at_item = at_item_data
                at.append(at_item)


        else:
            at = self.at


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "body": body,
            "name": name,
        })
        if at is not UNSET:
            field_dict["at"] = at

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        body = d.pop("body")

        name = d.pop("name")

        def _parse_at(data: object) -> list[float | str] | str | Unset:
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                at_type_1 = []
                _at_type_1 = data
                for at_type_1_item_data in (_at_type_1):
                    def _parse_at_type_1_item(data: object) -> float | str:
                        return cast(float | str, data)

                    at_type_1_item = _parse_at_type_1_item(at_type_1_item_data)

                    at_type_1.append(at_type_1_item)

                return at_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | str] | str | Unset, data)

        at = _parse_at(d.pop("at", UNSET))


        instance_ = cls(
            body=body,
            name=name,
            at=at,
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
