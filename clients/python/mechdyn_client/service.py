"""The calls a grader makes, typed, on top of the generated layer.

`Mechdyn` posts a job of any kind and reads it back as its kind's class
(`mechdyn_client.generated.models`), reads one value, a template's variants
(typed rows or CSV text) and a class's grades (CSV text). Every refusal is one
exception, `MechdynError`, carrying the service's problem document: its
`type`, `title`, `detail`, `status` and each invalid field's pointer and
message. A POST carries an `Idempotency-Key`, so the retries a busy service
asks for (503 with `Retry-After`) never compute or store a job twice.
"""

from __future__ import annotations

import time
import uuid
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from types import TracebackType
from typing import Any, TypeVar
from urllib.parse import quote

import httpx

from .generated.models import (
    JobOfBalancingResult,
    JobOfCamResult,
    JobOfCheckOutput,
    JobOfDynamicsResult,
    JobOfEquivalentResult,
    JobOfFlywheelResult,
    JobOfGearResult,
    JobOfKinetostaticsResult,
    JobOfMobilityResult,
    JobOfRotorResult,
    JobOfTrainResult,
    Variants,
)
from .generated.models.variant import Variant

#: A job's class, as the generated layer names it, and the route that computes it.
ROUTES: dict[type[Any], str] = {
    JobOfFlywheelResult: "/v1/flywheel",
    JobOfKinetostaticsResult: "/v1/kinetostatics",
    JobOfDynamicsResult: "/v1/dynamics",
    JobOfCamResult: "/v1/cams",
    JobOfGearResult: "/v1/gears/geometry",
    JobOfTrainResult: "/v1/gears/train",
    JobOfEquivalentResult: "/v1/equivalent-masses",
    JobOfRotorResult: "/v1/rotor",
    JobOfBalancingResult: "/v1/balancing",
    JobOfMobilityResult: "/v1/mobility",
    JobOfCheckOutput: "/v1/check",
}

J = TypeVar(
    "J",
    JobOfFlywheelResult,
    JobOfKinetostaticsResult,
    JobOfDynamicsResult,
    JobOfCamResult,
    JobOfGearResult,
    JobOfTrainResult,
    JobOfEquivalentResult,
    JobOfRotorResult,
    JobOfBalancingResult,
    JobOfMobilityResult,
    JobOfCheckOutput,
)


@dataclass(frozen=True)
class FieldProblem:
    """One invalid field: a JSON pointer into the request, a query parameter,
    or a CSV body's row and column; and what is wrong with it."""

    message: str
    pointer: str | None = None
    parameter: str | None = None
    row: int | None = None
    column: str | None = None


class MechdynError(Exception):
    """The service refused a request or could not answer it."""

    def __init__(self, status: int, problem: Mapping[str, Any], retry_after: float | None = None) -> None:
        self.status = status
        self.problem = dict(problem)
        self.type: str = str(problem.get("type", "about:blank"))
        self.title: str = str(problem.get("title", ""))
        self.detail: str = str(problem.get("detail", ""))
        self.retry_after = retry_after
        self.errors = [
            FieldProblem(
                message=str(e.get("message", "")),
                pointer=e.get("pointer"),
                parameter=e.get("parameter"),
                row=e.get("row"),
                column=e.get("column"),
            )
            for e in problem.get("errors") or []
            if isinstance(e, Mapping)
        ]
        super().__init__(str(self))

    def __str__(self) -> str:
        where = "; ".join(f"{e.pointer or e.parameter or e.row or ''}: {e.message}" for e in self.errors)
        return f"{self.status} {self.title}: {self.detail}" + (f" ({where})" if where else "")

    @classmethod
    def of(cls, response: httpx.Response) -> MechdynError:
        """The error an answer carries: its problem document, or its text."""
        try:
            problem = response.json()
        except ValueError:
            problem = None
        if not isinstance(problem, Mapping):
            problem = {"title": response.reason_phrase, "detail": response.text[:500]}
        after = response.headers.get("retry-after")
        return cls(response.status_code, problem, float(after) if after and after.isdigit() else None)


def _part(pointer: str) -> str:
    """A JSON pointer (`/flywheel_inertia/exact`, or without its `/`) as a URL path."""
    return quote(pointer.lstrip("/"), safe="/~")


class Mechdyn:
    """A mechdyn service at `base_url`.

    `token` is the service's API token, when it has one; `language` ("es")
    asks for Spanish texts; `retries` is how often a request refused 503 is
    tried again, after the wait the service asks for (at most 30 s each).
    """

    def __init__(
        self,
        base_url: str,
        *,
        token: str | None = None,
        timeout: float = 60.0,
        retries: int = 3,
        language: str | None = None,
        transport: httpx.BaseTransport | None = None,
    ) -> None:
        headers = {"Authorization": f"Bearer {token}"} if token else {}
        if language:
            headers["Accept-Language"] = language
        self.retries = retries
        self.http = httpx.Client(base_url=base_url.rstrip("/"), headers=headers, timeout=timeout, transport=transport)

    def __enter__(self) -> Mechdyn:
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None, tb: TracebackType | None) -> None:
        self.close()

    def close(self) -> None:
        self.http.close()

    def send(self, method: str, path: str, **kwargs: Any) -> httpx.Response:
        """One request, tried again while the service answers 503 with a
        wait; any other error status raised as a `MechdynError`."""
        if method == "POST":
            kwargs["headers"] = {"Idempotency-Key": str(uuid.uuid4()), **kwargs.get("headers", {})}
        for attempt in range(self.retries + 1):
            response = self.http.request(method, path, **kwargs)
            if response.status_code < 400:
                return response
            error = MechdynError.of(response)
            if response.status_code != 503 or attempt == self.retries:
                raise error
            time.sleep(min(error.retry_after or 1.0, 30.0))
        raise AssertionError("unreachable")

    def post(self, job: type[J], request: Mapping[str, Any], *, label: str | None = None) -> J:
        """Computes a job of `job`'s kind (`JobOfFlywheelResult`, …) and
        returns it typed: `post(JobOfFlywheelResult, {...}).result.inertia_exact`."""
        params = {"label": label} if label is not None else None
        return job.from_dict(self.send("POST", ROUTES[job], json=dict(request), params=params).json())

    def read(self, job: type[J], id: str) -> J:
        """A stored job, typed as `job`'s kind."""
        return job.from_dict(self.send("GET", f"/v1/jobs/{quote(id)}").json())

    def check(self, request: Mapping[str, Any], *, label: str | None = None) -> JobOfCheckOutput:
        """A student's answers checked (the body of `POST /v1/check`)."""
        return self.post(JobOfCheckOutput, request, label=label)

    def text(self, id: str, pointer: str, *, unit: str | None = None) -> str:
        """One part of a stored job's result as the service writes it."""
        params = {"unit": unit} if unit else None
        return self.send("GET", f"/v1/jobs/{quote(id)}/result/{_part(pointer)}", params=params).text

    def value(self, id: str, pointer: str, *, unit: str | None = None) -> float:
        """One number of a stored job's result, in SI or in `unit`."""
        return _number(self.text(id, pointer, unit=unit), pointer)

    def template_value(
        self, template: str, pointer: str, parameters: Mapping[str, Any] | None = None, *, unit: str | None = None
    ) -> float:
        """One number of a template's job for `parameters` (the others at
        their defaults), what a spreadsheet's WEBSERVICE() reads."""
        params: dict[str, Any] = {k: str(v) for k, v in (parameters or {}).items()}
        if unit:
            params["unit"] = unit
        path = f"/v1/templates/{quote(template)}/result/{_part(pointer)}"
        return _number(self.send("GET", path, params=params).text, pointer)

    def variants(self, template: str, *, seed: int = 1, count: int = 30, values: Iterable[str] = ()) -> list[Variant]:
        """Per-student variants from `seed` on, with the reference `values` asked for."""
        params = _variant_params(seed, count, values)
        answer = self.send("GET", f"/v1/templates/{quote(template)}/variants", params=params)
        return Variants.from_dict(answer.json()).variants

    def variants_csv(
        self, template: str, *, seed: int = 1, count: int = 30, values: Iterable[str] = (), decimal_comma: bool = False
    ) -> str:
        """The same variants as CSV text (`;` and decimal commas with `decimal_comma`)."""
        params = {**_variant_params(seed, count, values), "format": "csv"}
        if decimal_comma:
            params["decimal"] = "comma"
        return self.send("GET", f"/v1/templates/{quote(template)}/variants", params=params).text

    def grade_class(self, template: str, students: str, **tolerances: Any) -> str:
        """A class's CSV (`student`, `variant` or parameters, one column per
        answer) graded: the grades as CSV text. `tolerances` are the query's
        (`sigfigs=3`, `relative=0.005`, `reveal=False`, `decimal="comma"`)."""
        params = {k: str(v).lower() if isinstance(v, bool) else str(v) for k, v in tolerances.items()}
        path = f"/v1/templates/{quote(template)}/grade"
        headers = {"Content-Type": "text/csv"}
        return self.send("POST", path, content=students.encode(), params=params, headers=headers).text

    def table(self, template: str, rows: str, values: Iterable[str]) -> str:
        """A parameter study: a CSV of parameters, one row per variant, answered
        with the `values` of each as CSV text."""
        params = {"values": ",".join(values)}
        path = f"/v1/templates/{quote(template)}/table"
        return self.send("POST", path, content=rows.encode(), params=params, headers={"Content-Type": "text/csv"}).text


def _variant_params(seed: int, count: int, values: Iterable[str]) -> dict[str, str]:
    params = {"seed": str(seed), "count": str(count)}
    asked = ",".join(values)
    if asked:
        params["values"] = asked
    return params


def _number(text: str, pointer: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise ValueError(f"{pointer} is not a number: {text!r}") from None
