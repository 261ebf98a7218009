from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.load_type import LoadType
from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.function_spec import FunctionSpec





T = TypeVar("T", bound="LoadDto")



@_attrs_define
class LoadDto:
    """ A load. `force`: body, at, direction (fixed in the ground), magnitude (Function);
    `torque`: body, value (Function); `spring`: a, b ([body, point]), stiffness,
    free_length; `damper`: a, b, coefficient. Functions take `phi`, the first input's coordinate.

        Attributes:
            type_ (LoadType): Load types.
            a (list[list[float | str] | str] | None | Unset):
            at (list[float | str] | None | str | Unset):
            b (list[list[float | str] | str] | None | Unset):
            body (None | str | Unset):
            coefficient (float | None | str | Unset):
            direction (list[float] | None | Unset): [x, y]; in space [x, y, z], and a torque's axis.
            free_length (float | None | str | Unset):
            magnitude (float | FunctionSpec | None | str | Unset):
            stiffness (float | None | str | Unset):
            value (float | FunctionSpec | None | str | Unset):
     """

    type_: LoadType
    a: list[list[float | str] | str] | None | Unset = UNSET
    at: list[float | str] | None | str | Unset = UNSET
    b: list[list[float | str] | str] | None | Unset = UNSET
    body: None | str | Unset = UNSET
    coefficient: float | None | str | Unset = UNSET
    direction: list[float] | None | Unset = UNSET
    free_length: float | None | str | Unset = UNSET
    magnitude: float | FunctionSpec | None | str | Unset = UNSET
    stiffness: float | None | str | Unset = UNSET
    value: float | FunctionSpec | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        type_ = self.type_.value

        a: list[list[float | str] | str] | None | Unset
        if isinstance(self.a, Unset):
            a = UNSET
        elif isinstance(self.a, list):
            a = []
            for a_item_data in self.a:
                a_item: list[float | str] | str
                if isinstance(a_item_data, list):
                    a_item = []
                    for a_item_item_data in a_item_data:
                        a_item_item: float | str
                        a_item_item = a_item_item_data
                        a_item.append(a_item_item)


                else:
                    a_item = a_item_data
                a.append(a_item)


        else:
            a = self.a

        at: list[float | str] | None | str | Unset
        if isinstance(self.at, Unset):
            at = UNSET
        elif isinstance(self.at, list):
            at = []
            for at_item_data in self.at:
                at_item: float | str
                at_item = at_item_data
                at.append(at_item)


        else:
            at = self.at

        b: list[list[float | str] | str] | None | Unset
        if isinstance(self.b, Unset):
            b = UNSET
        elif isinstance(self.b, list):
            b = []
            for b_item_data in self.b:
                b_item: list[float | str] | str
                if isinstance(b_item_data, list):
                    b_item = []
                    for b_item_item_data in b_item_data:
                        b_item_item: float | str
                        b_item_item = b_item_item_data
                        b_item.append(b_item_item)


                else:
                    b_item = b_item_data
                b.append(b_item)


        else:
            b = self.b

        body: None | str | Unset
        if isinstance(self.body, Unset):
            body = UNSET
        else:
            body = self.body

        coefficient: float | None | str | Unset
        if isinstance(self.coefficient, Unset):
            coefficient = UNSET
        else:
            coefficient = self.coefficient

        direction: list[float] | None | Unset
        if isinstance(self.direction, Unset):
            direction = UNSET
        elif isinstance(self.direction, list):
            direction = self.direction


        else:
            direction = self.direction

        free_length: float | None | str | Unset
        if isinstance(self.free_length, Unset):
            free_length = UNSET
        else:
            free_length = self.free_length

        magnitude: dict[str, Any] | float | None | str | Unset
        if isinstance(self.magnitude, Unset):
            magnitude = UNSET
        elif isinstance(self.magnitude, FunctionSpec):
            magnitude = self.magnitude.to_dict()
        else:
            magnitude = self.magnitude

        stiffness: float | None | str | Unset
        if isinstance(self.stiffness, Unset):
            stiffness = UNSET
        else:
            stiffness = self.stiffness

        value: dict[str, Any] | float | None | str | Unset
        if isinstance(self.value, Unset):
            value = UNSET
        elif isinstance(self.value, FunctionSpec):
            value = self.value.to_dict()
        else:
            value = self.value


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "type": type_,
        })
        if a is not UNSET:
            field_dict["a"] = a
        if at is not UNSET:
            field_dict["at"] = at
        if b is not UNSET:
            field_dict["b"] = b
        if body is not UNSET:
            field_dict["body"] = body
        if coefficient is not UNSET:
            field_dict["coefficient"] = coefficient
        if direction is not UNSET:
            field_dict["direction"] = direction
        if free_length is not UNSET:
            field_dict["free_length"] = free_length
        if magnitude is not UNSET:
            field_dict["magnitude"] = magnitude
        if stiffness is not UNSET:
            field_dict["stiffness"] = stiffness
        if value is not UNSET:
            field_dict["value"] = value

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        d = dict(src_dict)
        type_ = LoadType(d.pop("type"))




        def _parse_a(data: object) -> list[list[float | str] | str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                a_type_0 = []
                _a_type_0 = data
                for componentsschemas_body_point_item_data in (_a_type_0):
                    def _parse_componentsschemas_body_point_item(data: object) -> list[float | str] | str:
                        try:
                            if not isinstance(data, list):
                                raise TypeError()
                            componentsschemas_body_point_item_type_1_type_1 = []
                            _componentsschemas_body_point_item_type_1_type_1 = data
                            for componentsschemas_body_point_item_type_1_type_1_item_data in (_componentsschemas_body_point_item_type_1_type_1):
                                def _parse_componentsschemas_body_point_item_type_1_type_1_item(data: object) -> float | str:
                                    return cast(float | str, data)

                                componentsschemas_body_point_item_type_1_type_1_item = _parse_componentsschemas_body_point_item_type_1_type_1_item(componentsschemas_body_point_item_type_1_type_1_item_data)

                                componentsschemas_body_point_item_type_1_type_1.append(componentsschemas_body_point_item_type_1_type_1_item)

                            return componentsschemas_body_point_item_type_1_type_1
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        return cast(list[float | str] | str, data)

                    componentsschemas_body_point_item = _parse_componentsschemas_body_point_item(componentsschemas_body_point_item_data)

                    a_type_0.append(componentsschemas_body_point_item)

                return a_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float | str] | str] | None | Unset, data)

        a = _parse_a(d.pop("a", UNSET))


        def _parse_at(data: object) -> list[float | str] | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
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
            return cast(list[float | str] | None | str | Unset, data)

        at = _parse_at(d.pop("at", UNSET))


        def _parse_b(data: object) -> list[list[float | str] | str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                b_type_0 = []
                _b_type_0 = data
                for componentsschemas_body_point_item_data in (_b_type_0):
                    def _parse_componentsschemas_body_point_item(data: object) -> list[float | str] | str:
                        try:
                            if not isinstance(data, list):
                                raise TypeError()
                            componentsschemas_body_point_item_type_1_type_1 = []
                            _componentsschemas_body_point_item_type_1_type_1 = data
                            for componentsschemas_body_point_item_type_1_type_1_item_data in (_componentsschemas_body_point_item_type_1_type_1):
                                def _parse_componentsschemas_body_point_item_type_1_type_1_item(data: object) -> float | str:
                                    return cast(float | str, data)

                                componentsschemas_body_point_item_type_1_type_1_item = _parse_componentsschemas_body_point_item_type_1_type_1_item(componentsschemas_body_point_item_type_1_type_1_item_data)

                                componentsschemas_body_point_item_type_1_type_1.append(componentsschemas_body_point_item_type_1_type_1_item)

                            return componentsschemas_body_point_item_type_1_type_1
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        return cast(list[float | str] | str, data)

                    componentsschemas_body_point_item = _parse_componentsschemas_body_point_item(componentsschemas_body_point_item_data)

                    b_type_0.append(componentsschemas_body_point_item)

                return b_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float | str] | str] | None | Unset, data)

        b = _parse_b(d.pop("b", UNSET))


        def _parse_body(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        body = _parse_body(d.pop("body", UNSET))


        def _parse_coefficient(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        coefficient = _parse_coefficient(d.pop("coefficient", UNSET))


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


        def _parse_free_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        free_length = _parse_free_length(d.pop("free_length", UNSET))


        def _parse_magnitude(data: object) -> float | FunctionSpec | None | str | Unset:
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

        magnitude = _parse_magnitude(d.pop("magnitude", UNSET))


        def _parse_stiffness(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        stiffness = _parse_stiffness(d.pop("stiffness", UNSET))


        def _parse_value(data: object) -> float | FunctionSpec | None | str | Unset:
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

        value = _parse_value(d.pop("value", UNSET))


        instance_ = cls(
            type_=type_,
            a=a,
            at=at,
            b=b,
            body=body,
            coefficient=coefficient,
            direction=direction,
            free_length=free_length,
            magnitude=magnitude,
            stiffness=stiffness,
            value=value,
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
