from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.mechanism_dto import MechanismDto
  from ..models.pair_counts import PairCounts





T = TypeVar("T", bound="MobilityRequest")



@_attrs_define
class MobilityRequest:
    """ A mechanism without inputs (its drawing), or the counts alone.

        Example:
            {'counts': {'bodies': 5, 'pairs': {'I': 5, 'II': 1}, 'space': 'planar'}}

        Attributes:
            counts (None | PairCounts | Unset):
            mechanism (MechanismDto | None | Unset):
     """

    counts: None | PairCounts | Unset = UNSET
    mechanism: MechanismDto | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.mechanism_dto import MechanismDto # noqa: PLC0415
        from ..models.pair_counts import PairCounts # noqa: PLC0415
        counts: dict[str, Any] | None | Unset
        if isinstance(self.counts, Unset):
            counts = UNSET
        elif isinstance(self.counts, PairCounts):
            counts = self.counts.to_dict()
        else:
            counts = self.counts

        mechanism: dict[str, Any] | None | Unset
        if isinstance(self.mechanism, Unset):
            mechanism = UNSET
        elif isinstance(self.mechanism, MechanismDto):
            mechanism = self.mechanism.to_dict()
        else:
            mechanism = self.mechanism


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
        })
        if counts is not UNSET:
            field_dict["counts"] = counts
        if mechanism is not UNSET:
            field_dict["mechanism"] = mechanism

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.mechanism_dto import MechanismDto # noqa: PLC0415
        from ..models.pair_counts import PairCounts # noqa: PLC0415
        d = dict(src_dict)
        def _parse_counts(data: object) -> None | PairCounts | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                counts_type_0 = PairCounts.from_dict(data)



                return counts_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PairCounts | Unset, data)

        counts = _parse_counts(d.pop("counts", UNSET))


        def _parse_mechanism(data: object) -> MechanismDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                mechanism_type_0 = MechanismDto.from_dict(data)



                return mechanism_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(MechanismDto | None | Unset, data)

        mechanism = _parse_mechanism(d.pop("mechanism", UNSET))


        instance_ = cls(
            counts=counts,
            mechanism=mechanism,
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
