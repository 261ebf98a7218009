from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.function_spec import FunctionSpec





T = TypeVar("T", bound="CamLiftDto")



@_attrs_define
class CamLiftDto:
    """ 
        Attributes:
            lift (float | FunctionSpec | str): A function of the cycle angle phi: a constant, {"expr"}, {"segments"} (zero
                outside them) or a periodic {"table"}; optional "unit" for its values
     """

    lift: float | FunctionSpec | str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        lift: dict[str, Any] | float | str
        if isinstance(self.lift, FunctionSpec):
            lift = self.lift.to_dict()
        else:
            lift = self.lift


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "lift": lift,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        d = dict(src_dict)
        def _parse_lift(data: object) -> float | FunctionSpec | str:
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_function_dto_type_1 = FunctionSpec.from_dict(data)



                return componentsschemas_function_dto_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | FunctionSpec | str, data)

        lift = _parse_lift(d.pop("lift"))


        instance_ = cls(
            lift=lift,
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
