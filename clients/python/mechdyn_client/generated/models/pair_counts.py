from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.mobility_space import MobilitySpace
from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.pair_counts_pairs import PairCountsPairs





T = TypeVar("T", bound="PairCounts")



@_attrs_define
class PairCounts:
    """ Bodies and pairs counted, as the course's exercises give them.

        Attributes:
            bodies (int): Bodies, the ground counted.
            pairs (PairCountsPairs): Pairs by class (`I` to `II` in the plane, `I` to `V` in space; a
                class-k pair leaves k relative freedoms).
            space (MobilitySpace | Unset): Plane (3 freedoms a body) or space (6).
     """

    bodies: int
    pairs: PairCountsPairs
    space: MobilitySpace | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.pair_counts_pairs import PairCountsPairs # noqa: PLC0415
        bodies = self.bodies

        pairs = self.pairs.to_dict()

        space: str | Unset = UNSET
        if not isinstance(self.space, Unset):
            space = self.space.value



        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "bodies": bodies,
            "pairs": pairs,
        })
        if space is not UNSET:
            field_dict["space"] = space

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.pair_counts_pairs import PairCountsPairs # noqa: PLC0415
        d = dict(src_dict)
        bodies = d.pop("bodies")

        pairs = PairCountsPairs.from_dict(d.pop("pairs"))




        _space = d.pop("space", UNSET)
        space: MobilitySpace | Unset
        if isinstance(_space,  Unset):
            space = UNSET
        else:
            space = MobilitySpace(_space)




        instance_ = cls(
            bodies=bodies,
            pairs=pairs,
            space=space,
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
