from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="BodyMotion")



@_attrs_define
class BodyMotion:
    """ Position, velocity and acceleration of a body's centre of mass and
    rotation. A massless body drawn without `cg` has no centre of mass:
    its x, y, v and a are null (`track` follows any of its points).

        Attributes:
            alpha (float):
            body (str):
            inertia_moment (float): The moment of the body's inertia forces about its centre of mass, −I_G·α (N·m).
            omega (float):
            theta (float): Rotation from the drawn configuration, rad.
            ax (float | None | Unset):
            ay (float | None | Unset):
            inertia_force (list[float] | None | Unset):
            vx (float | None | Unset):
            vy (float | None | Unset):
            x (float | None | Unset):
            y (float | None | Unset):
     """

    alpha: float
    body: str
    inertia_moment: float
    omega: float
    theta: float
    ax: float | None | Unset = UNSET
    ay: float | None | Unset = UNSET
    inertia_force: list[float] | None | Unset = UNSET
    vx: float | None | Unset = UNSET
    vy: float | None | Unset = UNSET
    x: float | None | Unset = UNSET
    y: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        alpha = self.alpha

        body = self.body

        inertia_moment = self.inertia_moment

        omega = self.omega

        theta = self.theta

        ax: float | None | Unset
        if isinstance(self.ax, Unset):
            ax = UNSET
        else:
            ax = self.ax

        ay: float | None | Unset
        if isinstance(self.ay, Unset):
            ay = UNSET
        else:
            ay = self.ay

        inertia_force: list[float] | None | Unset
        if isinstance(self.inertia_force, Unset):
            inertia_force = UNSET
        elif isinstance(self.inertia_force, list):
            inertia_force = self.inertia_force


        else:
            inertia_force = self.inertia_force

        vx: float | None | Unset
        if isinstance(self.vx, Unset):
            vx = UNSET
        else:
            vx = self.vx

        vy: float | None | Unset
        if isinstance(self.vy, Unset):
            vy = UNSET
        else:
            vy = self.vy

        x: float | None | Unset
        if isinstance(self.x, Unset):
            x = UNSET
        else:
            x = self.x

        y: float | None | Unset
        if isinstance(self.y, Unset):
            y = UNSET
        else:
            y = self.y


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "alpha": alpha,
            "body": body,
            "inertia_moment": inertia_moment,
            "omega": omega,
            "theta": theta,
        })
        if ax is not UNSET:
            field_dict["ax"] = ax
        if ay is not UNSET:
            field_dict["ay"] = ay
        if inertia_force is not UNSET:
            field_dict["inertia_force"] = inertia_force
        if vx is not UNSET:
            field_dict["vx"] = vx
        if vy is not UNSET:
            field_dict["vy"] = vy
        if x is not UNSET:
            field_dict["x"] = x
        if y is not UNSET:
            field_dict["y"] = y

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        alpha = d.pop("alpha")

        body = d.pop("body")

        inertia_moment = d.pop("inertia_moment")

        omega = d.pop("omega")

        theta = d.pop("theta")

        def _parse_ax(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        ax = _parse_ax(d.pop("ax", UNSET))


        def _parse_ay(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        ay = _parse_ay(d.pop("ay", UNSET))


        def _parse_inertia_force(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                inertia_force_type_0 = list(data)

                return inertia_force_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        inertia_force = _parse_inertia_force(d.pop("inertia_force", UNSET))


        def _parse_vx(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        vx = _parse_vx(d.pop("vx", UNSET))


        def _parse_vy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        vy = _parse_vy(d.pop("vy", UNSET))


        def _parse_x(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        x = _parse_x(d.pop("x", UNSET))


        def _parse_y(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        y = _parse_y(d.pop("y", UNSET))


        instance_ = cls(
            alpha=alpha,
            body=body,
            inertia_moment=inertia_moment,
            omega=omega,
            theta=theta,
            ax=ax,
            ay=ay,
            inertia_force=inertia_force,
            vx=vx,
            vy=vy,
            x=x,
            y=y,
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
