from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.in_spanish_parameters import InSpanishParameters
  from ..models.in_spanish_statement import InSpanishStatement





T = TypeVar("T", bound="InSpanish")



@_attrs_define
class InSpanish:
    """ A template's texts in Spanish (each optional: the English stands in).

        Attributes:
            parameters (InSpanishParameters | Unset): A description per parameter, by its name.
            source (None | str | Unset):
            statement (InSpanishStatement | Unset): A description per statement quantity, by its name.
            title (None | str | Unset):
     """

    parameters: InSpanishParameters | Unset = UNSET
    source: None | str | Unset = UNSET
    statement: InSpanishStatement | Unset = UNSET
    title: None | str | Unset = UNSET





    def to_dict(self) -> dict[str, Any]:
        from ..models.in_spanish_parameters import InSpanishParameters # noqa: PLC0415
        from ..models.in_spanish_statement import InSpanishStatement # noqa: PLC0415
        parameters: dict[str, Any] | Unset = UNSET
        if not isinstance(self.parameters, Unset):
            parameters = self.parameters.to_dict()

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

        field_dict.update({
        })
        if parameters is not UNSET:
            field_dict["parameters"] = parameters
        if source is not UNSET:
            field_dict["source"] = source
        if statement is not UNSET:
            field_dict["statement"] = statement
        if title is not UNSET:
            field_dict["title"] = title

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.in_spanish_parameters import InSpanishParameters # noqa: PLC0415
        from ..models.in_spanish_statement import InSpanishStatement # noqa: PLC0415
        d = dict(src_dict)
        _parameters = d.pop("parameters", UNSET)
        parameters: InSpanishParameters | Unset
        if isinstance(_parameters,  Unset):
            parameters = UNSET
        else:
            parameters = InSpanishParameters.from_dict(_parameters)




        def _parse_source(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        source = _parse_source(d.pop("source", UNSET))


        _statement = d.pop("statement", UNSET)
        statement: InSpanishStatement | Unset
        if isinstance(_statement,  Unset):
            statement = UNSET
        else:
            statement = InSpanishStatement.from_dict(_statement)




        def _parse_title(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        title = _parse_title(d.pop("title", UNSET))


        instance_ = cls(
            parameters=parameters,
            source=source,
            statement=statement,
            title=title,
        )

        return instance_

