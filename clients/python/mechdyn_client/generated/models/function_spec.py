from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.interpolation_dto import InterpolationDto
from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.segment_dto import SegmentDto
  from ..models.table_dto import TableDto





T = TypeVar("T", bound="FunctionSpec")



@_attrs_define
class FunctionSpec:
    """ The object form of a function: exactly one of `expr`, `segments`, `table`.

        Attributes:
            angle_unit (None | str | Unset): Unit of a table's angles given as numbers (default rad), e.g. "deg".
            csv (None | str | Unset): The table as CSV text: two columns, angle and value, an optional
                header row (`,`, `;` or tab between columns; a decimal comma with `;`). Example: phi_deg,torque
                0,0
                90,-500
                180,0
                270,0.
            expr (None | str | Unset):  Example: 500/pi - 500*sin(phi).
            interpolation (InterpolationDto | None | Unset):
            segments (list[SegmentDto] | None | Unset):
            table (None | TableDto | Unset):
            unit (None | str | Unset): Unit of the values (default SI), e.g. "ft*lbf".
     """

    angle_unit: None | str | Unset = UNSET
    csv: None | str | Unset = UNSET
    expr: None | str | Unset = UNSET
    interpolation: InterpolationDto | None | Unset = UNSET
    segments: list[SegmentDto] | None | Unset = UNSET
    table: None | TableDto | Unset = UNSET
    unit: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.segment_dto import SegmentDto # noqa: PLC0415
        from ..models.table_dto import TableDto # noqa: PLC0415
        angle_unit: None | str | Unset
        if isinstance(self.angle_unit, Unset):
            angle_unit = UNSET
        else:
            angle_unit = self.angle_unit

        csv: None | str | Unset
        if isinstance(self.csv, Unset):
            csv = UNSET
        else:
            csv = self.csv

        expr: None | str | Unset
        if isinstance(self.expr, Unset):
            expr = UNSET
        else:
            expr = self.expr

        interpolation: None | str | Unset
        if isinstance(self.interpolation, Unset):
            interpolation = UNSET
        elif isinstance(self.interpolation, InterpolationDto):
            interpolation = self.interpolation.value
        else:
            interpolation = self.interpolation

        segments: list[dict[str, Any]] | None | Unset
        if isinstance(self.segments, Unset):
            segments = UNSET
        elif isinstance(self.segments, list):
            segments = []
            for segments_item_data in self.segments:
                segments_item = segments_item_data.to_dict()
                segments.append(segments_item)


        else:
            segments = self.segments

        table: dict[str, Any] | None | Unset
        if isinstance(self.table, Unset):
            table = UNSET
        elif isinstance(self.table, TableDto):
            table = self.table.to_dict()
        else:
            table = self.table

        unit: None | str | Unset
        if isinstance(self.unit, Unset):
            unit = UNSET
        else:
            unit = self.unit


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
        })
        if angle_unit is not UNSET:
            field_dict["angle_unit"] = angle_unit
        if csv is not UNSET:
            field_dict["csv"] = csv
        if expr is not UNSET:
            field_dict["expr"] = expr
        if interpolation is not UNSET:
            field_dict["interpolation"] = interpolation
        if segments is not UNSET:
            field_dict["segments"] = segments
        if table is not UNSET:
            field_dict["table"] = table
        if unit is not UNSET:
            field_dict["unit"] = unit

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.segment_dto import SegmentDto # noqa: PLC0415
        from ..models.table_dto import TableDto # noqa: PLC0415
        d = dict(src_dict)
        def _parse_angle_unit(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        angle_unit = _parse_angle_unit(d.pop("angle_unit", UNSET))


        def _parse_csv(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        csv = _parse_csv(d.pop("csv", UNSET))


        def _parse_expr(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        expr = _parse_expr(d.pop("expr", UNSET))


        def _parse_interpolation(data: object) -> InterpolationDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                interpolation_type_0 = InterpolationDto(data)



                return interpolation_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(InterpolationDto | None | Unset, data)

        interpolation = _parse_interpolation(d.pop("interpolation", UNSET))


        def _parse_segments(data: object) -> list[SegmentDto] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                segments_type_0 = []
                _segments_type_0 = data
                for segments_type_0_item_data in (_segments_type_0):
                    segments_type_0_item = SegmentDto.from_dict(segments_type_0_item_data)



                    segments_type_0.append(segments_type_0_item)

                return segments_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[SegmentDto] | None | Unset, data)

        segments = _parse_segments(d.pop("segments", UNSET))


        def _parse_table(data: object) -> None | TableDto | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                table_type_0 = TableDto.from_dict(data)



                return table_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TableDto | Unset, data)

        table = _parse_table(d.pop("table", UNSET))


        def _parse_unit(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        unit = _parse_unit(d.pop("unit", UNSET))


        instance_ = cls(
            angle_unit=angle_unit,
            csv=csv,
            expr=expr,
            interpolation=interpolation,
            segments=segments,
            table=table,
            unit=unit,
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
