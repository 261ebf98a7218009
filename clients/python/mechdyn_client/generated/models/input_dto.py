from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.input_coordinate import InputCoordinate
from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.function_spec import FunctionSpec





T = TypeVar("T", bound="InputDto")



@_attrs_define
class InputDto:
    """ An input coordinate and its range: a driven joint, or where the
    statement puts the motion (a point along a direction, a body's rotation).

        Attributes:
            acceleration (float | None | str | Unset):
            body (None | str | Unset): With `point`: the body it belongs to, where several hold it (a pin
                in a slot). Alone: the body whose absolute rotation is the coordinate.
            coordinate (InputCoordinate | None | Unset):
            direction (list[float] | None | Unset):
            end (float | None | str | Unset):
            joint (None | str | Unset): A revolute (crank) or prismatic (linear actuator) joint: its relative
                rotation or displacement along the axis. Or a contact joint that
                carries a point along a curve (a ring on a rim): the arc length
                along its first curve, growing the way the curve runs — counter-
                clockwise round a circle or a polar curve (growing ψ), along a
                line's direction, from a spline's first point to its last — so that
                a ring at the top of a rim moving to the right has a negative speed.
            point (None | str | Unset): Instead of a joint: a point of `points` whose displacement along
                `direction` (a fixed direction of the ground) is the coordinate, m.
            reference (float | None | str | Unset):
            speed (float | FunctionSpec | None | str | Unset):
            start (float | None | str | Unset):
            steps (int | None | Unset): Number of positions start + k·(end − start)/steps, k = 0..steps−1 (default 360).
     """

    acceleration: float | None | str | Unset = UNSET
    body: None | str | Unset = UNSET
    coordinate: InputCoordinate | None | Unset = UNSET
    direction: list[float] | None | Unset = UNSET
    end: float | None | str | Unset = UNSET
    joint: None | str | Unset = UNSET
    point: None | str | Unset = UNSET
    reference: float | None | str | Unset = UNSET
    speed: float | FunctionSpec | None | str | Unset = UNSET
    start: float | None | str | Unset = UNSET
    steps: int | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        acceleration: float | None | str | Unset
        if isinstance(self.acceleration, Unset):
            acceleration = UNSET
        else:
            acceleration = self.acceleration

        body: None | str | Unset
        if isinstance(self.body, Unset):
            body = UNSET
        else:
            body = self.body

        coordinate: None | str | Unset
        if isinstance(self.coordinate, Unset):
            coordinate = UNSET
        elif isinstance(self.coordinate, InputCoordinate):
            coordinate = self.coordinate.value
        else:
            coordinate = self.coordinate

        direction: list[float] | None | Unset
        if isinstance(self.direction, Unset):
            direction = UNSET
        elif isinstance(self.direction, list):
            direction = self.direction


        else:
            direction = self.direction

        end: float | None | str | Unset
        if isinstance(self.end, Unset):
            end = UNSET
        else:
            end = self.end

        joint: None | str | Unset
        if isinstance(self.joint, Unset):
            joint = UNSET
        else:
            joint = self.joint

        point: None | str | Unset
        if isinstance(self.point, Unset):
            point = UNSET
        else:
            point = self.point

        reference: float | None | str | Unset
        if isinstance(self.reference, Unset):
            reference = UNSET
        else:
            reference = self.reference

        speed: dict[str, Any] | float | None | str | Unset
        if isinstance(self.speed, Unset):
            speed = UNSET
        elif isinstance(self.speed, FunctionSpec):
            speed = self.speed.to_dict()
        else:
            speed = self.speed

        start: float | None | str | Unset
        if isinstance(self.start, Unset):
            start = UNSET
        else:
            start = self.start

        steps: int | None | Unset
        if isinstance(self.steps, Unset):
            steps = UNSET
        else:
            steps = self.steps


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
        })
        if acceleration is not UNSET:
            field_dict["acceleration"] = acceleration
        if body is not UNSET:
            field_dict["body"] = body
        if coordinate is not UNSET:
            field_dict["coordinate"] = coordinate
        if direction is not UNSET:
            field_dict["direction"] = direction
        if end is not UNSET:
            field_dict["end"] = end
        if joint is not UNSET:
            field_dict["joint"] = joint
        if point is not UNSET:
            field_dict["point"] = point
        if reference is not UNSET:
            field_dict["reference"] = reference
        if speed is not UNSET:
            field_dict["speed"] = speed
        if start is not UNSET:
            field_dict["start"] = start
        if steps is not UNSET:
            field_dict["steps"] = steps

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        d = dict(src_dict)
        def _parse_acceleration(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        acceleration = _parse_acceleration(d.pop("acceleration", UNSET))


        def _parse_body(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        body = _parse_body(d.pop("body", UNSET))


        def _parse_coordinate(data: object) -> InputCoordinate | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                coordinate_type_0 = InputCoordinate(data)



                return coordinate_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(InputCoordinate | None | Unset, data)

        coordinate = _parse_coordinate(d.pop("coordinate", UNSET))


        def _parse_direction(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                direction_type_0 = list(data)

                return direction_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        direction = _parse_direction(d.pop("direction", UNSET))


        def _parse_end(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        end = _parse_end(d.pop("end", UNSET))


        def _parse_joint(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        joint = _parse_joint(d.pop("joint", UNSET))


        def _parse_point(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        point = _parse_point(d.pop("point", UNSET))


        def _parse_reference(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        reference = _parse_reference(d.pop("reference", UNSET))


        def _parse_speed(data: object) -> float | FunctionSpec | None | str | Unset:
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

        speed = _parse_speed(d.pop("speed", UNSET))


        def _parse_start(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        start = _parse_start(d.pop("start", UNSET))


        def _parse_steps(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        steps = _parse_steps(d.pop("steps", UNSET))


        instance_ = cls(
            acceleration=acceleration,
            body=body,
            coordinate=coordinate,
            direction=direction,
            end=end,
            joint=joint,
            point=point,
            reference=reference,
            speed=speed,
            start=start,
            steps=steps,
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
