from http import HTTPStatus
from typing import Any, cast
from urllib.parse import quote

import httpx

from ...client import AuthenticatedClient, Client
from ...types import Response, UNSET
from ... import errors

from ...models.new_template import NewTemplate
from ...models.problem import Problem
from ...models.template import Template
from typing import cast



def _get_kwargs(
    *,
    body: NewTemplate,

) -> dict[str, Any]:
    headers: dict[str, Any] = {}


    

    

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/templates",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs



def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Problem | Template | None:
    if response.status_code == 201:
        response_201 = Template.from_dict(response.json())



        return response_201

    if response.status_code == 400:
        response_400 = Problem.from_dict(response.json())



        return response_400

    if response.status_code == 401:
        response_401 = Problem.from_dict(response.json())



        return response_401

    if response.status_code == 408:
        response_408 = Problem.from_dict(response.json())



        return response_408

    if response.status_code == 409:
        response_409 = Problem.from_dict(response.json())



        return response_409

    if response.status_code == 411:
        response_411 = Problem.from_dict(response.json())



        return response_411

    if response.status_code == 413:
        response_413 = Problem.from_dict(response.json())



        return response_413

    if response.status_code == 415:
        response_415 = Problem.from_dict(response.json())



        return response_415

    if response.status_code == 422:
        response_422 = Problem.from_dict(response.json())



        return response_422

    if response.status_code == 500:
        response_500 = Problem.from_dict(response.json())



        return response_500

    if response.status_code == 503:
        response_503 = Problem.from_dict(response.json())



        return response_503

    if response.status_code == 507:
        response_507 = Problem.from_dict(response.json())



        return response_507

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[Problem | Template]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: NewTemplate,

) -> Response[Problem | Template]:
    """ Creates a template: `request` is solved once (a template that cannot be
    solved is refused with the usual 422, its pointers under `/request`).

    Args:
        body (NewTemplate): The body of `POST /v1/templates`. Example: {'kind': 'gears', 'name':
            'my-gear', 'parameters': {'z': {'description': 'Number of teeth', 'max': 200, 'min': 12,
            'pointer': '/teeth'}}, 'request': {'module': '4 mm', 'teeth': 30}, 'title': 'A spur
            gear'}.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | Template]
     """


    kwargs = _get_kwargs(
        body=body,

    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)

def sync(
    *,
    client: AuthenticatedClient | Client,
    body: NewTemplate,

) -> Problem | Template | None:
    """ Creates a template: `request` is solved once (a template that cannot be
    solved is refused with the usual 422, its pointers under `/request`).

    Args:
        body (NewTemplate): The body of `POST /v1/templates`. Example: {'kind': 'gears', 'name':
            'my-gear', 'parameters': {'z': {'description': 'Number of teeth', 'max': 200, 'min': 12,
            'pointer': '/teeth'}}, 'request': {'module': '4 mm', 'teeth': 30}, 'title': 'A spur
            gear'}.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | Template
     """


    return sync_detailed(
        client=client,
body=body,

    ).parsed

async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: NewTemplate,

) -> Response[Problem | Template]:
    """ Creates a template: `request` is solved once (a template that cannot be
    solved is refused with the usual 422, its pointers under `/request`).

    Args:
        body (NewTemplate): The body of `POST /v1/templates`. Example: {'kind': 'gears', 'name':
            'my-gear', 'parameters': {'z': {'description': 'Number of teeth', 'max': 200, 'min': 12,
            'pointer': '/teeth'}}, 'request': {'module': '4 mm', 'teeth': 30}, 'title': 'A spur
            gear'}.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | Template]
     """


    kwargs = _get_kwargs(
        body=body,

    )

    response = await client.get_async_httpx_client().request(
        **kwargs
    )

    return _build_response(client=client, response=response)

async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: NewTemplate,

) -> Problem | Template | None:
    """ Creates a template: `request` is solved once (a template that cannot be
    solved is refused with the usual 422, its pointers under `/request`).

    Args:
        body (NewTemplate): The body of `POST /v1/templates`. Example: {'kind': 'gears', 'name':
            'my-gear', 'parameters': {'z': {'description': 'Number of teeth', 'max': 200, 'min': 12,
            'pointer': '/teeth'}}, 'request': {'module': '4 mm', 'teeth': 30}, 'title': 'A spur
            gear'}.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | Template
     """


    return (await asyncio_detailed(
        client=client,
body=body,

    )).parsed
