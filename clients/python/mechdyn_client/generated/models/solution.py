from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.free_body import FreeBody
  from ..models.group import Group
  from ..models.solution_numbering import SolutionNumbering
  from ..models.virtual_power import VirtualPower





T = TypeVar("T", bound="Solution")



@_attrs_define
class Solution:
    """ `GET /v1/jobs/{id}/solution?step=k`.

        Attributes:
            bodies (list[FreeBody]):
            groups (list[Group]): The groups in that order, each with what its equations give.
            input_ (list[float]): Its inputs' coordinates, each in its unit (rad or m).
            numbering (SolutionNumbering): Each body's number, the ground 1.
            order (list[str]): The moving bodies in the order their equations are solved.
            step (int): The step (kinetostatics) or sample (dynamics) solved.
            virtual_power (VirtualPower): Each action's power at the step, summed over the bodies: the inputs'
                driving efforts, the loads, the weights and the inertia forces; the
                reactions' (the friction's: an ideal joint's two sides cancel); and
                their sum, zero to rounding.
     """

    bodies: list[FreeBody]
    groups: list[Group]
    input_: list[float]
    numbering: SolutionNumbering
    order: list[str]
    step: int
    virtual_power: VirtualPower
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.free_body import FreeBody # noqa: PLC0415
        from ..models.group import Group # noqa: PLC0415
        from ..models.solution_numbering import SolutionNumbering # noqa: PLC0415
        from ..models.virtual_power import VirtualPower # noqa: PLC0415
        bodies = []
        for bodies_item_data in self.bodies:
            bodies_item = bodies_item_data.to_dict()
            bodies.append(bodies_item)



        groups = []
        for groups_item_data in self.groups:
            groups_item = groups_item_data.to_dict()
            groups.append(groups_item)



        input_ = self.input_



        numbering = self.numbering.to_dict()

        order = self.order



        step = self.step

        virtual_power = self.virtual_power.to_dict()


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "bodies": bodies,
            "groups": groups,
            "input": input_,
            "numbering": numbering,
            "order": order,
            "step": step,
            "virtual_power": virtual_power,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.free_body import FreeBody # noqa: PLC0415
        from ..models.group import Group # noqa: PLC0415
        from ..models.solution_numbering import SolutionNumbering # noqa: PLC0415
        from ..models.virtual_power import VirtualPower # noqa: PLC0415
        d = dict(src_dict)
        bodies = []
        _bodies = d.pop("bodies")
        for bodies_item_data in (_bodies):
            bodies_item = FreeBody.from_dict(bodies_item_data)



            bodies.append(bodies_item)


        groups = []
        _groups = d.pop("groups")
        for groups_item_data in (_groups):
            groups_item = Group.from_dict(groups_item_data)



            groups.append(groups_item)


        input_ = cast(list[float], d.pop("input"))


        numbering = SolutionNumbering.from_dict(d.pop("numbering"))




        order = cast(list[str], d.pop("order"))


        step = d.pop("step")

        virtual_power = VirtualPower.from_dict(d.pop("virtual_power"))




        instance_ = cls(
            bodies=bodies,
            groups=groups,
            input_=input_,
            numbering=numbering,
            order=order,
            step=step,
            virtual_power=virtual_power,
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
