from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="ContactDto")



@_attrs_define
class ContactDto:
    """ A contact joint at a step: where its curves touch and what passes there.

        Attributes:
            curvature_radius (list[float | None]): Each curve's radius of curvature there (m; signed as the curve
                turns; null: straight, or a point).
            joint (str):
            normal (float): The first body's force on the second along the normal (N ≥ 0 pressing).
            point (list[float]): [x, y] (m), ground frame.
            sliding_velocity (float): (v₂ − v₁)·t of the material points at the contact (m/s): 0 rolling.
            tangential (float): ... and along the common tangent (N).
            velocities (list[list[float]]): The velocity (m/s, [vx, vy]) of the material point at the contact
                of each body: the first's, then the second's.
            jumped (bool | Unset): The contact jumped here from far off where it was followed to:
                another lobe (a warning says where).
            off_end (bool | Unset): The contact ran off the end of an open curve here (a warning says where).
            overlap (bool | Unset): The curves overlap around the contact here (a flat face on a concave
                stretch, a roller in a tighter hollow): the bodies would touch
                elsewhere, at another lobe (a warning says where).
            penetration (float | None | Unset): The bodies cut into each other here, away from the contact, this
                deep (m): the contact the equations follow cannot be, and none
                outside both bodies was found (a warning says where). Absent where
                they only touch.
            pressure_angle (float | None | Unset): The angle between the normal and the follower's velocity there (rad),
                where the second body turns or slides on the ground.
            state (None | str | Unset): Direct dynamics, a rolling contact with friction: "rolling" or
                "slipping" at this instant.
     """

    curvature_radius: list[float | None]
    joint: str
    normal: float
    point: list[float]
    sliding_velocity: float
    tangential: float
    velocities: list[list[float]]
    jumped: bool | Unset = UNSET
    off_end: bool | Unset = UNSET
    overlap: bool | Unset = UNSET
    penetration: float | None | Unset = UNSET
    pressure_angle: float | None | Unset = UNSET
    state: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        curvature_radius = []
        for curvature_radius_item_data in self.curvature_radius:
            curvature_radius_item: float | None
            curvature_radius_item = curvature_radius_item_data
            curvature_radius.append(curvature_radius_item)



        joint = self.joint

        normal = self.normal

        point = self.point



        sliding_velocity = self.sliding_velocity

        tangential = self.tangential

        velocities = []
        for velocities_item_data in self.velocities:
            velocities_item = velocities_item_data


            velocities.append(velocities_item)



        jumped = self.jumped

        off_end = self.off_end

        overlap = self.overlap

        penetration: float | None | Unset
        if isinstance(self.penetration, Unset):
            penetration = UNSET
        else:
            penetration = self.penetration

        pressure_angle: float | None | Unset
        if isinstance(self.pressure_angle, Unset):
            pressure_angle = UNSET
        else:
            pressure_angle = self.pressure_angle

        state: None | str | Unset
        if isinstance(self.state, Unset):
            state = UNSET
        else:
            state = self.state


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "curvature_radius": curvature_radius,
            "joint": joint,
            "normal": normal,
            "point": point,
            "sliding_velocity": sliding_velocity,
            "tangential": tangential,
            "velocities": velocities,
        })
        if jumped is not UNSET:
            field_dict["jumped"] = jumped
        if off_end is not UNSET:
            field_dict["off_end"] = off_end
        if overlap is not UNSET:
            field_dict["overlap"] = overlap
        if penetration is not UNSET:
            field_dict["penetration"] = penetration
        if pressure_angle is not UNSET:
            field_dict["pressure_angle"] = pressure_angle
        if state is not UNSET:
            field_dict["state"] = state

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        curvature_radius = []
        _curvature_radius = d.pop("curvature_radius")
        for curvature_radius_item_data in (_curvature_radius):
            def _parse_curvature_radius_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            curvature_radius_item = _parse_curvature_radius_item(curvature_radius_item_data)

            curvature_radius.append(curvature_radius_item)


        joint = d.pop("joint")

        normal = d.pop("normal")

        point = cast(list[float], d.pop("point"))


        sliding_velocity = d.pop("sliding_velocity")

        tangential = d.pop("tangential")

        velocities = []
        _velocities = d.pop("velocities")
        for velocities_item_data in (_velocities):
            velocities_item = cast(list[float], velocities_item_data)

            velocities.append(velocities_item)


        jumped = d.pop("jumped", UNSET)

        off_end = d.pop("off_end", UNSET)

        overlap = d.pop("overlap", UNSET)

        def _parse_penetration(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        penetration = _parse_penetration(d.pop("penetration", UNSET))


        def _parse_pressure_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        pressure_angle = _parse_pressure_angle(d.pop("pressure_angle", UNSET))


        def _parse_state(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        state = _parse_state(d.pop("state", UNSET))


        instance_ = cls(
            curvature_radius=curvature_radius,
            joint=joint,
            normal=normal,
            point=point,
            sliding_velocity=sliding_velocity,
            tangential=tangential,
            velocities=velocities,
            jumped=jumped,
            off_end=off_end,
            overlap=overlap,
            penetration=penetration,
            pressure_angle=pressure_angle,
            state=state,
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
