from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.job_balancing import JobBalancing
  from ..models.job_cams import JobCams
  from ..models.job_check import JobCheck
  from ..models.job_dynamics import JobDynamics
  from ..models.job_equivalent_masses import JobEquivalentMasses
  from ..models.job_flywheel import JobFlywheel
  from ..models.job_gear_train import JobGearTrain
  from ..models.job_gears import JobGears
  from ..models.job_kinetostatics import JobKinetostatics
  from ..models.job_mobility import JobMobility
  from ..models.job_rotor import JobRotor





T = TypeVar("T", bound="JobList")



@_attrs_define
class JobList:
    """ A page of jobs, newest first.

        Attributes:
            items (list[JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears |
                JobGearTrain | JobKinetostatics | JobMobility | JobRotor]):
            next_ (None | str | Unset): Relative URL of the next page, or null on the last one.
     """

    items: list[JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor]
    next_: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.job_balancing import JobBalancing # noqa: PLC0415
        from ..models.job_cams import JobCams # noqa: PLC0415
        from ..models.job_check import JobCheck # noqa: PLC0415
        from ..models.job_dynamics import JobDynamics # noqa: PLC0415
        from ..models.job_equivalent_masses import JobEquivalentMasses # noqa: PLC0415
        from ..models.job_flywheel import JobFlywheel # noqa: PLC0415
        from ..models.job_gear_train import JobGearTrain # noqa: PLC0415
        from ..models.job_gears import JobGears # noqa: PLC0415
        from ..models.job_kinetostatics import JobKinetostatics # noqa: PLC0415
        from ..models.job_mobility import JobMobility # noqa: PLC0415
        from ..models.job_rotor import JobRotor # noqa: PLC0415
        items = []
        for items_item_data in self.items:
            items_item: dict[str, Any]
            if isinstance(items_item_data, JobFlywheel):
                items_item = items_item_data.to_dict()
            elif isinstance(items_item_data, JobKinetostatics):
                items_item = items_item_data.to_dict()
            elif isinstance(items_item_data, JobDynamics):
                items_item = items_item_data.to_dict()
            elif isinstance(items_item_data, JobGears):
                items_item = items_item_data.to_dict()
            elif isinstance(items_item_data, JobGearTrain):
                items_item = items_item_data.to_dict()
            elif isinstance(items_item_data, JobEquivalentMasses):
                items_item = items_item_data.to_dict()
            elif isinstance(items_item_data, JobRotor):
                items_item = items_item_data.to_dict()
            elif isinstance(items_item_data, JobBalancing):
                items_item = items_item_data.to_dict()
            elif isinstance(items_item_data, JobMobility):
                items_item = items_item_data.to_dict()
            elif isinstance(items_item_data, JobCams):
                items_item = items_item_data.to_dict()
            else:
                items_item = items_item_data.to_dict()

            items.append(items_item)



        next_: None | str | Unset
        if isinstance(self.next_, Unset):
            next_ = UNSET
        else:
            next_ = self.next_


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "items": items,
        })
        if next_ is not UNSET:
            field_dict["next"] = next_

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.job_balancing import JobBalancing # noqa: PLC0415
        from ..models.job_cams import JobCams # noqa: PLC0415
        from ..models.job_check import JobCheck # noqa: PLC0415
        from ..models.job_dynamics import JobDynamics # noqa: PLC0415
        from ..models.job_equivalent_masses import JobEquivalentMasses # noqa: PLC0415
        from ..models.job_flywheel import JobFlywheel # noqa: PLC0415
        from ..models.job_gear_train import JobGearTrain # noqa: PLC0415
        from ..models.job_gears import JobGears # noqa: PLC0415
        from ..models.job_kinetostatics import JobKinetostatics # noqa: PLC0415
        from ..models.job_mobility import JobMobility # noqa: PLC0415
        from ..models.job_rotor import JobRotor # noqa: PLC0415
        d = dict(src_dict)
        items = []
        _items = d.pop("items")
        for items_item_data in (_items):
            def _parse_items_item(data: object) -> JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor:
                try:
                    if not isinstance(data, dict):
                        raise TypeError()
                    componentsschemas_job_type_0 = JobFlywheel.from_dict(data)



                    return componentsschemas_job_type_0
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                try:
                    if not isinstance(data, dict):
                        raise TypeError()
                    componentsschemas_job_type_1 = JobKinetostatics.from_dict(data)



                    return componentsschemas_job_type_1
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                try:
                    if not isinstance(data, dict):
                        raise TypeError()
                    componentsschemas_job_type_2 = JobDynamics.from_dict(data)



                    return componentsschemas_job_type_2
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                try:
                    if not isinstance(data, dict):
                        raise TypeError()
                    componentsschemas_job_type_3 = JobGears.from_dict(data)



                    return componentsschemas_job_type_3
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                try:
                    if not isinstance(data, dict):
                        raise TypeError()
                    componentsschemas_job_type_4 = JobGearTrain.from_dict(data)



                    return componentsschemas_job_type_4
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                try:
                    if not isinstance(data, dict):
                        raise TypeError()
                    componentsschemas_job_type_5 = JobEquivalentMasses.from_dict(data)



                    return componentsschemas_job_type_5
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                try:
                    if not isinstance(data, dict):
                        raise TypeError()
                    componentsschemas_job_type_6 = JobRotor.from_dict(data)



                    return componentsschemas_job_type_6
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                try:
                    if not isinstance(data, dict):
                        raise TypeError()
                    componentsschemas_job_type_7 = JobBalancing.from_dict(data)



                    return componentsschemas_job_type_7
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                try:
                    if not isinstance(data, dict):
                        raise TypeError()
                    componentsschemas_job_type_8 = JobMobility.from_dict(data)



                    return componentsschemas_job_type_8
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                try:
                    if not isinstance(data, dict):
                        raise TypeError()
                    componentsschemas_job_type_9 = JobCams.from_dict(data)



                    return componentsschemas_job_type_9
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_job_type_10 = JobCheck.from_dict(data)



                return componentsschemas_job_type_10

            items_item = _parse_items_item(items_item_data)

            items.append(items_item)


        def _parse_next_(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        next_ = _parse_next_(d.pop("next", UNSET))


        instance_ = cls(
            items=items,
            next_=next_,
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
