from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.table_row_parameters import TableRowParameters
  from ..models.table_row_values import TableRowValues





T = TypeVar("T", bound="TableRow")



@_attrs_define
class TableRow:
    """ One variant of a study.

        Attributes:
            parameters (TableRowParameters):
            values (TableRowValues): The values asked for, by pointer (as given).
            error (None | str | Unset): Why this row failed, or which values its job's result does not have
                (with the job's warnings); null when every value is there.
            job (None | str | Unset): The job's id, when it was computed.
     """

    parameters: TableRowParameters
    values: TableRowValues
    error: None | str | Unset = UNSET
    job: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.table_row_parameters import TableRowParameters # noqa: PLC0415
        from ..models.table_row_values import TableRowValues # noqa: PLC0415
        parameters = self.parameters.to_dict()

        values = self.values.to_dict()

        error: None | str | Unset
        if isinstance(self.error, Unset):
            error = UNSET
        else:
            error = self.error

        job: None | str | Unset
        if isinstance(self.job, Unset):
            job = UNSET
        else:
            job = self.job


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "parameters": parameters,
            "values": values,
        })
        if error is not UNSET:
            field_dict["error"] = error
        if job is not UNSET:
            field_dict["job"] = job

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.table_row_parameters import TableRowParameters # noqa: PLC0415
        from ..models.table_row_values import TableRowValues # noqa: PLC0415
        d = dict(src_dict)
        parameters = TableRowParameters.from_dict(d.pop("parameters"))




        values = TableRowValues.from_dict(d.pop("values"))




        def _parse_error(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        error = _parse_error(d.pop("error", UNSET))


        def _parse_job(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        job = _parse_job(d.pop("job", UNSET))


        instance_ = cls(
            parameters=parameters,
            values=values,
            error=error,
            job=job,
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
