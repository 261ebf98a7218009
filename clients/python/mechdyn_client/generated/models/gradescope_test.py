from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset







T = TypeVar("T", bound="GradescopeTest")



@_attrs_define
class GradescopeTest:
    """ 
        Attributes:
            max_score (float):
            name (str):
            number (str): "1", "2", ...: the answers' order.
            output (str): The answer's feedback.
            score (float):
            status (str): `passed` or `failed`.
            visibility (str):
     """

    max_score: float
    name: str
    number: str
    output: str
    score: float
    status: str
    visibility: str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        max_score = self.max_score

        name = self.name

        number = self.number

        output = self.output

        score = self.score

        status = self.status

        visibility = self.visibility


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "max_score": max_score,
            "name": name,
            "number": number,
            "output": output,
            "score": score,
            "status": status,
            "visibility": visibility,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        max_score = d.pop("max_score")

        name = d.pop("name")

        number = d.pop("number")

        output = d.pop("output")

        score = d.pop("score")

        status = d.pop("status")

        visibility = d.pop("visibility")

        instance_ = cls(
            max_score=max_score,
            name=name,
            number=number,
            output=output,
            score=score,
            status=status,
            visibility=visibility,
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
