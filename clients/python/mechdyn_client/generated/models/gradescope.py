from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.gradescope_messages import GradescopeMessages
  from ..models.gradescope_test import GradescopeTest





T = TypeVar("T", bound="Gradescope")



@_attrs_define
class Gradescope:
    """ Gradescope's autograder results document.

        Attributes:
            max_score (float):
            output (str):
            score (float): Points earned (one per answer that passes).
            stdout_visibility (str):
            tests (list[GradescopeTest]):
            visibility (str): `visible`: the student sees the tests at once.
            messages (GradescopeMessages | Unset): As [`PrairieLearn::messages`].
     """

    max_score: float
    output: str
    score: float
    stdout_visibility: str
    tests: list[GradescopeTest]
    visibility: str
    messages: GradescopeMessages | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.gradescope_messages import GradescopeMessages # noqa: PLC0415
        from ..models.gradescope_test import GradescopeTest # noqa: PLC0415
        max_score = self.max_score

        output = self.output

        score = self.score

        stdout_visibility = self.stdout_visibility

        tests = []
        for tests_item_data in self.tests:
            tests_item = tests_item_data.to_dict()
            tests.append(tests_item)



        visibility = self.visibility

        messages: dict[str, Any] | Unset = UNSET
        if not isinstance(self.messages, Unset):
            messages = self.messages.to_dict()


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "max_score": max_score,
            "output": output,
            "score": score,
            "stdout_visibility": stdout_visibility,
            "tests": tests,
            "visibility": visibility,
        })
        if messages is not UNSET:
            field_dict["messages"] = messages

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.gradescope_messages import GradescopeMessages # noqa: PLC0415
        from ..models.gradescope_test import GradescopeTest # noqa: PLC0415
        d = dict(src_dict)
        max_score = d.pop("max_score")

        output = d.pop("output")

        score = d.pop("score")

        stdout_visibility = d.pop("stdout_visibility")

        tests = []
        _tests = d.pop("tests")
        for tests_item_data in (_tests):
            tests_item = GradescopeTest.from_dict(tests_item_data)



            tests.append(tests_item)


        visibility = d.pop("visibility")

        _messages = d.pop("messages", UNSET)
        messages: GradescopeMessages | Unset
        if isinstance(_messages,  Unset):
            messages = UNSET
        else:
            messages = GradescopeMessages.from_dict(_messages)




        instance_ = cls(
            max_score=max_score,
            output=output,
            score=score,
            stdout_visibility=stdout_visibility,
            tests=tests,
            visibility=visibility,
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
