from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.mechanism_space import MechanismSpace
from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.body_dto import BodyDto
  from ..models.dimension_dto import DimensionDto
  from ..models.joint_dto import JointDto
  from ..models.mechanism_dto_points_type_0 import MechanismDtoPointsType0





T = TypeVar("T", bound="MechanismDto")



@_attrs_define
class MechanismDto:
    """ A mechanism drawn in one assembled configuration, planar (see the
    example of KinetostaticsRequest) or, with `"space": "spatial"`, in
    three dimensions.

        Attributes:
            bodies (list[BodyDto]):
            joints (list[JointDto]):
            dimensions (list[DimensionDto] | None | Unset): The statement's dimensions: `points` are then a sketch, moved as
                little as they can be (a point that cannot move — a pivot with the
                ground, a point of no moving body — weighs 10⁶ times another, and
                the sketch picks the branch) until every dimension holds; a body's
                `cg` given as [x, y] moves with its body; the result's
                `assembled_points` says where the points went.
            gravity (list[float] | None | Unset): Gravitational acceleration [gx, gy] (in space [gx, gy, gz]), m/s² (default
                none).
            points (MechanismDtoPointsType0 | None | Unset): Named points in the drawn configuration: `{NAME: [x, y]}` (in
                space
                `[x, y, z]`), each coordinate in m or a length with its unit (`"8 cm"`).
            space (MechanismSpace | None | Unset):
     """

    bodies: list[BodyDto]
    joints: list[JointDto]
    dimensions: list[DimensionDto] | None | Unset = UNSET
    gravity: list[float] | None | Unset = UNSET
    points: MechanismDtoPointsType0 | None | Unset = UNSET
    space: MechanismSpace | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.body_dto import BodyDto # noqa: PLC0415
        from ..models.dimension_dto import DimensionDto # noqa: PLC0415
        from ..models.joint_dto import JointDto # noqa: PLC0415
        from ..models.mechanism_dto_points_type_0 import MechanismDtoPointsType0 # noqa: PLC0415
        bodies = []
        for bodies_item_data in self.bodies:
            bodies_item = bodies_item_data.to_dict()
            bodies.append(bodies_item)



        joints = []
        for joints_item_data in self.joints:
            joints_item = joints_item_data.to_dict()
            joints.append(joints_item)



        dimensions: list[dict[str, Any]] | None | Unset
        if isinstance(self.dimensions, Unset):
            dimensions = UNSET
        elif isinstance(self.dimensions, list):
            dimensions = []
            for dimensions_item_data in self.dimensions:
                dimensions_item = dimensions_item_data.to_dict()
                dimensions.append(dimensions_item)


        else:
            dimensions = self.dimensions

        gravity: list[float] | None | Unset
        if isinstance(self.gravity, Unset):
            gravity = UNSET
        elif isinstance(self.gravity, list):
            gravity = self.gravity


        else:
            gravity = self.gravity

        points: dict[str, Any] | None | Unset
        if isinstance(self.points, Unset):
            points = UNSET
        elif isinstance(self.points, MechanismDtoPointsType0):
            points = self.points.to_dict()
        else:
            points = self.points

        space: None | str | Unset
        if isinstance(self.space, Unset):
            space = UNSET
        elif isinstance(self.space, MechanismSpace):
            space = self.space.value
        else:
            space = self.space


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "bodies": bodies,
            "joints": joints,
        })
        if dimensions is not UNSET:
            field_dict["dimensions"] = dimensions
        if gravity is not UNSET:
            field_dict["gravity"] = gravity
        if points is not UNSET:
            field_dict["points"] = points
        if space is not UNSET:
            field_dict["space"] = space

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.body_dto import BodyDto # noqa: PLC0415
        from ..models.dimension_dto import DimensionDto # noqa: PLC0415
        from ..models.joint_dto import JointDto # noqa: PLC0415
        from ..models.mechanism_dto_points_type_0 import MechanismDtoPointsType0 # noqa: PLC0415
        d = dict(src_dict)
        bodies = []
        _bodies = d.pop("bodies")
        for bodies_item_data in (_bodies):
            bodies_item = BodyDto.from_dict(bodies_item_data)



            bodies.append(bodies_item)


        joints = []
        _joints = d.pop("joints")
        for joints_item_data in (_joints):
            joints_item = JointDto.from_dict(joints_item_data)



            joints.append(joints_item)


        def _parse_dimensions(data: object) -> list[DimensionDto] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                dimensions_type_0 = []
                _dimensions_type_0 = data
                for dimensions_type_0_item_data in (_dimensions_type_0):
                    dimensions_type_0_item = DimensionDto.from_dict(dimensions_type_0_item_data)



                    dimensions_type_0.append(dimensions_type_0_item)

                return dimensions_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[DimensionDto] | None | Unset, data)

        dimensions = _parse_dimensions(d.pop("dimensions", UNSET))


        def _parse_gravity(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                gravity_type_0 = list(data)

                return gravity_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        gravity = _parse_gravity(d.pop("gravity", UNSET))


        def _parse_points(data: object) -> MechanismDtoPointsType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                points_type_0 = MechanismDtoPointsType0.from_dict(data)



                return points_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(MechanismDtoPointsType0 | None | Unset, data)

        points = _parse_points(d.pop("points", UNSET))


        def _parse_space(data: object) -> MechanismSpace | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                space_type_0 = MechanismSpace(data)



                return space_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(MechanismSpace | None | Unset, data)

        space = _parse_space(d.pop("space", UNSET))


        instance_ = cls(
            bodies=bodies,
            joints=joints,
            dimensions=dimensions,
            gravity=gravity,
            points=points,
            space=space,
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
