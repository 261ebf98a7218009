from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="InertiaDto")



@_attrs_define
class InertiaDto:
    """ Moments and products of inertia about G in the frame's axes, kg·m²; the
    tensor is [[xx, −xy, −xz], [−xy, yy, −yz], [−xz, −yz, zz]] (products default 0).

        Attributes:
            xx (float):
            yy (float):
            zz (float):
            xy (float | None | Unset):
            xz (float | None | Unset):
            yz (float | None | Unset):
     """

    xx: float
    yy: float
    zz: float
    xy: float | None | Unset = UNSET
    xz: float | None | Unset = UNSET
    yz: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        xx = self.xx

        yy = self.yy

        zz = self.zz

        xy: float | None | Unset
        if isinstance(self.xy, Unset):
            xy = UNSET
        else:
            xy = self.xy

        xz: float | None | Unset
        if isinstance(self.xz, Unset):
            xz = UNSET
        else:
            xz = self.xz

        yz: float | None | Unset
        if isinstance(self.yz, Unset):
            yz = UNSET
        else:
            yz = self.yz


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "xx": xx,
            "yy": yy,
            "zz": zz,
        })
        if xy is not UNSET:
            field_dict["xy"] = xy
        if xz is not UNSET:
            field_dict["xz"] = xz
        if yz is not UNSET:
            field_dict["yz"] = yz

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        xx = d.pop("xx")

        yy = d.pop("yy")

        zz = d.pop("zz")

        def _parse_xy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        xy = _parse_xy(d.pop("xy", UNSET))


        def _parse_xz(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        xz = _parse_xz(d.pop("xz", UNSET))


        def _parse_yz(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        yz = _parse_yz(d.pop("yz", UNSET))


        instance_ = cls(
            xx=xx,
            yy=yy,
            zz=zz,
            xy=xy,
            xz=xz,
            yz=yz,
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
