from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.disk_dto import DiskDto





T = TypeVar("T", bound="FlywheelDto")



@_attrs_define
class FlywheelDto:
    """ Where the flywheel sits and how to size it.

        Attributes:
            disk (DiskDto | None | Unset):
            ratio (float | None | Unset): ω of the flywheel's shaft / ω of the reference shaft (default 1).
     """

    disk: DiskDto | None | Unset = UNSET
    ratio: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.disk_dto import DiskDto # noqa: PLC0415
        disk: dict[str, Any] | None | Unset
        if isinstance(self.disk, Unset):
            disk = UNSET
        elif isinstance(self.disk, DiskDto):
            disk = self.disk.to_dict()
        else:
            disk = self.disk

        ratio: float | None | Unset
        if isinstance(self.ratio, Unset):
            ratio = UNSET
        else:
            ratio = self.ratio


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
        })
        if disk is not UNSET:
            field_dict["disk"] = disk
        if ratio is not UNSET:
            field_dict["ratio"] = ratio

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.disk_dto import DiskDto # noqa: PLC0415
        d = dict(src_dict)
        def _parse_disk(data: object) -> DiskDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                disk_type_0 = DiskDto.from_dict(data)



                return disk_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(DiskDto | None | Unset, data)

        disk = _parse_disk(d.pop("disk", UNSET))


        def _parse_ratio(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        ratio = _parse_ratio(d.pop("ratio", UNSET))


        instance_ = cls(
            disk=disk,
            ratio=ratio,
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
