from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.job_kinetostatics_kind import JobKinetostaticsKind
from ..models.job_status import JobStatus
from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.job_kinetostatics_request import JobKinetostaticsRequest
  from ..models.kinetostatics_result import KinetostaticsResult
  from ..models.problem import Problem
  from ..models.timing import Timing





T = TypeVar("T", bound="JobKinetostatics")



@_attrs_define
class JobKinetostatics:
    """ A stored job of kind `kinetostatics`: its `result` is KinetostaticsResult.

        Attributes:
            created_at (str): RFC 3339, UTC.
            engine_version (str): Version of mechdyn that computed the result.
            id (str): Random UUID.
            kind (JobKinetostaticsKind):
            request (JobKinetostaticsRequest): The request body exactly as sent.
            status (JobStatus): Where a job is. A POST answered at once stores its job `done`; one sent
                with `Prefer: respond-async` is `queued`, then `running` on a replica,
                then `done` or `failed`.
            timing (Timing):
            label (None | str | Unset): The label stored with the job (`?label=` on its POST); absent without one.
            problem (None | Problem | Unset):
            result (KinetostaticsResult | None | Unset): The result; its schema depends on `kind` (e.g. FlywheelResult).
                Absent until the job is done.
     """

    created_at: str
    engine_version: str
    id: str
    kind: JobKinetostaticsKind
    request: JobKinetostaticsRequest
    status: JobStatus
    timing: Timing
    label: None | str | Unset = UNSET
    problem: None | Problem | Unset = UNSET
    result: KinetostaticsResult | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.job_kinetostatics_request import JobKinetostaticsRequest # noqa: PLC0415
        from ..models.kinetostatics_result import KinetostaticsResult # noqa: PLC0415
        from ..models.problem import Problem # noqa: PLC0415
        from ..models.timing import Timing # noqa: PLC0415
        created_at = self.created_at

        engine_version = self.engine_version

        id = self.id

        kind = self.kind.value

        request = self.request.to_dict()

        status = self.status.value

        timing = self.timing.to_dict()

        label: None | str | Unset
        if isinstance(self.label, Unset):
            label = UNSET
        else:
            label = self.label

        problem: dict[str, Any] | None | Unset
        if isinstance(self.problem, Unset):
            problem = UNSET
        elif isinstance(self.problem, Problem):
            problem = self.problem.to_dict()
        else:
            problem = self.problem

        result: dict[str, Any] | None | Unset
        if isinstance(self.result, Unset):
            result = UNSET
        elif isinstance(self.result, KinetostaticsResult):
            result = self.result.to_dict()
        else:
            result = self.result


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "created_at": created_at,
            "engine_version": engine_version,
            "id": id,
            "kind": kind,
            "request": request,
            "status": status,
            "timing": timing,
        })
        if label is not UNSET:
            field_dict["label"] = label
        if problem is not UNSET:
            field_dict["problem"] = problem
        if result is not UNSET:
            field_dict["result"] = result

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.job_kinetostatics_request import JobKinetostaticsRequest # noqa: PLC0415
        from ..models.kinetostatics_result import KinetostaticsResult # noqa: PLC0415
        from ..models.problem import Problem # noqa: PLC0415
        from ..models.timing import Timing # noqa: PLC0415
        d = dict(src_dict)
        created_at = d.pop("created_at")

        engine_version = d.pop("engine_version")

        id = d.pop("id")

        kind = JobKinetostaticsKind(d.pop("kind"))




        request = JobKinetostaticsRequest.from_dict(d.pop("request"))




        status = JobStatus(d.pop("status"))




        timing = Timing.from_dict(d.pop("timing"))




        def _parse_label(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        label = _parse_label(d.pop("label", UNSET))


        def _parse_problem(data: object) -> None | Problem | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                problem_type_0 = Problem.from_dict(data)



                return problem_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | Problem | Unset, data)

        problem = _parse_problem(d.pop("problem", UNSET))


        def _parse_result(data: object) -> KinetostaticsResult | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                result_type_0 = KinetostaticsResult.from_dict(data)



                return result_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(KinetostaticsResult | None | Unset, data)

        result = _parse_result(d.pop("result", UNSET))


        instance_ = cls(
            created_at=created_at,
            engine_version=engine_version,
            id=id,
            kind=kind,
            request=request,
            status=status,
            timing=timing,
            label=label,
            problem=problem,
            result=result,
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
