from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.reactions_dto import ReactionsDto





T = TypeVar("T", bound="RotorStateDto")



@_attrs_define
class RotorStateDto:
    """ One instant. Vectors are in the rotating axes x'y'z' except `reactions_fixed`.

        Attributes:
            angle (float):
            angular_momentum_g (list[float]): K about G and about O, kg·m²/s.
            angular_momentum_o (list[float]):
            gyroscopic_moment (list[float]): Ω i' × I_G·ω_r, N·m.
            kinetic_energy (float):
            momentum (list[float]): Q = m·V_G, N·s.
            reactions (ReactionsDto): The bearing forces in one set of axes: due to the motion, to the weight, and both.
            reactions_fixed (ReactionsDto): The bearing forces in one set of axes: due to the motion, to the weight, and
                both.
            speed (float):
            t (float):
     """

    angle: float
    angular_momentum_g: list[float]
    angular_momentum_o: list[float]
    gyroscopic_moment: list[float]
    kinetic_energy: float
    momentum: list[float]
    reactions: ReactionsDto
    reactions_fixed: ReactionsDto
    speed: float
    t: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.reactions_dto import ReactionsDto # noqa: PLC0415
        angle = self.angle

        angular_momentum_g = self.angular_momentum_g



        angular_momentum_o = self.angular_momentum_o



        gyroscopic_moment = self.gyroscopic_moment



        kinetic_energy = self.kinetic_energy

        momentum = self.momentum



        reactions = self.reactions.to_dict()

        reactions_fixed = self.reactions_fixed.to_dict()

        speed = self.speed

        t = self.t


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "angle": angle,
            "angular_momentum_g": angular_momentum_g,
            "angular_momentum_o": angular_momentum_o,
            "gyroscopic_moment": gyroscopic_moment,
            "kinetic_energy": kinetic_energy,
            "momentum": momentum,
            "reactions": reactions,
            "reactions_fixed": reactions_fixed,
            "speed": speed,
            "t": t,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.reactions_dto import ReactionsDto # noqa: PLC0415
        d = dict(src_dict)
        angle = d.pop("angle")

        angular_momentum_g = cast(list[float], d.pop("angular_momentum_g"))


        angular_momentum_o = cast(list[float], d.pop("angular_momentum_o"))


        gyroscopic_moment = cast(list[float], d.pop("gyroscopic_moment"))


        kinetic_energy = d.pop("kinetic_energy")

        momentum = cast(list[float], d.pop("momentum"))


        reactions = ReactionsDto.from_dict(d.pop("reactions"))




        reactions_fixed = ReactionsDto.from_dict(d.pop("reactions_fixed"))




        speed = d.pop("speed")

        t = d.pop("t")

        instance_ = cls(
            angle=angle,
            angular_momentum_g=angular_momentum_g,
            angular_momentum_o=angular_momentum_o,
            gyroscopic_moment=gyroscopic_moment,
            kinetic_energy=kinetic_energy,
            momentum=momentum,
            reactions=reactions,
            reactions_fixed=reactions_fixed,
            speed=speed,
            t=t,
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
