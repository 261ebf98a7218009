from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="BodyDto")



@_attrs_define
class BodyDto:
    """ 
        Attributes:
            name (str):
            cg (list[float | str] | None | str | Unset):
            inertia (float | list[float | list[float] | str] | None | str | Unset):
            mass (float | None | str | Unset):
     """

    name: str
    cg: list[float | str] | None | str | Unset = UNSET
    inertia: float | list[float | list[float] | str] | None | str | Unset = UNSET
    mass: float | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        name = self.name

        cg: list[float | str] | None | str | Unset
        if isinstance(self.cg, Unset):
            cg = UNSET
        elif isinstance(self.cg, list):
            cg = []
            for cg_item_data in self.cg:
                cg_item: float | str
                cg_item = cg_item_data
                cg.append(cg_item)


        else:
            cg = self.cg

        inertia: float | list[float | list[float] | str] | None | str | Unset
        if isinstance(self.inertia, Unset):
            inertia = UNSET
        elif isinstance(self.inertia, list):
            inertia = []
            for inertia_item_data in self.inertia:
                inertia_item: float | list[float] | str
                if isinstance(inertia_item_data, list):
                    inertia_item = inertia_item_data


                else:
                    inertia_item = inertia_item_data
                inertia.append(inertia_item)


        else:
            inertia = self.inertia

        mass: float | None | str | Unset
        if isinstance(self.mass, Unset):
            mass = UNSET
        else:
            mass = self.mass


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "name": name,
        })
        if cg is not UNSET:
            field_dict["cg"] = cg
        if inertia is not UNSET:
            field_dict["inertia"] = inertia
        if mass is not UNSET:
            field_dict["mass"] = mass

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        name = d.pop("name")

        def _parse_cg(data: object) -> list[float | str] | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_point_ref_type_1 = []
                _componentsschemas_point_ref_type_1 = data
                for componentsschemas_point_ref_type_1_item_data in (_componentsschemas_point_ref_type_1):
                    def _parse_componentsschemas_point_ref_type_1_item(data: object) -> float | str:
                        return cast(float | str, data)

                    componentsschemas_point_ref_type_1_item = _parse_componentsschemas_point_ref_type_1_item(componentsschemas_point_ref_type_1_item_data)

                    componentsschemas_point_ref_type_1.append(componentsschemas_point_ref_type_1_item)

                return componentsschemas_point_ref_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | str] | None | str | Unset, data)

        cg = _parse_cg(d.pop("cg", UNSET))


        def _parse_inertia(data: object) -> float | list[float | list[float] | str] | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_body_inertia_type_2 = []
                _componentsschemas_body_inertia_type_2 = data
                for componentsschemas_body_inertia_type_2_item_data in (_componentsschemas_body_inertia_type_2):
                    def _parse_componentsschemas_body_inertia_type_2_item(data: object) -> float | list[float] | str:
                        try:
                            if not isinstance(data, list):
                                raise TypeError()
                            componentsschemas_body_inertia_type_2_item_type_2 = list(data)

                            return componentsschemas_body_inertia_type_2_item_type_2
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        return cast(float | list[float] | str, data)

                    componentsschemas_body_inertia_type_2_item = _parse_componentsschemas_body_inertia_type_2_item(componentsschemas_body_inertia_type_2_item_data)

                    componentsschemas_body_inertia_type_2.append(componentsschemas_body_inertia_type_2_item)

                return componentsschemas_body_inertia_type_2
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float | list[float] | str] | None | str | Unset, data)

        inertia = _parse_inertia(d.pop("inertia", UNSET))


        def _parse_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        mass = _parse_mass(d.pop("mass", UNSET))


        instance_ = cls(
            name=name,
            cg=cg,
            inertia=inertia,
            mass=mass,
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
