//! A 1-DOF mechanism seen from its input: the reduced inertia I*(φ), its
//! slope dI*/dφ and the reduced torque M*(φ) of its loads, evaluated exactly
//! at any φ (Zhukovsky):
//!
//! ```text
//! g = dq/dφ (Φ_q g = e_driver),  h = d²q/dφ² (Φ_q h = γ at unit speed)
//! I* = gᵀ M g,   dI*/dφ = 2 gᵀ M h,   M* = gᵀ Q(q, q̇ = g·ω)
//! ```
//!
//! Every evaluation assembles the mechanism by Newton–Raphson from the
//! nearest of a ring of anchor configurations, so quadrature and root finding
//! see the true functions, not an interpolation of a coarse grid.

use super::function::{Curve, Function};
use super::kinematics::{Conditions, Workspace, sweep};
use super::kinetostatics::{Load, applied_forces};
use super::model::Mechanism;
use super::{Deadline, EngineError};
use std::f64::consts::PI;
use std::sync::{Arc, Mutex};

/// Anchor configurations per period.
const ANCHORS: usize = 360;

/// The last evaluation, φ and [I*, dI*/dφ, M*] there (None where it does
/// not assemble): the three are usually asked at the same φ in turn.
pub type Last = Mutex<Option<(f64, Option<[f64; 3]>)>>;

/// What a machine function returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reduced {
    Inertia,
    InertiaSlope,
    Torque,
}

/// A 1-DOF machine reduced to its input, planar ([`Machine`]) or spatial.
pub trait Reduces: Send + Sync + std::fmt::Debug {
    /// I*, dI*/dφ or M* at φ; NaN where the mechanism cannot be assembled
    /// or once the deadline has passed.
    fn eval(&self, phi: f64, what: Reduced) -> f64;
    /// The loads' breakpoints in (0, period), for the flywheel's pieces.
    fn breakpoints(&self) -> Vec<f64>;
}

/// One reduced quantity of a machine as a function of φ.
#[derive(Debug)]
pub struct ReducedCurve {
    pub machine: Arc<dyn Reduces>,
    pub what: Reduced,
}

impl ReducedCurve {
    /// `what` of `machine` as a function of φ.
    pub fn function(machine: Arc<dyn Reduces>, what: Reduced) -> Function {
        Function::Curve(Arc::new(Self { machine, what }))
    }
}

impl Curve for ReducedCurve {
    fn eval(&self, phi: f64) -> f64 {
        self.machine.eval(phi, self.what)
    }
    fn derivative(&self) -> Option<Arc<dyn Curve>> {
        let machine = self.machine.clone();
        (self.what == Reduced::Inertia).then(|| Arc::new(ReducedCurve { machine, what: Reduced::InertiaSlope }) as _)
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.machine.breakpoints()
    }
}

/// An assembled configuration q at φ with its velocity coefficients g and h.
#[derive(Debug)]
pub struct Anchor {
    pub phi: f64,
    pub q: Vec<f64>,
    pub g: Vec<f64>,
    pub h: Vec<f64>,
}

/// A driven 1-DOF mechanism with its loads, reduced to its input coordinate.
#[derive(Debug)]
pub struct Machine {
    mechanism: Mechanism,
    loads: Vec<Load>,
    /// Input speed used for velocity-dependent loads (dampers).
    speed: f64,
    period: f64,
    anchors: Vec<Anchor>,
    last: Last,
    /// Past it, every evaluation is NaN (the caller reports the budget).
    deadline: Deadline,
}

impl Machine {
    /// Assembles the mechanism around one period of its (single) input.
    pub fn new(
        mechanism: Mechanism,
        loads: Vec<Load>,
        speed: f64,
        period: f64,
        deadline: Deadline,
    ) -> Result<Self, EngineError> {
        let dof = super::mobility::mobility(&mechanism, &mechanism.reference_q()).dof;
        if dof != 1 {
            return Err(EngineError::DofMismatch { dof, inputs: 1 });
        }
        let positions: Vec<Vec<[f64; 3]>> =
            (0..ANCHORS).map(|k| vec![[period * k as f64 / ANCHORS as f64, 1.0, 0.0]]).collect();
        let configurations = sweep(&mechanism, &positions, &deadline, Conditions::Scaled)?;
        let passed: Vec<bool> = configurations.iter().map(|c| !c.singular).collect();
        let anchors: Vec<Anchor> = configurations
            .into_iter()
            .zip(&positions)
            .map(|(c, p)| Anchor { phi: p[0][0], q: c.q, g: c.qd, h: c.qdd })
            .collect();
        // A position it cannot pass (Φ_q singular there, or a point running
        // out to infinity between two anchors and back from the other side):
        // I* and M* are not finite there.
        let mut impassable: Vec<f64> = anchors.iter().zip(&passed).filter(|(_, p)| !**p).map(|(a, _)| a.phi).collect();
        let (coordinates, angle) = (mechanism.n_body_coordinates(), |c: usize| c % 3 == 2);
        // The mechanism's size: its farthest centre of mass from the origin.
        let size = anchors
            .iter()
            .flat_map(|a| (0..coordinates).filter(|&c| !angle(c)).map(|c| a.q[c].abs()))
            .fold(0.0, f64::max);
        impassable.extend(jumps(&anchors, &passed, (coordinates, size), angle));
        impassable.sort_by(f64::total_cmp);
        if let Some(&input) = impassable.first() {
            return Err(EngineError::SingularCycle { input, count: impassable.len() });
        }
        Ok(Self { mechanism, loads, speed, period, anchors, last: Mutex::new(None), deadline })
    }

    /// The mechanism's coordinates q at φ (the period's configuration: the
    /// input taken modulo the period), None where it cannot be assembled.
    pub fn pose(&self, phi: f64) -> Option<Vec<f64>> {
        self.assembled(phi).map(|(q, _, _)| q)
    }

    /// The machine's mechanism (without its drivers' positions).
    pub fn mechanism(&self) -> &Mechanism {
        &self.mechanism
    }

    /// q at φ with its workspace holding q̇ and q̈ per unit input speed, and
    /// φ within the period.
    fn assembled(&self, phi: f64) -> Option<(Vec<f64>, Workspace, f64)> {
        let u = phi.rem_euclid(self.period);
        let k = ((u / self.period * ANCHORS as f64).round() as usize) % ANCHORS;
        let Anchor { phi: at, q: q0, g: g0, h: h0 } = &self.anchors[k];
        let mut d = u - at;
        if d > self.period / 2.0 {
            d -= self.period;
        }
        let mut q: Vec<f64> = (0..q0.len()).map(|i| q0[i] + g0[i] * d + 0.5 * h0[i] * d * d).collect();
        // The input measured from the anchor (u − period just below a full
        // turn): the same configuration, and Newton starts next to it instead
        // of a whole turn away, where it may settle on the other branch.
        let unit = [[at + d, 1.0, 0.0]];
        let m = &self.mechanism;
        let mut ws = Workspace::default();
        ws.assemble(m, &mut q, &unit, 0).ok()?;
        ws.motion(m, &q, &unit).then_some(())?;
        Some((q, ws, u))
    }

    fn reduced(&self, phi: f64) -> Option<[f64; 3]> {
        let (q, ws, u) = self.assembled(phi)?;
        let m = &self.mechanism;
        let (g, h) = (&ws.qd, &ws.qdd);
        let mass = |k: usize| m.mass_of(k);
        let inertia = (0..g.len()).map(|k| mass(k) * g[k] * g[k]).sum();
        let slope = 2.0 * (0..g.len()).map(|k| mass(k) * g[k] * h[k]).sum::<f64>();
        let qd: Vec<f64> = g.iter().map(|v| v * self.speed).collect();
        let qv = applied_forces(m, &self.loads, &q, &qd, u, [self.speed, 0.0]);
        let torque = g.iter().zip(qv.iter()).map(|(a, b)| a * b).sum();
        Some([inertia, slope, torque])
    }
}

impl Reduces for Machine {
    fn breakpoints(&self) -> Vec<f64> {
        let mut b = Vec::new();
        for load in &self.loads {
            match load {
                Load::Force { magnitude: f, .. } | Load::Torque { value: f, .. } => {
                    b.extend(f.breakpoints(self.period))
                }
                _ => {}
            }
        }
        b
    }

    fn eval(&self, phi: f64, what: Reduced) -> f64 {
        if self.deadline.expired() {
            return f64::NAN;
        }
        remembered(&self.last, phi, what, || self.reduced(phi))
    }
}

/// `what` of the values at φ, from `last` where it was the last φ asked
/// (I*, dI*/dφ and M* are usually asked at the same φ in turn), else
/// from `reduce`; NaN where there are none.
pub fn remembered(last: &Last, phi: f64, what: Reduced, reduce: impl FnOnce() -> Option<[f64; 3]>) -> f64 {
    let cached = last.lock().ok().and_then(|l| l.filter(|(at, _)| *at == phi));
    let values = match cached {
        Some((_, v)) => v,
        None => {
            let v = reduce();
            if let Ok(mut l) = last.lock() {
                *l = Some((phi, v));
            }
            v
        }
    };
    values.map_or(f64::NAN, |[i, di, m]| match what {
        Reduced::Inertia => i,
        Reduced::InertiaSlope => di,
        Reduced::Torque => m,
    })
}

/// The inputs halfway between two anchors where a body coordinate jumps: its step
/// to the next anchor off the trapezoid rule's, q_{k+1} − q_k ≈ (g_k +
/// g_{k+1})·Δφ/2, by more than half the larger of the two (a smooth motion
/// is off by ~Δφ²·q‴/(12 q′) of it, 1e-4 here) and by more than a millionth
/// of its largest step and a billionth of the mechanism's size (rounding, a
/// coordinate that does not move); angles modulo 2π. A point running out to
/// infinity between two anchors comes back from the other side (y = d·tan φ:
/// both slopes huge and positive, the step negative). Pairs with a singular
/// anchor (not `passed`, its slopes unknown) are left to it. Coordinate c
/// is an angle where `angle(c)`; `size` is the mechanism's, m.
pub fn jumps(
    anchors: &[Anchor],
    passed: &[bool],
    (coordinates, size): (usize, f64),
    angle: impl Fn(usize) -> bool,
) -> Vec<f64> {
    let wrapped = |c: usize, d: f64| if angle(c) { (d + PI).rem_euclid(2.0 * PI) - PI } else { d };
    let step = |k: usize, c: usize| wrapped(c, anchors[k + 1].q[c] - anchors[k].q[c]);
    let pairs = anchors.len().saturating_sub(1);
    let largest: Vec<f64> =
        (0..coordinates).map(|c| (0..pairs).map(|k| step(k, c).abs()).fold(0.0, f64::max)).collect();
    (0..pairs)
        .filter(|&k| passed[k] && passed[k + 1])
        .filter(|&k| {
            let (a, b) = (&anchors[k], &anchors[k + 1]);
            (0..coordinates).any(|c| {
                let (taken, trapezoid) = (step(k, c), (a.g[c] + b.g[c]) * (b.phi - a.phi) / 2.0);
                let off = (taken - trapezoid).abs();
                let floor = 1e-6 * largest[c].max(if angle(c) { 1e-3 } else { 1e-3 * size });
                off > 0.5 * taken.abs().max(trapezoid.abs()) && off > floor
            })
        })
        .map(|k| (anchors[k].phi + anchors[k + 1].phi) / 2.0)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::samples::offset_slider_crank;

    /// dI*/dφ = 2gᵀMh against a central difference of I* (h = 1e-6).
    #[test]
    fn the_inertia_slope_matches_a_finite_difference() {
        let m =
            Machine::new(offset_slider_crank(), Vec::new(), 0.0, 2.0 * std::f64::consts::PI, Deadline::none()).unwrap();
        for phi in [0.3, 1.7, 4.0] {
            let fd = (m.eval(phi + 1e-6, Reduced::Inertia) - m.eval(phi - 1e-6, Reduced::Inertia)) / 2e-6;
            let an = m.eval(phi, Reduced::InertiaSlope);
            assert!((fd - an).abs() < 1e-8, "{phi}: {an} vs {fd}");
        }
    }

    /// Just below a full turn the nearest anchor is φ = 0: I* there must
    /// continue I*(δ) − 2δ·I*'(0) (to O(δ³)), the same branch of assembly.
    #[test]
    fn the_functions_are_continuous_across_the_full_turn() {
        let period = 2.0 * std::f64::consts::PI;
        let m = Machine::new(offset_slider_crank(), Vec::new(), 0.0, period, Deadline::none()).unwrap();
        for delta in [1e-3, 5e-3] {
            let below = m.eval(period - delta, Reduced::Inertia);
            let taylor = m.eval(delta, Reduced::Inertia) - 2.0 * delta * m.eval(0.0, Reduced::InertiaSlope);
            assert!((below - taylor).abs() < 1e-4 * delta * delta, "δ = {delta}: {below} vs {taylor}");
        }
    }
}
