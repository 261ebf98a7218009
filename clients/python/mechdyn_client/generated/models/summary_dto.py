from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.summary_dto_max_reaction import SummaryDtoMaxReaction





T = TypeVar("T", bound="SummaryDto")



@_attrs_define
class SummaryDto:
    """ 
        Attributes:
            max_jacobian_condition (float):
            max_reaction (SummaryDtoMaxReaction): Largest reaction force magnitude per joint (null when undetermined or not
                computed).
            max_scaled_condition (float): The largest `scaled_condition` of the regular steps.
            near_singular_inputs (list[float | list[float]]): Inputs where the scaled condition number exceeds 1e4 (results
                valid but sensitive).
            singular (bool): Whether any sampled position is singular (scaled condition number above 1e6):
                its step has no driving action, reactions or reduced quantities.
            singular_inputs (list[float | list[float]]):
            max_abs_driving (float | list[float] | None | Unset):
            max_shaking_force (float | None | Unset): The largest |shaking force| over the sweep (N), where `outputs` has
                "shaking".
            max_shaking_force_balanced (float | None | Unset): The largest |shaking force| with the `counterweights` (N).
            max_shaking_moment (float | None | Unset): The largest |shaking moment| over the sweep (N·m).
            mean_driving (float | list[float] | None | Unset):
            rms_driving (float | list[float] | None | Unset):
            virtual_power_residual (float | None | Unset): Largest |driving from multipliers − driving from virtual power| /
                max |driving|.
     """

    max_jacobian_condition: float
    max_reaction: SummaryDtoMaxReaction
    max_scaled_condition: float
    near_singular_inputs: list[float | list[float]]
    singular: bool
    singular_inputs: list[float | list[float]]
    max_abs_driving: float | list[float] | None | Unset = UNSET
    max_shaking_force: float | None | Unset = UNSET
    max_shaking_force_balanced: float | None | Unset = UNSET
    max_shaking_moment: float | None | Unset = UNSET
    mean_driving: float | list[float] | None | Unset = UNSET
    rms_driving: float | list[float] | None | Unset = UNSET
    virtual_power_residual: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.summary_dto_max_reaction import SummaryDtoMaxReaction # noqa: PLC0415
        max_jacobian_condition = self.max_jacobian_condition

        max_reaction = self.max_reaction.to_dict()

        max_scaled_condition = self.max_scaled_condition

        near_singular_inputs = []
        for near_singular_inputs_item_data in self.near_singular_inputs:
            near_singular_inputs_item: float | list[float]
            if isinstance(near_singular_inputs_item_data, list):
                near_singular_inputs_item = near_singular_inputs_item_data


            else:
                near_singular_inputs_item = near_singular_inputs_item_data
            near_singular_inputs.append(near_singular_inputs_item)



        singular = self.singular

        singular_inputs = []
        for singular_inputs_item_data in self.singular_inputs:
            singular_inputs_item: float | list[float]
            if isinstance(singular_inputs_item_data, list):
                singular_inputs_item = singular_inputs_item_data


            else:
                singular_inputs_item = singular_inputs_item_data
            singular_inputs.append(singular_inputs_item)



        max_abs_driving: float | list[float] | None | Unset
        if isinstance(self.max_abs_driving, Unset):
            max_abs_driving = UNSET
        elif isinstance(self.max_abs_driving, list):
            max_abs_driving = self.max_abs_driving


        else:
            max_abs_driving = self.max_abs_driving

        max_shaking_force: float | None | Unset
        if isinstance(self.max_shaking_force, Unset):
            max_shaking_force = UNSET
        else:
            max_shaking_force = self.max_shaking_force

        max_shaking_force_balanced: float | None | Unset
        if isinstance(self.max_shaking_force_balanced, Unset):
            max_shaking_force_balanced = UNSET
        else:
            max_shaking_force_balanced = self.max_shaking_force_balanced

        max_shaking_moment: float | None | Unset
        if isinstance(self.max_shaking_moment, Unset):
            max_shaking_moment = UNSET
        else:
            max_shaking_moment = self.max_shaking_moment

        mean_driving: float | list[float] | None | Unset
        if isinstance(self.mean_driving, Unset):
            mean_driving = UNSET
        elif isinstance(self.mean_driving, list):
            mean_driving = self.mean_driving


        else:
            mean_driving = self.mean_driving

        rms_driving: float | list[float] | None | Unset
        if isinstance(self.rms_driving, Unset):
            rms_driving = UNSET
        elif isinstance(self.rms_driving, list):
            rms_driving = self.rms_driving


        else:
            rms_driving = self.rms_driving

        virtual_power_residual: float | None | Unset
        if isinstance(self.virtual_power_residual, Unset):
            virtual_power_residual = UNSET
        else:
            virtual_power_residual = self.virtual_power_residual


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "max_jacobian_condition": max_jacobian_condition,
            "max_reaction": max_reaction,
            "max_scaled_condition": max_scaled_condition,
            "near_singular_inputs": near_singular_inputs,
            "singular": singular,
            "singular_inputs": singular_inputs,
        })
        if max_abs_driving is not UNSET:
            field_dict["max_abs_driving"] = max_abs_driving
        if max_shaking_force is not UNSET:
            field_dict["max_shaking_force"] = max_shaking_force
        if max_shaking_force_balanced is not UNSET:
            field_dict["max_shaking_force_balanced"] = max_shaking_force_balanced
        if max_shaking_moment is not UNSET:
            field_dict["max_shaking_moment"] = max_shaking_moment
        if mean_driving is not UNSET:
            field_dict["mean_driving"] = mean_driving
        if rms_driving is not UNSET:
            field_dict["rms_driving"] = rms_driving
        if virtual_power_residual is not UNSET:
            field_dict["virtual_power_residual"] = virtual_power_residual

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.summary_dto_max_reaction import SummaryDtoMaxReaction # noqa: PLC0415
        d = dict(src_dict)
        max_jacobian_condition = d.pop("max_jacobian_condition")

        max_reaction = SummaryDtoMaxReaction.from_dict(d.pop("max_reaction"))




        max_scaled_condition = d.pop("max_scaled_condition")

        near_singular_inputs = []
        _near_singular_inputs = d.pop("near_singular_inputs")
        for near_singular_inputs_item_data in (_near_singular_inputs):
            def _parse_near_singular_inputs_item(data: object) -> float | list[float]:
                try:
                    if not isinstance(data, list):
                        raise TypeError()
                    componentsschemas_scalars_type_1 = list(data)

                    return componentsschemas_scalars_type_1
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                return cast(float | list[float], data)

            near_singular_inputs_item = _parse_near_singular_inputs_item(near_singular_inputs_item_data)

            near_singular_inputs.append(near_singular_inputs_item)


        singular = d.pop("singular")

        singular_inputs = []
        _singular_inputs = d.pop("singular_inputs")
        for singular_inputs_item_data in (_singular_inputs):
            def _parse_singular_inputs_item(data: object) -> float | list[float]:
                try:
                    if not isinstance(data, list):
                        raise TypeError()
                    componentsschemas_scalars_type_1 = list(data)

                    return componentsschemas_scalars_type_1
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                return cast(float | list[float], data)

            singular_inputs_item = _parse_singular_inputs_item(singular_inputs_item_data)

            singular_inputs.append(singular_inputs_item)


        def _parse_max_abs_driving(data: object) -> float | list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_scalars_type_1 = list(data)

                return componentsschemas_scalars_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float] | None | Unset, data)

        max_abs_driving = _parse_max_abs_driving(d.pop("max_abs_driving", UNSET))


        def _parse_max_shaking_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        max_shaking_force = _parse_max_shaking_force(d.pop("max_shaking_force", UNSET))


        def _parse_max_shaking_force_balanced(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        max_shaking_force_balanced = _parse_max_shaking_force_balanced(d.pop("max_shaking_force_balanced", UNSET))


        def _parse_max_shaking_moment(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        max_shaking_moment = _parse_max_shaking_moment(d.pop("max_shaking_moment", UNSET))


        def _parse_mean_driving(data: object) -> float | list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_scalars_type_1 = list(data)

                return componentsschemas_scalars_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float] | None | Unset, data)

        mean_driving = _parse_mean_driving(d.pop("mean_driving", UNSET))


        def _parse_rms_driving(data: object) -> float | list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                componentsschemas_scalars_type_1 = list(data)

                return componentsschemas_scalars_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float] | None | Unset, data)

        rms_driving = _parse_rms_driving(d.pop("rms_driving", UNSET))


        def _parse_virtual_power_residual(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        virtual_power_residual = _parse_virtual_power_residual(d.pop("virtual_power_residual", UNSET))


        instance_ = cls(
            max_jacobian_condition=max_jacobian_condition,
            max_reaction=max_reaction,
            max_scaled_condition=max_scaled_condition,
            near_singular_inputs=near_singular_inputs,
            singular=singular,
            singular_inputs=singular_inputs,
            max_abs_driving=max_abs_driving,
            max_shaking_force=max_shaking_force,
            max_shaking_force_balanced=max_shaking_force_balanced,
            max_shaking_moment=max_shaking_moment,
            mean_driving=mean_driving,
            rms_driving=rms_driving,
            virtual_power_residual=virtual_power_residual,
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
