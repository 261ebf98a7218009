from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.function_spec import FunctionSpec





T = TypeVar("T", bound="PolarDto")



@_attrs_define
class PolarDto:
    """ 
        Attributes:
            center (list[float | str] | str):
            radius (float | FunctionSpec | str): A function of the cycle angle phi: a constant, {"expr"}, {"segments"} (zero
                outside them) or a periodic {"table"}; optional "unit" for its values
            zero (list[float] | None | Unset): The body-fixed direction ψ = 0 as drawn, [x, y]; default [1, 0].
     """

    center: list[float | str] | str
    radius: float | FunctionSpec | str
    zero: list[float] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        center: list[float | str] | str
        if isinstance(self.center, list):
            center = []
            for center_item_data in self.center:
                center_item: float | str
                center_item = center_item_data
                center.append(center_item)


        else:
            center = self.center

        radius: dict[str, Any] | float | str
        if isinstance(self.radius, FunctionSpec):
            radius = self.radius.to_dict()
        else:
            radius = self.radius

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
            "center": center,
            "radius": radius,
        })
        if zero is not UNSET:
            field_dict["zero"] = zero

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        d = dict(src_dict)
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


        def _parse_radius(data: object) -> float | FunctionSpec | str:
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_function_dto_type_1 = FunctionSpec.from_dict(data)



                return componentsschemas_function_dto_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | FunctionSpec | str, data)

        radius = _parse_radius(d.pop("radius"))


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
            center=center,
            radius=radius,
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
