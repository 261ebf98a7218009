from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.job_status import JobStatus
from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.balancing_result import BalancingResult
  from ..models.job_of_balancing_result_request import JobOfBalancingResultRequest
  from ..models.timing import Timing





T = TypeVar("T", bound="JobOfBalancingResult")



@_attrs_define
class JobOfBalancingResult:
    """ A job of one kind, for the OpenAPI document (the answer of a POST): its
    `result` has that kind's schema. The same fields as [`Job`].

        Attributes:
            created_at (str): RFC 3339, UTC.
            engine_version (str): Version of mechdyn that computed the result.
            id (str): Random UUID.
            kind (str):
            request (JobOfBalancingResultRequest): The request body exactly as sent.
            result (BalancingResult):
            status (JobStatus): Where a job is. A POST answered at once stores its job `done`; one sent
                with `Prefer: respond-async` is `queued`, then `running` on a replica,
                then `done` or `failed`.
            timing (Timing):
            label (None | str | Unset): The label stored with the job (`?label=` on its POST); absent without one.
     """

    created_at: str
    engine_version: str
    id: str
    kind: str
    request: JobOfBalancingResultRequest
    result: BalancingResult
    status: JobStatus
    timing: Timing
    label: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.balancing_result import BalancingResult # noqa: PLC0415
        from ..models.job_of_balancing_result_request import JobOfBalancingResultRequest # noqa: PLC0415
        from ..models.timing import Timing # noqa: PLC0415
        created_at = self.created_at

        engine_version = self.engine_version

        id = self.id

        kind = self.kind

        request = self.request.to_dict()

        result = self.result.to_dict()

        status = self.status.value

        timing = self.timing.to_dict()

        label: None | str | Unset
        if isinstance(self.label, Unset):
            label = UNSET
        else:
            label = self.label


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "created_at": created_at,
            "engine_version": engine_version,
            "id": id,
            "kind": kind,
            "request": request,
            "result": result,
            "status": status,
            "timing": timing,
        })
        if label is not UNSET:
            field_dict["label"] = label

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.balancing_result import BalancingResult # noqa: PLC0415
        from ..models.job_of_balancing_result_request import JobOfBalancingResultRequest # noqa: PLC0415
        from ..models.timing import Timing # noqa: PLC0415
        d = dict(src_dict)
        created_at = d.pop("created_at")

        engine_version = d.pop("engine_version")

        id = d.pop("id")

        kind = d.pop("kind")

        request = JobOfBalancingResultRequest.from_dict(d.pop("request"))




        result = BalancingResult.from_dict(d.pop("result"))




        status = JobStatus(d.pop("status"))




        timing = Timing.from_dict(d.pop("timing"))




        def _parse_label(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        label = _parse_label(d.pop("label", UNSET))


        instance_ = cls(
            created_at=created_at,
            engine_version=engine_version,
            id=id,
            kind=kind,
            request=request,
            result=result,
            status=status,
            timing=timing,
            label=label,
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
