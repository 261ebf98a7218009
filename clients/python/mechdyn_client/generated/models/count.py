from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset







T = TypeVar("T", bound="Count")



@_attrs_define
class Count:
    """ Grübler's (Kutzbach's) count.

        Attributes:
            equations (int): 3(n − 1) in the plane, 6(n − 1) in space.
            formula (str): The count written out, e.g. `3(5 − 1) − (2·5 + 1·1) = 1`.
            mobility (int): M = equations − unknowns.
            unknowns (int): The freedoms the pairs remove (their reactions' components).
            unknowns_with_actions (int): The kinetostatic problem's unknowns as the course's notes count them:
                the driving actions (one an input coordinate, the mobility) and the
                reactions, N_INC = G + 2P_I + P_II in the plane (12 for seed 002's
                question 1, as many as its 3(N − 1) equations).
     """

    equations: int
    formula: str
    mobility: int
    unknowns: int
    unknowns_with_actions: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        equations = self.equations

        formula = self.formula

        mobility = self.mobility

        unknowns = self.unknowns

        unknowns_with_actions = self.unknowns_with_actions


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "equations": equations,
            "formula": formula,
            "mobility": mobility,
            "unknowns": unknowns,
            "unknowns_with_actions": unknowns_with_actions,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        equations = d.pop("equations")

        formula = d.pop("formula")

        mobility = d.pop("mobility")

        unknowns = d.pop("unknowns")

        unknowns_with_actions = d.pop("unknowns_with_actions")

        instance_ = cls(
            equations=equations,
            formula=formula,
            mobility=mobility,
            unknowns=unknowns,
            unknowns_with_actions=unknowns_with_actions,
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
