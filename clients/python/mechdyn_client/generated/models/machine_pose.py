from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.body_position import BodyPosition





T = TypeVar("T", bound="MachinePose")



@_attrs_define
class MachinePose:
    """ A machine's moving bodies at one input angle.

        Attributes:
            angle (float): φ, rad.
            bodies (list[BodyPosition]):
     """

    angle: float
    bodies: list[BodyPosition]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.body_position import BodyPosition # noqa: PLC0415
        angle = self.angle

        bodies = []
        for bodies_item_data in self.bodies:
            bodies_item = bodies_item_data.to_dict()
            bodies.append(bodies_item)




        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "angle": angle,
            "bodies": bodies,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.body_position import BodyPosition # noqa: PLC0415
        d = dict(src_dict)
        angle = d.pop("angle")

        bodies = []
        _bodies = d.pop("bodies")
        for bodies_item_data in (_bodies):
            bodies_item = BodyPosition.from_dict(bodies_item_data)



            bodies.append(bodies_item)


        instance_ = cls(
            angle=angle,
            bodies=bodies,
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
