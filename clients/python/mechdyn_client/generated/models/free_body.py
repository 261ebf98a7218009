from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.couple import Couple
  from ..models.equations import Equations
  from ..models.force import Force





T = TypeVar("T", bound="FreeBody")



@_attrs_define
class FreeBody:
    """ One body alone, with every action on it.

        Attributes:
            body (str):
            cg (list[float]): Its centre of mass G at the step, m: [x, y], in space [x, y, z].
            couples (list[Couple]):
            equations (Equations): The body's three equations with its actions' numbers (six in space):
                each is zero to rounding.
            forces (list[Force]):
            number (int):
     """

    body: str
    cg: list[float]
    couples: list[Couple]
    equations: Equations
    forces: list[Force]
    number: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.couple import Couple # noqa: PLC0415
        from ..models.equations import Equations # noqa: PLC0415
        from ..models.force import Force # noqa: PLC0415
        body = self.body

        cg = self.cg



        couples = []
        for couples_item_data in self.couples:
            couples_item = couples_item_data.to_dict()
            couples.append(couples_item)



        equations = self.equations.to_dict()

        forces = []
        for forces_item_data in self.forces:
            forces_item = forces_item_data.to_dict()
            forces.append(forces_item)



        number = self.number


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "body": body,
            "cg": cg,
            "couples": couples,
            "equations": equations,
            "forces": forces,
            "number": number,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.couple import Couple # noqa: PLC0415
        from ..models.equations import Equations # noqa: PLC0415
        from ..models.force import Force # noqa: PLC0415
        d = dict(src_dict)
        body = d.pop("body")

        cg = cast(list[float], d.pop("cg"))


        couples = []
        _couples = d.pop("couples")
        for couples_item_data in (_couples):
            couples_item = Couple.from_dict(couples_item_data)



            couples.append(couples_item)


        equations = Equations.from_dict(d.pop("equations"))




        forces = []
        _forces = d.pop("forces")
        for forces_item_data in (_forces):
            forces_item = Force.from_dict(forces_item_data)



            forces.append(forces_item)


        number = d.pop("number")

        instance_ = cls(
            body=body,
            cg=cg,
            couples=couples,
            equations=equations,
            forces=forces,
            number=number,
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
