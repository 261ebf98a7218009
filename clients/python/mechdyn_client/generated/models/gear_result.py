from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.notes_messages import NotesMessages





T = TypeVar("T", bound="GearResult")



@_attrs_define
class GearResult:
    """ Radii and tooth thickness, m and rad.

        Attributes:
            warnings (list[str]): What to know before trusting the numbers: a condition met on the
                way (a tolerance nearly spent, a geometry nearly singular, a law
                of design broken), in the asker's language.
            base_radius (float):
            pitch_radius (float):
            root_radius (float):
            thickness (float): The tooth's arc on the circle of `thickness_radius`: e_T = R_T[e_A/R_A + 2(inv φ_A − inv
                φ_T)];
                a ring's tooth is the space between those teeth, 2πR_T/z − e_T.
            thickness_at_pitch (float): πm/2.
            thickness_pressure_angle (float): Pressure angle of the involute at `thickness_radius`.
            thickness_radius (float):
            tip_radius (float): Tip (addendum) circle: outside the pitch circle, inside it for an internal gear.
            messages (NotesMessages | Unset): The catalogue's message each text of this result was written from,
                by JSON pointer into the result (`/warnings/0`, `/accuracy/method`):
                match a warning by its `id`; the texts themselves are in the
                language asked for (`Accept-Language`, `?lang=`).
     """

    warnings: list[str]
    base_radius: float
    pitch_radius: float
    root_radius: float
    thickness: float
    thickness_at_pitch: float
    thickness_pressure_angle: float
    thickness_radius: float
    tip_radius: float
    messages: NotesMessages | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        warnings = self.warnings



        base_radius = self.base_radius

        pitch_radius = self.pitch_radius

        root_radius = self.root_radius

        thickness = self.thickness

        thickness_at_pitch = self.thickness_at_pitch

        thickness_pressure_angle = self.thickness_pressure_angle

        thickness_radius = self.thickness_radius

        tip_radius = self.tip_radius

        messages: dict[str, Any] | Unset = UNSET
        if not isinstance(self.messages, Unset):
            messages = self.messages.to_dict()


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "warnings": warnings,
            "base_radius": base_radius,
            "pitch_radius": pitch_radius,
            "root_radius": root_radius,
            "thickness": thickness,
            "thickness_at_pitch": thickness_at_pitch,
            "thickness_pressure_angle": thickness_pressure_angle,
            "thickness_radius": thickness_radius,
            "tip_radius": tip_radius,
        })
        if messages is not UNSET:
            field_dict["messages"] = messages

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        d = dict(src_dict)
        warnings = cast(list[str], d.pop("warnings"))


        base_radius = d.pop("base_radius")

        pitch_radius = d.pop("pitch_radius")

        root_radius = d.pop("root_radius")

        thickness = d.pop("thickness")

        thickness_at_pitch = d.pop("thickness_at_pitch")

        thickness_pressure_angle = d.pop("thickness_pressure_angle")

        thickness_radius = d.pop("thickness_radius")

        tip_radius = d.pop("tip_radius")

        _messages = d.pop("messages", UNSET)
        messages: NotesMessages | Unset
        if isinstance(_messages,  Unset):
            messages = UNSET
        else:
            messages = NotesMessages.from_dict(_messages)




        instance_ = cls(
            warnings=warnings,
            base_radius=base_radius,
            pitch_radius=pitch_radius,
            root_radius=root_radius,
            thickness=thickness,
            thickness_at_pitch=thickness_at_pitch,
            thickness_pressure_angle=thickness_pressure_angle,
            thickness_radius=thickness_radius,
            tip_radius=tip_radius,
            messages=messages,
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
