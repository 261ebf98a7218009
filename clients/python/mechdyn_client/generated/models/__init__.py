""" Contains all the data models used in inputs/outputs """

from .accuracy_dto import AccuracyDto
from .angle_unit import AngleUnit
from .area_dto import AreaDto
from .at_angle import AtAngle
from .balance_dto import BalanceDto
from .balancing_correction_dto import BalancingCorrectionDto
from .balancing_request import BalancingRequest
from .balancing_residual_dto import BalancingResidualDto
from .balancing_result import BalancingResult
from .bearing_forces_dto import BearingForcesDto
from .body_dto import BodyDto
from .body_motion import BodyMotion
from .body_motion_3 import BodyMotion3
from .body_position import BodyPosition
from .cam_curve_dto import CamCurveDto
from .cam_dynamics_dto import CamDynamicsDto
from .cam_follower_dto import CamFollowerDto
from .cam_follower_motion import CamFollowerMotion
from .cam_follower_type import CamFollowerType
from .cam_friction_dto import CamFrictionDto
from .cam_lift_dto import CamLiftDto
from .cam_request import CamRequest
from .cam_result import CamResult
from .cam_sample import CamSample
from .cam_segment_dto import CamSegmentDto
from .cam_sense import CamSense
from .cam_size_dto import CamSizeDto
from .cam_spring_dto import CamSpringDto
from .cam_summary import CamSummary
from .check_dto import CheckDto
from .check_format import CheckFormat
from .check_item import CheckItem
from .check_request import CheckRequest
from .check_request_answers import CheckRequestAnswers
from .check_request_parameters_type_0 import CheckRequestParametersType0
from .check_request_request_type_0 import CheckRequestRequestType0
from .check_request_tolerances_type_0 import CheckRequestTolerancesType0
from .check_result import CheckResult
from .check_result_messages import CheckResultMessages
from .circle_dto import CircleDto
from .contact_dto import ContactDto
from .correction_plane_dto import CorrectionPlaneDto
from .count import Count
from .counterweight_dto import CounterweightDto
from .couple import Couple
from .curve_dto_type_0 import CurveDtoType0
from .curve_dto_type_1 import CurveDtoType1
from .curve_dto_type_2 import CurveDtoType2
from .curve_dto_type_3 import CurveDtoType3
from .curve_dto_type_4 import CurveDtoType4
from .curve_dto_type_5 import CurveDtoType5
from .decimal_mark import DecimalMark
from .dimension_dto import DimensionDto
from .disk_dto import DiskDto
from .disk_out import DiskOut
from .dynamic_unbalance_dto import DynamicUnbalanceDto
from .dynamics_accuracy import DynamicsAccuracy
from .dynamics_machine import DynamicsMachine
from .dynamics_request import DynamicsRequest
from .dynamics_request_constants_type_0 import DynamicsRequestConstantsType0
from .dynamics_result import DynamicsResult
from .dynamics_sample import DynamicsSample
from .dynamics_torque import DynamicsTorque
from .energy_dto import EnergyDto
from .equations import Equations
from .equivalent_request import EquivalentRequest
from .equivalent_request_points import EquivalentRequestPoints
from .equivalent_result import EquivalentResult
from .equivalent_result_masses import EquivalentResultMasses
from .event_dto import EventDto
from .field_error import FieldError
from .flywheel_dto import FlywheelDto
from .flywheel_request import FlywheelRequest
from .flywheel_request_constants_type_0 import FlywheelRequestConstantsType0
from .flywheel_result import FlywheelResult
from .flywheel_result_assembled_points_type_0 import FlywheelResultAssembledPointsType0
from .flywheel_sample import FlywheelSample
from .force import Force
from .format_ import Format
from .frame_dto import FrameDto
from .free_body import FreeBody
from .friction_dto import FrictionDto
from .function_spec import FunctionSpec
from .gear_request import GearRequest
from .gear_result import GearResult
from .get_template_job_parameters import GetTemplateJobParameters
from .get_template_result_part_parameters import GetTemplateResultPartParameters
from .given_speed import GivenSpeed
from .given_torque import GivenTorque
from .gradescope import Gradescope
from .gradescope_messages import GradescopeMessages
from .gradescope_test import GradescopeTest
from .group import Group
from .grubler_dto import GrublerDto
from .health import Health
from .in_spanish import InSpanish
from .in_spanish_parameters import InSpanishParameters
from .in_spanish_statement import InSpanishStatement
from .inertia_dto import InertiaDto
from .inertia_pair import InertiaPair
from .initial import Initial
from .input_coordinate import InputCoordinate
from .input_dto import InputDto
from .input_info import InputInfo
from .input_state import InputState
from .integrator_choice import IntegratorChoice
from .interpolation_dto import InterpolationDto
from .item_work import ItemWork
from .job_balancing import JobBalancing
from .job_balancing_kind import JobBalancingKind
from .job_balancing_request import JobBalancingRequest
from .job_cams import JobCams
from .job_cams_kind import JobCamsKind
from .job_cams_request import JobCamsRequest
from .job_check import JobCheck
from .job_check_kind import JobCheckKind
from .job_check_request import JobCheckRequest
from .job_dynamics import JobDynamics
from .job_dynamics_kind import JobDynamicsKind
from .job_dynamics_request import JobDynamicsRequest
from .job_equivalent_masses import JobEquivalentMasses
from .job_equivalent_masses_kind import JobEquivalentMassesKind
from .job_equivalent_masses_request import JobEquivalentMassesRequest
from .job_flywheel import JobFlywheel
from .job_flywheel_kind import JobFlywheelKind
from .job_flywheel_request import JobFlywheelRequest
from .job_gear_train import JobGearTrain
from .job_gear_train_kind import JobGearTrainKind
from .job_gear_train_request import JobGearTrainRequest
from .job_gears import JobGears
from .job_gears_kind import JobGearsKind
from .job_gears_request import JobGearsRequest
from .job_kinetostatics import JobKinetostatics
from .job_kinetostatics_kind import JobKinetostaticsKind
from .job_kinetostatics_request import JobKinetostaticsRequest
from .job_list import JobList
from .job_mobility import JobMobility
from .job_mobility_kind import JobMobilityKind
from .job_mobility_request import JobMobilityRequest
from .job_of_balancing_result import JobOfBalancingResult
from .job_of_balancing_result_request import JobOfBalancingResultRequest
from .job_of_cam_result import JobOfCamResult
from .job_of_cam_result_request import JobOfCamResultRequest
from .job_of_check_output import JobOfCheckOutput
from .job_of_check_output_request import JobOfCheckOutputRequest
from .job_of_dynamics_result import JobOfDynamicsResult
from .job_of_dynamics_result_request import JobOfDynamicsResultRequest
from .job_of_equivalent_result import JobOfEquivalentResult
from .job_of_equivalent_result_request import JobOfEquivalentResultRequest
from .job_of_flywheel_result import JobOfFlywheelResult
from .job_of_flywheel_result_request import JobOfFlywheelResultRequest
from .job_of_gear_result import JobOfGearResult
from .job_of_gear_result_request import JobOfGearResultRequest
from .job_of_kinetostatics_result import JobOfKinetostaticsResult
from .job_of_kinetostatics_result_request import JobOfKinetostaticsResultRequest
from .job_of_mobility_result import JobOfMobilityResult
from .job_of_mobility_result_request import JobOfMobilityResultRequest
from .job_of_rotor_result import JobOfRotorResult
from .job_of_rotor_result_request import JobOfRotorResultRequest
from .job_of_train_result import JobOfTrainResult
from .job_of_train_result_request import JobOfTrainResultRequest
from .job_rotor import JobRotor
from .job_rotor_kind import JobRotorKind
from .job_rotor_request import JobRotorRequest
from .job_status import JobStatus
from .joint_dto import JointDto
from .joint_type import JointType
from .kinetic_energy import KineticEnergy
from .kinetic_energy_bodies import KineticEnergyBodies
from .kinetostatics_accuracy import KinetostaticsAccuracy
from .kinetostatics_request import KinetostaticsRequest
from .kinetostatics_request_constants_type_0 import KinetostaticsRequestConstantsType0
from .kinetostatics_result import KinetostaticsResult
from .kinetostatics_result_assembled_points_type_0 import KinetostaticsResultAssembledPointsType0
from .line_dto import LineDto
from .list_jobs_kind import ListJobsKind
from .load_dto import LoadDto
from .load_type import LoadType
from .machine_dto import MachineDto
from .machine_dynamics import MachineDynamics
from .machine_dynamics_assembled_points_type_0 import MachineDynamicsAssembledPointsType0
from .machine_pose import MachinePose
from .machine_sample import MachineSample
from .mechanism_dto import MechanismDto
from .mechanism_dto_points_type_0 import MechanismDtoPointsType0
from .mechanism_space import MechanismSpace
from .member_result import MemberResult
from .mesh_dto import MeshDto
from .message_doc import MessageDoc
from .message_doc_args import MessageDocArgs
from .mobility_request import MobilityRequest
from .mobility_result import MobilityResult
from .mobility_space import MobilitySpace
from .new_template import NewTemplate
from .new_template_derived import NewTemplateDerived
from .new_template_parameters import NewTemplateParameters
from .new_template_request import NewTemplateRequest
from .new_template_statement import NewTemplateStatement
from .notes import Notes
from .notes_messages import NotesMessages
from .output_kind import OutputKind
from .page_template_parameters import PageTemplateParameters
from .pair_counts import PairCounts
from .pair_counts_pairs import PairCountsPairs
from .parameter import Parameter
from .plot_link import PlotLink
from .plot_list import PlotList
from .point_mass_dto import PointMassDto
from .point_state import PointState
from .polar_dto import PolarDto
from .potential_energy import PotentialEnergy
from .prairie_learn import PrairieLearn
from .prairie_learn_messages import PrairieLearnMessages
from .prairie_learn_test import PrairieLearnTest
from .problem import Problem
from .reaction_3 import Reaction3
from .reaction_dto import ReactionDto
from .reactions_dto import ReactionsDto
from .readiness import Readiness
from .rotor_request import RotorRequest
from .rotor_result import RotorResult
from .rotor_state_dto import RotorStateDto
from .scalar import Scalar
from .segment_dto import SegmentDto
from .segment_peaks import SegmentPeaks
from .shaking_dto import ShakingDto
from .sign_in import SignIn
from .solution import Solution
from .solution_numbering import SolutionNumbering
from .spatial_machine_dynamics import SpatialMachineDynamics
from .spatial_machine_sample import SpatialMachineSample
from .spline_dto import SplineDto
from .stated import Stated
from .step_dto import StepDto
from .step_dto_energy_contribution_type_0 import StepDtoEnergyContributionType0
from .summary_dto import SummaryDto
from .summary_dto_max_reaction import SummaryDtoMaxReaction
from .support_dto import SupportDto
from .table_dto import TableDto
from .table_request import TableRequest
from .table_request_rows_item import TableRequestRowsItem
from .table_response import TableResponse
from .table_row import TableRow
from .table_row_parameters import TableRowParameters
from .table_row_values import TableRowValues
from .template import Template
from .template_derived import TemplateDerived
from .template_list import TemplateList
from .template_parameters import TemplateParameters
from .template_request import TemplateRequest
from .template_statement import TemplateStatement
from .timing import Timing
from .tolerance_dto import ToleranceDto
from .torque_dto import TorqueDto
from .track_dto_type_1 import TrackDtoType1
from .train_request import TrainRequest
from .train_result import TrainResult
from .unbalance_dto import UnbalanceDto
from .values import Values
from .variant import Variant
from .variant_parameters import VariantParameters
from .variant_values import VariantValues
from .variants import Variants
from .virtual_power import VirtualPower
from .virtual_power_actions import VirtualPowerActions

__all__ = (
    "AccuracyDto",
    "AngleUnit",
    "AreaDto",
    "AtAngle",
    "BalanceDto",
    "BalancingCorrectionDto",
    "BalancingRequest",
    "BalancingResidualDto",
    "BalancingResult",
    "BearingForcesDto",
    "BodyDto",
    "BodyMotion",
    "BodyMotion3",
    "BodyPosition",
    "CamCurveDto",
    "CamDynamicsDto",
    "CamFollowerDto",
    "CamFollowerMotion",
    "CamFollowerType",
    "CamFrictionDto",
    "CamLiftDto",
    "CamRequest",
    "CamResult",
    "CamSample",
    "CamSegmentDto",
    "CamSense",
    "CamSizeDto",
    "CamSpringDto",
    "CamSummary",
    "CheckDto",
    "CheckFormat",
    "CheckItem",
    "CheckRequest",
    "CheckRequestAnswers",
    "CheckRequestParametersType0",
    "CheckRequestRequestType0",
    "CheckRequestTolerancesType0",
    "CheckResult",
    "CheckResultMessages",
    "CircleDto",
    "ContactDto",
    "CorrectionPlaneDto",
    "Count",
    "CounterweightDto",
    "Couple",
    "CurveDtoType0",
    "CurveDtoType1",
    "CurveDtoType2",
    "CurveDtoType3",
    "CurveDtoType4",
    "CurveDtoType5",
    "DecimalMark",
    "DimensionDto",
    "DiskDto",
    "DiskOut",
    "DynamicsAccuracy",
    "DynamicsMachine",
    "DynamicsRequest",
    "DynamicsRequestConstantsType0",
    "DynamicsResult",
    "DynamicsSample",
    "DynamicsTorque",
    "DynamicUnbalanceDto",
    "EnergyDto",
    "Equations",
    "EquivalentRequest",
    "EquivalentRequestPoints",
    "EquivalentResult",
    "EquivalentResultMasses",
    "EventDto",
    "FieldError",
    "FlywheelDto",
    "FlywheelRequest",
    "FlywheelRequestConstantsType0",
    "FlywheelResult",
    "FlywheelResultAssembledPointsType0",
    "FlywheelSample",
    "Force",
    "Format",
    "FrameDto",
    "FreeBody",
    "FrictionDto",
    "FunctionSpec",
    "GearRequest",
    "GearResult",
    "GetTemplateJobParameters",
    "GetTemplateResultPartParameters",
    "GivenSpeed",
    "GivenTorque",
    "Gradescope",
    "GradescopeMessages",
    "GradescopeTest",
    "Group",
    "GrublerDto",
    "Health",
    "InertiaDto",
    "InertiaPair",
    "Initial",
    "InputCoordinate",
    "InputDto",
    "InputInfo",
    "InputState",
    "InSpanish",
    "InSpanishParameters",
    "InSpanishStatement",
    "IntegratorChoice",
    "InterpolationDto",
    "ItemWork",
    "JobBalancing",
    "JobBalancingKind",
    "JobBalancingRequest",
    "JobCams",
    "JobCamsKind",
    "JobCamsRequest",
    "JobCheck",
    "JobCheckKind",
    "JobCheckRequest",
    "JobDynamics",
    "JobDynamicsKind",
    "JobDynamicsRequest",
    "JobEquivalentMasses",
    "JobEquivalentMassesKind",
    "JobEquivalentMassesRequest",
    "JobFlywheel",
    "JobFlywheelKind",
    "JobFlywheelRequest",
    "JobGears",
    "JobGearsKind",
    "JobGearsRequest",
    "JobGearTrain",
    "JobGearTrainKind",
    "JobGearTrainRequest",
    "JobKinetostatics",
    "JobKinetostaticsKind",
    "JobKinetostaticsRequest",
    "JobList",
    "JobMobility",
    "JobMobilityKind",
    "JobMobilityRequest",
    "JobOfBalancingResult",
    "JobOfBalancingResultRequest",
    "JobOfCamResult",
    "JobOfCamResultRequest",
    "JobOfCheckOutput",
    "JobOfCheckOutputRequest",
    "JobOfDynamicsResult",
    "JobOfDynamicsResultRequest",
    "JobOfEquivalentResult",
    "JobOfEquivalentResultRequest",
    "JobOfFlywheelResult",
    "JobOfFlywheelResultRequest",
    "JobOfGearResult",
    "JobOfGearResultRequest",
    "JobOfKinetostaticsResult",
    "JobOfKinetostaticsResultRequest",
    "JobOfMobilityResult",
    "JobOfMobilityResultRequest",
    "JobOfRotorResult",
    "JobOfRotorResultRequest",
    "JobOfTrainResult",
    "JobOfTrainResultRequest",
    "JobRotor",
    "JobRotorKind",
    "JobRotorRequest",
    "JobStatus",
    "JointDto",
    "JointType",
    "KineticEnergy",
    "KineticEnergyBodies",
    "KinetostaticsAccuracy",
    "KinetostaticsRequest",
    "KinetostaticsRequestConstantsType0",
    "KinetostaticsResult",
    "KinetostaticsResultAssembledPointsType0",
    "LineDto",
    "ListJobsKind",
    "LoadDto",
    "LoadType",
    "MachineDto",
    "MachineDynamics",
    "MachineDynamicsAssembledPointsType0",
    "MachinePose",
    "MachineSample",
    "MechanismDto",
    "MechanismDtoPointsType0",
    "MechanismSpace",
    "MemberResult",
    "MeshDto",
    "MessageDoc",
    "MessageDocArgs",
    "MobilityRequest",
    "MobilityResult",
    "MobilitySpace",
    "NewTemplate",
    "NewTemplateDerived",
    "NewTemplateParameters",
    "NewTemplateRequest",
    "NewTemplateStatement",
    "Notes",
    "NotesMessages",
    "OutputKind",
    "PageTemplateParameters",
    "PairCounts",
    "PairCountsPairs",
    "Parameter",
    "PlotLink",
    "PlotList",
    "PointMassDto",
    "PointState",
    "PolarDto",
    "PotentialEnergy",
    "PrairieLearn",
    "PrairieLearnMessages",
    "PrairieLearnTest",
    "Problem",
    "Reaction3",
    "ReactionDto",
    "ReactionsDto",
    "Readiness",
    "RotorRequest",
    "RotorResult",
    "RotorStateDto",
    "Scalar",
    "SegmentDto",
    "SegmentPeaks",
    "ShakingDto",
    "SignIn",
    "Solution",
    "SolutionNumbering",
    "SpatialMachineDynamics",
    "SpatialMachineSample",
    "SplineDto",
    "Stated",
    "StepDto",
    "StepDtoEnergyContributionType0",
    "SummaryDto",
    "SummaryDtoMaxReaction",
    "SupportDto",
    "TableDto",
    "TableRequest",
    "TableRequestRowsItem",
    "TableResponse",
    "TableRow",
    "TableRowParameters",
    "TableRowValues",
    "Template",
    "TemplateDerived",
    "TemplateList",
    "TemplateParameters",
    "TemplateRequest",
    "TemplateStatement",
    "Timing",
    "ToleranceDto",
    "TorqueDto",
    "TrackDtoType1",
    "TrainRequest",
    "TrainResult",
    "UnbalanceDto",
    "Values",
    "Variant",
    "VariantParameters",
    "Variants",
    "VariantValues",
    "VirtualPower",
    "VirtualPowerActions",
)
