//! The configurations along a list of input positions, each continued from
//! the last regular one. One [`Workspace`] and one [`Configuration`] serve
//! the whole sweep: Φ_q, its LU and the vectors are refilled in place, and
//! each position is handed over by reference before the next is solved.

use super::cut::{Cuts, Settled};
use super::{Conditions, Configuration, Dyads, SINGULAR_CONDITION, Trig, Workspace, unreachable};
use crate::engine::model::Mechanism;
use crate::engine::{Deadline, EngineError, Progress};
use nalgebra::DMatrix;

/// The configurations along the given input positions, starting from the
/// reference configuration and continuing from each position to the next.
///
/// Each position's condition numbers are those `conditions` asks
/// ([`Conditions`]): κ₂ exactly (an SVD) when exact or where the estimate
/// from Φ_q's LU exceeds [`super::ESTIMATE_LIMIT`]; else the estimate
/// ([`super::estimated_condition`]).
pub fn sweep(
    m: &Mechanism,
    positions: &[Vec<[f64; 3]>],
    deadline: &Deadline,
    conditions: Conditions,
) -> Result<Vec<Configuration>, EngineError> {
    let mut out: Vec<Configuration> = Vec::with_capacity(positions.len());
    sweep_each(m, positions, deadline, conditions, |_, c| {
        out.push(c.clone());
        Ok(())
    })?;
    Ok(out)
}

/// [`sweep`], handing each position's configuration to `each` as soon as
/// it is known (with its index) instead of keeping them all: what is done
/// with a position stays in the cache, and the sweep allocates nothing
/// after its first two positions. An error of `each` stops the sweep.
pub fn sweep_each(
    m: &Mechanism,
    positions: &[Vec<[f64; 3]>],
    deadline: &Deadline,
    conditions: Conditions,
    mut each: impl FnMut(usize, &Configuration) -> Result<(), EngineError>,
) -> Result<(), EngineError> {
    let mut ws = Workspace { cols: m.column_lengths(), ..Workspace::default() };
    let mut base = m.reference_q();
    if let Some(first) = positions.first() {
        approach(m, &mut ws, &mut base, first, deadline).map_err(|e| match e {
            EngineError::BudgetExceeded { .. } => e,
            e => unreachable(m, e),
        })?;
    }
    let (mut predictor, mut prediction) = (Predictor::default(), Vec::new());
    let mut failure: Option<EngineError> = None;
    let mut c = Configuration::default();
    let single = m.drivers.len() == 1;
    let (dyads, mut trig) = (Dyads::new(m), Trig::default());
    let cuts = Cuts::new(m);
    // The least jump of each curve parameter: 1e-3 of its period (of its length scale unbounded).
    let lengths = &ws.cols[m.n_body_coordinates()..];
    let periods = m.parameter_periods();
    let jump_scale: Vec<f64> = periods.iter().zip(lengths).map(|(p, c)| 1e-3 * p.unwrap_or(*c)).collect();
    for (step, inputs) in positions.iter().enumerate() {
        // The clock read every 8th position (a read was 2 % of K1's sweep).
        if step % 8 == 0 {
            deadline.check(|| Progress::Assembled { step, of: positions.len() })?;
        }
        let predict = |q: &mut Vec<f64>| predictor.predict(&base, inputs[0][0], q);
        predict(&mut c.q);
        let predicted = if predictor.from.is_some() && m.n_parameters() > 0 {
            prediction.clone_from(&c.q);
            Some(prediction.as_slice())
        } else {
            None
        };
        // Placed in closed form where the mechanism is a crank and dyads (on
        // the branch of the prediction); else, or where a dyad will not
        // close, Newton starts from the prediction.
        c.placed = dyads.as_ref().is_some_and(|d| d.place(m, inputs[0][0], &mut c.q, &mut trig));
        if dyads.is_some() && !c.placed {
            predict(&mut c.q);
        }
        let mut newton = match ws.assemble(m, &mut c.q, inputs, step) {
            Ok(r) => r,
            // One position that will not assemble between two that do is a
            // singular point passed; two in a row is a position out of reach.
            Err(e) if failure.is_none() => {
                failure = Some(e);
                c.set_singular([f64::INFINITY; 2], 0, f64::NAN);
                each(step, &c)?;
                continue;
            }
            Err(_) => {
                return Err(unreachable(m, failure.unwrap_or(EngineError::Singular { step, input: inputs[0][0] })));
            }
        };
        failure = None;
        // A contact that cuts into its cam is moved to where it rests (a jump).
        let settled = if cuts.is_empty() {
            Settled::default()
        } else {
            cuts.settle(m, &mut ws, (&mut c.q, predicted), (inputs, step), &mut newton)
        };
        let (iterations, residual) = newton;
        c.jumped.clear();
        if let Some(predicted) = predicted {
            c.jumped.extend(jumps(m.n_body_coordinates(), (&jump_scale, &periods), [&base, predicted, &c.q]));
        }
        if !settled.moved.is_empty() {
            c.jumped.extend(&settled.moved);
            c.jumped.sort_unstable();
            c.jumped.dedup();
        }
        c.cuts.clone_from(&settled.cut);
        // One input: g = dq/dφ and h = d²q/dφ² give q̇ = gω and q̈ = gα + hω²
        // (γ is quadratic in q̇), and they are the next step's predictor.
        let unit = [[inputs[0][0], 1.0, 0.0]];
        let solved = ws.motion(m, &c.q, if single { &unit } else { inputs });
        let [cond, scaled] = if solved { ws.conditions(conditions) } else { [f64::INFINITY; 2] };
        if !solved || scaled > SINGULAR_CONDITION {
            c.set_singular([cond, scaled], iterations, residual);
            each(step, &c)?;
            continue;
        }
        if single {
            let [_, w, alpha] = inputs[0];
            c.qd.clear();
            c.qd.extend(ws.qd.iter().map(|g| g * w));
            c.qdd.clear();
            c.qdd.extend(ws.qd.iter().zip(&ws.qdd).map(|(g, h)| g * alpha + h * w * w));
            c.g.get_or_insert_with(Vec::new).clone_from(&ws.qd);
            predictor.update(&ws.qd, &ws.qdd, inputs[0][0]);
        } else {
            c.qd.clone_from(&ws.qd);
            c.qdd.clone_from(&ws.qdd);
            c.g = None;
        }
        base.clone_from(&c.q);
        if iterations == 0 && !c.placed {
            // Taken as predicted (Φ within Newton's tolerance, not zero): the
            // next position continues from q refined by a Newton step on the
            // velocities' LU, so that what is left of Φ here does not add to
            // its prediction's error (it made every other position take a
            // Newton step of its own).
            ws.refine(&mut base);
        }
        c.trig.clear();
        c.trig.extend_from_slice(ws.sys.trig());
        // Φ_q and its LU change hands: the workspace refills the last ones.
        std::mem::swap(&mut c.jacobian, &mut ws.sys.jacobian);
        std::mem::swap(&mut c.lu, &mut ws.lu);
        (c.condition, c.scaled_condition, c.iterations, c.residual) = (cond, scaled, iterations, residual);
        c.singular = false;
        each(step, &c)?;
    }
    match failure {
        Some(e) => Err(unreachable(m, e)),
        None => Ok(()),
    }
}

/// Where the next position starts Newton, from the last regular one (one
/// input φ): q + g·d + ½h·d² + j·d³/6, d the step in φ, g = dq/dφ and h =
/// d²q/dφ² there, and j ≈ (h − h₋)/(φ − φ₋) from the regular position
/// before it, where that term is a tenth of the quadratic one or less
/// (near a singular position h runs away, and the quadratic predictor
/// stays on the branch). With it a fine sweep of a mechanism Newton places
/// (a cam: 3600 positions) starts within Newton's tolerance and confirms
/// it: an evaluation of Φ and Φ_q and a factorisation a position fewer.
#[derive(Default)]
struct Predictor {
    g: Vec<f64>,
    h: Vec<f64>,
    /// φ of the last regular position.
    from: Option<f64>,
    /// h₋ and φ₋: the regular position before it.
    before: Option<(Vec<f64>, f64)>,
}

impl Predictor {
    fn predict(&self, base: &[f64], phi: f64, q: &mut Vec<f64>) {
        q.clear();
        q.extend_from_slice(base);
        let Some(from) = self.from else { return };
        let d = phi - from;
        let (g, h) = (&self.g, &self.h);
        q.iter_mut().enumerate().for_each(|(k, v)| *v += g[k] * d + 0.5 * h[k] * d * d);
        let Some((h0, at)) = self.before.as_ref().filter(|(_, at)| (from - at) * d > 0.0) else { return };
        let third = |k: usize| (h[k] - h0[k]) / (from - at) * d * d * d / 6.0;
        let (cubic, quadratic) =
            (0..h.len()).fold((0.0f64, 0.0f64), |(c, s), k| (c.max(third(k).abs()), s.max((0.5 * h[k] * d * d).abs())));
        if cubic <= 0.1 * quadratic {
            q.iter_mut().enumerate().for_each(|(k, v)| *v += third(k));
        }
    }

    /// The last regular position's g, h and φ.
    fn update(&mut self, g: &[f64], h: &[f64], phi: f64) {
        if let Some(from) = self.from {
            // h₋ takes the last h's storage, h the storage of the one before.
            let mut last = self.before.take().map(|(v, _)| v).unwrap_or_default();
            std::mem::swap(&mut last, &mut self.h);
            self.before = Some((last, from));
        }
        self.g.clear();
        self.g.extend_from_slice(g);
        self.h.clear();
        self.h.extend_from_slice(h);
        self.from = Some(phi);
    }
}

/// The curve parameters' columns (from `first`) where q settled far from
/// the prediction: Newton's correction more than twice the predicted
/// change from the last position (the predictor's error is a small
/// part of it), the parameter's own period discounted, and more than
/// `least` (1e-3 of the curve's period; 1e-3 of the mechanism's size along
/// a line or an open curve).
fn jumps<'a>(
    first: usize,
    (least, periods): (&'a [f64], &'a [Option<f64>]),
    [base, predicted, q]: [&'a [f64]; 3],
) -> impl Iterator<Item = usize> + 'a {
    (first..q.len()).filter(move |&c| {
        let (step, off) = ((predicted[c] - base[c]).abs(), (q[c] - predicted[c]).abs());
        let off = periods[c - first].map_or(off, |p| off.rem_euclid(p).min(p - off.rem_euclid(p)));
        off > 2.0 * step && off > least[c - first]
    })
}

impl Configuration {
    /// A singular position at the q it holds: nothing but q is valid.
    fn set_singular(&mut self, [condition, scaled]: [f64; 2], iterations: usize, residual: f64) {
        let n = self.q.len();
        (self.qd, self.qdd, self.g, self.jacobian) = (vec![0.0; n], vec![0.0; n], None, DMatrix::zeros(0, 0));
        self.trig.clear();
        (self.condition, self.scaled_condition, self.iterations, self.residual) =
            (condition, scaled, iterations, residual);
        self.singular = true;
        self.jumped.clear();
        self.cuts.clear();
    }
}

/// Largest change of an input coordinate per continuation step on the way
/// from the drawn configuration to the first position (rad, or of the
/// mechanism's size L).
const APPROACH_STEP: f64 = 0.05;

/// Moves q from the drawn configuration (inputs at their `reference`) to the
/// first requested position in small steps, so the assembly branch drawn is
/// the branch solved; the `deadline` read at every step (up to 10 000 of
/// them, each a Newton solve).
fn approach(
    m: &Mechanism,
    ws: &mut Workspace,
    q: &mut [f64],
    target: &[[f64; 3]],
    deadline: &Deadline,
) -> Result<(), EngineError> {
    let from: Vec<f64> = m.drivers.iter().map(|d| d.reference).collect();
    let span =
        (from.iter().zip(target).zip(m.input_lengths())).map(|((a, t), c)| (t[0] - a).abs() / c).fold(0.0, f64::max);
    let n = (span / APPROACH_STEP).ceil().min(10_000.0) as usize;
    for k in 1..n {
        deadline.check(|| Progress::Approach { step: k, of: n })?;
        let f = k as f64 / n as f64;
        let inputs: Vec<[f64; 3]> = from.iter().zip(target).map(|(a, t)| [a + f * (t[0] - a), 0.0, 0.0]).collect();
        ws.assemble(m, q, &inputs, 0)?;
    }
    Ok(())
}
