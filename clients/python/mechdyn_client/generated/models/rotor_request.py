from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.frame_dto import FrameDto
  from ..models.inertia_dto import InertiaDto





T = TypeVar("T", bound="RotorRequest")



@_attrs_define
class RotorRequest:
    """ The body (about its centre of mass G, in the frame's axes x'y'z', x' the
    bearings' axis), its spin relative to the frame, the bearings and the
    frame's motion. Exactly one of `angles` and `times` (default: 12 angles
    over a turn).

        Example:
            {'angles': [0, '90 deg'], 'bearings': [-0.15, 0.15], 'cg': [0, -0.04, 0.1], 'frame': {'speed': '10 rad/s'},
                'gravity': [0, -9.8, 0], 'inertia': {'xx': 0.00375, 'yy': 0.0075, 'zz': 0.00375}, 'mass': '1.5 kg', 'spin': [0,
                20, 0]}

        Attributes:
            bearings (list[float]): x' of bearing D and of bearing E (E takes the axial thrust), m.
            cg (list[float]): G from the origin O on the axis, m.
            frame (FrameDto): The frame's motion about x: speed Ω₀ and angle φ₀ at t = 0, constant acceleration γ.
            inertia (InertiaDto): Moments and products of inertia about G in the frame's axes, kg·m²; the
                tensor is [[xx, −xy, −xz], [−xy, yy, −yz], [−xz, −yz, zz]] (products default 0).
            mass (float | str): A quantity: a number in SI units, or a string "VALUE UNIT"
            angles (list[float | str] | None | Unset): Angles of the frame's turn at which to evaluate (not with `times`).
            gravity (list[float] | None | Unset): Gravity in the fixed axes (which coincide with x'y'z' at angle 0), m/s²
                (default [0, −9.81, 0]).
            spin (list[float] | None | Unset): The body's angular velocity relative to the frame, rad/s (default 0).
                The body must be symmetric about it (its inertia stays constant in the frame).
            times (list[float | str] | None | Unset): Instants at which to evaluate (not with `angles`).
     """

    bearings: list[float]
    cg: list[float]
    frame: FrameDto
    inertia: InertiaDto
    mass: float | str
    angles: list[float | str] | None | Unset = UNSET
    gravity: list[float] | None | Unset = UNSET
    spin: list[float] | None | Unset = UNSET
    times: list[float | str] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.frame_dto import FrameDto # noqa: PLC0415
        from ..models.inertia_dto import InertiaDto # noqa: PLC0415
        bearings = self.bearings



        cg = self.cg



        frame = self.frame.to_dict()

        inertia = self.inertia.to_dict()

        mass: float | str
        mass = self.mass

        angles: list[float | str] | None | Unset
        if isinstance(self.angles, Unset):
            angles = UNSET
        elif isinstance(self.angles, list):
            angles = []
            for angles_item_data in self.angles:
                angles_item: float | str
                angles_item = angles_item_data
                angles.append(angles_item)


        else:
            angles = self.angles

        gravity: list[float] | None | Unset
        if isinstance(self.gravity, Unset):
            gravity = UNSET
        elif isinstance(self.gravity, list):
            gravity = self.gravity


        else:
            gravity = self.gravity

        spin: list[float] | None | Unset
        if isinstance(self.spin, Unset):
            spin = UNSET
        elif isinstance(self.spin, list):
            spin = self.spin


        else:
            spin = self.spin

        times: list[float | str] | None | Unset
        if isinstance(self.times, Unset):
            times = UNSET
        elif isinstance(self.times, list):
            times = []
            for times_item_data in self.times:
                times_item: float | str
                times_item = times_item_data
                times.append(times_item)


        else:
            times = self.times


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "bearings": bearings,
            "cg": cg,
            "frame": frame,
            "inertia": inertia,
            "mass": mass,
        })
        if angles is not UNSET:
            field_dict["angles"] = angles
        if gravity is not UNSET:
            field_dict["gravity"] = gravity
        if spin is not UNSET:
            field_dict["spin"] = spin
        if times is not UNSET:
            field_dict["times"] = times

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.frame_dto import FrameDto # noqa: PLC0415
        from ..models.inertia_dto import InertiaDto # noqa: PLC0415
        d = dict(src_dict)
        bearings = cast(list[float], d.pop("bearings"))


        cg = cast(list[float], d.pop("cg"))


        frame = FrameDto.from_dict(d.pop("frame"))




        inertia = InertiaDto.from_dict(d.pop("inertia"))




        def _parse_mass(data: object) -> float | str:
            return cast(float | str, data)

        mass = _parse_mass(d.pop("mass"))


        def _parse_angles(data: object) -> list[float | str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                angles_type_0 = []
                _angles_type_0 = data
                for angles_type_0_item_data in (_angles_type_0):
                    def _parse_angles_type_0_item(data: object) -> float | str:
                        return cast(float | str, data)

                    angles_type_0_item = _parse_angles_type_0_item(angles_type_0_item_data)

                    angles_type_0.append(angles_type_0_item)

                return angles_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | str] | None | Unset, data)

        angles = _parse_angles(d.pop("angles", UNSET))


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


        def _parse_spin(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spin_type_0 = list(data)

                return spin_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        spin = _parse_spin(d.pop("spin", UNSET))


        def _parse_times(data: object) -> list[float | str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                times_type_0 = []
                _times_type_0 = data
                for times_type_0_item_data in (_times_type_0):
                    def _parse_times_type_0_item(data: object) -> float | str:
                        return cast(float | str, data)

                    times_type_0_item = _parse_times_type_0_item(times_type_0_item_data)

                    times_type_0.append(times_type_0_item)

                return times_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | str] | None | Unset, data)

        times = _parse_times(d.pop("times", UNSET))


        instance_ = cls(
            bearings=bearings,
            cg=cg,
            frame=frame,
            inertia=inertia,
            mass=mass,
            angles=angles,
            gravity=gravity,
            spin=spin,
            times=times,
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
