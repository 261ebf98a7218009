from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="DimensionDto")



@_attrs_define
class DimensionDto:
    """ One dimension of the statement: exactly one of `distance` ([P, Q]: |PQ|),
    `angle` ([P, Q]: the direction of P→Q from +x, counter-clockwise), `x`
    or `y` (P's coordinate), each with its `value` (a length or an angle);
    or `on` M `between` [A, B] at the fraction `ratio` of A→B (0.5: the midpoint).

        Example:
            {'distance': ['O2', 'A'], 'value': '100 mm'}

        Attributes:
            angle (list[str] | None | Unset):
            between (list[str] | None | Unset):
            distance (list[str] | None | Unset):
            on (None | str | Unset): With `between` and `ratio`: the point M = A + ratio·(B − A).
            ratio (float | None | Unset):
            value (float | None | str | Unset):
            x (None | str | Unset):
            y (None | str | Unset):
     """

    angle: list[str] | None | Unset = UNSET
    between: list[str] | None | Unset = UNSET
    distance: list[str] | None | Unset = UNSET
    on: None | str | Unset = UNSET
    ratio: float | None | Unset = UNSET
    value: float | None | str | Unset = UNSET
    x: None | str | Unset = UNSET
    y: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        angle: list[str] | None | Unset
        if isinstance(self.angle, Unset):
            angle = UNSET
        elif isinstance(self.angle, list):
            angle = self.angle


        else:
            angle = self.angle

        between: list[str] | None | Unset
        if isinstance(self.between, Unset):
            between = UNSET
        elif isinstance(self.between, list):
            between = self.between


        else:
            between = self.between

        distance: list[str] | None | Unset
        if isinstance(self.distance, Unset):
            distance = UNSET
        elif isinstance(self.distance, list):
            distance = self.distance


        else:
            distance = self.distance

        on: None | str | Unset
        if isinstance(self.on, Unset):
            on = UNSET
        else:
            on = self.on

        ratio: float | None | Unset
        if isinstance(self.ratio, Unset):
            ratio = UNSET
        else:
            ratio = self.ratio

        value: float | None | str | Unset
        if isinstance(self.value, Unset):
            value = UNSET
        else:
            value = self.value

        x: None | str | Unset
        if isinstance(self.x, Unset):
            x = UNSET
        else:
            x = self.x

        y: None | str | Unset
        if isinstance(self.y, Unset):
            y = UNSET
        else:
            y = self.y


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
        })
        if angle is not UNSET:
            field_dict["angle"] = angle
        if between is not UNSET:
            field_dict["between"] = between
        if distance is not UNSET:
            field_dict["distance"] = distance
        if on is not UNSET:
            field_dict["on"] = on
        if ratio is not UNSET:
            field_dict["ratio"] = ratio
        if value is not UNSET:
            field_dict["value"] = value
        if x is not UNSET:
            field_dict["x"] = x
        if y is not UNSET:
            field_dict["y"] = y

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        def _parse_angle(data: object) -> list[str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                angle_type_0 = list(data)

                return angle_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[str] | None | Unset, data)

        angle = _parse_angle(d.pop("angle", UNSET))


        def _parse_between(data: object) -> list[str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                between_type_0 = list(data)

                return between_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[str] | None | Unset, data)

        between = _parse_between(d.pop("between", UNSET))


        def _parse_distance(data: object) -> list[str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                distance_type_0 = list(data)

                return distance_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[str] | None | Unset, data)

        distance = _parse_distance(d.pop("distance", UNSET))


        def _parse_on(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        on = _parse_on(d.pop("on", UNSET))


        def _parse_ratio(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        ratio = _parse_ratio(d.pop("ratio", UNSET))


        def _parse_value(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        value = _parse_value(d.pop("value", UNSET))


        def _parse_x(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        x = _parse_x(d.pop("x", UNSET))


        def _parse_y(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        y = _parse_y(d.pop("y", UNSET))


        instance_ = cls(
            angle=angle,
            between=between,
            distance=distance,
            on=on,
            ratio=ratio,
            value=value,
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
