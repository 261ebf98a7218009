from http import HTTPStatus
from typing import Any, cast
from urllib.parse import quote

import httpx

from ...client import AuthenticatedClient, Client
from ...types import Response, UNSET
from ... import errors

from ...models.job_balancing import JobBalancing
from ...models.job_cams import JobCams
from ...models.job_check import JobCheck
from ...models.job_dynamics import JobDynamics
from ...models.job_equivalent_masses import JobEquivalentMasses
from ...models.job_flywheel import JobFlywheel
from ...models.job_gear_train import JobGearTrain
from ...models.job_gears import JobGears
from ...models.job_kinetostatics import JobKinetostatics
from ...models.job_mobility import JobMobility
from ...models.job_of_mobility_result import JobOfMobilityResult
from ...models.job_rotor import JobRotor
from ...models.mobility_request import MobilityRequest
from ...models.problem import Problem
from ...types import UNSET, Unset
from typing import cast



def _get_kwargs(
    *,
    body: MobilityRequest,
    label: str | Unset = UNSET,
    prefer: str | Unset = UNSET,
    idempotency_key: str | Unset = UNSET,

) -> dict[str, Any]:
    headers: dict[str, Any] = {}
    if not isinstance(prefer, Unset):
        headers["Prefer"] = prefer

    if not isinstance(idempotency_key, Unset):
        headers["Idempotency-Key"] = idempotency_key



    

    params: dict[str, Any] = {}

    params["label"] = label


    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}


    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/mobility",
        "params": params,
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs



def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | JobOfMobilityResult | Problem | None:
    if response.status_code == 201:
        response_201 = JobOfMobilityResult.from_dict(response.json())



        return response_201

    if response.status_code == 202:
        def _parse_response_202(data: object) -> JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor:
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_job_type_0 = JobFlywheel.from_dict(data)



                return componentsschemas_job_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_job_type_1 = JobKinetostatics.from_dict(data)



                return componentsschemas_job_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_job_type_2 = JobDynamics.from_dict(data)



                return componentsschemas_job_type_2
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_job_type_3 = JobGears.from_dict(data)



                return componentsschemas_job_type_3
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_job_type_4 = JobGearTrain.from_dict(data)



                return componentsschemas_job_type_4
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_job_type_5 = JobEquivalentMasses.from_dict(data)



                return componentsschemas_job_type_5
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_job_type_6 = JobRotor.from_dict(data)



                return componentsschemas_job_type_6
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_job_type_7 = JobBalancing.from_dict(data)



                return componentsschemas_job_type_7
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_job_type_8 = JobMobility.from_dict(data)



                return componentsschemas_job_type_8
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_job_type_9 = JobCams.from_dict(data)



                return componentsschemas_job_type_9
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            componentsschemas_job_type_10 = JobCheck.from_dict(data)



            return componentsschemas_job_type_10

        response_202 = _parse_response_202(response.json())

        return response_202

    if response.status_code == 400:
        response_400 = Problem.from_dict(response.json())



        return response_400

    if response.status_code == 401:
        response_401 = Problem.from_dict(response.json())



        return response_401

    if response.status_code == 408:
        response_408 = Problem.from_dict(response.json())



        return response_408

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


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | JobOfMobilityResult | Problem]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: MobilityRequest,
    label: str | Unset = UNSET,
    prefer: str | Unset = UNSET,
    idempotency_key: str | Unset = UNSET,

) -> Response[JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | JobOfMobilityResult | Problem]:
    """ Degrees of freedom of a mechanism, from its drawing or from the counts of its bodies and pairs.

    Args:
        label (str | Unset):
        prefer (str | Unset):
        idempotency_key (str | Unset):
        body (MobilityRequest): A mechanism without inputs (its drawing), or the counts alone.
            Example: {'counts': {'bodies': 5, 'pairs': {'I': 5, 'II': 1}, 'space': 'planar'}}.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | JobOfMobilityResult | Problem]
     """


    kwargs = _get_kwargs(
        body=body,
label=label,
prefer=prefer,
idempotency_key=idempotency_key,

    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)

def sync(
    *,
    client: AuthenticatedClient | Client,
    body: MobilityRequest,
    label: str | Unset = UNSET,
    prefer: str | Unset = UNSET,
    idempotency_key: str | Unset = UNSET,

) -> JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | JobOfMobilityResult | Problem | None:
    """ Degrees of freedom of a mechanism, from its drawing or from the counts of its bodies and pairs.

    Args:
        label (str | Unset):
        prefer (str | Unset):
        idempotency_key (str | Unset):
        body (MobilityRequest): A mechanism without inputs (its drawing), or the counts alone.
            Example: {'counts': {'bodies': 5, 'pairs': {'I': 5, 'II': 1}, 'space': 'planar'}}.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | JobOfMobilityResult | Problem
     """


    return sync_detailed(
        client=client,
body=body,
label=label,
prefer=prefer,
idempotency_key=idempotency_key,

    ).parsed

async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: MobilityRequest,
    label: str | Unset = UNSET,
    prefer: str | Unset = UNSET,
    idempotency_key: str | Unset = UNSET,

) -> Response[JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | JobOfMobilityResult | Problem]:
    """ Degrees of freedom of a mechanism, from its drawing or from the counts of its bodies and pairs.

    Args:
        label (str | Unset):
        prefer (str | Unset):
        idempotency_key (str | Unset):
        body (MobilityRequest): A mechanism without inputs (its drawing), or the counts alone.
            Example: {'counts': {'bodies': 5, 'pairs': {'I': 5, 'II': 1}, 'space': 'planar'}}.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | JobOfMobilityResult | Problem]
     """


    kwargs = _get_kwargs(
        body=body,
label=label,
prefer=prefer,
idempotency_key=idempotency_key,

    )

    response = await client.get_async_httpx_client().request(
        **kwargs
    )

    return _build_response(client=client, response=response)

async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: MobilityRequest,
    label: str | Unset = UNSET,
    prefer: str | Unset = UNSET,
    idempotency_key: str | Unset = UNSET,

) -> JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | JobOfMobilityResult | Problem | None:
    """ Degrees of freedom of a mechanism, from its drawing or from the counts of its bodies and pairs.

    Args:
        label (str | Unset):
        prefer (str | Unset):
        idempotency_key (str | Unset):
        body (MobilityRequest): A mechanism without inputs (its drawing), or the counts alone.
            Example: {'counts': {'bodies': 5, 'pairs': {'I': 5, 'II': 1}, 'space': 'planar'}}.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | JobOfMobilityResult | Problem
     """


    return (await asyncio_detailed(
        client=client,
body=body,
label=label,
prefer=prefer,
idempotency_key=idempotency_key,

    )).parsed
