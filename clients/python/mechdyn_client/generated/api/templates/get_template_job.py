from http import HTTPStatus
from typing import Any, cast
from urllib.parse import quote

import httpx

from ...client import AuthenticatedClient, Client
from ...types import Response, UNSET
from ... import errors

from ...models.get_template_job_parameters import GetTemplateJobParameters
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
from ...models.job_rotor import JobRotor
from ...models.problem import Problem
from ...types import UNSET, Unset
from typing import cast



def _get_kwargs(
    id: str,
    *,
    parameters: GetTemplateJobParameters | Unset = UNSET,

) -> dict[str, Any]:
    

    

    params: dict[str, Any] = {}

    json_parameters: dict[str, Any] | Unset = UNSET
    if not isinstance(parameters, Unset):
        json_parameters = parameters.to_dict()
    if not isinstance(json_parameters, Unset):
        params.update(json_parameters)



    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}


    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/v1/templates/{id}/job".format(id=quote(str(id), safe=""),),
        "params": params,
    }


    return _kwargs



def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | Problem | None:
    if response.status_code == 200:
        def _parse_response_200(data: object) -> JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor:
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

        response_200 = _parse_response_200(response.json())

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


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | Problem]:
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
    parameters: GetTemplateJobParameters | Unset = UNSET,

) -> Response[JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | Problem]:
    """ The job a template gives for its parameters (`?NAME=VALUE&...`, the
    others at their defaults): the stored one when asked before, else computed and stored.

    Args:
        id (str):
        parameters (GetTemplateJobParameters | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | Problem]
     """


    kwargs = _get_kwargs(
        id=id,
parameters=parameters,

    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)

def sync(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    parameters: GetTemplateJobParameters | Unset = UNSET,

) -> JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | Problem | None:
    """ The job a template gives for its parameters (`?NAME=VALUE&...`, the
    others at their defaults): the stored one when asked before, else computed and stored.

    Args:
        id (str):
        parameters (GetTemplateJobParameters | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | Problem
     """


    return sync_detailed(
        id=id,
client=client,
parameters=parameters,

    ).parsed

async def asyncio_detailed(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    parameters: GetTemplateJobParameters | Unset = UNSET,

) -> Response[JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | Problem]:
    """ The job a template gives for its parameters (`?NAME=VALUE&...`, the
    others at their defaults): the stored one when asked before, else computed and stored.

    Args:
        id (str):
        parameters (GetTemplateJobParameters | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | Problem]
     """


    kwargs = _get_kwargs(
        id=id,
parameters=parameters,

    )

    response = await client.get_async_httpx_client().request(
        **kwargs
    )

    return _build_response(client=client, response=response)

async def asyncio(
    id: str,
    *,
    client: AuthenticatedClient | Client,
    parameters: GetTemplateJobParameters | Unset = UNSET,

) -> JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | Problem | None:
    """ The job a template gives for its parameters (`?NAME=VALUE&...`, the
    others at their defaults): the stored one when asked before, else computed and stored.

    Args:
        id (str):
        parameters (GetTemplateJobParameters | Unset):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        JobBalancing | JobCams | JobCheck | JobDynamics | JobEquivalentMasses | JobFlywheel | JobGears | JobGearTrain | JobKinetostatics | JobMobility | JobRotor | Problem
     """


    return (await asyncio_detailed(
        id=id,
client=client,
parameters=parameters,

    )).parsed
