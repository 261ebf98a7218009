from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset







T = TypeVar("T", bound="SegmentPeaks")



@_attrs_define
class SegmentPeaks:
    """ 
        Attributes:
            from_ (float): rad.
            law (str):
            peak_acceleration (float):
            peak_jerk (float):
            peak_velocity (float): The largest |s′|ω (m/s), |s″|ω² (m/s²), |s‴|ω³ (m/s³) in the segment.
            to (float):
     """

    from_: float
    law: str
    peak_acceleration: float
    peak_jerk: float
    peak_velocity: float
    to: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from_ = self.from_

        law = self.law

        peak_acceleration = self.peak_acceleration

        peak_jerk = self.peak_jerk

        peak_velocity = self.peak_velocity

        to = self.to


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "from": from_,
            "law": law,
            "peak_acceleration": peak_acceleration,
            "peak_jerk": peak_jerk,
            "peak_velocity": peak_velocity,
            "to": to,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        from_ = d.pop("from")

        law = d.pop("law")

        peak_acceleration = d.pop("peak_acceleration")

        peak_jerk = d.pop("peak_jerk")

        peak_velocity = d.pop("peak_velocity")

        to = d.pop("to")

        instance_ = cls(
            from_=from_,
            law=law,
            peak_acceleration=peak_acceleration,
            peak_jerk=peak_jerk,
            peak_velocity=peak_velocity,
            to=to,
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
