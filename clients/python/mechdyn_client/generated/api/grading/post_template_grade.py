from http import HTTPStatus
from typing import Any, cast
from urllib.parse import quote

import httpx

from ...client import AuthenticatedClient, Client
from ...types import Response, UNSET
from ... import errors

from ...models.decimal_mark import DecimalMark
from ...models.problem import Problem
from ...types import File, FileTypes
from ...types import UNSET, Unset
from io import BytesIO
from typing import cast



def _get_kwargs(
    id: str,
    *,
    body: File,
    relative: float | Unset = UNSET,
    absolute: float | Unset = UNSET,
    sigfigs: int | Unset = UNSET,
    zero_level: float | Unset = UNSET,
    reveal: bool | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> dict[str, Any]:
    headers: dict[str, Any] = {}


    

    params: dict[str, Any] = {}

    params["relative"] = relative

    params["absolute"] = absolute

    params["sigfigs"] = sigfigs

    params["zero_level"] = zero_level

    params["reveal"] = reveal

    json_decimal: str | Unset = UNSET
    if not isinstance(decimal, Unset):
        json_decimal = decimal.value

    params["decimal"] = json_decimal


    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}


    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/templates/{id}/grade".format(id=quote(str(id), safe=""),),
        "params": params,
    }

    _kwargs["content"] = body.payload
    headers["Content-Type"] = "text/csv"

    _kwargs["headers"] = headers
    return _kwargs



def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Problem | str | None:
    if response.status_code == 200:
        response_200 = response.text
        return response_200

    if response.status_code == 400:
        response_400 = Problem.from_dict(response.json())



        return response_400

    if response.status_code == 404:
        response_404 = Problem.from_dict(response.json())



        return response_404

    if response.status_code == 409:
        response_409 = Problem.from_dict(response.json())



        return response_409

    if response.status_code == 413:
        response_413 = Problem.from_dict(response.json())



        return response_413

    if response.status_code == 415:
        response_415 = Problem.from_dict(response.json())



        return response_415

    if response.status_code == 503:
        response_503 = Problem.from_dict(response.json())



        return response_503

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[Problem | str]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    body: File,
    relative: float | Unset = UNSET,
    absolute: float | Unset = UNSET,
    sigfigs: int | Unset = UNSET,
    zero_level: float | Unset = UNSET,
    reveal: bool | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Response[Problem | str]:
    """ Grades a class: one row per student (`student`, the student's
    parameters or `variant`, answer columns named by pointer, optionally
    `pointer [unit]` for bare numbers); answers CSV with `student`, `score`,
    per answer `POINTER pass` and `POINTER relative_error`, `feedback` and
    `error` (a row that cannot be graded says why; the others are graded).

    Args:
        id (str):
        relative (float | Unset):
        absolute (float | Unset):
        sigfigs (int | Unset):
        zero_level (float | Unset):
        reveal (bool | Unset):
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).
        body (File): The text/csv text, as bytes

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | str]
     """


    kwargs = _get_kwargs(
        id=id,
body=body,
relative=relative,
absolute=absolute,
sigfigs=sigfigs,
zero_level=zero_level,
reveal=reveal,
decimal=decimal,

    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)

def sync(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    body: File,
    relative: float | Unset = UNSET,
    absolute: float | Unset = UNSET,
    sigfigs: int | Unset = UNSET,
    zero_level: float | Unset = UNSET,
    reveal: bool | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Problem | str | None:
    """ Grades a class: one row per student (`student`, the student's
    parameters or `variant`, answer columns named by pointer, optionally
    `pointer [unit]` for bare numbers); answers CSV with `student`, `score`,
    per answer `POINTER pass` and `POINTER relative_error`, `feedback` and
    `error` (a row that cannot be graded says why; the others are graded).

    Args:
        id (str):
        relative (float | Unset):
        absolute (float | Unset):
        sigfigs (int | Unset):
        zero_level (float | Unset):
        reveal (bool | Unset):
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).
        body (File): The text/csv text, as bytes

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | str
     """


    return sync_detailed(
        id=id,
client=client,
body=body,
relative=relative,
absolute=absolute,
sigfigs=sigfigs,
zero_level=zero_level,
reveal=reveal,
decimal=decimal,

    ).parsed

async def asyncio_detailed(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    body: File,
    relative: float | Unset = UNSET,
    absolute: float | Unset = UNSET,
    sigfigs: int | Unset = UNSET,
    zero_level: float | Unset = UNSET,
    reveal: bool | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Response[Problem | str]:
    """ Grades a class: one row per student (`student`, the student's
    parameters or `variant`, answer columns named by pointer, optionally
    `pointer [unit]` for bare numbers); answers CSV with `student`, `score`,
    per answer `POINTER pass` and `POINTER relative_error`, `feedback` and
    `error` (a row that cannot be graded says why; the others are graded).

    Args:
        id (str):
        relative (float | Unset):
        absolute (float | Unset):
        sigfigs (int | Unset):
        zero_level (float | Unset):
        reveal (bool | Unset):
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).
        body (File): The text/csv text, as bytes

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | str]
     """


    kwargs = _get_kwargs(
        id=id,
body=body,
relative=relative,
absolute=absolute,
sigfigs=sigfigs,
zero_level=zero_level,
reveal=reveal,
decimal=decimal,

    )

    response = await client.get_async_httpx_client().request(
        **kwargs
    )

    return _build_response(client=client, response=response)

async def asyncio(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    body: File,
    relative: float | Unset = UNSET,
    absolute: float | Unset = UNSET,
    sigfigs: int | Unset = UNSET,
    zero_level: float | Unset = UNSET,
    reveal: bool | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Problem | str | None:
    """ Grades a class: one row per student (`student`, the student's
    parameters or `variant`, answer columns named by pointer, optionally
    `pointer [unit]` for bare numbers); answers CSV with `student`, `score`,
    per answer `POINTER pass` and `POINTER relative_error`, `feedback` and
    `error` (a row that cannot be graded says why; the others are graded).

    Args:
        id (str):
        relative (float | Unset):
        absolute (float | Unset):
        sigfigs (int | Unset):
        zero_level (float | Unset):
        reveal (bool | Unset):
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).
        body (File): The text/csv text, as bytes

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | str
     """


    return (await asyncio_detailed(
        id=id,
client=client,
body=body,
relative=relative,
absolute=absolute,
sigfigs=sigfigs,
zero_level=zero_level,
reveal=reveal,
decimal=decimal,

    )).parsed
