from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.variant_parameters import VariantParameters
  from ..models.variant_values import VariantValues





T = TypeVar("T", bound="Variant")



@_attrs_define
class Variant:
    """ One variant with its reference values.

        Attributes:
            error (None | str): Why its job failed, or which values its result does not have (with
                the job's warnings); null when every value is there.
            job (None | str): The reference job, when values were asked for (null otherwise).
            parameters (VariantParameters): The drawn parameters, each in its parameter's unit (those without a range are
                absent: at their defaults).
            values (VariantValues): The values asked for (`values=`), by pointer as given.
            variant (int): Its seed.
     """

    error: None | str
    job: None | str
    parameters: VariantParameters
    values: VariantValues
    variant: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.variant_parameters import VariantParameters # noqa: PLC0415
        from ..models.variant_values import VariantValues # noqa: PLC0415
        error: None | str
        error = self.error

        job: None | str
        job = self.job

        parameters = self.parameters.to_dict()

        values = self.values.to_dict()

        variant = self.variant


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "error": error,
            "job": job,
            "parameters": parameters,
            "values": values,
            "variant": variant,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.variant_parameters import VariantParameters # noqa: PLC0415
        from ..models.variant_values import VariantValues # noqa: PLC0415
        d = dict(src_dict)
        def _parse_error(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        error = _parse_error(d.pop("error"))


        def _parse_job(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        job = _parse_job(d.pop("job"))


        parameters = VariantParameters.from_dict(d.pop("parameters"))




        values = VariantValues.from_dict(d.pop("values"))




        variant = d.pop("variant")

        instance_ = cls(
            error=error,
            job=job,
            parameters=parameters,
            values=values,
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
