from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.input_dto import InputDto
  from ..models.load_dto import LoadDto
  from ..models.mechanism_dto import MechanismDto





T = TypeVar("T", bound="MachineDto")



@_attrs_define
class MachineDto:
    """ A driven mechanism with its loads, as in kinetostatics, in the plane or
    in space (`"space": "spatial"`: the input a revolute's rotation or a
    cylindrical's). The input's `speed`, `start`, `end` and `steps` do not
    apply: the flywheel's mean speed and period rule.

        Attributes:
            input_ (InputDto): An input coordinate and its range: a driven joint, or where the
                statement puts the motion (a point along a direction, a body's rotation).
            mechanism (MechanismDto): A mechanism drawn in one assembled configuration, planar (see the
                example of KinetostaticsRequest) or, with `"space": "spatial"`, in
                three dimensions.
            loads (list[LoadDto] | None | Unset):
     """

    input_: InputDto
    mechanism: MechanismDto
    loads: list[LoadDto] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.input_dto import InputDto # noqa: PLC0415
        from ..models.load_dto import LoadDto # noqa: PLC0415
        from ..models.mechanism_dto import MechanismDto # noqa: PLC0415
        input_ = self.input_.to_dict()

        mechanism = self.mechanism.to_dict()

        loads: list[dict[str, Any]] | None | Unset
        if isinstance(self.loads, Unset):
            loads = UNSET
        elif isinstance(self.loads, list):
            loads = []
            for loads_item_data in self.loads:
                loads_item = loads_item_data.to_dict()
                loads.append(loads_item)


        else:
            loads = self.loads


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "input": input_,
            "mechanism": mechanism,
        })
        if loads is not UNSET:
            field_dict["loads"] = loads

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.input_dto import InputDto # noqa: PLC0415
        from ..models.load_dto import LoadDto # noqa: PLC0415
        from ..models.mechanism_dto import MechanismDto # noqa: PLC0415
        d = dict(src_dict)
        input_ = InputDto.from_dict(d.pop("input"))




        mechanism = MechanismDto.from_dict(d.pop("mechanism"))




        def _parse_loads(data: object) -> list[LoadDto] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                loads_type_0 = []
                _loads_type_0 = data
                for loads_type_0_item_data in (_loads_type_0):
                    loads_type_0_item = LoadDto.from_dict(loads_type_0_item_data)



                    loads_type_0.append(loads_type_0_item)

                return loads_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[LoadDto] | None | Unset, data)

        loads = _parse_loads(d.pop("loads", UNSET))


        instance_ = cls(
            input_=input_,
            mechanism=mechanism,
            loads=loads,
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
