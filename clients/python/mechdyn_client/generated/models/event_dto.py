from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="EventDto")



@_attrs_define
class EventDto:
    """ 
        Attributes:
            angle (float):
            kind (str): "turn" (a multiple of 2π first crossed, either direction: a whole turn; a swing back across one is
                none), "slip" (a
                rolling contact with friction starts to slip, or its slip turns
                back), "roll" (a slipping contact rolls again), "separation" (a
                contact's normal force fell to 0, or was below 0 at the start: the
                bodies part, and the run stops there) or "end".
            speed (float):
            t (float):
            joint (None | str | Unset): The contact joint of a "slip", "roll" or "separation" event.
            t_energy_form (float | None | Unset): Reduced form with actions of φ only: the time of the event by the
                energy form t = ∫dφ/ω, ω from ½I*ω² = T₀ + ∫M*dφ (nested quadratures,
                no differential equation), while the motion has not turned back.
     """

    angle: float
    kind: str
    speed: float
    t: float
    joint: None | str | Unset = UNSET
    t_energy_form: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        angle = self.angle

        kind = self.kind

        speed = self.speed

        t = self.t

        joint: None | str | Unset
        if isinstance(self.joint, Unset):
            joint = UNSET
        else:
            joint = self.joint

        t_energy_form: float | None | Unset
        if isinstance(self.t_energy_form, Unset):
            t_energy_form = UNSET
        else:
            t_energy_form = self.t_energy_form


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "angle": angle,
            "kind": kind,
            "speed": speed,
            "t": t,
        })
        if joint is not UNSET:
            field_dict["joint"] = joint
        if t_energy_form is not UNSET:
            field_dict["t_energy_form"] = t_energy_form

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        angle = d.pop("angle")

        kind = d.pop("kind")

        speed = d.pop("speed")

        t = d.pop("t")

        def _parse_joint(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        joint = _parse_joint(d.pop("joint", UNSET))


        def _parse_t_energy_form(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        t_energy_form = _parse_t_energy_form(d.pop("t_energy_form", UNSET))


        instance_ = cls(
            angle=angle,
            kind=kind,
            speed=speed,
            t=t,
            joint=joint,
            t_energy_form=t_energy_form,
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
