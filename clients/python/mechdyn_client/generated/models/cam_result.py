from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.cam_sample import CamSample
  from ..models.cam_summary import CamSummary
  from ..models.notes_messages import NotesMessages
  from ..models.segment_peaks import SegmentPeaks





T = TypeVar("T", bound="CamResult")



@_attrs_define
class CamResult:
    """ 
        Attributes:
            warnings (list[str]): What to know before trusting the numbers: a condition met on the
                way (a tolerance nearly spent, a geometry nearly singular, a law
                of design broken), in the asker's language.
            method (str): How the numbers were made.
            samples (list[CamSample]):
            segments (list[SegmentPeaks]): A program's segments (empty for a lift Function).
            summary (CamSummary):
            messages (NotesMessages | Unset): The catalogue's message each text of this result was written from,
                by JSON pointer into the result (`/warnings/0`, `/accuracy/method`):
                match a warning by its `id`; the texts themselves are in the
                language asked for (`Accept-Language`, `?lang=`).
     """

    warnings: list[str]
    method: str
    samples: list[CamSample]
    segments: list[SegmentPeaks]
    summary: CamSummary
    messages: NotesMessages | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.cam_sample import CamSample # noqa: PLC0415
        from ..models.cam_summary import CamSummary # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        from ..models.segment_peaks import SegmentPeaks # noqa: PLC0415
        warnings = self.warnings



        method = self.method

        samples = []
        for samples_item_data in self.samples:
            samples_item = samples_item_data.to_dict()
            samples.append(samples_item)



        segments = []
        for segments_item_data in self.segments:
            segments_item = segments_item_data.to_dict()
            segments.append(segments_item)



        summary = self.summary.to_dict()

        messages: dict[str, Any] | Unset = UNSET
        if not isinstance(self.messages, Unset):
            messages = self.messages.to_dict()


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "warnings": warnings,
            "method": method,
            "samples": samples,
            "segments": segments,
            "summary": summary,
        })
        if messages is not UNSET:
            field_dict["messages"] = messages

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.cam_sample import CamSample # noqa: PLC0415
        from ..models.cam_summary import CamSummary # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        from ..models.segment_peaks import SegmentPeaks # noqa: PLC0415
        d = dict(src_dict)
        warnings = cast(list[str], d.pop("warnings"))


        method = d.pop("method")

        samples = []
        _samples = d.pop("samples")
        for samples_item_data in (_samples):
            samples_item = CamSample.from_dict(samples_item_data)



            samples.append(samples_item)


        segments = []
        _segments = d.pop("segments")
        for segments_item_data in (_segments):
            segments_item = SegmentPeaks.from_dict(segments_item_data)



            segments.append(segments_item)


        summary = CamSummary.from_dict(d.pop("summary"))




        _messages = d.pop("messages", UNSET)
        messages: NotesMessages | Unset
        if isinstance(_messages,  Unset):
            messages = UNSET
        else:
            messages = NotesMessages.from_dict(_messages)




        instance_ = cls(
            warnings=warnings,
            method=method,
            samples=samples,
            segments=segments,
            summary=summary,
            messages=messages,
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
