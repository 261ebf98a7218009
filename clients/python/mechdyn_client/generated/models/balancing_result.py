from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.balancing_correction_dto import BalancingCorrectionDto
  from ..models.balancing_residual_dto import BalancingResidualDto
  from ..models.bearing_forces_dto import BearingForcesDto
  from ..models.dynamic_unbalance_dto import DynamicUnbalanceDto
  from ..models.notes_messages import NotesMessages
  from ..models.unbalance_dto import UnbalanceDto





T = TypeVar("T", bound="BalancingResult")



@_attrs_define
class BalancingResult:
    """ 
        Attributes:
            warnings (list[str]): What to know before trusting the numbers: a condition met on the
                way (a tolerance nearly spent, a geometry nearly singular, a law
                of design broken), in the asker's language.
            corrections (list[BalancingCorrectionDto]): One per plane, ordered by z.
            dynamic_unbalance (DynamicUnbalanceDto): The dynamic unbalance D = Σ m·r·(z − z₁)·e^{iθ} about the first
                correction plane z₁ (`about`).
            method (str):
            residual (BalancingResidualDto): The unbalance left after the corrections: |U| and |D(z₁)| (rounding
                alone with two planes; one plane leaves the couple).
            static_unbalance (UnbalanceDto): A vector by its size and its angle (rad, CCW from the rotor's x axis, in [0,
                2π)).
            messages (NotesMessages | Unset): The catalogue's message each text of this result was written from,
                by JSON pointer into the result (`/warnings/0`, `/accuracy/method`):
                match a warning by its `id`; the texts themselves are in the
                language asked for (`Accept-Language`, `?lang=`).
            reactions (BearingForcesDto | None | Unset):
     """

    warnings: list[str]
    corrections: list[BalancingCorrectionDto]
    dynamic_unbalance: DynamicUnbalanceDto
    method: str
    residual: BalancingResidualDto
    static_unbalance: UnbalanceDto
    messages: NotesMessages | Unset = UNSET
    reactions: BearingForcesDto | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.balancing_correction_dto import BalancingCorrectionDto # noqa: PLC0415
        from ..models.balancing_residual_dto import BalancingResidualDto # noqa: PLC0415
        from ..models.bearing_forces_dto import BearingForcesDto # noqa: PLC0415
        from ..models.dynamic_unbalance_dto import DynamicUnbalanceDto # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        from ..models.unbalance_dto import UnbalanceDto # noqa: PLC0415
        warnings = self.warnings



        corrections = []
        for corrections_item_data in self.corrections:
            corrections_item = corrections_item_data.to_dict()
            corrections.append(corrections_item)



        dynamic_unbalance = self.dynamic_unbalance.to_dict()

        method = self.method

        residual = self.residual.to_dict()

        static_unbalance = self.static_unbalance.to_dict()

        messages: dict[str, Any] | Unset = UNSET
        if not isinstance(self.messages, Unset):
            messages = self.messages.to_dict()

        reactions: dict[str, Any] | None | Unset
        if isinstance(self.reactions, Unset):
            reactions = UNSET
        elif isinstance(self.reactions, BearingForcesDto):
            reactions = self.reactions.to_dict()
        else:
            reactions = self.reactions


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "warnings": warnings,
            "corrections": corrections,
            "dynamic_unbalance": dynamic_unbalance,
            "method": method,
            "residual": residual,
            "static_unbalance": static_unbalance,
        })
        if messages is not UNSET:
            field_dict["messages"] = messages
        if reactions is not UNSET:
            field_dict["reactions"] = reactions

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.balancing_correction_dto import BalancingCorrectionDto # noqa: PLC0415
        from ..models.balancing_residual_dto import BalancingResidualDto # noqa: PLC0415
        from ..models.bearing_forces_dto import BearingForcesDto # noqa: PLC0415
        from ..models.dynamic_unbalance_dto import DynamicUnbalanceDto # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        from ..models.unbalance_dto import UnbalanceDto # noqa: PLC0415
        d = dict(src_dict)
        warnings = cast(list[str], d.pop("warnings"))


        corrections = []
        _corrections = d.pop("corrections")
        for corrections_item_data in (_corrections):
            corrections_item = BalancingCorrectionDto.from_dict(corrections_item_data)



            corrections.append(corrections_item)


        dynamic_unbalance = DynamicUnbalanceDto.from_dict(d.pop("dynamic_unbalance"))




        method = d.pop("method")

        residual = BalancingResidualDto.from_dict(d.pop("residual"))




        static_unbalance = UnbalanceDto.from_dict(d.pop("static_unbalance"))




        _messages = d.pop("messages", UNSET)
        messages: NotesMessages | Unset
        if isinstance(_messages,  Unset):
            messages = UNSET
        else:
            messages = NotesMessages.from_dict(_messages)




        def _parse_reactions(data: object) -> BearingForcesDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                reactions_type_0 = BearingForcesDto.from_dict(data)



                return reactions_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(BearingForcesDto | None | Unset, data)

        reactions = _parse_reactions(d.pop("reactions", UNSET))


        instance_ = cls(
            warnings=warnings,
            corrections=corrections,
            dynamic_unbalance=dynamic_unbalance,
            method=method,
            residual=residual,
            static_unbalance=static_unbalance,
            messages=messages,
            reactions=reactions,
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
