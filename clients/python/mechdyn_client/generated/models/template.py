from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.in_spanish import InSpanish
  from ..models.template_derived import TemplateDerived
  from ..models.template_parameters import TemplateParameters
  from ..models.template_request import TemplateRequest
  from ..models.template_statement import TemplateStatement





T = TypeVar("T", bound="Template")



@_attrs_define
class Template:
    """ A problem with parameters.

        Attributes:
            id (str): The template's name (a slug) or a random UUID. Example: p103-slider-flywheel.
            kind (str): The kind of job it gives, e.g. `flywheel`.
            parameters (TemplateParameters):
            request (TemplateRequest): A complete, valid request of that kind.
            builtin (bool | Unset): Shipped with the service (true) or created by a client.
            derived (TemplateDerived | Unset): Fields of `request` that follow the parameters: `{pointer:
                expression}`, each expression of the parameters' names (their values
                in SI), e.g. a bar's inertia `"m*1^2/12"` as its mass m changes.
            distinct (bool | Unset): Variants drawn without repetition: variant v is the (v mod M)-th of
                a fixed shuffle of the M combinations of the parameters' values, so
                any M consecutive variants differ (the generator is written down in
                the service's `engine/variants.rs`). Default false: each parameter
                drawn on its own, as before.
            es (InSpanish | None | Unset):
            source (None | str | Unset): Where the problem comes from (built-in templates).
            statement (TemplateStatement | Unset): The statement's quantities, by name: where the statement prints a
                magnitude (a resisting torque C_r), the field it comes from and its
                sign, so that `/statement/NAME` of the template's job is that number
                as printed (see [`Stated`]).
            title (None | str | Unset):
     """

    id: str
    kind: str
    parameters: TemplateParameters
    request: TemplateRequest
    builtin: bool | Unset = UNSET
    derived: TemplateDerived | Unset = UNSET
    distinct: bool | Unset = UNSET
    es: InSpanish | None | Unset = UNSET
    source: None | str | Unset = UNSET
    statement: TemplateStatement | Unset = UNSET
    title: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.in_spanish import InSpanish # noqa: PLC0415
        from ..models.template_derived import TemplateDerived # noqa: PLC0415
        from ..models.template_parameters import TemplateParameters # noqa: PLC0415
        from ..models.template_request import TemplateRequest # noqa: PLC0415
        from ..models.template_statement import TemplateStatement # noqa: PLC0415
        id = self.id

        kind = self.kind

        parameters = self.parameters.to_dict()

        request = self.request.to_dict()

        builtin = self.builtin

        derived: dict[str, Any] | Unset = UNSET
        if not isinstance(self.derived, Unset):
            derived = self.derived.to_dict()

        distinct = self.distinct

        es: dict[str, Any] | None | Unset
        if isinstance(self.es, Unset):
            es = UNSET
        elif isinstance(self.es, InSpanish):
            es = self.es.to_dict()
        else:
            es = self.es

        source: None | str | Unset
        if isinstance(self.source, Unset):
            source = UNSET
        else:
            source = self.source

        statement: dict[str, Any] | Unset = UNSET
        if not isinstance(self.statement, Unset):
            statement = self.statement.to_dict()

        title: None | str | Unset
        if isinstance(self.title, Unset):
            title = UNSET
        else:
            title = self.title


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "id": id,
            "kind": kind,
            "parameters": parameters,
            "request": request,
        })
        if builtin is not UNSET:
            field_dict["builtin"] = builtin
        if derived is not UNSET:
            field_dict["derived"] = derived
        if distinct is not UNSET:
            field_dict["distinct"] = distinct
        if es is not UNSET:
            field_dict["es"] = es
        if source is not UNSET:
            field_dict["source"] = source
        if statement is not UNSET:
            field_dict["statement"] = statement
        if title is not UNSET:
            field_dict["title"] = title

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.in_spanish import InSpanish # noqa: PLC0415
        from ..models.template_derived import TemplateDerived # noqa: PLC0415
        from ..models.template_parameters import TemplateParameters # noqa: PLC0415
        from ..models.template_request import TemplateRequest # noqa: PLC0415
        from ..models.template_statement import TemplateStatement # noqa: PLC0415
        d = dict(src_dict)
        id = d.pop("id")

        kind = d.pop("kind")

        parameters = TemplateParameters.from_dict(d.pop("parameters"))




        request = TemplateRequest.from_dict(d.pop("request"))




        builtin = d.pop("builtin", UNSET)

        _derived = d.pop("derived", UNSET)
        derived: TemplateDerived | Unset
        if isinstance(_derived,  Unset):
            derived = UNSET
        else:
            derived = TemplateDerived.from_dict(_derived)




        distinct = d.pop("distinct", UNSET)

        def _parse_es(data: object) -> InSpanish | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                es_type_0 = InSpanish.from_dict(data)



                return es_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(InSpanish | None | Unset, data)

        es = _parse_es(d.pop("es", UNSET))


        def _parse_source(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        source = _parse_source(d.pop("source", UNSET))


        _statement = d.pop("statement", UNSET)
        statement: TemplateStatement | Unset
        if isinstance(_statement,  Unset):
            statement = UNSET
        else:
            statement = TemplateStatement.from_dict(_statement)




        def _parse_title(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        title = _parse_title(d.pop("title", UNSET))


        instance_ = cls(
            id=id,
            kind=kind,
            parameters=parameters,
            request=request,
            builtin=builtin,
            derived=derived,
            distinct=distinct,
            es=es,
            source=source,
            statement=statement,
            title=title,
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
