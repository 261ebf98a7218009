from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="CamSample")



@_attrs_define
class CamSample:
    """ 
        Attributes:
            acceleration (float): s″ω², m/s².
            curvature_radius (float): The profile's radius of curvature (m; > 0 convex, < 0 concave).
            d2lift (float):
            d3lift (float):
            dlift (float): s′ = ds/dθ, m/rad.
            jerk (float): s‴ω³, m/s³.
            lift (float): s, m.
            pitch_point (list[float]): [x, y] (m) in the cam's frame (x: the follower's direction at θ = 0):
                a roller's centre, a knife's edge, a flat face's point on its axis.
            pressure_angle (float): rad (0 for a flat face), signed.
            profile_point (list[float]): The contact point on the profile, [x, y] (m) in the cam's frame.
            theta (float): Cam angle, rad.
            velocity (float): s′ω, m/s.
            cam_torque (float | None | Unset): With `dynamics`: the torque that turns the cam at `speed` (N·m).
            contact_force (float | None | Unset): With `dynamics`: the force between cam and follower (N; < 0: they would
                separate).
            pitch_curvature_radius (float | None | Unset): A roller's pitch curve's radius of curvature (m).
     """

    acceleration: float
    curvature_radius: float
    d2lift: float
    d3lift: float
    dlift: float
    jerk: float
    lift: float
    pitch_point: list[float]
    pressure_angle: float
    profile_point: list[float]
    theta: float
    velocity: float
    cam_torque: float | None | Unset = UNSET
    contact_force: float | None | Unset = UNSET
    pitch_curvature_radius: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        acceleration = self.acceleration

        curvature_radius = self.curvature_radius

        d2lift = self.d2lift

        d3lift = self.d3lift

        dlift = self.dlift

        jerk = self.jerk

        lift = self.lift

        pitch_point = self.pitch_point



        pressure_angle = self.pressure_angle

        profile_point = self.profile_point



        theta = self.theta

        velocity = self.velocity

        cam_torque: float | None | Unset
        if isinstance(self.cam_torque, Unset):
            cam_torque = UNSET
        else:
            cam_torque = self.cam_torque

        contact_force: float | None | Unset
        if isinstance(self.contact_force, Unset):
            contact_force = UNSET
        else:
            contact_force = self.contact_force

        pitch_curvature_radius: float | None | Unset
        if isinstance(self.pitch_curvature_radius, Unset):
            pitch_curvature_radius = UNSET
        else:
            pitch_curvature_radius = self.pitch_curvature_radius


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "acceleration": acceleration,
            "curvature_radius": curvature_radius,
            "d2lift": d2lift,
            "d3lift": d3lift,
            "dlift": dlift,
            "jerk": jerk,
            "lift": lift,
            "pitch_point": pitch_point,
            "pressure_angle": pressure_angle,
            "profile_point": profile_point,
            "theta": theta,
            "velocity": velocity,
        })
        if cam_torque is not UNSET:
            field_dict["cam_torque"] = cam_torque
        if contact_force is not UNSET:
            field_dict["contact_force"] = contact_force
        if pitch_curvature_radius is not UNSET:
            field_dict["pitch_curvature_radius"] = pitch_curvature_radius

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        acceleration = d.pop("acceleration")

        curvature_radius = d.pop("curvature_radius")

        d2lift = d.pop("d2lift")

        d3lift = d.pop("d3lift")

        dlift = d.pop("dlift")

        jerk = d.pop("jerk")

        lift = d.pop("lift")

        pitch_point = cast(list[float], d.pop("pitch_point"))


        pressure_angle = d.pop("pressure_angle")

        profile_point = cast(list[float], d.pop("profile_point"))


        theta = d.pop("theta")

        velocity = d.pop("velocity")

        def _parse_cam_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        cam_torque = _parse_cam_torque(d.pop("cam_torque", UNSET))


        def _parse_contact_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        contact_force = _parse_contact_force(d.pop("contact_force", UNSET))


        def _parse_pitch_curvature_radius(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        pitch_curvature_radius = _parse_pitch_curvature_radius(d.pop("pitch_curvature_radius", UNSET))


        instance_ = cls(
            acceleration=acceleration,
            curvature_radius=curvature_radius,
            d2lift=d2lift,
            d3lift=d3lift,
            dlift=dlift,
            jerk=jerk,
            lift=lift,
            pitch_point=pitch_point,
            pressure_angle=pressure_angle,
            profile_point=profile_point,
            theta=theta,
            velocity=velocity,
            cam_torque=cam_torque,
            contact_force=contact_force,
            pitch_curvature_radius=pitch_curvature_radius,
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
