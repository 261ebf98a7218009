from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="KinetostaticsAccuracy")



@_attrs_define
class KinetostaticsAccuracy:
    """ 
        Attributes:
            max_constraint_residual (float): Largest |Φ(q)| left by Newton–Raphson, m or rad.
            max_friction_iterations (int): Largest number of fixed-point iterations of joint friction (0 without friction).
            max_newton_iterations (int):
            method (str):
            virtual_power_residual (float | None | Unset): Same as summary.virtual_power_residual: the two independent
                driving actions agree to this.
     """

    max_constraint_residual: float
    max_friction_iterations: int
    max_newton_iterations: int
    method: str
    virtual_power_residual: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        max_constraint_residual = self.max_constraint_residual

        max_friction_iterations = self.max_friction_iterations

        max_newton_iterations = self.max_newton_iterations

        method = self.method

        virtual_power_residual: float | None | Unset
        if isinstance(self.virtual_power_residual, Unset):
            virtual_power_residual = UNSET
        else:
            virtual_power_residual = self.virtual_power_residual


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "max_constraint_residual": max_constraint_residual,
            "max_friction_iterations": max_friction_iterations,
            "max_newton_iterations": max_newton_iterations,
            "method": method,
        })
        if virtual_power_residual is not UNSET:
            field_dict["virtual_power_residual"] = virtual_power_residual

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        max_constraint_residual = d.pop("max_constraint_residual")

        max_friction_iterations = d.pop("max_friction_iterations")

        max_newton_iterations = d.pop("max_newton_iterations")

        method = d.pop("method")

        def _parse_virtual_power_residual(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        virtual_power_residual = _parse_virtual_power_residual(d.pop("virtual_power_residual", UNSET))


        instance_ = cls(
            max_constraint_residual=max_constraint_residual,
            max_friction_iterations=max_friction_iterations,
            max_newton_iterations=max_newton_iterations,
            method=method,
            virtual_power_residual=virtual_power_residual,
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
