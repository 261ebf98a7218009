from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="Equations")



@_attrs_define
class Equations:
    """ The body's three equations with its actions' numbers (six in space):
    each is zero to rounding.

        Attributes:
            sum_fx (float): ΣF_x, N.
            sum_fy (float): ΣF_y, N.
            sum_moment_about_cg (float): ΣM_G, about the body's centre of mass (about z through it in space), N·m.
            sum_fz (float | None | Unset): ΣF_z, N, in space.
            sum_mx_about_cg (float | None | Unset): ΣM_G about x, N·m, in space.
            sum_my_about_cg (float | None | Unset): ΣM_G about y, N·m, in space.
     """

    sum_fx: float
    sum_fy: float
    sum_moment_about_cg: float
    sum_fz: float | None | Unset = UNSET
    sum_mx_about_cg: float | None | Unset = UNSET
    sum_my_about_cg: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        sum_fx = self.sum_fx

        sum_fy = self.sum_fy

        sum_moment_about_cg = self.sum_moment_about_cg

        sum_fz: float | None | Unset
        if isinstance(self.sum_fz, Unset):
            sum_fz = UNSET
        else:
            sum_fz = self.sum_fz

        sum_mx_about_cg: float | None | Unset
        if isinstance(self.sum_mx_about_cg, Unset):
            sum_mx_about_cg = UNSET
        else:
            sum_mx_about_cg = self.sum_mx_about_cg

        sum_my_about_cg: float | None | Unset
        if isinstance(self.sum_my_about_cg, Unset):
            sum_my_about_cg = UNSET
        else:
            sum_my_about_cg = self.sum_my_about_cg


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "sum_fx": sum_fx,
            "sum_fy": sum_fy,
            "sum_moment_about_cg": sum_moment_about_cg,
        })
        if sum_fz is not UNSET:
            field_dict["sum_fz"] = sum_fz
        if sum_mx_about_cg is not UNSET:
            field_dict["sum_mx_about_cg"] = sum_mx_about_cg
        if sum_my_about_cg is not UNSET:
            field_dict["sum_my_about_cg"] = sum_my_about_cg

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        sum_fx = d.pop("sum_fx")

        sum_fy = d.pop("sum_fy")

        sum_moment_about_cg = d.pop("sum_moment_about_cg")

        def _parse_sum_fz(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        sum_fz = _parse_sum_fz(d.pop("sum_fz", UNSET))


        def _parse_sum_mx_about_cg(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        sum_mx_about_cg = _parse_sum_mx_about_cg(d.pop("sum_mx_about_cg", UNSET))


        def _parse_sum_my_about_cg(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        sum_my_about_cg = _parse_sum_my_about_cg(d.pop("sum_my_about_cg", UNSET))


        instance_ = cls(
            sum_fx=sum_fx,
            sum_fy=sum_fy,
            sum_moment_about_cg=sum_moment_about_cg,
            sum_fz=sum_fz,
            sum_mx_about_cg=sum_mx_about_cg,
            sum_my_about_cg=sum_my_about_cg,
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
