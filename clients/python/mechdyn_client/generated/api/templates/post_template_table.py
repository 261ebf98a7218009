from http import HTTPStatus
from typing import Any, cast
from urllib.parse import quote

import httpx

from ...client import AuthenticatedClient, Client
from ...types import Response, UNSET
from ... import errors

from ...models.decimal_mark import DecimalMark
from ...models.problem import Problem
from ...models.table_request import TableRequest
from ...models.table_response import TableResponse
from ...types import File, FileTypes
from ...types import UNSET, Unset
from io import BytesIO
from typing import cast



def _get_kwargs(
    id: str,
    *,
    body:    TableRequest  |     File  | Unset = UNSET,
    values: str | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> dict[str, Any]:
    headers: dict[str, Any] = {}


    

    params: dict[str, Any] = {}

    params["values"] = values

    json_decimal: str | Unset = UNSET
    if not isinstance(decimal, Unset):
        json_decimal = decimal.value

    params["decimal"] = json_decimal


    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}


    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/templates/{id}/table".format(id=quote(str(id), safe=""),),
        "params": params,
    }

    if isinstance(body, TableRequest):
        _kwargs["json"] = body.to_dict()

        headers["Content-Type"] = "application/json"
    if isinstance(body, File):
        _kwargs["content"] = body.payload
        headers["Content-Type"] = "text/csv"

    _kwargs["headers"] = headers
    return _kwargs



def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Problem | TableResponse | None:
    if response.status_code == 200:
        response_200 = TableResponse.from_dict(response.json())



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


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[Problem | TableResponse]:
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
    body:    TableRequest  |     File  | Unset = UNSET,
    values: str | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Response[Problem | TableResponse]:
    """ A parameter study: one variant per row of a CSV (or JSON) table.

    Args:
        id (str):
        values (str | Unset):
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).
        body (TableRequest): A study as JSON. Example: {'rows': [{'F': 1000}, {'F': '1.2 kN*m',
            'eps': '3 %'}], 'values': ['inertia_exact']}.
        body (File): The text/csv text, as bytes

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | TableResponse]
     """


    kwargs = _get_kwargs(
        id=id,
body=body,
values=values,
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
    body:    TableRequest  |     File  | Unset = UNSET,
    values: str | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Problem | TableResponse | None:
    """ A parameter study: one variant per row of a CSV (or JSON) table.

    Args:
        id (str):
        values (str | Unset):
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).
        body (TableRequest): A study as JSON. Example: {'rows': [{'F': 1000}, {'F': '1.2 kN*m',
            'eps': '3 %'}], 'values': ['inertia_exact']}.
        body (File): The text/csv text, as bytes

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | TableResponse
     """


    return sync_detailed(
        id=id,
client=client,
body=body,
values=values,
decimal=decimal,

    ).parsed

async def asyncio_detailed(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    body:    TableRequest  |     File  | Unset = UNSET,
    values: str | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Response[Problem | TableResponse]:
    """ A parameter study: one variant per row of a CSV (or JSON) table.

    Args:
        id (str):
        values (str | Unset):
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).
        body (TableRequest): A study as JSON. Example: {'rows': [{'F': 1000}, {'F': '1.2 kN*m',
            'eps': '3 %'}], 'values': ['inertia_exact']}.
        body (File): The text/csv text, as bytes

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | TableResponse]
     """


    kwargs = _get_kwargs(
        id=id,
body=body,
values=values,
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
    body:    TableRequest  |     File  | Unset = UNSET,
    values: str | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Problem | TableResponse | None:
    """ A parameter study: one variant per row of a CSV (or JSON) table.

    Args:
        id (str):
        values (str | Unset):
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).
        body (TableRequest): A study as JSON. Example: {'rows': [{'F': 1000}, {'F': '1.2 kN*m',
            'eps': '3 %'}], 'values': ['inertia_exact']}.
        body (File): The text/csv text, as bytes

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | TableResponse
     """


    return (await asyncio_detailed(
        id=id,
client=client,
body=body,
values=values,
decimal=decimal,

    )).parsed
