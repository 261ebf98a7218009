from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.virtual_power_actions import VirtualPowerActions





T = TypeVar("T", bound="VirtualPower")



@_attrs_define
class VirtualPower:
    """ Each action's power at the step, summed over the bodies: the inputs'
    driving efforts, the loads, the weights and the inertia forces; the
    reactions' (the friction's: an ideal joint's two sides cancel); and
    their sum, zero to rounding.

        Attributes:
            actions (VirtualPowerActions): By action name (`M_m`, `W3`, `F_I3`, `M_I3`, a load's name), W.
            reactions (float): Every reaction's power summed, W (0 without friction).
            total (float): The sum of all, W.
     """

    actions: VirtualPowerActions
    reactions: float
    total: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.virtual_power_actions import VirtualPowerActions # noqa: PLC0415
        actions = self.actions.to_dict()

        reactions = self.reactions

        total = self.total


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "actions": actions,
            "reactions": reactions,
            "total": total,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.virtual_power_actions import VirtualPowerActions # noqa: PLC0415
        d = dict(src_dict)
        actions = VirtualPowerActions.from_dict(d.pop("actions"))




        reactions = d.pop("reactions")

        total = d.pop("total")

        instance_ = cls(
            actions=actions,
            reactions=reactions,
            total=total,
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
