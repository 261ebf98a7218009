from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.cam_follower_motion import CamFollowerMotion
from ..models.cam_follower_type import CamFollowerType
from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="CamFollowerDto")



@_attrs_define
class CamFollowerDto:
    """ 
        Attributes:
            type_ (CamFollowerType):
            arm (float | None | str | Unset):
            motion (CamFollowerMotion | None | Unset):
            offset (float | None | str | Unset):
            pivot (float | None | str | Unset):
            roller_radius (float | None | str | Unset):
     """

    type_: CamFollowerType
    arm: float | None | str | Unset = UNSET
    motion: CamFollowerMotion | None | Unset = UNSET
    offset: float | None | str | Unset = UNSET
    pivot: float | None | str | Unset = UNSET
    roller_radius: float | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        type_ = self.type_.value

        arm: float | None | str | Unset
        if isinstance(self.arm, Unset):
            arm = UNSET
        else:
            arm = self.arm

        motion: None | str | Unset
        if isinstance(self.motion, Unset):
            motion = UNSET
        elif isinstance(self.motion, CamFollowerMotion):
            motion = self.motion.value
        else:
            motion = self.motion

        offset: float | None | str | Unset
        if isinstance(self.offset, Unset):
            offset = UNSET
        else:
            offset = self.offset

        pivot: float | None | str | Unset
        if isinstance(self.pivot, Unset):
            pivot = UNSET
        else:
            pivot = self.pivot

        roller_radius: float | None | str | Unset
        if isinstance(self.roller_radius, Unset):
            roller_radius = UNSET
        else:
            roller_radius = self.roller_radius


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "type": type_,
        })
        if arm is not UNSET:
            field_dict["arm"] = arm
        if motion is not UNSET:
            field_dict["motion"] = motion
        if offset is not UNSET:
            field_dict["offset"] = offset
        if pivot is not UNSET:
            field_dict["pivot"] = pivot
        if roller_radius is not UNSET:
            field_dict["roller_radius"] = roller_radius

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        type_ = CamFollowerType(d.pop("type"))




        def _parse_arm(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        arm = _parse_arm(d.pop("arm", UNSET))


        def _parse_motion(data: object) -> CamFollowerMotion | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                motion_type_0 = CamFollowerMotion(data)



                return motion_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(CamFollowerMotion | None | Unset, data)

        motion = _parse_motion(d.pop("motion", UNSET))


        def _parse_offset(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        offset = _parse_offset(d.pop("offset", UNSET))


        def _parse_pivot(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        pivot = _parse_pivot(d.pop("pivot", UNSET))


        def _parse_roller_radius(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        roller_radius = _parse_roller_radius(d.pop("roller_radius", UNSET))


        instance_ = cls(
            type_=type_,
            arm=arm,
            motion=motion,
            offset=offset,
            pivot=pivot,
            roller_radius=roller_radius,
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
