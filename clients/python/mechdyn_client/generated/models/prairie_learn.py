from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.prairie_learn_messages import PrairieLearnMessages
  from ..models.prairie_learn_test import PrairieLearnTest





T = TypeVar("T", bound="PrairieLearn")



@_attrs_define
class PrairieLearn:
    """ PrairieLearn's external-grader results document.

        Attributes:
            gradable (bool): Whether the submission could be graded (false: a format error, no points).
            message (str): Shown to the student above the tests.
            output (str):
            score (float): Share of the points earned, 0 to 1.
            tests (list[PrairieLearnTest]):
            messages (PrairieLearnMessages | Unset): mechdyn's: the message each text was written from, by JSON pointer
                (a platform ignores it; the texts are in the asker's language).
     """

    gradable: bool
    message: str
    output: str
    score: float
    tests: list[PrairieLearnTest]
    messages: PrairieLearnMessages | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.prairie_learn_messages import PrairieLearnMessages # noqa: PLC0415
        from ..models.prairie_learn_test import PrairieLearnTest # noqa: PLC0415
        gradable = self.gradable

        message = self.message

        output = self.output

        score = self.score

        tests = []
        for tests_item_data in self.tests:
            tests_item = tests_item_data.to_dict()
            tests.append(tests_item)



        messages: dict[str, Any] | Unset = UNSET
        if not isinstance(self.messages, Unset):
            messages = self.messages.to_dict()


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "gradable": gradable,
            "message": message,
            "output": output,
            "score": score,
            "tests": tests,
        })
        if messages is not UNSET:
            field_dict["messages"] = messages

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.prairie_learn_messages import PrairieLearnMessages # noqa: PLC0415
        from ..models.prairie_learn_test import PrairieLearnTest # noqa: PLC0415
        d = dict(src_dict)
        gradable = d.pop("gradable")

        message = d.pop("message")

        output = d.pop("output")

        score = d.pop("score")

        tests = []
        _tests = d.pop("tests")
        for tests_item_data in (_tests):
            tests_item = PrairieLearnTest.from_dict(tests_item_data)



            tests.append(tests_item)


        _messages = d.pop("messages", UNSET)
        messages: PrairieLearnMessages | Unset
        if isinstance(_messages,  Unset):
            messages = UNSET
        else:
            messages = PrairieLearnMessages.from_dict(_messages)




        instance_ = cls(
            gradable=gradable,
            message=message,
            output=output,
            score=score,
            tests=tests,
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
