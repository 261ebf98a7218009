from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.table_request_rows_item import TableRequestRowsItem





T = TypeVar("T", bound="TableRequest")



@_attrs_define
class TableRequest:
    """ A study as JSON.

        Example:
            {'rows': [{'F': 1000}, {'F': '1.2 kN*m', 'eps': '3 %'}], 'values': ['inertia_exact']}

        Attributes:
            rows (list[TableRequestRowsItem]): One object of parameters per variant (a number in the parameter's unit, or a
                quantity string).
            values (list[str]): JSON pointers into the result of the values to answer.
     """

    rows: list[TableRequestRowsItem]
    values: list[str]





    def to_dict(self) -> dict[str, Any]:
        from ..models.table_request_rows_item import TableRequestRowsItem # noqa: PLC0415
        rows = []
        for rows_item_data in self.rows:
            rows_item = rows_item_data.to_dict()
            rows.append(rows_item)



        values = self.values




        field_dict: dict[str, Any] = {}

        field_dict.update({
            "rows": rows,
            "values": values,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.table_request_rows_item import TableRequestRowsItem # noqa: PLC0415
        d = dict(src_dict)
        rows = []
        _rows = d.pop("rows")
        for rows_item_data in (_rows):
            rows_item = TableRequestRowsItem.from_dict(rows_item_data)



            rows.append(rows_item)


        values = cast(list[str], d.pop("values"))


        instance_ = cls(
            rows=rows,
            values=values,
        )

        return instance_

