from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="GearRequest")



@_attrs_define
class GearRequest:
    """ A standard involute spur gear.

        Example:
            {'module': '4 mm', 'teeth': 30}

        Attributes:
            module (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            teeth (float):
            addendum (float | None | Unset): In modules (default 1).
            dedendum (float | None | Unset): In modules (default 1.25).
            internal (bool | None | Unset): An internal gear (ring), default false.
            pressure_angle (float | None | str | Unset):
            radius (float | None | str | Unset):
     """

    module: float | str
    teeth: float
    addendum: float | None | Unset = UNSET
    dedendum: float | None | Unset = UNSET
    internal: bool | None | Unset = UNSET
    pressure_angle: float | None | str | Unset = UNSET
    radius: float | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        module: float | str
        module = self.module

        teeth = self.teeth

        addendum: float | None | Unset
        if isinstance(self.addendum, Unset):
            addendum = UNSET
        else:
            addendum = self.addendum

        dedendum: float | None | Unset
        if isinstance(self.dedendum, Unset):
            dedendum = UNSET
        else:
            dedendum = self.dedendum

        internal: bool | None | Unset
        if isinstance(self.internal, Unset):
            internal = UNSET
        else:
            internal = self.internal

        pressure_angle: float | None | str | Unset
        if isinstance(self.pressure_angle, Unset):
            pressure_angle = UNSET
        else:
            pressure_angle = self.pressure_angle

        radius: float | None | str | Unset
        if isinstance(self.radius, Unset):
            radius = UNSET
        else:
            radius = self.radius


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "module": module,
            "teeth": teeth,
        })
        if addendum is not UNSET:
            field_dict["addendum"] = addendum
        if dedendum is not UNSET:
            field_dict["dedendum"] = dedendum
        if internal is not UNSET:
            field_dict["internal"] = internal
        if pressure_angle is not UNSET:
            field_dict["pressure_angle"] = pressure_angle
        if radius is not UNSET:
            field_dict["radius"] = radius

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        def _parse_module(data: object) -> float | str:
            return cast(float | str, data)

        module = _parse_module(d.pop("module"))


        teeth = d.pop("teeth")

        def _parse_addendum(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        addendum = _parse_addendum(d.pop("addendum", UNSET))


        def _parse_dedendum(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        dedendum = _parse_dedendum(d.pop("dedendum", UNSET))


        def _parse_internal(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        internal = _parse_internal(d.pop("internal", UNSET))


        def _parse_pressure_angle(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        pressure_angle = _parse_pressure_angle(d.pop("pressure_angle", UNSET))


        def _parse_radius(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        radius = _parse_radius(d.pop("radius", UNSET))


        instance_ = cls(
            module=module,
            teeth=teeth,
            addendum=addendum,
            dedendum=dedendum,
            internal=internal,
            pressure_angle=pressure_angle,
            radius=radius,
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
