from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..models.integrator_choice import IntegratorChoice
from ..types import UNSET, Unset
from typing import cast






T = TypeVar("T", bound="DynamicsAccuracy")



@_attrs_define
class DynamicsAccuracy:
    """ 
        Attributes:
            energy_residual (float): (W − ΔT)/max(|W|, |ΔT|, T₀, T_end, T_peak): the work of the actions against
                the change of kinetic energy. W is a quadrature over the angle when the
                reduced actions depend on φ only, else the integrated power.
            estimated_error (float): A bound of the error of the angle (rad; for a mechanism, of its first
                input's coordinate, in its unit — m for a slider): 1.5 times
                `global_error` where that was made, or Σ over the steps of the
                integrator's local error estimate (for a mechanism's angle the largest
                over its bodies' angles too) where larger or where no `global_error`
                could be had — a first-order estimate that ignores how errors grow
                along the motion. `error_estimate` says which.
            function_evaluations (int):
            integrator (IntegratorChoice): `dopri5`: Dormand–Prince 5(4), 6 evaluations a step; `dop853`: Hairer's
                DOP853, order 8, 15 evaluations a step and far fewer steps at tight
                tolerances and over long smooth runs; `radau5`: Radau IIA, order 5,
                implicit, for stiff models (a stiff spring): its steps follow the slow
                motion and damp a mode far faster than it — on a model that is not
                stiff each of its steps solves a Newton system, and a run takes 20 to 30
                times as long as with `dop853` for an error far below the tolerance, so
                ask for it only for a stiff model, or leave it to `auto`; `auto`: in the reduced form
                DOP853 at a tolerance of 1e-5 or less, Dormand–Prince above; for a
                `machine` Dormand–Prince (its accelerations jump near singular
                positions, where a high order gains nothing); either, finding its steps
                held by stability (15 steps beyond its stability interval), hands the
                run to `radau5` from the start (`accuracy.stiff_at` says when). A
                `machine` asked to run with `dop853` or `radau5` that meets a singular
                position (a parallelogram lying flat) is run again with `dopri5`, whose
                steps the fold's hold keeps on the mechanism's branch
                (`accuracy.integrator_replaced_at` and a warning say when). See
                docs/BENCHMARKS.md.
            method (str):
            steps (int):
            constraint_drift (float | None | Unset): Mechanism form: the largest constraint violation |Φ| (m or rad)
                removed by the projection after a step.
            energy_conserved (bool | None | Unset): Mechanism form: whether the energy T + V was held to its initial
                value throughout the run (see `machine.conserve_energy`; skipped near
                turning points, as `energy_held_steps` says): false where the loads
                have no potential, where the hold was turned off, and where a
                singular position was met (the hold stops there).
            energy_form_time_difference (float | None | Unset): The largest |t − t_energy_form| over the events (s), when
                any has one:
                an independent measure of the integration's error.
            energy_held_steps (int | None | Unset): Mechanism form: the steps after which T + V was E₀ (not near turning
                points, where the correction would exceed 1 %, nor after a singular
                position); compare with `steps`.
            error_estimate (str | Unset): How `estimated_error` was found, and where `global_error` is absent, why.
            global_error (float | None | Unset): The largest difference of the angle over the samples between this run
                and the same run at a tolerance a hundred times tighter: the global
                error, growth included. Absent where it did not fit (`error_estimate`).
            integrator_replaced_at (float | None | Unset): Mechanism form: the integrator asked (`dop853` or `radau5`) met a
                singular position at this time, s, where its steps leave the
                mechanism's branch (it may fold into another assembly); the run was
                made again from the start with `dopri5`, the pair whose steps the
                fold's hold keeps on the branch, and `integrator`, `steps` and
                `function_evaluations` are that run's (a warning says so too).
            stiff_at (float | None | Unset): Chosen automatically, the explicit pair found the model stiff (its
                steps held by stability, not accuracy) at this time, s, and the run
                was made again from the start with Radau IIA; `steps` and
                `function_evaluations` count both runs (as they do where a run
                ending at an angle was made twice for its samples: see `method`).
     """

    energy_residual: float
    estimated_error: float
    function_evaluations: int
    integrator: IntegratorChoice
    method: str
    steps: int
    constraint_drift: float | None | Unset = UNSET
    energy_conserved: bool | None | Unset = UNSET
    energy_form_time_difference: float | None | Unset = UNSET
    energy_held_steps: int | None | Unset = UNSET
    error_estimate: str | Unset = UNSET
    global_error: float | None | Unset = UNSET
    integrator_replaced_at: float | None | Unset = UNSET
    stiff_at: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        energy_residual = self.energy_residual

        estimated_error = self.estimated_error

        function_evaluations = self.function_evaluations

        integrator = self.integrator.value

        method = self.method

        steps = self.steps

        constraint_drift: float | None | Unset
        if isinstance(self.constraint_drift, Unset):
            constraint_drift = UNSET
        else:
            constraint_drift = self.constraint_drift

        energy_conserved: bool | None | Unset
        if isinstance(self.energy_conserved, Unset):
            energy_conserved = UNSET
        else:
            energy_conserved = self.energy_conserved

        energy_form_time_difference: float | None | Unset
        if isinstance(self.energy_form_time_difference, Unset):
            energy_form_time_difference = UNSET
        else:
            energy_form_time_difference = self.energy_form_time_difference

        energy_held_steps: int | None | Unset
        if isinstance(self.energy_held_steps, Unset):
            energy_held_steps = UNSET
        else:
            energy_held_steps = self.energy_held_steps

        error_estimate = self.error_estimate

        global_error: float | None | Unset
        if isinstance(self.global_error, Unset):
            global_error = UNSET
        else:
            global_error = self.global_error

        integrator_replaced_at: float | None | Unset
        if isinstance(self.integrator_replaced_at, Unset):
            integrator_replaced_at = UNSET
        else:
            integrator_replaced_at = self.integrator_replaced_at

        stiff_at: float | None | Unset
        if isinstance(self.stiff_at, Unset):
            stiff_at = UNSET
        else:
            stiff_at = self.stiff_at


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "energy_residual": energy_residual,
            "estimated_error": estimated_error,
            "function_evaluations": function_evaluations,
            "integrator": integrator,
            "method": method,
            "steps": steps,
        })
        if constraint_drift is not UNSET:
            field_dict["constraint_drift"] = constraint_drift
        if energy_conserved is not UNSET:
            field_dict["energy_conserved"] = energy_conserved
        if energy_form_time_difference is not UNSET:
            field_dict["energy_form_time_difference"] = energy_form_time_difference
        if energy_held_steps is not UNSET:
            field_dict["energy_held_steps"] = energy_held_steps
        if error_estimate is not UNSET:
            field_dict["error_estimate"] = error_estimate
        if global_error is not UNSET:
            field_dict["global_error"] = global_error
        if integrator_replaced_at is not UNSET:
            field_dict["integrator_replaced_at"] = integrator_replaced_at
        if stiff_at is not UNSET:
            field_dict["stiff_at"] = stiff_at

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        energy_residual = d.pop("energy_residual")

        estimated_error = d.pop("estimated_error")

        function_evaluations = d.pop("function_evaluations")

        integrator = IntegratorChoice(d.pop("integrator"))




        method = d.pop("method")

        steps = d.pop("steps")

        def _parse_constraint_drift(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        constraint_drift = _parse_constraint_drift(d.pop("constraint_drift", UNSET))


        def _parse_energy_conserved(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        energy_conserved = _parse_energy_conserved(d.pop("energy_conserved", UNSET))


        def _parse_energy_form_time_difference(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        energy_form_time_difference = _parse_energy_form_time_difference(d.pop("energy_form_time_difference", UNSET))


        def _parse_energy_held_steps(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        energy_held_steps = _parse_energy_held_steps(d.pop("energy_held_steps", UNSET))


        error_estimate = d.pop("error_estimate", UNSET)

        def _parse_global_error(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        global_error = _parse_global_error(d.pop("global_error", UNSET))


        def _parse_integrator_replaced_at(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        integrator_replaced_at = _parse_integrator_replaced_at(d.pop("integrator_replaced_at", UNSET))


        def _parse_stiff_at(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        stiff_at = _parse_stiff_at(d.pop("stiff_at", UNSET))


        instance_ = cls(
            energy_residual=energy_residual,
            estimated_error=estimated_error,
            function_evaluations=function_evaluations,
            integrator=integrator,
            method=method,
            steps=steps,
            constraint_drift=constraint_drift,
            energy_conserved=energy_conserved,
            energy_form_time_difference=energy_form_time_difference,
            energy_held_steps=energy_held_steps,
            error_estimate=error_estimate,
            global_error=global_error,
            integrator_replaced_at=integrator_replaced_at,
            stiff_at=stiff_at,
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
