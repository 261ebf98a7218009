from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast






T = TypeVar("T", bound="SegmentDto")



@_attrs_define
class SegmentDto:
    """ 
        Attributes:
            expr (str): Expression of `phi`. Example: -500*sin(phi).
            from_ (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            to (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
     """

    expr: str
    from_: float | str
    to: float | str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        expr = self.expr

        from_: float | str
        from_ = self.from_

        to: float | str
        to = self.to


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "expr": expr,
            "from": from_,
            "to": to,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        expr = d.pop("expr")

        def _parse_from_(data: object) -> float | str:
            return cast(float | str, data)

        from_ = _parse_from_(d.pop("from"))


        def _parse_to(data: object) -> float | str:
            return cast(float | str, data)

        to = _parse_to(d.pop("to"))


        instance_ = cls(
            expr=expr,
            from_=from_,
            to=to,
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
