from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.check_item import CheckItem
  from ..models.check_result_messages import CheckResultMessages





T = TypeVar("T", bound="CheckResult")



@_attrs_define
class CheckResult:
    """ The result of a check (format `mechdyn`).

        Attributes:
            items (list[CheckItem]):
            passed (int):
            score (float): Share of the answers that pass, 0 to 1.
            total (int):
            job (None | str | Unset): Id of the reference job: in the service's store, readable by anyone
                who can reach the API (`reveal` shapes the feedback only); offline,
                in that run's store in memory.
            messages (CheckResultMessages | Unset): The catalogue's message each feedback was written from, by JSON
                pointer (`/items/0/feedback`), as a kind's result has them.
     """

    items: list[CheckItem]
    passed: int
    score: float
    total: int
    job: None | str | Unset = UNSET
    messages: CheckResultMessages | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.check_item import CheckItem # noqa: PLC0415
        from ..models.check_result_messages import CheckResultMessages # noqa: PLC0415
        items = []
        for items_item_data in self.items:
            items_item = items_item_data.to_dict()
            items.append(items_item)



        passed = self.passed

        score = self.score

        total = self.total

        job: None | str | Unset
        if isinstance(self.job, Unset):
            job = UNSET
        else:
            job = self.job

        messages: dict[str, Any] | Unset = UNSET
        if not isinstance(self.messages, Unset):
            messages = self.messages.to_dict()


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "items": items,
            "passed": passed,
            "score": score,
            "total": total,
        })
        if job is not UNSET:
            field_dict["job"] = job
        if messages is not UNSET:
            field_dict["messages"] = messages

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.check_item import CheckItem # noqa: PLC0415
        from ..models.check_result_messages import CheckResultMessages # noqa: PLC0415
        d = dict(src_dict)
        items = []
        _items = d.pop("items")
        for items_item_data in (_items):
            items_item = CheckItem.from_dict(items_item_data)



            items.append(items_item)


        passed = d.pop("passed")

        score = d.pop("score")

        total = d.pop("total")

        def _parse_job(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        job = _parse_job(d.pop("job", UNSET))


        _messages = d.pop("messages", UNSET)
        messages: CheckResultMessages | Unset
        if isinstance(_messages,  Unset):
            messages = UNSET
        else:
            messages = CheckResultMessages.from_dict(_messages)




        instance_ = cls(
            items=items,
            passed=passed,
            score=score,
            total=total,
            job=job,
            messages=messages,
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
