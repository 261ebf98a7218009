from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="Couple")



@_attrs_define
class Couple:
    """ A couple on the body: about z, counter-clockwise positive (seen from +z),
    and in space about x and y too.

        Attributes:
            kind (str):
            moment (float): M_z, N·m.
            name (str): `M_I3`, `M23` (a pin's friction, a guide's couple), `M_m`.
            power (float): M·ω of the body, W.
            by (None | str | Unset):
            joint (None | str | Unset):
            mx (float | None | Unset): M_x, N·m, in space.
            my (float | None | Unset): M_y, N·m, in space.
     """

    kind: str
    moment: float
    name: str
    power: float
    by: None | str | Unset = UNSET
    joint: None | str | Unset = UNSET
    mx: float | None | Unset = UNSET
    my: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        kind = self.kind

        moment = self.moment

        name = self.name

        power = self.power

        by: None | str | Unset
        if isinstance(self.by, Unset):
            by = UNSET
        else:
            by = self.by

        joint: None | str | Unset
        if isinstance(self.joint, Unset):
            joint = UNSET
        else:
            joint = self.joint

        mx: float | None | Unset
        if isinstance(self.mx, Unset):
            mx = UNSET
        else:
            mx = self.mx

        my: float | None | Unset
        if isinstance(self.my, Unset):
            my = UNSET
        else:
            my = self.my


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "kind": kind,
            "moment": moment,
            "name": name,
            "power": power,
        })
        if by is not UNSET:
            field_dict["by"] = by
        if joint is not UNSET:
            field_dict["joint"] = joint
        if mx is not UNSET:
            field_dict["mx"] = mx
        if my is not UNSET:
            field_dict["my"] = my

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        kind = d.pop("kind")

        moment = d.pop("moment")

        name = d.pop("name")

        power = d.pop("power")

        def _parse_by(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        by = _parse_by(d.pop("by", UNSET))


        def _parse_joint(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        joint = _parse_joint(d.pop("joint", UNSET))


        def _parse_mx(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mx = _parse_mx(d.pop("mx", UNSET))


        def _parse_my(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        my = _parse_my(d.pop("my", UNSET))


        instance_ = cls(
            kind=kind,
            moment=moment,
            name=name,
            power=power,
            by=by,
            joint=joint,
            mx=mx,
            my=my,
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
