from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset







T = TypeVar("T", bound="GrublerDto")



@_attrs_define
class GrublerDto:
    """ 
        Attributes:
            equations (int): 3(N − 1) equilibrium equations (in space 6(N − 1)).
            mobility (int): 3(N − 1) − 2·P_I − P_II, N counting the ground; in space Kutzbach's
                6(N − 1) − Σ(6 − fᵢ).
            unknowns (int): Reaction components 2·P_I + P_II plus one driving action per input;
                in space the reactions' Σ(6 − fᵢ) alone (equations − unknowns is
                then the mobility).
     """

    equations: int
    mobility: int
    unknowns: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        equations = self.equations

        mobility = self.mobility

        unknowns = self.unknowns


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "equations": equations,
            "mobility": mobility,
            "unknowns": unknowns,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        equations = d.pop("equations")

        mobility = d.pop("mobility")

        unknowns = d.pop("unknowns")

        instance_ = cls(
            equations=equations,
            mobility=mobility,
            unknowns=unknowns,
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
