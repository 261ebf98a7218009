from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.cam_friction_dto import CamFrictionDto
  from ..models.cam_spring_dto import CamSpringDto
  from ..models.function_spec import FunctionSpec





T = TypeVar("T", bound="CamDynamicsDto")



@_attrs_define
class CamDynamicsDto:
    """ 
        Attributes:
            follower_mass (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            force (float | FunctionSpec | None | str | Unset):
            friction (CamFrictionDto | None | Unset):
            spring (CamSpringDto | None | Unset):
     """

    follower_mass: float | str
    force: float | FunctionSpec | None | str | Unset = UNSET
    friction: CamFrictionDto | None | Unset = UNSET
    spring: CamSpringDto | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.cam_friction_dto import CamFrictionDto # noqa: PLC0415
        from ..models.cam_spring_dto import CamSpringDto # noqa: PLC0415
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        follower_mass: float | str
        follower_mass = self.follower_mass

        force: dict[str, Any] | float | None | str | Unset
        if isinstance(self.force, Unset):
            force = UNSET
        elif isinstance(self.force, FunctionSpec):
            force = self.force.to_dict()
        else:
            force = self.force

        friction: dict[str, Any] | None | Unset
        if isinstance(self.friction, Unset):
            friction = UNSET
        elif isinstance(self.friction, CamFrictionDto):
            friction = self.friction.to_dict()
        else:
            friction = self.friction

        spring: dict[str, Any] | None | Unset
        if isinstance(self.spring, Unset):
            spring = UNSET
        elif isinstance(self.spring, CamSpringDto):
            spring = self.spring.to_dict()
        else:
            spring = self.spring


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "follower_mass": follower_mass,
        })
        if force is not UNSET:
            field_dict["force"] = force
        if friction is not UNSET:
            field_dict["friction"] = friction
        if spring is not UNSET:
            field_dict["spring"] = spring

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.cam_friction_dto import CamFrictionDto # noqa: PLC0415
        from ..models.cam_spring_dto import CamSpringDto # noqa: PLC0415
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        d = dict(src_dict)
        def _parse_follower_mass(data: object) -> float | str:
            return cast(float | str, data)

        follower_mass = _parse_follower_mass(d.pop("follower_mass"))


        def _parse_force(data: object) -> float | FunctionSpec | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_function_dto_type_1 = FunctionSpec.from_dict(data)



                return componentsschemas_function_dto_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | FunctionSpec | None | str | Unset, data)

        force = _parse_force(d.pop("force", UNSET))


        def _parse_friction(data: object) -> CamFrictionDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                friction_type_0 = CamFrictionDto.from_dict(data)



                return friction_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(CamFrictionDto | None | Unset, data)

        friction = _parse_friction(d.pop("friction", UNSET))


        def _parse_spring(data: object) -> CamSpringDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                spring_type_0 = CamSpringDto.from_dict(data)



                return spring_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(CamSpringDto | None | Unset, data)

        spring = _parse_spring(d.pop("spring", UNSET))


        instance_ = cls(
            follower_mass=follower_mass,
            force=force,
            friction=friction,
            spring=spring,
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
