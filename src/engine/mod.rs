//! The calculation engine: pure math on validated SI inputs.
//!
//! Nothing here knows about HTTP, JSON, SQL or files; inputs are plain
//! structs, results are plain structs, and conditions worth reporting are
//! result values, not errors. Errors carry the context needed to explain
//! them ([`EngineError`]).

pub mod balancing;
pub mod cam;
pub mod constraints;
pub mod curves;
pub mod deadline;
pub mod dynamics;
pub mod equivalent;
pub mod expr;
pub mod flywheel;
pub mod function;
pub mod gear_train;
pub mod gears;
pub mod grading;
pub mod kinematics;
pub mod kinetostatics;
pub mod machine;
pub mod mobility;
pub mod model;
pub mod numeric;
pub mod rotor;
pub mod samples;
pub mod shaking;
pub mod sketch;
pub mod spatial;
pub mod touch;
pub mod variants;

pub use deadline::{Deadline, Phase, Progress};

/// Why a problem has no answer.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum EngineError {
    /// A function evaluates to NaN or infinity inside the cycle.
    #[error("{function} is not finite at phi = {phi} rad")]
    NotFinite { function: String, phi: f64 },
    /// A reduced inertia below zero.
    #[error("{function} is negative ({value} kg*m^2) at phi = {phi} rad")]
    NegativeInertia { function: String, phi: f64, value: f64 },
    /// The loads do no zero net work over a cycle and nothing balances them.
    #[error(
        "the cycle is not in steady state: the net work of the torques over a cycle is {net_work} J \
         (largest lobe {largest_area} J); add a torque with \"balance\": true or correct the loads"
    )]
    NotSteady { net_work: f64, largest_area: f64 },
    /// Newton–Raphson did not assemble the mechanism at an input position;
    /// `joint` is where the gap stayed widest (the loop that does not close).
    #[error(
        "the mechanism cannot be assembled at input {input} (step {step}): the loop through {joint} does not close \
         (Newton-Raphson stopped {residual:.1e} short; e.g. a non-Grashof crank asked for a full turn)"
    )]
    NewtonDiverged { step: usize, input: f64, residual: f64, joint: String },
    /// The joints leave no degree of freedom: a structure, which no input can move.
    #[error(
        "the mechanism is locked: its joints leave it no degree of freedom (0 by the rank of the joint Jacobian; \
         Grübler's count 3(N - 1) - 2 P_I - P_II = {grubler}), so no input can move it; remove a joint or \
         make one a slider"
    )]
    Locked { grubler: i64 },
    /// The constraint Jacobian is singular (a dead centre or toggle position the input cannot pass).
    #[error(
        "the mechanism is at a singular position at step {step} (input {input}): the constraint Jacobian loses rank"
    )]
    Singular { step: usize, input: f64 },
    /// A machine's cycle passes positions it cannot pass (singular, or where
    /// its configuration jumps): its reduced inertia and torque are not finite there.
    #[error(
        "the machine cannot pass {count} position(s) of its cycle, the first at input {input}: the constraint \
         Jacobian loses rank there or a point runs out to infinity, so I* and M* are not finite over the cycle"
    )]
    SingularCycle { input: f64, count: usize },
    /// The inputs do not match the degrees of freedom (a body left free, or inputs that conflict).
    #[error(
        "the mechanism has {dof} degree(s) of freedom but {inputs} input(s): give one input per degree of \
         freedom (a body with too few joints moves freely; too many inputs conflict)"
    )]
    DofMismatch { dof: usize, inputs: usize },
    /// No finite effort drives the mechanism at this position with the
    /// given friction (self-locking); it would with every coefficient
    /// scaled below `limit` (in 0..1).
    #[error(
        "no finite effort drives the mechanism at input {input} (step {step}) with this friction (self-locking); \
         it would move with friction coefficients below {limit} of the given ones"
    )]
    FrictionDiverged { step: usize, input: f64, limit: f64 },
    /// The actuators' efforts do no work on the inputs' motion here: they cannot drive them.
    #[error(
        "the actuator(s) {actuators} cannot drive the inputs at input {input} (step {step}): moving the inputs \
         does not move them (their effort would be carried by the joints); choose an actuator the input's motion moves"
    )]
    Unactuated { step: usize, input: f64, actuators: String },
    /// The computation produced a non-finite number (never returned as a result).
    #[error("the computation produced a non-finite number; the input is numerically degenerate")]
    NotFiniteResult,
    /// The job ran out of its wall-clock compute budget and was stopped.
    #[error(
        "the compute budget of {seconds} s ran out ({progress}); ask for fewer steps, samples or bodies, \
         or a looser tolerance"
    )]
    BudgetExceeded { seconds: f64, progress: deadline::Progress },
}
