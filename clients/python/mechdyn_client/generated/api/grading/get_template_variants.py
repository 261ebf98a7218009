from http import HTTPStatus
from typing import Any, cast
from urllib.parse import quote

import httpx

from ...client import AuthenticatedClient, Client
from ...types import Response, UNSET
from ... import errors

from ...models.decimal_mark import DecimalMark
from ...models.format_ import Format
from ...models.problem import Problem
from ...models.variants import Variants
from ...types import UNSET, Unset
from typing import cast



def _get_kwargs(
    id: str,
    *,
    seed: int | Unset = UNSET,
    count: int | Unset = UNSET,
    values: str | Unset = UNSET,
    format_: Format | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> dict[str, Any]:
    

    

    params: dict[str, Any] = {}

    params["seed"] = seed

    params["count"] = count

    params["values"] = values

    json_format_: str | Unset = UNSET
    if not isinstance(format_, Unset):
        json_format_ = format_.value

    params["format"] = json_format_

    json_decimal: str | Unset = UNSET
    if not isinstance(decimal, Unset):
        json_decimal = decimal.value

    params["decimal"] = json_decimal


    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}


    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/v1/templates/{id}/variants".format(id=quote(str(id), safe=""),),
        "params": params,
    }


    return _kwargs



def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Problem | Variants | None:
    if response.status_code == 200:
        response_200 = Variants.from_dict(response.json())



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

    if response.status_code == 503:
        response_503 = Problem.from_dict(response.json())



        return response_503

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[Problem | Variants]:
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
    seed: int | Unset = UNSET,
    count: int | Unset = UNSET,
    values: str | Unset = UNSET,
    format_: Format | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Response[Problem | Variants]:
    """ Seeded variants: per-student parameter sets with their reference values.

     Variant `v` is the single draw with seed `v` (the generator: SplitMix64
    seeded with `v`, one draw per parameter in name order, mapped onto the
    parameter's `choices` or `min`/`max`/`step` grid; see docs/grading.md), so the
    same template and seed give the same parameters everywhere and forever.

    Args:
        id (str):
        seed (int | Unset):
        count (int | Unset):
        values (str | Unset):
        format_ (Format | Unset): `?format=` of the values.
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | Variants]
     """


    kwargs = _get_kwargs(
        id=id,
seed=seed,
count=count,
values=values,
format_=format_,
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
    seed: int | Unset = UNSET,
    count: int | Unset = UNSET,
    values: str | Unset = UNSET,
    format_: Format | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Problem | Variants | None:
    """ Seeded variants: per-student parameter sets with their reference values.

     Variant `v` is the single draw with seed `v` (the generator: SplitMix64
    seeded with `v`, one draw per parameter in name order, mapped onto the
    parameter's `choices` or `min`/`max`/`step` grid; see docs/grading.md), so the
    same template and seed give the same parameters everywhere and forever.

    Args:
        id (str):
        seed (int | Unset):
        count (int | Unset):
        values (str | Unset):
        format_ (Format | Unset): `?format=` of the values.
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | Variants
     """


    return sync_detailed(
        id=id,
client=client,
seed=seed,
count=count,
values=values,
format_=format_,
decimal=decimal,

    ).parsed

async def asyncio_detailed(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    seed: int | Unset = UNSET,
    count: int | Unset = UNSET,
    values: str | Unset = UNSET,
    format_: Format | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Response[Problem | Variants]:
    """ Seeded variants: per-student parameter sets with their reference values.

     Variant `v` is the single draw with seed `v` (the generator: SplitMix64
    seeded with `v`, one draw per parameter in name order, mapped onto the
    parameter's `choices` or `min`/`max`/`step` grid; see docs/grading.md), so the
    same template and seed give the same parameters everywhere and forever.

    Args:
        id (str):
        seed (int | Unset):
        count (int | Unset):
        values (str | Unset):
        format_ (Format | Unset): `?format=` of the values.
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | Variants]
     """


    kwargs = _get_kwargs(
        id=id,
seed=seed,
count=count,
values=values,
format_=format_,
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
    seed: int | Unset = UNSET,
    count: int | Unset = UNSET,
    values: str | Unset = UNSET,
    format_: Format | Unset = UNSET,
    decimal: DecimalMark | Unset = UNSET,

) -> Problem | Variants | None:
    """ Seeded variants: per-student parameter sets with their reference values.

     Variant `v` is the single draw with seed `v` (the generator: SplitMix64
    seeded with `v`, one draw per parameter in name order, mapped onto the
    parameter's `choices` or `min`/`max`/`step` grid; see docs/grading.md), so the
    same template and seed give the same parameters everywhere and forever.

    Args:
        id (str):
        seed (int | Unset):
        count (int | Unset):
        values (str | Unset):
        format_ (Format | Unset): `?format=` of the values.
        decimal (DecimalMark | Unset): `?decimal=` of a text answer (the OpenAPI document's enum).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | Variants
     """


    return (await asyncio_detailed(
        id=id,
client=client,
seed=seed,
count=count,
values=values,
format_=format_,
decimal=decimal,

    )).parsed
