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





T = TypeVar("T", bound="TorqueDto")



@_attrs_define
class TorqueDto:
    """ A torque item: `value` (a Function), or `"balance": true`.

        Attributes:
            name (str):
            balance (bool | None | Unset): A constant torque solved so that the cycle work is zero (at most one item).
            ratio (float | None | Unset): ω of the shaft it acts on / ω of the reference shaft (default 1).
            value (float | FunctionSpec | None | str | Unset):
     """

    name: str
    balance: bool | None | Unset = UNSET
    ratio: float | None | Unset = UNSET
    value: float | FunctionSpec | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        name = self.name

        balance: bool | None | Unset
        if isinstance(self.balance, Unset):
            balance = UNSET
        else:
            balance = self.balance

        ratio: float | None | Unset
        if isinstance(self.ratio, Unset):
            ratio = UNSET
        else:
            ratio = self.ratio

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
            "name": name,
        })
        if balance is not UNSET:
            field_dict["balance"] = balance
        if ratio is not UNSET:
            field_dict["ratio"] = ratio
        if value is not UNSET:
            field_dict["value"] = value

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.function_spec import FunctionSpec # noqa: PLC0415
        d = dict(src_dict)
        name = d.pop("name")

        def _parse_balance(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        balance = _parse_balance(d.pop("balance", UNSET))


        def _parse_ratio(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        ratio = _parse_ratio(d.pop("ratio", UNSET))


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
            name=name,
            balance=balance,
            ratio=ratio,
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
