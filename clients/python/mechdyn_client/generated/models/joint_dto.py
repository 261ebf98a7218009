from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.joint_type import JointType
from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.curve_dto_type_0 import CurveDtoType0
  from ..models.curve_dto_type_1 import CurveDtoType1
  from ..models.curve_dto_type_2 import CurveDtoType2
  from ..models.curve_dto_type_3 import CurveDtoType3
  from ..models.curve_dto_type_4 import CurveDtoType4
  from ..models.curve_dto_type_5 import CurveDtoType5
  from ..models.friction_dto import FrictionDto





T = TypeVar("T", bound="JointDto")



@_attrs_define
class JointDto:
    """ A joint between two bodies (`ground` is implicit). `axis` for prismatic and
    pin_slot (in space also revolute, cylindrical and sphere_in_cylinder; a
    spherical joint's optional `axis` is the one a rotation input turns
    about: the angle about it from a perpendicular fixed in the first body
    to the same perpendicular carried by the second), fixed in the first body: a prismatic joint's first body is the
    guide and its second slides along it; a pin_slot's first body carries
    the slot and its second the pin (swapping them is another mechanism).
    `ratio` or `teeth` (and `internal`) and optional `carrier` for gears.
    A contact's `curves` (the first body's, then the second's) must touch as
    drawn; its `at` is where they do (optional: a hint where they touch at
    several points).

        Attributes:
            bodies (list[str]):
            name (str):
            type_ (JointType): Joint types.
            at (list[float | str] | None | str | Unset):
            axes (list[list[float]] | None | Unset): A universal joint's axes [a, b] ([x, y, z] each): a fixed in the
                first body, b in the second, perpendicular as drawn.
            axis (list[float] | None | Unset): [x, y], in space [x, y, z]: any length (made unit).
            carrier (None | str | Unset): Gear: the carrier body (default ground).
            curves (list[CurveDtoType0 | CurveDtoType1 | CurveDtoType2 | CurveDtoType3 | CurveDtoType4 | CurveDtoType5] |
                None | Unset): Contact: the curve fixed in each body, in `bodies` order.
            friction (FrictionDto | None | Unset):
            internal (bool | None | Unset): Gear: internal mesh (default false).
            length (float | None | str | Unset):
            module (float | None | str | Unset):
            pressure_angle (float | None | str | Unset):
            ratio (float | None | Unset): Gear: ω₂ − ω_c = ratio·(ω₁ − ω_c).
            rolling (bool | None | Unset): Contact: rolling without slipping (equal arc lengths; default false, sliding).
            slider_length (float | None | str | Unset):
            teeth (list[float] | None | Unset): Gear: tooth numbers [z₁, z₂].
     """

    bodies: list[str]
    name: str
    type_: JointType
    at: list[float | str] | None | str | Unset = UNSET
    axes: list[list[float]] | None | Unset = UNSET
    axis: list[float] | None | Unset = UNSET
    carrier: None | str | Unset = UNSET
    curves: list[CurveDtoType0 | CurveDtoType1 | CurveDtoType2 | CurveDtoType3 | CurveDtoType4 | CurveDtoType5] | None | Unset = UNSET
    friction: FrictionDto | None | Unset = UNSET
    internal: bool | None | Unset = UNSET
    length: float | None | str | Unset = UNSET
    module: float | None | str | Unset = UNSET
    pressure_angle: float | None | str | Unset = UNSET
    ratio: float | None | Unset = UNSET
    rolling: bool | None | Unset = UNSET
    slider_length: float | None | str | Unset = UNSET
    teeth: list[float] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.curve_dto_type_0 import CurveDtoType0 # noqa: PLC0415
        from ..models.curve_dto_type_1 import CurveDtoType1 # noqa: PLC0415
        from ..models.curve_dto_type_2 import CurveDtoType2 # noqa: PLC0415
        from ..models.curve_dto_type_3 import CurveDtoType3 # noqa: PLC0415
        from ..models.curve_dto_type_4 import CurveDtoType4 # noqa: PLC0415
        from ..models.curve_dto_type_5 import CurveDtoType5 # noqa: PLC0415
        from ..models.friction_dto import FrictionDto # noqa: PLC0415
        bodies = self.bodies



        name = self.name

        type_ = self.type_.value

        at: list[float | str] | None | str | Unset
        if isinstance(self.at, Unset):
            at = UNSET
        elif isinstance(self.at, list):
            at = []
            for at_item_data in self.at:
                at_item: float | str
                at_item = at_item_data
                at.append(at_item)


        else:
            at = self.at

        axes: list[list[float]] | None | Unset
        if isinstance(self.axes, Unset):
            axes = UNSET
        elif isinstance(self.axes, list):
            axes = []
            for axes_item_data in self.axes:
                axes_item = axes_item_data


                axes.append(axes_item)


        else:
            axes = self.axes

        axis: list[float] | None | Unset
        if isinstance(self.axis, Unset):
            axis = UNSET
        elif isinstance(self.axis, list):
            axis = self.axis


        else:
            axis = self.axis

        carrier: None | str | Unset
        if isinstance(self.carrier, Unset):
            carrier = UNSET
        else:
            carrier = self.carrier

        curves: list[dict[str, Any]] | None | Unset
        if isinstance(self.curves, Unset):
            curves = UNSET
        elif isinstance(self.curves, list):
            curves = []
            for curves_item_data in self.curves:
                curves_item: dict[str, Any]
                if isinstance(curves_item_data, CurveDtoType0):
                    curves_item = curves_item_data.to_dict()
                elif isinstance(curves_item_data, CurveDtoType1):
                    curves_item = curves_item_data.to_dict()
                elif isinstance(curves_item_data, CurveDtoType2):
                    curves_item = curves_item_data.to_dict()
                elif isinstance(curves_item_data, CurveDtoType3):
                    curves_item = curves_item_data.to_dict()
                elif isinstance(curves_item_data, CurveDtoType4):
                    curves_item = curves_item_data.to_dict()
                else:
                    curves_item = curves_item_data.to_dict()

                curves.append(curves_item)


        else:
            curves = self.curves

        friction: dict[str, Any] | None | Unset
        if isinstance(self.friction, Unset):
            friction = UNSET
        elif isinstance(self.friction, FrictionDto):
            friction = self.friction.to_dict()
        else:
            friction = self.friction

        internal: bool | None | Unset
        if isinstance(self.internal, Unset):
            internal = UNSET
        else:
            internal = self.internal

        length: float | None | str | Unset
        if isinstance(self.length, Unset):
            length = UNSET
        else:
            length = self.length

        module: float | None | str | Unset
        if isinstance(self.module, Unset):
            module = UNSET
        else:
            module = self.module

        pressure_angle: float | None | str | Unset
        if isinstance(self.pressure_angle, Unset):
            pressure_angle = UNSET
        else:
            pressure_angle = self.pressure_angle

        ratio: float | None | Unset
        if isinstance(self.ratio, Unset):
            ratio = UNSET
        else:
            ratio = self.ratio

        rolling: bool | None | Unset
        if isinstance(self.rolling, Unset):
            rolling = UNSET
        else:
            rolling = self.rolling

        slider_length: float | None | str | Unset
        if isinstance(self.slider_length, Unset):
            slider_length = UNSET
        else:
            slider_length = self.slider_length

        teeth: list[float] | None | Unset
        if isinstance(self.teeth, Unset):
            teeth = UNSET
        elif isinstance(self.teeth, list):
            teeth = self.teeth


        else:
            teeth = self.teeth


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "bodies": bodies,
            "name": name,
            "type": type_,
        })
        if at is not UNSET:
            field_dict["at"] = at
        if axes is not UNSET:
            field_dict["axes"] = axes
        if axis is not UNSET:
            field_dict["axis"] = axis
        if carrier is not UNSET:
            field_dict["carrier"] = carrier
        if curves is not UNSET:
            field_dict["curves"] = curves
        if friction is not UNSET:
            field_dict["friction"] = friction
        if internal is not UNSET:
            field_dict["internal"] = internal
        if length is not UNSET:
            field_dict["length"] = length
        if module is not UNSET:
            field_dict["module"] = module
        if pressure_angle is not UNSET:
            field_dict["pressure_angle"] = pressure_angle
        if ratio is not UNSET:
            field_dict["ratio"] = ratio
        if rolling is not UNSET:
            field_dict["rolling"] = rolling
        if slider_length is not UNSET:
            field_dict["slider_length"] = slider_length
        if teeth is not UNSET:
            field_dict["teeth"] = teeth

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.curve_dto_type_0 import CurveDtoType0 # noqa: PLC0415
        from ..models.curve_dto_type_1 import CurveDtoType1 # noqa: PLC0415
        from ..models.curve_dto_type_2 import CurveDtoType2 # noqa: PLC0415
        from ..models.curve_dto_type_3 import CurveDtoType3 # noqa: PLC0415
        from ..models.curve_dto_type_4 import CurveDtoType4 # noqa: PLC0415
        from ..models.curve_dto_type_5 import CurveDtoType5 # noqa: PLC0415
        from ..models.friction_dto import FrictionDto # noqa: PLC0415
        d = dict(src_dict)
        bodies = cast(list[str], d.pop("bodies"))


        name = d.pop("name")

        type_ = JointType(d.pop("type"))




        def _parse_at(data: object) -> list[float | str] | None | str | Unset:
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

        at = _parse_at(d.pop("at", UNSET))


        def _parse_axes(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                axes_type_0 = []
                _axes_type_0 = data
                for axes_type_0_item_data in (_axes_type_0):
                    axes_type_0_item = cast(list[float], axes_type_0_item_data)

                    axes_type_0.append(axes_type_0_item)

                return axes_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        axes = _parse_axes(d.pop("axes", UNSET))


        def _parse_axis(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                axis_type_0 = list(data)

                return axis_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        axis = _parse_axis(d.pop("axis", UNSET))


        def _parse_carrier(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        carrier = _parse_carrier(d.pop("carrier", UNSET))


        def _parse_curves(data: object) -> list[CurveDtoType0 | CurveDtoType1 | CurveDtoType2 | CurveDtoType3 | CurveDtoType4 | CurveDtoType5] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                curves_type_0 = []
                _curves_type_0 = data
                for curves_type_0_item_data in (_curves_type_0):
                    def _parse_curves_type_0_item(data: object) -> CurveDtoType0 | CurveDtoType1 | CurveDtoType2 | CurveDtoType3 | CurveDtoType4 | CurveDtoType5:
                        try:
                            if not isinstance(data, dict):
                                raise TypeError()
                            componentsschemas_curve_dto_type_0 = CurveDtoType0.from_dict(data)



                            return componentsschemas_curve_dto_type_0
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        try:
                            if not isinstance(data, dict):
                                raise TypeError()
                            componentsschemas_curve_dto_type_1 = CurveDtoType1.from_dict(data)



                            return componentsschemas_curve_dto_type_1
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        try:
                            if not isinstance(data, dict):
                                raise TypeError()
                            componentsschemas_curve_dto_type_2 = CurveDtoType2.from_dict(data)



                            return componentsschemas_curve_dto_type_2
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        try:
                            if not isinstance(data, dict):
                                raise TypeError()
                            componentsschemas_curve_dto_type_3 = CurveDtoType3.from_dict(data)



                            return componentsschemas_curve_dto_type_3
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        try:
                            if not isinstance(data, dict):
                                raise TypeError()
                            componentsschemas_curve_dto_type_4 = CurveDtoType4.from_dict(data)



                            return componentsschemas_curve_dto_type_4
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        if not isinstance(data, dict):
                            raise TypeError()
                        componentsschemas_curve_dto_type_5 = CurveDtoType5.from_dict(data)



                        return componentsschemas_curve_dto_type_5

                    curves_type_0_item = _parse_curves_type_0_item(curves_type_0_item_data)

                    curves_type_0.append(curves_type_0_item)

                return curves_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[CurveDtoType0 | CurveDtoType1 | CurveDtoType2 | CurveDtoType3 | CurveDtoType4 | CurveDtoType5] | None | Unset, data)

        curves = _parse_curves(d.pop("curves", UNSET))


        def _parse_friction(data: object) -> FrictionDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                friction_type_0 = FrictionDto.from_dict(data)



                return friction_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(FrictionDto | None | Unset, data)

        friction = _parse_friction(d.pop("friction", UNSET))


        def _parse_internal(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        internal = _parse_internal(d.pop("internal", UNSET))


        def _parse_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        length = _parse_length(d.pop("length", UNSET))


        def _parse_module(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        module = _parse_module(d.pop("module", UNSET))


        def _parse_pressure_angle(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        pressure_angle = _parse_pressure_angle(d.pop("pressure_angle", UNSET))


        def _parse_ratio(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        ratio = _parse_ratio(d.pop("ratio", UNSET))


        def _parse_rolling(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        rolling = _parse_rolling(d.pop("rolling", UNSET))


        def _parse_slider_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        slider_length = _parse_slider_length(d.pop("slider_length", UNSET))


        def _parse_teeth(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                teeth_type_0 = list(data)

                return teeth_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        teeth = _parse_teeth(d.pop("teeth", UNSET))


        instance_ = cls(
            bodies=bodies,
            name=name,
            type_=type_,
            at=at,
            axes=axes,
            axis=axis,
            carrier=carrier,
            curves=curves,
            friction=friction,
            internal=internal,
            length=length,
            module=module,
            pressure_angle=pressure_angle,
            ratio=ratio,
            rolling=rolling,
            slider_length=slider_length,
            teeth=teeth,
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
