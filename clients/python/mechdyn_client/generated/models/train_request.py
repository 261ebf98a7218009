from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.given_speed import GivenSpeed
  from ..models.given_torque import GivenTorque
  from ..models.mesh_dto import MeshDto





T = TypeVar("T", bound="TrainRequest")



@_attrs_define
class TrainRequest:
    """ Seed 002's differential: sun 1 (60 teeth), planets 3 (30) on carrier 2,
    ring 4 (120, internal); 1 and 2 turn at 100 and 50 rpm, 15 N·m on 1.

        Example:
            {'members': ['1', '2', '3', '4'], 'meshes': [{'a': '1', 'b': '3', 'carrier': '2', 'teeth_a': 60, 'teeth_b': 30},
                {'a': '3', 'b': '4', 'carrier': '2', 'internal': True, 'teeth_a': 30, 'teeth_b': 120}], 'speeds': [{'member':
                '1', 'speed': '100 rpm'}, {'member': '2', 'speed': '50 rpm'}], 'torques': [{'member': '1', 'torque': '15 N*m'}],
                'unknown_torques': ['2', '4']}

        Attributes:
            members (list[str]): Names of the moving members (shafts with their wheels, carriers);
                `ground` is the frame.
            meshes (list[MeshDto]):
            speeds (list[GivenSpeed]): As many as the train has degrees of freedom.
            torques (list[GivenTorque] | None | Unset): Known external torques (default none).
            unknown_torques (list[str] | None | Unset): Members whose external torque keeps the motion steady, as many as
                the
                degrees of freedom (default none: speeds only).
     """

    members: list[str]
    meshes: list[MeshDto]
    speeds: list[GivenSpeed]
    torques: list[GivenTorque] | None | Unset = UNSET
    unknown_torques: list[str] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.given_speed import GivenSpeed # noqa: PLC0415
        from ..models.given_torque import GivenTorque # noqa: PLC0415
        from ..models.mesh_dto import MeshDto # noqa: PLC0415
        members = self.members



        meshes = []
        for meshes_item_data in self.meshes:
            meshes_item = meshes_item_data.to_dict()
            meshes.append(meshes_item)



        speeds = []
        for speeds_item_data in self.speeds:
            speeds_item = speeds_item_data.to_dict()
            speeds.append(speeds_item)



        torques: list[dict[str, Any]] | None | Unset
        if isinstance(self.torques, Unset):
            torques = UNSET
        elif isinstance(self.torques, list):
            torques = []
            for torques_item_data in self.torques:
                torques_item = torques_item_data.to_dict()
                torques.append(torques_item)


        else:
            torques = self.torques

        unknown_torques: list[str] | None | Unset
        if isinstance(self.unknown_torques, Unset):
            unknown_torques = UNSET
        elif isinstance(self.unknown_torques, list):
            unknown_torques = self.unknown_torques


        else:
            unknown_torques = self.unknown_torques


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "members": members,
            "meshes": meshes,
            "speeds": speeds,
        })
        if torques is not UNSET:
            field_dict["torques"] = torques
        if unknown_torques is not UNSET:
            field_dict["unknown_torques"] = unknown_torques

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.given_speed import GivenSpeed # noqa: PLC0415
        from ..models.given_torque import GivenTorque # noqa: PLC0415
        from ..models.mesh_dto import MeshDto # noqa: PLC0415
        d = dict(src_dict)
        members = cast(list[str], d.pop("members"))


        meshes = []
        _meshes = d.pop("meshes")
        for meshes_item_data in (_meshes):
            meshes_item = MeshDto.from_dict(meshes_item_data)



            meshes.append(meshes_item)


        speeds = []
        _speeds = d.pop("speeds")
        for speeds_item_data in (_speeds):
            speeds_item = GivenSpeed.from_dict(speeds_item_data)



            speeds.append(speeds_item)


        def _parse_torques(data: object) -> list[GivenTorque] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                torques_type_0 = []
                _torques_type_0 = data
                for torques_type_0_item_data in (_torques_type_0):
                    torques_type_0_item = GivenTorque.from_dict(torques_type_0_item_data)



                    torques_type_0.append(torques_type_0_item)

                return torques_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[GivenTorque] | None | Unset, data)

        torques = _parse_torques(d.pop("torques", UNSET))


        def _parse_unknown_torques(data: object) -> list[str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                unknown_torques_type_0 = list(data)

                return unknown_torques_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[str] | None | Unset, data)

        unknown_torques = _parse_unknown_torques(d.pop("unknown_torques", UNSET))


        instance_ = cls(
            members=members,
            meshes=meshes,
            speeds=speeds,
            torques=torques,
            unknown_torques=unknown_torques,
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
