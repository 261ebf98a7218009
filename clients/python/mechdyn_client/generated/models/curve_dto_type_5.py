from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.cam_curve_dto import CamCurveDto





T = TypeVar("T", bound="CurveDtoType5")



@_attrs_define
class CurveDtoType5:
    """ A disk cam's profile generated from its follower's program.

        Attributes:
            cam (CamCurveDto): A disk cam's profile made for a translating follower from its program
                (the fields of `POST /v1/cams` that shape it): the envelope of a flat
                face, or the pitch curve of a roller (its `roller_radius`; a knife edge
                has none) on an axis `offset` from the centre moved in by the roller's
                radius; lift s(θ) at the cam's counter-clockwise turn θ from the drawing.
                Draw the follower's face, roller or edge touching it at θ = 0.
     """

    cam: CamCurveDto
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.cam_curve_dto import CamCurveDto # noqa: PLC0415
        cam = self.cam.to_dict()


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "cam": cam,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.cam_curve_dto import CamCurveDto # noqa: PLC0415
        d = dict(src_dict)
        cam = CamCurveDto.from_dict(d.pop("cam"))




        instance_ = cls(
            cam=cam,
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
