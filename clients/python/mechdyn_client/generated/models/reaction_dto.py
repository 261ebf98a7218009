from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="ReactionDto")



@_attrs_define
class ReactionDto:
    """ The force body `by` exerts on body `on` at the joint (ground frame) and the
    couple about the joint point, the joint's friction included (the force
    along a slide, the couple of a pin), so that every body's forces
    balance. Null when redundant constraints leave it undetermined.

        Attributes:
            by (str):
            determinate (bool):
            joint (str):
            on (str):
            ends (list[float] | None | Unset): A prismatic joint with a `length`: the normal forces N₁, N₂ at the
                guide's ends (at − L/2 and at + L/2 along the axis), N, on `on`.
            fx (float | None | Unset):
            fy (float | None | Unset):
            moment (float | None | Unset):
            mu_required (float | None | Unset): A rolling contact: |tangential|/normal, the least friction coefficient that
                rolls.
            normal (float | None | Unset): A contact: the normal force (N ≥ 0 when the bodies press on each other).
            tangential (float | None | Unset): A contact: the force along the common tangent (the friction, or the
                force rolling needs). A sliding contact that is an input, or an
                input's actuator, leaves out the driving effort: it is the
                actuator's (in `driving`), acting along the contact's arc length.
     """

    by: str
    determinate: bool
    joint: str
    on: str
    ends: list[float] | None | Unset = UNSET
    fx: float | None | Unset = UNSET
    fy: float | None | Unset = UNSET
    moment: float | None | Unset = UNSET
    mu_required: float | None | Unset = UNSET
    normal: float | None | Unset = UNSET
    tangential: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        by = self.by

        determinate = self.determinate

        joint = self.joint

        on = self.on

        ends: list[float] | None | Unset
        if isinstance(self.ends, Unset):
            ends = UNSET
        elif isinstance(self.ends, list):
            ends = self.ends


        else:
            ends = self.ends

        fx: float | None | Unset
        if isinstance(self.fx, Unset):
            fx = UNSET
        else:
            fx = self.fx

        fy: float | None | Unset
        if isinstance(self.fy, Unset):
            fy = UNSET
        else:
            fy = self.fy

        moment: float | None | Unset
        if isinstance(self.moment, Unset):
            moment = UNSET
        else:
            moment = self.moment

        mu_required: float | None | Unset
        if isinstance(self.mu_required, Unset):
            mu_required = UNSET
        else:
            mu_required = self.mu_required

        normal: float | None | Unset
        if isinstance(self.normal, Unset):
            normal = UNSET
        else:
            normal = self.normal

        tangential: float | None | Unset
        if isinstance(self.tangential, Unset):
            tangential = UNSET
        else:
            tangential = self.tangential


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "by": by,
            "determinate": determinate,
            "joint": joint,
            "on": on,
        })
        if ends is not UNSET:
            field_dict["ends"] = ends
        if fx is not UNSET:
            field_dict["fx"] = fx
        if fy is not UNSET:
            field_dict["fy"] = fy
        if moment is not UNSET:
            field_dict["moment"] = moment
        if mu_required is not UNSET:
            field_dict["mu_required"] = mu_required
        if normal is not UNSET:
            field_dict["normal"] = normal
        if tangential is not UNSET:
            field_dict["tangential"] = tangential

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        by = d.pop("by")

        determinate = d.pop("determinate")

        joint = d.pop("joint")

        on = d.pop("on")

        def _parse_ends(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                ends_type_0 = list(data)

                return ends_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        ends = _parse_ends(d.pop("ends", UNSET))


        def _parse_fx(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        fx = _parse_fx(d.pop("fx", UNSET))


        def _parse_fy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        fy = _parse_fy(d.pop("fy", UNSET))


        def _parse_moment(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        moment = _parse_moment(d.pop("moment", UNSET))


        def _parse_mu_required(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mu_required = _parse_mu_required(d.pop("mu_required", UNSET))


        def _parse_normal(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        normal = _parse_normal(d.pop("normal", UNSET))


        def _parse_tangential(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tangential = _parse_tangential(d.pop("tangential", UNSET))


        instance_ = cls(
            by=by,
            determinate=determinate,
            joint=joint,
            on=on,
            ends=ends,
            fx=fx,
            fy=fy,
            moment=moment,
            mu_required=mu_required,
            normal=normal,
            tangential=tangential,
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
