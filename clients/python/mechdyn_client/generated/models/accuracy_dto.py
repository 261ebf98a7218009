from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="AccuracyDto")



@_attrs_define
class AccuracyDto:
    """ 
        Attributes:
            estimated_relative_error (float): Estimated relative error of the works, ΔE and the inertias.
            function_evaluations (int):
            method (str):
            quadrature_error (float): Summed quadrature error estimate, J.
            check_relative_difference (float | None | Unset): max(|ε_check − ε|/ε, |ω_check − ω_a|/ω_a): agreement of the
                independent check.
     """

    estimated_relative_error: float
    function_evaluations: int
    method: str
    quadrature_error: float
    check_relative_difference: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        estimated_relative_error = self.estimated_relative_error

        function_evaluations = self.function_evaluations

        method = self.method

        quadrature_error = self.quadrature_error

        check_relative_difference: float | None | Unset
        if isinstance(self.check_relative_difference, Unset):
            check_relative_difference = UNSET
        else:
            check_relative_difference = self.check_relative_difference


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "estimated_relative_error": estimated_relative_error,
            "function_evaluations": function_evaluations,
            "method": method,
            "quadrature_error": quadrature_error,
        })
        if check_relative_difference is not UNSET:
            field_dict["check_relative_difference"] = check_relative_difference

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        estimated_relative_error = d.pop("estimated_relative_error")

        function_evaluations = d.pop("function_evaluations")

        method = d.pop("method")

        quadrature_error = d.pop("quadrature_error")

        def _parse_check_relative_difference(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        check_relative_difference = _parse_check_relative_difference(d.pop("check_relative_difference", UNSET))


        instance_ = cls(
            estimated_relative_error=estimated_relative_error,
            function_evaluations=function_evaluations,
            method=method,
            quadrature_error=quadrature_error,
            check_relative_difference=check_relative_difference,
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
