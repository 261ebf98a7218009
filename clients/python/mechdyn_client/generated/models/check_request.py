from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.check_format import CheckFormat
from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.check_request_answers import CheckRequestAnswers
  from ..models.check_request_parameters_type_0 import CheckRequestParametersType0
  from ..models.check_request_request_type_0 import CheckRequestRequestType0
  from ..models.check_request_tolerances_type_0 import CheckRequestTolerancesType0
  from ..models.tolerance_dto import ToleranceDto





T = TypeVar("T", bound="CheckRequest")



@_attrs_define
class CheckRequest:
    """ The body of `POST /v1/check`: one reference (`template`, `kind` with
    `request`, or `job`) and the answers.

        Example:
            {'answers': {'energy_fluctuation': 1100, 'inertia_exact': '424 kg*m^2', 'omega_max': 6.4}, 'parameters': {'F':
                600}, 'template': 'p103-slider-flywheel', 'tolerance': {'relative': 0.01}}

        Attributes:
            answers (CheckRequestAnswers): JSON pointer into the result (the leading `/` optional) → the answer:
                a number in SI or `"VALUE UNIT"` (e.g. `"260 slug*ft^2"`).
            format_ (CheckFormat | None | Unset):
            job (None | str | Unset): The reference is this stored job.
            kind (None | str | Unset): The reference is the job of `request` of this kind.
            parameters (CheckRequestParametersType0 | None | Unset): The template's parameters by name: a number in the
                parameter's unit, or a quantity (`"300 rpm"`).
            request (CheckRequestRequestType0 | None | Unset):
            required (list[str] | None | Unset): The answers the score counts (pointers): one missing from `answers`
                fails as "no answer", so a student gains nothing by leaving one out.
                Default: the answers given.
            reveal (bool | None | Unset): Whether the feedback shows the expected value and the relative error (default
                true).
            template (None | str | Unset): A template's id: the reference is its job for `parameters` (or `variant`).
            tolerance (None | ToleranceDto | Unset):
            tolerances (CheckRequestTolerancesType0 | None | Unset): Per answer (by its pointer), over `tolerance`.
            variant (int | None | Unset): A seeded variant of the template (`GET /v1/templates/{id}/variants` lists them), 0
                to 2^63 − 1.
     """

    answers: CheckRequestAnswers
    format_: CheckFormat | None | Unset = UNSET
    job: None | str | Unset = UNSET
    kind: None | str | Unset = UNSET
    parameters: CheckRequestParametersType0 | None | Unset = UNSET
    request: CheckRequestRequestType0 | None | Unset = UNSET
    required: list[str] | None | Unset = UNSET
    reveal: bool | None | Unset = UNSET
    template: None | str | Unset = UNSET
    tolerance: None | ToleranceDto | Unset = UNSET
    tolerances: CheckRequestTolerancesType0 | None | Unset = UNSET
    variant: int | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.check_request_answers import CheckRequestAnswers # noqa: PLC0415
        from ..models.check_request_parameters_type_0 import CheckRequestParametersType0 # noqa: PLC0415
        from ..models.check_request_request_type_0 import CheckRequestRequestType0 # noqa: PLC0415
        from ..models.check_request_tolerances_type_0 import CheckRequestTolerancesType0 # noqa: PLC0415
        from ..models.tolerance_dto import ToleranceDto # noqa: PLC0415
        answers = self.answers.to_dict()

        format_: None | str | Unset
        if isinstance(self.format_, Unset):
            format_ = UNSET
        elif isinstance(self.format_, CheckFormat):
            format_ = self.format_.value
        else:
            format_ = self.format_

        job: None | str | Unset
        if isinstance(self.job, Unset):
            job = UNSET
        else:
            job = self.job

        kind: None | str | Unset
        if isinstance(self.kind, Unset):
            kind = UNSET
        else:
            kind = self.kind

        parameters: dict[str, Any] | None | Unset
        if isinstance(self.parameters, Unset):
            parameters = UNSET
        elif isinstance(self.parameters, CheckRequestParametersType0):
            parameters = self.parameters.to_dict()
        else:
            parameters = self.parameters

        request: dict[str, Any] | None | Unset
        if isinstance(self.request, Unset):
            request = UNSET
        elif isinstance(self.request, CheckRequestRequestType0):
            request = self.request.to_dict()
        else:
            request = self.request

        required: list[str] | None | Unset
        if isinstance(self.required, Unset):
            required = UNSET
        elif isinstance(self.required, list):
            required = self.required


        else:
            required = self.required

        reveal: bool | None | Unset
        if isinstance(self.reveal, Unset):
            reveal = UNSET
        else:
            reveal = self.reveal

        template: None | str | Unset
        if isinstance(self.template, Unset):
            template = UNSET
        else:
            template = self.template

        tolerance: dict[str, Any] | None | Unset
        if isinstance(self.tolerance, Unset):
            tolerance = UNSET
        elif isinstance(self.tolerance, ToleranceDto):
            tolerance = self.tolerance.to_dict()
        else:
            tolerance = self.tolerance

        tolerances: dict[str, Any] | None | Unset
        if isinstance(self.tolerances, Unset):
            tolerances = UNSET
        elif isinstance(self.tolerances, CheckRequestTolerancesType0):
            tolerances = self.tolerances.to_dict()
        else:
            tolerances = self.tolerances

        variant: int | None | Unset
        if isinstance(self.variant, Unset):
            variant = UNSET
        else:
            variant = self.variant


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "answers": answers,
        })
        if format_ is not UNSET:
            field_dict["format"] = format_
        if job is not UNSET:
            field_dict["job"] = job
        if kind is not UNSET:
            field_dict["kind"] = kind
        if parameters is not UNSET:
            field_dict["parameters"] = parameters
        if request is not UNSET:
            field_dict["request"] = request
        if required is not UNSET:
            field_dict["required"] = required
        if reveal is not UNSET:
            field_dict["reveal"] = reveal
        if template is not UNSET:
            field_dict["template"] = template
        if tolerance is not UNSET:
            field_dict["tolerance"] = tolerance
        if tolerances is not UNSET:
            field_dict["tolerances"] = tolerances
        if variant is not UNSET:
            field_dict["variant"] = variant

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.check_request_answers import CheckRequestAnswers # noqa: PLC0415
        from ..models.check_request_parameters_type_0 import CheckRequestParametersType0 # noqa: PLC0415
        from ..models.check_request_request_type_0 import CheckRequestRequestType0 # noqa: PLC0415
        from ..models.check_request_tolerances_type_0 import CheckRequestTolerancesType0 # noqa: PLC0415
        from ..models.tolerance_dto import ToleranceDto # noqa: PLC0415
        d = dict(src_dict)
        answers = CheckRequestAnswers.from_dict(d.pop("answers"))




        def _parse_format_(data: object) -> CheckFormat | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                format_type_0 = CheckFormat(data)



                return format_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(CheckFormat | None | Unset, data)

        format_ = _parse_format_(d.pop("format", UNSET))


        def _parse_job(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        job = _parse_job(d.pop("job", UNSET))


        def _parse_kind(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        kind = _parse_kind(d.pop("kind", UNSET))


        def _parse_parameters(data: object) -> CheckRequestParametersType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                parameters_type_0 = CheckRequestParametersType0.from_dict(data)



                return parameters_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(CheckRequestParametersType0 | None | Unset, data)

        parameters = _parse_parameters(d.pop("parameters", UNSET))


        def _parse_request(data: object) -> CheckRequestRequestType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                request_type_0 = CheckRequestRequestType0.from_dict(data)



                return request_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(CheckRequestRequestType0 | None | Unset, data)

        request = _parse_request(d.pop("request", UNSET))


        def _parse_required(data: object) -> list[str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                required_type_0 = list(data)

                return required_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[str] | None | Unset, data)

        required = _parse_required(d.pop("required", UNSET))


        def _parse_reveal(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        reveal = _parse_reveal(d.pop("reveal", UNSET))


        def _parse_template(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        template = _parse_template(d.pop("template", UNSET))


        def _parse_tolerance(data: object) -> None | ToleranceDto | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                tolerance_type_0 = ToleranceDto.from_dict(data)



                return tolerance_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | ToleranceDto | Unset, data)

        tolerance = _parse_tolerance(d.pop("tolerance", UNSET))


        def _parse_tolerances(data: object) -> CheckRequestTolerancesType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                tolerances_type_0 = CheckRequestTolerancesType0.from_dict(data)



                return tolerances_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(CheckRequestTolerancesType0 | None | Unset, data)

        tolerances = _parse_tolerances(d.pop("tolerances", UNSET))


        def _parse_variant(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        variant = _parse_variant(d.pop("variant", UNSET))


        instance_ = cls(
            answers=answers,
            format_=format_,
            job=job,
            kind=kind,
            parameters=parameters,
            request=request,
            required=required,
            reveal=reveal,
            template=template,
            tolerance=tolerance,
            tolerances=tolerances,
            variant=variant,
        )


        instance_.additional_properties = d
        return instance_

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> Any:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
