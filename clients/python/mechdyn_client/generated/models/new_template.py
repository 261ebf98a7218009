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
  from ..models.new_template_derived import NewTemplateDerived
  from ..models.new_template_parameters import NewTemplateParameters
  from ..models.new_template_request import NewTemplateRequest
  from ..models.new_template_statement import NewTemplateStatement





T = TypeVar("T", bound="NewTemplate")



@_attrs_define
class NewTemplate:
    """ The body of `POST /v1/templates`.

        Example:
            {'kind': 'gears', 'name': 'my-gear', 'parameters': {'z': {'description': 'Number of teeth', 'max': 200, 'min':
                12, 'pointer': '/teeth'}}, 'request': {'module': '4 mm', 'teeth': 30}, 'title': 'A spur gear'}

        Attributes:
            kind (str):  Example: flywheel.
            parameters (NewTemplateParameters):
            request (NewTemplateRequest):
            derived (NewTemplateDerived | Unset): Fields of `request` that follow the parameters (see Template).
            distinct (bool | Unset): Variants without repetition (see Template).
            es (InSpanish | None | Unset):
            name (None | str | Unset): A slug (lower-case letters, digits, `-`), unique: the template's id.
            statement (NewTemplateStatement | Unset): The statement's quantities (see Template).
            title (None | str | Unset):
     """

    kind: str
    parameters: NewTemplateParameters
    request: NewTemplateRequest
    derived: NewTemplateDerived | Unset = UNSET
    distinct: bool | Unset = UNSET
    es: InSpanish | None | Unset = UNSET
    name: None | str | Unset = UNSET
    statement: NewTemplateStatement | Unset = UNSET
    title: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.in_spanish import InSpanish # noqa: PLC0415
        from ..models.new_template_derived import NewTemplateDerived # noqa: PLC0415
        from ..models.new_template_parameters import NewTemplateParameters # noqa: PLC0415
        from ..models.new_template_request import NewTemplateRequest # noqa: PLC0415
        from ..models.new_template_statement import NewTemplateStatement # noqa: PLC0415
        kind = self.kind

        parameters = self.parameters.to_dict()

        request = self.request.to_dict()

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

        name: None | str | Unset
        if isinstance(self.name, Unset):
            name = UNSET
        else:
            name = self.name

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
            "kind": kind,
            "parameters": parameters,
            "request": request,
        })
        if derived is not UNSET:
            field_dict["derived"] = derived
        if distinct is not UNSET:
            field_dict["distinct"] = distinct
        if es is not UNSET:
            field_dict["es"] = es
        if name is not UNSET:
            field_dict["name"] = name
        if statement is not UNSET:
            field_dict["statement"] = statement
        if title is not UNSET:
            field_dict["title"] = title

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.in_spanish import InSpanish # noqa: PLC0415
        from ..models.new_template_derived import NewTemplateDerived # noqa: PLC0415
        from ..models.new_template_parameters import NewTemplateParameters # noqa: PLC0415
        from ..models.new_template_request import NewTemplateRequest # noqa: PLC0415
        from ..models.new_template_statement import NewTemplateStatement # noqa: PLC0415
        d = dict(src_dict)
        kind = d.pop("kind")

        parameters = NewTemplateParameters.from_dict(d.pop("parameters"))




        request = NewTemplateRequest.from_dict(d.pop("request"))




        _derived = d.pop("derived", UNSET)
        derived: NewTemplateDerived | Unset
        if isinstance(_derived,  Unset):
            derived = UNSET
        else:
            derived = NewTemplateDerived.from_dict(_derived)




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


        def _parse_name(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        name = _parse_name(d.pop("name", UNSET))


        _statement = d.pop("statement", UNSET)
        statement: NewTemplateStatement | Unset
        if isinstance(_statement,  Unset):
            statement = UNSET
        else:
            statement = NewTemplateStatement.from_dict(_statement)




        def _parse_title(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        title = _parse_title(d.pop("title", UNSET))


        instance_ = cls(
            kind=kind,
            parameters=parameters,
            request=request,
            derived=derived,
            distinct=distinct,
            es=es,
            name=name,
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
