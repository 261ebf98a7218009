from http import HTTPStatus
from typing import Any, cast
from urllib.parse import quote

import httpx

from ...client import AuthenticatedClient, Client
from ...types import Response, UNSET
from ... import errors

from ...models.problem import Problem
from ...models.solution import Solution
from ...types import UNSET, Unset
from typing import cast



def _get_kwargs(
    id: str,
    *,
    step: int | Unset = UNSET,

) -> dict[str, Any]:
    

    

    params: dict[str, Any] = {}

    params["step"] = step


    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}


    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/v1/jobs/{id}/solution".format(id=quote(str(id), safe=""),),
        "params": params,
    }


    return _kwargs



def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Problem | Solution | None:
    if response.status_code == 200:
        response_200 = Solution.from_dict(response.json())



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

    if response.status_code == 422:
        response_422 = Problem.from_dict(response.json())



        return response_422

    if response.status_code == 503:
        response_503 = Problem.from_dict(response.json())



        return response_503

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[Problem | Solution]:
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
    step: int | Unset = UNSET,

) -> Response[Problem | Solution]:
    """ Every moving body of a kinetostatics job alone at step k (default 0):
    each force and couple on it, named as the notes name them (R_ij the
    force of body i on body j, the ground 1; F_Ij, M_Ij the inertia force
    and couple; W_j the weight; M_m the driving couple), its three
    equations of equilibrium with these numbers (each zero to rounding), the
    order in which the bodies' equations are solved (the Assur groups from
    the last) with what each group's give, and the same actions' powers,
    whose sum is zero (virtual power). The step is solved again from the
    stored request, on the same branch: the numbers are the job's.

    Args:
        id (str):
        step (int | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | Solution]
     """


    kwargs = _get_kwargs(
        id=id,
step=step,

    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)

def sync(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    step: int | Unset = UNSET,

) -> Problem | Solution | None:
    """ Every moving body of a kinetostatics job alone at step k (default 0):
    each force and couple on it, named as the notes name them (R_ij the
    force of body i on body j, the ground 1; F_Ij, M_Ij the inertia force
    and couple; W_j the weight; M_m the driving couple), its three
    equations of equilibrium with these numbers (each zero to rounding), the
    order in which the bodies' equations are solved (the Assur groups from
    the last) with what each group's give, and the same actions' powers,
    whose sum is zero (virtual power). The step is solved again from the
    stored request, on the same branch: the numbers are the job's.

    Args:
        id (str):
        step (int | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | Solution
     """


    return sync_detailed(
        id=id,
client=client,
step=step,

    ).parsed

async def asyncio_detailed(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    step: int | Unset = UNSET,

) -> Response[Problem | Solution]:
    """ Every moving body of a kinetostatics job alone at step k (default 0):
    each force and couple on it, named as the notes name them (R_ij the
    force of body i on body j, the ground 1; F_Ij, M_Ij the inertia force
    and couple; W_j the weight; M_m the driving couple), its three
    equations of equilibrium with these numbers (each zero to rounding), the
    order in which the bodies' equations are solved (the Assur groups from
    the last) with what each group's give, and the same actions' powers,
    whose sum is zero (virtual power). The step is solved again from the
    stored request, on the same branch: the numbers are the job's.

    Args:
        id (str):
        step (int | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | Solution]
     """


    kwargs = _get_kwargs(
        id=id,
step=step,

    )

    response = await client.get_async_httpx_client().request(
        **kwargs
    )

    return _build_response(client=client, response=response)

async def asyncio(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    step: int | Unset = UNSET,

) -> Problem | Solution | None:
    """ Every moving body of a kinetostatics job alone at step k (default 0):
    each force and couple on it, named as the notes name them (R_ij the
    force of body i on body j, the ground 1; F_Ij, M_Ij the inertia force
    and couple; W_j the weight; M_m the driving couple), its three
    equations of equilibrium with these numbers (each zero to rounding), the
    order in which the bodies' equations are solved (the Assur groups from
    the last) with what each group's give, and the same actions' powers,
    whose sum is zero (virtual power). The step is solved again from the
    stored request, on the same branch: the numbers are the job's.

    Args:
        id (str):
        step (int | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | Solution
     """


    return (await asyncio_detailed(
        id=id,
client=client,
step=step,

    )).parsed
