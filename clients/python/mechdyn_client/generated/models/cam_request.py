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
  from ..models.cam_dynamics_dto import CamDynamicsDto
  from ..models.cam_follower_dto import CamFollowerDto
  from ..models.cam_lift_dto import CamLiftDto
  from ..models.cam_segment_dto import CamSegmentDto
  from ..models.cam_size_dto import CamSizeDto





T = TypeVar("T", bound="CamRequest")



@_attrs_define
class CamRequest:
    """ A disk cam to design (see the example).

        Example:
            {'dynamics': {'follower_mass': '0.5 kg', 'spring': {'preload': '20 N', 'stiffness': '2000 N/m'}}, 'follower':
                {'motion': 'translating', 'offset': '0 mm', 'roller_radius': '10 mm', 'type': 'roller'}, 'program': [{'law':
                'cycloidal', 'lift': '20 mm', 'to': '90 deg'}, {'law': 'dwell', 'lift': '20 mm', 'to': '180 deg'}, {'law':
                'polynomial-345', 'lift': '0 mm', 'to': '270 deg'}, {'law': 'dwell', 'lift': '0 mm', 'to': '360 deg'}],
                'samples': 360, 'size': {'max_pressure_angle': '30 deg'}, 'speed': '300 rpm'}

        Attributes:
            follower (CamFollowerDto):
            program (CamLiftDto | list[CamSegmentDto]): Segments end to end (a list), or a lift Function of `theta` (an
                object).
            speed (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            base_radius (float | None | str | Unset):
            direction (CamSense | None | Unset):
            dynamics (CamDynamicsDto | None | Unset):
            samples (int | None | Unset): Angles evenly spaced over the turn (default 360).
            size (CamSizeDto | None | Unset):
     """

    follower: CamFollowerDto
    program: CamLiftDto | list[CamSegmentDto]
    speed: float | str
    base_radius: float | None | str | Unset = UNSET
    direction: CamSense | None | Unset = UNSET
    dynamics: CamDynamicsDto | None | Unset = UNSET
    samples: int | None | Unset = UNSET
    size: CamSizeDto | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.cam_dynamics_dto import CamDynamicsDto # noqa: PLC0415
        from ..models.cam_follower_dto import CamFollowerDto # noqa: PLC0415
        from ..models.cam_lift_dto import CamLiftDto # noqa: PLC0415
        from ..models.cam_segment_dto import CamSegmentDto # noqa: PLC0415
        from ..models.cam_size_dto import CamSizeDto # noqa: PLC0415
        follower = self.follower.to_dict()

        program: dict[str, Any] | list[dict[str, Any]]
        if isinstance(self.program, list):
            program = []
            for program_item_data in self.program:
                program_item = program_item_data.to_dict()
                program.append(program_item)


        else:
            program = self.program.to_dict()


        speed: float | str
        speed = self.speed

        base_radius: float | None | str | Unset
        if isinstance(self.base_radius, Unset):
            base_radius = UNSET
        else:
            base_radius = self.base_radius

        direction: None | str | Unset
        if isinstance(self.direction, Unset):
            direction = UNSET
        elif isinstance(self.direction, CamSense):
            direction = self.direction.value
        else:
            direction = self.direction

        dynamics: dict[str, Any] | None | Unset
        if isinstance(self.dynamics, Unset):
            dynamics = UNSET
        elif isinstance(self.dynamics, CamDynamicsDto):
            dynamics = self.dynamics.to_dict()
        else:
            dynamics = self.dynamics

        samples: int | None | Unset
        if isinstance(self.samples, Unset):
            samples = UNSET
        else:
            samples = self.samples

        size: dict[str, Any] | None | Unset
        if isinstance(self.size, Unset):
            size = UNSET
        elif isinstance(self.size, CamSizeDto):
            size = self.size.to_dict()
        else:
            size = self.size


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "follower": follower,
            "program": program,
            "speed": speed,
        })
        if base_radius is not UNSET:
            field_dict["base_radius"] = base_radius
        if direction is not UNSET:
            field_dict["direction"] = direction
        if dynamics is not UNSET:
            field_dict["dynamics"] = dynamics
        if samples is not UNSET:
            field_dict["samples"] = samples
        if size is not UNSET:
            field_dict["size"] = size

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.cam_dynamics_dto import CamDynamicsDto # noqa: PLC0415
        from ..models.cam_follower_dto import CamFollowerDto # noqa: PLC0415
        from ..models.cam_lift_dto import CamLiftDto # noqa: PLC0415
        from ..models.cam_segment_dto import CamSegmentDto # noqa: PLC0415
        from ..models.cam_size_dto import CamSizeDto # noqa: PLC0415
        d = dict(src_dict)
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


        def _parse_speed(data: object) -> float | str:
            return cast(float | str, data)

        speed = _parse_speed(d.pop("speed"))


        def _parse_base_radius(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        base_radius = _parse_base_radius(d.pop("base_radius", UNSET))


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


        def _parse_dynamics(data: object) -> CamDynamicsDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                dynamics_type_0 = CamDynamicsDto.from_dict(data)



                return dynamics_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(CamDynamicsDto | None | Unset, data)

        dynamics = _parse_dynamics(d.pop("dynamics", UNSET))


        def _parse_samples(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        samples = _parse_samples(d.pop("samples", UNSET))


        def _parse_size(data: object) -> CamSizeDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                size_type_0 = CamSizeDto.from_dict(data)



                return size_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(CamSizeDto | None | Unset, data)

        size = _parse_size(d.pop("size", UNSET))


        instance_ = cls(
            follower=follower,
            program=program,
            speed=speed,
            base_radius=base_radius,
            direction=direction,
            dynamics=dynamics,
            samples=samples,
            size=size,
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
