from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="ShakingDto")



@_attrs_define
class ShakingDto:
    """ The force and moment the moving links' inertia puts on the frame at a
    step: F = −Σ m·a_G and M = −Σ (r_G × m·a_G + I_G·α) about the origin
    (with no gravity and no load, the sum of what the links put on the frame).

        Attributes:
            force (list[float]): N.
            moment (float): About the origin, N·m.
            balanced_force (list[float] | None | Unset): With the result's `counterweights` added (`balance`): F plus their
                inertia forces, N.
     """

    force: list[float]
    moment: float
    balanced_force: list[float] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        force = self.force



        moment = self.moment

        balanced_force: list[float] | None | Unset
        if isinstance(self.balanced_force, Unset):
            balanced_force = UNSET
        elif isinstance(self.balanced_force, list):
            balanced_force = self.balanced_force


        else:
            balanced_force = self.balanced_force


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "force": force,
            "moment": moment,
        })
        if balanced_force is not UNSET:
            field_dict["balanced_force"] = balanced_force

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        force = cast(list[float], d.pop("force"))


        moment = d.pop("moment")

        def _parse_balanced_force(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                balanced_force_type_0 = list(data)

                return balanced_force_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        balanced_force = _parse_balanced_force(d.pop("balanced_force", UNSET))


        instance_ = cls(
            force=force,
            moment=moment,
            balanced_force=balanced_force,
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
