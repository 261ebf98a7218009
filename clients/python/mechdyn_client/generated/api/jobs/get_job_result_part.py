from http import HTTPStatus
from typing import Any, cast
from urllib.parse import quote

import httpx

from ...client import AuthenticatedClient, Client
from ...types import Response, UNSET
from ... import errors

from ...models.decimal_mark import DecimalMark
from ...models.problem import Problem
from ...types import UNSET, Unset
from typing import cast



def _get_kwargs(
    id: str,
    pointer: str,
    *,
    unit: str | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,
    errors: str | Unset = UNSET,

) -> dict[str, Any]:
    

    

    params: dict[str, Any] = {}

    params["unit"] = unit

    json_decimal: str | Unset = UNSET
    if not isinstance(decimal, Unset):
        json_decimal = decimal.value

    params["decimal"] = json_decimal

    params["errors"] = errors


    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}


    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/v1/jobs/{id}/result/{pointer}".format(id=quote(str(id), safe=""),pointer=quote(str(pointer), safe=""),),
        "params": params,
    }


    return _kwargs



def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Any | Problem | None:
    if response.status_code == 200:
        response_200 = response.json()
        return response_200

    if response.status_code == 400:
        response_400 = Problem.from_dict(response.json())



        return response_400

    if response.status_code == 401:
        response_401 = Problem.from_dict(response.json())



        return response_401

    if response.status_code == 404:
        response_404 = Problem.from_dict(response.json())



        return response_404

    if response.status_code == 409:
        response_409 = Problem.from_dict(response.json())



        return response_409

    if response.status_code == 503:
        response_503 = Problem.from_dict(response.json())



        return response_503

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[Any | Problem]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    id: str,
    pointer: str,
    *,
    client: AuthenticatedClient | Client,
    unit: str | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,
    errors: str | Unset = UNSET,

) -> Response[Any | Problem]:
    """ One part of a job's result, by JSON pointer.

     A number, text, flag or null is answered alone as `text/plain` (numbers
    in shortest round-trip form), unless `Accept: application/json` asks for
    JSON; an object or an array is answered as JSON. `?unit=` converts a
    number to another unit of its dimension (`?unit=slug*ft^2`).

    Args:
        id (str):
        pointer (str):
        unit (str | Unset):
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).
        errors (str | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Any | Problem]
     """


    kwargs = _get_kwargs(
        id=id,
pointer=pointer,
unit=unit,
decimal=decimal,
errors=errors,

    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)

def sync(
    id: str,
    pointer: str,
    *,
    client: AuthenticatedClient | Client,
    unit: str | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,
    errors: str | Unset = UNSET,

) -> Any | Problem | None:
    """ One part of a job's result, by JSON pointer.

     A number, text, flag or null is answered alone as `text/plain` (numbers
    in shortest round-trip form), unless `Accept: application/json` asks for
    JSON; an object or an array is answered as JSON. `?unit=` converts a
    number to another unit of its dimension (`?unit=slug*ft^2`).

    Args:
        id (str):
        pointer (str):
        unit (str | Unset):
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).
        errors (str | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Any | Problem
     """


    return sync_detailed(
        id=id,
pointer=pointer,
client=client,
unit=unit,
decimal=decimal,
errors=errors,

    ).parsed

async def asyncio_detailed(
    id: str,
    pointer: str,
    *,
    client: AuthenticatedClient | Client,
    unit: str | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,
    errors: str | Unset = UNSET,

) -> Response[Any | Problem]:
    """ One part of a job's result, by JSON pointer.

     A number, text, flag or null is answered alone as `text/plain` (numbers
    in shortest round-trip form), unless `Accept: application/json` asks for
    JSON; an object or an array is answered as JSON. `?unit=` converts a
    number to another unit of its dimension (`?unit=slug*ft^2`).

    Args:
        id (str):
        pointer (str):
        unit (str | Unset):
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).
        errors (str | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Any | Problem]
     """


    kwargs = _get_kwargs(
        id=id,
pointer=pointer,
unit=unit,
decimal=decimal,
errors=errors,

    )

    response = await client.get_async_httpx_client().request(
        **kwargs
    )

    return _build_response(client=client, response=response)

async def asyncio(
    id: str,
    pointer: str,
    *,
    client: AuthenticatedClient | Client,
    unit: str | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,
    errors: str | Unset = UNSET,

) -> Any | Problem | None:
    """ One part of a job's result, by JSON pointer.

     A number, text, flag or null is answered alone as `text/plain` (numbers
    in shortest round-trip form), unless `Accept: application/json` asks for
    JSON; an object or an array is answered as JSON. `?unit=` converts a
    number to another unit of its dimension (`?unit=slug*ft^2`).

    Args:
        id (str):
        pointer (str):
        unit (str | Unset):
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).
        errors (str | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Any | Problem
     """


    return (await asyncio_detailed(
        id=id,
pointer=pointer,
client=client,
unit=unit,
decimal=decimal,
errors=errors,

    )).parsed
