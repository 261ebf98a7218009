from http import HTTPStatus
from typing import Any, cast
from urllib.parse import quote

import httpx

from ...client import AuthenticatedClient, Client
from ...types import Response, UNSET
from ... import errors

from ...models.job_list import JobList
from ...models.list_jobs_kind import ListJobsKind
from ...models.problem import Problem
from ...types import UNSET, Unset
from typing import cast



def _get_kwargs(
    *,
    kind: ListJobsKind | Unset = UNSET,
    label: str | Unset = UNSET,
    limit: int | Unset = UNSET,
    before: int | Unset = UNSET,

) -> dict[str, Any]:
    

    

    params: dict[str, Any] = {}

    json_kind: str | Unset = UNSET
    if not isinstance(kind, Unset):
        json_kind = kind.value

    params["kind"] = json_kind

    params["label"] = label

    params["limit"] = limit

    params["before"] = before


    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}


    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/v1/jobs",
        "params": params,
    }


    return _kwargs



def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> JobList | Problem | None:
    if response.status_code == 200:
        response_200 = JobList.from_dict(response.json())



        return response_200

    if response.status_code == 400:
        response_400 = Problem.from_dict(response.json())



        return response_400

    if response.status_code == 401:
        response_401 = Problem.from_dict(response.json())



        return response_401

    if response.status_code == 503:
        response_503 = Problem.from_dict(response.json())



        return response_503

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[JobList | Problem]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    kind: ListJobsKind | Unset = UNSET,
    label: str | Unset = UNSET,
    limit: int | Unset = UNSET,
    before: int | Unset = UNSET,

) -> Response[JobList | Problem]:
    """ Lists jobs, newest first, a page at a time.

     A page is shorter than `limit` when its jobs together would exceed the
    limit on a result; `next` then goes on from there.

    Args:
        kind (ListJobsKind | Unset):
        label (str | Unset):
        limit (int | Unset):
        before (int | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[JobList | Problem]
     """


    kwargs = _get_kwargs(
        kind=kind,
label=label,
limit=limit,
before=before,

    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)

def sync(
    *,
    client: AuthenticatedClient | Client,
    kind: ListJobsKind | Unset = UNSET,
    label: str | Unset = UNSET,
    limit: int | Unset = UNSET,
    before: int | Unset = UNSET,

) -> JobList | Problem | None:
    """ Lists jobs, newest first, a page at a time.

     A page is shorter than `limit` when its jobs together would exceed the
    limit on a result; `next` then goes on from there.

    Args:
        kind (ListJobsKind | Unset):
        label (str | Unset):
        limit (int | Unset):
        before (int | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        JobList | Problem
     """


    return sync_detailed(
        client=client,
kind=kind,
label=label,
limit=limit,
before=before,

    ).parsed

async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    kind: ListJobsKind | Unset = UNSET,
    label: str | Unset = UNSET,
    limit: int | Unset = UNSET,
    before: int | Unset = UNSET,

) -> Response[JobList | Problem]:
    """ Lists jobs, newest first, a page at a time.

     A page is shorter than `limit` when its jobs together would exceed the
    limit on a result; `next` then goes on from there.

    Args:
        kind (ListJobsKind | Unset):
        label (str | Unset):
        limit (int | Unset):
        before (int | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[JobList | Problem]
     """


    kwargs = _get_kwargs(
        kind=kind,
label=label,
limit=limit,
before=before,

    )

    response = await client.get_async_httpx_client().request(
        **kwargs
    )

    return _build_response(client=client, response=response)

async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    kind: ListJobsKind | Unset = UNSET,
    label: str | Unset = UNSET,
    limit: int | Unset = UNSET,
    before: int | Unset = UNSET,

) -> JobList | Problem | None:
    """ Lists jobs, newest first, a page at a time.

     A page is shorter than `limit` when its jobs together would exceed the
    limit on a result; `next` then goes on from there.

    Args:
        kind (ListJobsKind | Unset):
        label (str | Unset):
        limit (int | Unset):
        before (int | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        JobList | Problem
     """


    return (await asyncio_detailed(
        client=client,
kind=kind,
label=label,
limit=limit,
before=before,

    )).parsed
