from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="MeshDto")



@_attrs_define
class MeshDto:
    """ Wheel a (on member `a`) meshing with wheel b, axes held by `carrier`.

        Attributes:
            a (str):
            b (str):
            teeth_a (float):
            teeth_b (float):
            carrier (None | str | Unset): The member holding both axes (default `ground`: an ordinary mesh).
            internal (bool | None | Unset): Wheel b is an internal gear (ring); default false.
     """

    a: str
    b: str
    teeth_a: float
    teeth_b: float
    carrier: None | str | Unset = UNSET
    internal: bool | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        a = self.a

        b = self.b

        teeth_a = self.teeth_a

        teeth_b = self.teeth_b

        carrier: None | str | Unset
        if isinstance(self.carrier, Unset):
            carrier = UNSET
        else:
            carrier = self.carrier

        internal: bool | None | Unset
        if isinstance(self.internal, Unset):
            internal = UNSET
        else:
            internal = self.internal


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "a": a,
            "b": b,
            "teeth_a": teeth_a,
            "teeth_b": teeth_b,
        })
        if carrier is not UNSET:
            field_dict["carrier"] = carrier
        if internal is not UNSET:
            field_dict["internal"] = internal

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        a = d.pop("a")

        b = d.pop("b")

        teeth_a = d.pop("teeth_a")

        teeth_b = d.pop("teeth_b")

        def _parse_carrier(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        carrier = _parse_carrier(d.pop("carrier", UNSET))


        def _parse_internal(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        internal = _parse_internal(d.pop("internal", UNSET))


        instance_ = cls(
            a=a,
            b=b,
            teeth_a=teeth_a,
            teeth_b=teeth_b,
            carrier=carrier,
            internal=internal,
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
