from http import HTTPStatus
from typing import Any, cast
from urllib.parse import quote

import httpx

from ...client import AuthenticatedClient, Client
from ...types import Response, UNSET
from ... import errors

from ...models.angle_unit import AngleUnit
from ...models.decimal_mark import DecimalMark
from ...models.problem import Problem
from ...types import UNSET, Unset
from typing import cast



def _get_kwargs(
    id: str,
    *,
    angles: AngleUnit | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> dict[str, Any]:
    

    

    params: dict[str, Any] = {}

    json_angles: str | Unset = UNSET
    if not isinstance(angles, Unset):
        json_angles = angles.value

    params["angles"] = json_angles

    json_decimal: str | Unset = UNSET
    if not isinstance(decimal, Unset):
        json_decimal = decimal.value

    params["decimal"] = json_decimal


    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}


    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/v1/jobs/{id}/result.csv".format(id=quote(str(id), safe=""),),
        "params": params,
    }


    return _kwargs



def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Problem | str | None:
    if response.status_code == 200:
        response_200 = response.text
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
    angles: AngleUnit | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Response[Problem | str]:
    """ The job's tabular result as CSV: one row per sample, header with units.

     A kind without a table (or a job asked for none, e.g. `samples: 0`)
    answers its values instead, `pointer,value,unit`: never an empty body.

    Args:
        id (str):
        angles (AngleUnit | Unset): How angles are written, `?angles=` (the OpenAPI document's
            enum).
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | str]
     """


    kwargs = _get_kwargs(
        id=id,
angles=angles,
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
    angles: AngleUnit | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Problem | str | None:
    """ The job's tabular result as CSV: one row per sample, header with units.

     A kind without a table (or a job asked for none, e.g. `samples: 0`)
    answers its values instead, `pointer,value,unit`: never an empty body.

    Args:
        id (str):
        angles (AngleUnit | Unset): How angles are written, `?angles=` (the OpenAPI document's
            enum).
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | str
     """


    return sync_detailed(
        id=id,
client=client,
angles=angles,
decimal=decimal,

    ).parsed

async def asyncio_detailed(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    angles: AngleUnit | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Response[Problem | str]:
    """ The job's tabular result as CSV: one row per sample, header with units.

     A kind without a table (or a job asked for none, e.g. `samples: 0`)
    answers its values instead, `pointer,value,unit`: never an empty body.

    Args:
        id (str):
        angles (AngleUnit | Unset): How angles are written, `?angles=` (the OpenAPI document's
            enum).
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | str]
     """


    kwargs = _get_kwargs(
        id=id,
angles=angles,
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
    angles: AngleUnit | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Problem | str | None:
    """ The job's tabular result as CSV: one row per sample, header with units.

     A kind without a table (or a job asked for none, e.g. `samples: 0`)
    answers its values instead, `pointer,value,unit`: never an empty body.

    Args:
        id (str):
        angles (AngleUnit | Unset): How angles are written, `?angles=` (the OpenAPI document's
            enum).
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | str
     """


    return (await asyncio_detailed(
        id=id,
client=client,
angles=angles,
decimal=decimal,

    )).parsed
