from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, BinaryIO, TextIO, TYPE_CHECKING, Generator

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

from ..types import UNSET, Unset
from typing import cast

if TYPE_CHECKING:
  from ..models.accuracy_dto import AccuracyDto
  from ..models.area_dto import AreaDto
  from ..models.check_dto import CheckDto
  from ..models.disk_out import DiskOut
  from ..models.flywheel_result_assembled_points_type_0 import FlywheelResultAssembledPointsType0
  from ..models.flywheel_sample import FlywheelSample
  from ..models.inertia_pair import InertiaPair
  from ..models.item_work import ItemWork
  from ..models.machine_pose import MachinePose
  from ..models.notes_messages import NotesMessages





T = TypeVar("T", bound="FlywheelResult")



@_attrs_define
class FlywheelResult:
    """ Result of a flywheel job (SI units: rad, rad/s, N·m, J, W, kg·m², kg, m).

        Attributes:
            warnings (list[str]): What to know before trusting the numbers: a condition met on the
                way (a tolerance nearly spent, a geometry nearly singular, a law
                of design broken), in the asker's language.
            accuracy (AccuracyDto):
            areas (list[AreaDto]):
            crossings (list[float]): Angles in (0, period) where M* changes sign.
            cumulative (list[float]): S_i: running sums of the areas.
            energy_fluctuation (float): ΔE = S_max − S_min, J.
            flywheel_inertia (InertiaPair):
            inertia_approximate (float): ΔE/(ε ω_a²), I* neglected: the total inertia on the reference shaft, kg·m².
            inertia_exact (float): The total inertia on the reference shaft, exactly (Wittenbauer): the
                constant inertia I with which I + I*(φ) runs at exactly ε and ω_a, plus
                `least_reduced_inertia` (the machine's inertia there at every angle, a
                pulley's), kg·m². The same whether a pulley is a body of the `machine`
                or `existing_inertia`.
            item_work (list[ItemWork]):
            kinetic_energy_at_start (float): ½(I + I*(0))ω(0)², J.
            least_reduced_inertia (float): min I*(φ) over the cycle (of `reduced_inertia` and the `machine`), kg·m².
            mean_power (float): Mean power of the torques doing positive work over the cycle, W.
            omega_at_start (float): ω at φ = 0 in the exact steady state.
            omega_max (float):
            omega_min (float):
            phi_at_omega_max (float):
            phi_at_omega_min (float):
            samples (list[FlywheelSample]):
            messages (NotesMessages | Unset): The catalogue's message each text of this result was written from,
                by JSON pointer into the result (`/warnings/0`, `/accuracy/method`):
                match a warning by its `id`; the texts themselves are in the
                language asked for (`Accept-Language`, `?lang=`).
            assembled_points (FlywheelResultAssembledPointsType0 | None | Unset): Where a machine's points went, for a
                mechanism given by its `dimensions` (m).
            balance_torque (float | None | Unset): Solved balance torque on its own shaft, N·m.
            check (CheckDto | None | Unset):
            disk (DiskOut | None | Unset):
            machine_poses (list[MachinePose] | None | Unset): A `machine`'s moving bodies at evenly spaced input angles over
                the
                period (its motion on the page).
     """

    warnings: list[str]
    accuracy: AccuracyDto
    areas: list[AreaDto]
    crossings: list[float]
    cumulative: list[float]
    energy_fluctuation: float
    flywheel_inertia: InertiaPair
    inertia_approximate: float
    inertia_exact: float
    item_work: list[ItemWork]
    kinetic_energy_at_start: float
    least_reduced_inertia: float
    mean_power: float
    omega_at_start: float
    omega_max: float
    omega_min: float
    phi_at_omega_max: float
    phi_at_omega_min: float
    samples: list[FlywheelSample]
    messages: NotesMessages | Unset = UNSET
    assembled_points: FlywheelResultAssembledPointsType0 | None | Unset = UNSET
    balance_torque: float | None | Unset = UNSET
    check: CheckDto | None | Unset = UNSET
    disk: DiskOut | None | Unset = UNSET
    machine_poses: list[MachinePose] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)





    def to_dict(self) -> dict[str, Any]:
        from ..models.accuracy_dto import AccuracyDto # noqa: PLC0415
        from ..models.area_dto import AreaDto # noqa: PLC0415
        from ..models.check_dto import CheckDto # noqa: PLC0415
        from ..models.disk_out import DiskOut # noqa: PLC0415
        from ..models.flywheel_result_assembled_points_type_0 import FlywheelResultAssembledPointsType0 # noqa: PLC0415
        from ..models.flywheel_sample import FlywheelSample # noqa: PLC0415
        from ..models.inertia_pair import InertiaPair # noqa: PLC0415
        from ..models.item_work import ItemWork # noqa: PLC0415
        from ..models.machine_pose import MachinePose # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        warnings = self.warnings



        accuracy = self.accuracy.to_dict()

        areas = []
        for areas_item_data in self.areas:
            areas_item = areas_item_data.to_dict()
            areas.append(areas_item)



        crossings = self.crossings



        cumulative = self.cumulative



        energy_fluctuation = self.energy_fluctuation

        flywheel_inertia = self.flywheel_inertia.to_dict()

        inertia_approximate = self.inertia_approximate

        inertia_exact = self.inertia_exact

        item_work = []
        for item_work_item_data in self.item_work:
            item_work_item = item_work_item_data.to_dict()
            item_work.append(item_work_item)



        kinetic_energy_at_start = self.kinetic_energy_at_start

        least_reduced_inertia = self.least_reduced_inertia

        mean_power = self.mean_power

        omega_at_start = self.omega_at_start

        omega_max = self.omega_max

        omega_min = self.omega_min

        phi_at_omega_max = self.phi_at_omega_max

        phi_at_omega_min = self.phi_at_omega_min

        samples = []
        for samples_item_data in self.samples:
            samples_item = samples_item_data.to_dict()
            samples.append(samples_item)



        messages: dict[str, Any] | Unset = UNSET
        if not isinstance(self.messages, Unset):
            messages = self.messages.to_dict()

        assembled_points: dict[str, Any] | None | Unset
        if isinstance(self.assembled_points, Unset):
            assembled_points = UNSET
        elif isinstance(self.assembled_points, FlywheelResultAssembledPointsType0):
            assembled_points = self.assembled_points.to_dict()
        else:
            assembled_points = self.assembled_points

        balance_torque: float | None | Unset
        if isinstance(self.balance_torque, Unset):
            balance_torque = UNSET
        else:
            balance_torque = self.balance_torque

        check: dict[str, Any] | None | Unset
        if isinstance(self.check, Unset):
            check = UNSET
        elif isinstance(self.check, CheckDto):
            check = self.check.to_dict()
        else:
            check = self.check

        disk: dict[str, Any] | None | Unset
        if isinstance(self.disk, Unset):
            disk = UNSET
        elif isinstance(self.disk, DiskOut):
            disk = self.disk.to_dict()
        else:
            disk = self.disk

        machine_poses: list[dict[str, Any]] | None | Unset
        if isinstance(self.machine_poses, Unset):
            machine_poses = UNSET
        elif isinstance(self.machine_poses, list):
            machine_poses = []
            for machine_poses_item_data in self.machine_poses:
                machine_poses_item = machine_poses_item_data.to_dict()
                machine_poses.append(machine_poses_item)


        else:
            machine_poses = self.machine_poses


        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({
            "warnings": warnings,
            "accuracy": accuracy,
            "areas": areas,
            "crossings": crossings,
            "cumulative": cumulative,
            "energy_fluctuation": energy_fluctuation,
            "flywheel_inertia": flywheel_inertia,
            "inertia_approximate": inertia_approximate,
            "inertia_exact": inertia_exact,
            "item_work": item_work,
            "kinetic_energy_at_start": kinetic_energy_at_start,
            "least_reduced_inertia": least_reduced_inertia,
            "mean_power": mean_power,
            "omega_at_start": omega_at_start,
            "omega_max": omega_max,
            "omega_min": omega_min,
            "phi_at_omega_max": phi_at_omega_max,
            "phi_at_omega_min": phi_at_omega_min,
            "samples": samples,
        })
        if messages is not UNSET:
            field_dict["messages"] = messages
        if assembled_points is not UNSET:
            field_dict["assembled_points"] = assembled_points
        if balance_torque is not UNSET:
            field_dict["balance_torque"] = balance_torque
        if check is not UNSET:
            field_dict["check"] = check
        if disk is not UNSET:
            field_dict["disk"] = disk
        if machine_poses is not UNSET:
            field_dict["machine_poses"] = machine_poses

        return field_dict



    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.accuracy_dto import AccuracyDto # noqa: PLC0415
        from ..models.area_dto import AreaDto # noqa: PLC0415
        from ..models.check_dto import CheckDto # noqa: PLC0415
        from ..models.disk_out import DiskOut # noqa: PLC0415
        from ..models.flywheel_result_assembled_points_type_0 import FlywheelResultAssembledPointsType0 # noqa: PLC0415
        from ..models.flywheel_sample import FlywheelSample # noqa: PLC0415
        from ..models.inertia_pair import InertiaPair # noqa: PLC0415
        from ..models.item_work import ItemWork # noqa: PLC0415
        from ..models.machine_pose import MachinePose # noqa: PLC0415
        from ..models.notes_messages import NotesMessages # noqa: PLC0415
        d = dict(src_dict)
        warnings = cast(list[str], d.pop("warnings"))


        accuracy = AccuracyDto.from_dict(d.pop("accuracy"))




        areas = []
        _areas = d.pop("areas")
        for areas_item_data in (_areas):
            areas_item = AreaDto.from_dict(areas_item_data)



            areas.append(areas_item)


        crossings = cast(list[float], d.pop("crossings"))


        cumulative = cast(list[float], d.pop("cumulative"))


        energy_fluctuation = d.pop("energy_fluctuation")

        flywheel_inertia = InertiaPair.from_dict(d.pop("flywheel_inertia"))




        inertia_approximate = d.pop("inertia_approximate")

        inertia_exact = d.pop("inertia_exact")

        item_work = []
        _item_work = d.pop("item_work")
        for item_work_item_data in (_item_work):
            item_work_item = ItemWork.from_dict(item_work_item_data)



            item_work.append(item_work_item)


        kinetic_energy_at_start = d.pop("kinetic_energy_at_start")

        least_reduced_inertia = d.pop("least_reduced_inertia")

        mean_power = d.pop("mean_power")

        omega_at_start = d.pop("omega_at_start")

        omega_max = d.pop("omega_max")

        omega_min = d.pop("omega_min")

        phi_at_omega_max = d.pop("phi_at_omega_max")

        phi_at_omega_min = d.pop("phi_at_omega_min")

        samples = []
        _samples = d.pop("samples")
        for samples_item_data in (_samples):
            samples_item = FlywheelSample.from_dict(samples_item_data)



            samples.append(samples_item)


        _messages = d.pop("messages", UNSET)
        messages: NotesMessages | Unset
        if isinstance(_messages,  Unset):
            messages = UNSET
        else:
            messages = NotesMessages.from_dict(_messages)




        def _parse_assembled_points(data: object) -> FlywheelResultAssembledPointsType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                assembled_points_type_0 = FlywheelResultAssembledPointsType0.from_dict(data)



                return assembled_points_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(FlywheelResultAssembledPointsType0 | None | Unset, data)

        assembled_points = _parse_assembled_points(d.pop("assembled_points", UNSET))


        def _parse_balance_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        balance_torque = _parse_balance_torque(d.pop("balance_torque", UNSET))


        def _parse_check(data: object) -> CheckDto | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                check_type_0 = CheckDto.from_dict(data)



                return check_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(CheckDto | None | Unset, data)

        check = _parse_check(d.pop("check", UNSET))


        def _parse_disk(data: object) -> DiskOut | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                disk_type_0 = DiskOut.from_dict(data)



                return disk_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(DiskOut | None | Unset, data)

        disk = _parse_disk(d.pop("disk", UNSET))


        def _parse_machine_poses(data: object) -> list[MachinePose] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                machine_poses_type_0 = []
                _machine_poses_type_0 = data
                for machine_poses_type_0_item_data in (_machine_poses_type_0):
                    machine_poses_type_0_item = MachinePose.from_dict(machine_poses_type_0_item_data)



                    machine_poses_type_0.append(machine_poses_type_0_item)

                return machine_poses_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[MachinePose] | None | Unset, data)

        machine_poses = _parse_machine_poses(d.pop("machine_poses", UNSET))


        instance_ = cls(
            warnings=warnings,
            accuracy=accuracy,
            areas=areas,
            crossings=crossings,
            cumulative=cumulative,
            energy_fluctuation=energy_fluctuation,
            flywheel_inertia=flywheel_inertia,
            inertia_approximate=inertia_approximate,
            inertia_exact=inertia_exact,
            item_work=item_work,
            kinetic_energy_at_start=kinetic_energy_at_start,
            least_reduced_inertia=least_reduced_inertia,
            mean_power=mean_power,
            omega_at_start=omega_at_start,
            omega_max=omega_max,
            omega_min=omega_min,
            phi_at_omega_max=phi_at_omega_max,
            phi_at_omega_min=phi_at_omega_min,
            samples=samples,
            messages=messages,
            assembled_points=assembled_points,
            balance_torque=balance_torque,
            check=check,
            disk=disk,
            machine_poses=machine_poses,
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
