from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.correction_plane_dto import CorrectionPlaneDto
  from ..models.point_mass_dto import PointMassDto
  from ..models.rotor_request import RotorRequest





T = TypeVar("T", bound="BalancingRequest")



@_attrs_define
class BalancingRequest:
    """ A rigid rotor turning about z: its unbalance as point masses (`masses`)
    or as a rotor request's body (`rotor`, its x' axis the rotor's z), and
    one correction plane (static balancing) or two (dynamic). With `speed`
    and `bearings` (or the rotor's own frame speed and bearings) the
    bearing forces before and after balancing.

        Example:
            {'bearings': ['-50 mm', '450 mm'], 'masses': [{'angle': '30 deg', 'mass': '0.2 kg', 'plane': '50 mm', 'radius':
                '100 mm'}, {'angle': '150 deg', 'mass': '0.15 kg', 'plane': '200 mm', 'radius': '80 mm'}, {'angle': '270 deg',
                'mass': '0.1 kg', 'plane': '350 mm', 'radius': '120 mm'}], 'planes': [{'radius': '100 mm', 'z': '0 mm'},
                {'radius': '100 mm', 'z': '400 mm'}], 'speed': '1500 rpm'}

        Attributes:
            planes (list[CorrectionPlaneDto]): One plane (static balancing) or two (dynamic), in any order.
            bearings (list[float | str] | None | Unset): z of bearings A and B (default: the rotor's bearings).
            masses (list[PointMassDto] | None | Unset): Point masses (not with `rotor`), at most 1000.
            rotor (None | RotorRequest | Unset):
            speed (float | None | str | Unset):
     """

    planes: list[CorrectionPlaneDto]
    bearings: list[float | str] | None | Unset = UNSET
    masses: list[PointMassDto] | None | Unset = UNSET
    rotor: None | RotorRequest | Unset = UNSET
    speed: float | None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.correction_plane_dto import CorrectionPlaneDto # noqa: PLC0415
        from ..models.point_mass_dto import PointMassDto # noqa: PLC0415
        from ..models.rotor_request import RotorRequest # noqa: PLC0415
        planes = []
        for planes_item_data in self.planes:
            planes_item = planes_item_data.to_dict()
            planes.append(planes_item)



        bearings: list[float | str] | None | Unset
        if isinstance(self.bearings, Unset):
            bearings = UNSET
        elif isinstance(self.bearings, list):
            bearings = []
            for bearings_item_data in self.bearings:
                bearings_item: float | str
                bearings_item = bearings_item_data
                bearings.append(bearings_item)


        else:
            bearings = self.bearings

        masses: list[dict[str, Any]] | None | Unset
        if isinstance(self.masses, Unset):
            masses = UNSET
        elif isinstance(self.masses, list):
            masses = []
            for masses_item_data in self.masses:
                masses_item = masses_item_data.to_dict()
                masses.append(masses_item)


        else:
            masses = self.masses

        rotor: dict[str, Any] | None | Unset
        if isinstance(self.rotor, Unset):
            rotor = UNSET
        elif isinstance(self.rotor, RotorRequest):
            rotor = self.rotor.to_dict()
        else:
            rotor = self.rotor

        speed: float | None | str | Unset
        if isinstance(self.speed, Unset):
            speed = UNSET
        else:
            speed = self.speed


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "planes": planes,
        })
        if bearings is not UNSET:
            field_dict["bearings"] = bearings
        if masses is not UNSET:
            field_dict["masses"] = masses
        if rotor is not UNSET:
            field_dict["rotor"] = rotor
        if speed is not UNSET:
            field_dict["speed"] = speed

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.correction_plane_dto import CorrectionPlaneDto # noqa: PLC0415
        from ..models.point_mass_dto import PointMassDto # noqa: PLC0415
        from ..models.rotor_request import RotorRequest # noqa: PLC0415
        d = dict(src_dict)
        planes = []
        _planes = d.pop("planes")
        for planes_item_data in (_planes):
            planes_item = CorrectionPlaneDto.from_dict(planes_item_data)



            planes.append(planes_item)


        def _parse_bearings(data: object) -> list[float | str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                bearings_type_0 = []
                _bearings_type_0 = data
                for bearings_type_0_item_data in (_bearings_type_0):
                    def _parse_bearings_type_0_item(data: object) -> float | str:
                        return cast(float | str, data)

                    bearings_type_0_item = _parse_bearings_type_0_item(bearings_type_0_item_data)

                    bearings_type_0.append(bearings_type_0_item)

                return bearings_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | str] | None | Unset, data)

        bearings = _parse_bearings(d.pop("bearings", UNSET))


        def _parse_masses(data: object) -> list[PointMassDto] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                masses_type_0 = []
                _masses_type_0 = data
                for masses_type_0_item_data in (_masses_type_0):
                    masses_type_0_item = PointMassDto.from_dict(masses_type_0_item_data)



                    masses_type_0.append(masses_type_0_item)

                return masses_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[PointMassDto] | None | Unset, data)

        masses = _parse_masses(d.pop("masses", UNSET))


        def _parse_rotor(data: object) -> None | RotorRequest | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                rotor_type_0 = RotorRequest.from_dict(data)



                return rotor_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | RotorRequest | Unset, data)

        rotor = _parse_rotor(d.pop("rotor", UNSET))


        def _parse_speed(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        speed = _parse_speed(d.pop("speed", UNSET))


        instance_ = cls(
            planes=planes,
            bearings=bearings,
            masses=masses,
            rotor=rotor,
            speed=speed,
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
