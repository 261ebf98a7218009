from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.cam_sense import CamSense
from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.cam_follower_dto import CamFollowerDto
  from ..models.cam_lift_dto import CamLiftDto
  from ..models.cam_segment_dto import CamSegmentDto





T = TypeVar("T", bound="CamCurveDto")



@_attrs_define
class CamCurveDto:
    """ A disk cam's profile made for a translating follower from its program
    (the fields of `POST /v1/cams` that shape it): the envelope of a flat
    face, or the pitch curve of a roller (its `roller_radius`; a knife edge
    has none) on an axis `offset` from the centre moved in by the roller's
    radius; lift s(θ) at the cam's counter-clockwise turn θ from the drawing.
    Draw the follower's face, roller or edge touching it at θ = 0.

        Attributes:
            base_radius (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            center (list[float | str] | str):
            follower (CamFollowerDto):
            program (CamLiftDto | list[CamSegmentDto]): Segments end to end (a list), or a lift Function of `theta` (an
                object).
            direction (CamSense | None | Unset):
            zero (list[float] | None | Unset): The follower's direction (from the centre towards it) as drawn, at
                θ = 0, [x, y]; default [1, 0].
     """

    base_radius: float | str
    center: list[float | str] | str
    follower: CamFollowerDto
    program: CamLiftDto | list[CamSegmentDto]
    direction: CamSense | None | Unset = UNSET
    zero: list[float] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.cam_follower_dto import CamFollowerDto # noqa: PLC0415
        from ..models.cam_lift_dto import CamLiftDto # noqa: PLC0415
        from ..models.cam_segment_dto import CamSegmentDto # noqa: PLC0415
        base_radius: float | str
        base_radius = self.base_radius

        center: list[float | str] | str
        if isinstance(self.center, list):
            center = []
            for center_item_data in self.center:
                center_item: float | str
                center_item = center_item_data
                center.append(center_item)


        else:
            center = self.center

        follower = self.follower.to_dict()

        program: dict[str, Any] | list[dict[str, Any]]
        if isinstance(self.program, list):
            program = []
            for program_item_data in self.program:
                program_item = program_item_data.to_dict()
                program.append(program_item)


        else:
            program = self.program.to_dict()


        direction: None | str | Unset
        if isinstance(self.direction, Unset):
            direction = UNSET
        elif isinstance(self.direction, CamSense):
            direction = self.direction.value
        else:
            direction = self.direction

        zero: list[float] | None | Unset
        if isinstance(self.zero, Unset):
            zero = UNSET
        elif isinstance(self.zero, list):
            zero = self.zero


        else:
            zero = self.zero


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "base_radius": base_radius,
            "center": center,
            "follower": follower,
            "program": program,
        })
        if direction is not UNSET:
            field_dict["direction"] = direction
        if zero is not UNSET:
            field_dict["zero"] = zero

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.cam_follower_dto import CamFollowerDto # noqa: PLC0415
        from ..models.cam_lift_dto import CamLiftDto # noqa: PLC0415
        from ..models.cam_segment_dto import CamSegmentDto # noqa: PLC0415
        d = dict(src_dict)
        def _parse_base_radius(data: object) -> float | str:
            return cast(float | str, data)

        base_radius = _parse_base_radius(d.pop("base_radius"))


        def _parse_center(data: object) -> list[float | str] | str:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_point_ref_type_1 = []
                _componentsschemas_point_ref_type_1 = data
                for componentsschemas_point_ref_type_1_item_data in (_componentsschemas_point_ref_type_1):
                    def _parse_componentsschemas_point_ref_type_1_item(data: object) -> float | str:
                        return cast(float | str, data)

                    componentsschemas_point_ref_type_1_item = _parse_componentsschemas_point_ref_type_1_item(componentsschemas_point_ref_type_1_item_data)

                    componentsschemas_point_ref_type_1.append(componentsschemas_point_ref_type_1_item)

                return componentsschemas_point_ref_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | str] | str, data)

        center = _parse_center(d.pop("center"))


        follower = CamFollowerDto.from_dict(d.pop("follower"))




        def _parse_program(data: object) -> CamLiftDto | list[CamSegmentDto]:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_cam_program_dto_type_0 = []
                _componentsschemas_cam_program_dto_type_0 = data
                for componentsschemas_cam_program_dto_type_0_item_data in (_componentsschemas_cam_program_dto_type_0):
                    componentsschemas_cam_program_dto_type_0_item = CamSegmentDto.from_dict(componentsschemas_cam_program_dto_type_0_item_data)



                    componentsschemas_cam_program_dto_type_0.append(componentsschemas_cam_program_dto_type_0_item)

                return componentsschemas_cam_program_dto_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            componentsschemas_cam_program_dto_type_1 = CamLiftDto.from_dict(data)



            return componentsschemas_cam_program_dto_type_1

        program = _parse_program(d.pop("program"))


        def _parse_direction(data: object) -> CamSense | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                direction_type_0 = CamSense(data)



                return direction_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(CamSense | None | Unset, data)

        direction = _parse_direction(d.pop("direction", UNSET))


        def _parse_zero(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                zero_type_0 = list(data)

                return zero_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        zero = _parse_zero(d.pop("zero", UNSET))


        instance_ = cls(
            base_radius=base_radius,
            center=center,
            follower=follower,
            program=program,
            direction=direction,
            zero=zero,
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
