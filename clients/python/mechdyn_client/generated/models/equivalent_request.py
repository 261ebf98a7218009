from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.equivalent_request_points import EquivalentRequestPoints





T = TypeVar("T", bound="EquivalentRequest")



@_attrs_define
class EquivalentRequest:
    """ A link (mass, inertia about its centre of mass G, G) and the points where
    the masses go (at most 20; include G itself for the three-mass bar).

        Example:
            {'cg': [0.2, 0], 'inertia': 0.09, 'mass': 3, 'points': {'A': [0, 0], 'B': [0.6, 0], 'G': [0.2, 0]}}

        Attributes:
            cg (list[float]): G, m.
            inertia (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            mass (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            points (EquivalentRequestPoints): Named points, m.
     """

    cg: list[float]
    inertia: float | str
    mass: float | str
    points: EquivalentRequestPoints
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.equivalent_request_points import EquivalentRequestPoints # noqa: PLC0415
        cg = self.cg



        inertia: float | str
        inertia = self.inertia

        mass: float | str
        mass = self.mass

        points = self.points.to_dict()


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "cg": cg,
            "inertia": inertia,
            "mass": mass,
            "points": points,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.equivalent_request_points import EquivalentRequestPoints # noqa: PLC0415
        d = dict(src_dict)
        cg = cast(list[float], d.pop("cg"))


        def _parse_inertia(data: object) -> float | str:
            return cast(float | str, data)

        inertia = _parse_inertia(d.pop("inertia"))


        def _parse_mass(data: object) -> float | str:
            return cast(float | str, data)

        mass = _parse_mass(d.pop("mass"))


        points = EquivalentRequestPoints.from_dict(d.pop("points"))




        instance_ = cls(
            cg=cg,
            inertia=inertia,
            mass=mass,
            points=points,
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
