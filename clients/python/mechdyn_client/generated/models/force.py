from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="Force")



@_attrs_define
class Force:
    """ A force on the body at the point `at`.

        Attributes:
            at (list[float]): Where it acts at the step, m: [x, y], in space [x, y, z].
            fx (float): N
            fy (float): N
            kind (str): `reaction`, `inertia`, `weight`, `load` or `driving`.
            name (str): `R23`, `F_I3`, `W3`, a load's name, `F_m`.
            power (float): Its power at the step, F·v of its point, W.
            by (None | str | Unset): The body it comes from (a reaction).
            fz (float | None | Unset): N, in space.
            joint (None | str | Unset): The joint it acts through (a reaction, a driving effort at a joint).
     """

    at: list[float]
    fx: float
    fy: float
    kind: str
    name: str
    power: float
    by: None | str | Unset = UNSET
    fz: float | None | Unset = UNSET
    joint: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        at = self.at



        fx = self.fx

        fy = self.fy

        kind = self.kind

        name = self.name

        power = self.power

        by: None | str | Unset
        if isinstance(self.by, Unset):
            by = UNSET
        else:
            by = self.by

        fz: float | None | Unset
        if isinstance(self.fz, Unset):
            fz = UNSET
        else:
            fz = self.fz

        joint: None | str | Unset
        if isinstance(self.joint, Unset):
            joint = UNSET
        else:
            joint = self.joint


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "at": at,
            "fx": fx,
            "fy": fy,
            "kind": kind,
            "name": name,
            "power": power,
        })
        if by is not UNSET:
            field_dict["by"] = by
        if fz is not UNSET:
            field_dict["fz"] = fz
        if joint is not UNSET:
            field_dict["joint"] = joint

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        at = cast(list[float], d.pop("at"))


        fx = d.pop("fx")

        fy = d.pop("fy")

        kind = d.pop("kind")

        name = d.pop("name")

        power = d.pop("power")

        def _parse_by(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        by = _parse_by(d.pop("by", UNSET))


        def _parse_fz(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        fz = _parse_fz(d.pop("fz", UNSET))


        def _parse_joint(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        joint = _parse_joint(d.pop("joint", UNSET))


        instance_ = cls(
            at=at,
            fx=fx,
            fy=fy,
            kind=kind,
            name=name,
            power=power,
            by=by,
            fz=fz,
            joint=joint,
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
