from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from typing import cast

if TYPE_CHECKING:
  from ..models.message_doc_args import MessageDocArgs





T = TypeVar("T", bound="MessageDoc")



@_attrs_define
class MessageDoc:
    """ A message of the catalogue as a result stores it (for the OpenAPI
    document; [`Msg`] is what the code holds).

        Example:
            {'args': {'at': 118.5, 'limit': 30.0, 'max': 34.2}, 'id': 'warning-cam-pressure-translating'}

        Attributes:
            args (MessageDocArgs): Its arguments by name: a text, a number, a count (an integer), or a
                message of the same shape.
            id (str): The message's id in the catalogue.
     """

    args: MessageDocArgs
    id: str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.message_doc_args import MessageDocArgs # noqa: PLC0415
        args = self.args.to_dict()

        id = self.id


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "args": args,
            "id": id,
        })

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.message_doc_args import MessageDocArgs # noqa: PLC0415
        d = dict(src_dict)
        args = MessageDocArgs.from_dict(d.pop("args"))




        id = d.pop("id")

        instance_ = cls(
            args=args,
            id=id,
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
