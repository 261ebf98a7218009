//! Contacts whose bodies cut into each other away from where they touch.
//!
//! A contact's equations hold its curves tangent at one point and see
//! nothing else of either body: past a concave stretch of a cam the
//! tangency they follow can leave a flat face across a hollow, a roller in
//! a hollow narrower than itself, or a face on the cam's far side — the
//! follower inside the cam. After Newton, each such contact is checked
//! whole: the profile's points against the tool's material. Where they cut
//! in, the contact is moved to the deepest point and solved again (the
//! support the follower truly rests on, a jump the results then say), and
//! where no contact outside both bodies is found, the depth is reported.
//!
//! Symbols: the *tool* is the contact's line (a flat face, its material on
//! the side σ·perp(d) that faced away from the profile as drawn) or circle
//! (a roller or disk, its material inside; a track's outside); the
//! *profile* is the other curve (a cam, a polar curve, a spline), sampled
//! at N parameters u_k, s_k its points relative to its body's centre of
//! mass. Both are compared in the profile's body frame. The depth δ(u) of
//! a profile point into the tool's material is (s − a)·ν for a face
//! through a with ν = σ·perp(d), R − |s − c| for a disk of centre c and
//! |s − c| − R for a track. Every sampled local maximum that may hide a
//! cut (δ_k + |Δ²δ_k| ≥ 0, Δ² the second difference: a bound of the
//! parabola through it and its neighbours) is refined by Newton on
//! δ′(u) = 0 — at the contact itself, where δ′ = 0 already, δ″ < 0 says it
//! is the maximum — and the contact cuts where the largest δ exceeds
//! 1e-8·L (L the mechanism's size): a proper contact's own point has δ = 0
//! to Newton's rounding. A cut narrower than the samples' spacing (1/1024
//! of the profile) and shallower than its Δ² can be missed. Pairs of lines and circles are exact already (convex, the
//! tangency is the only contact); two profiles are not checked.

use super::Workspace;
use crate::engine::curves::{Curve, Domain};
use crate::engine::model::{BodyId, JointKind, Mechanism, dot, perp, rotate};
use std::f64::consts::{PI, TAU};

/// Samples of a profile (a whole period, or an open curve end to end).
const SAMPLES: usize = 1024;
/// New contacts tried per position before the least cut one is kept.
const ROUNDS: usize = 4;
/// A q this far from the continuation's prediction ([`strayed`]) is checked
/// against the prediction's own contact: a smooth step strays ~Δφ²·q″/2,
/// under 1 % of the mechanism at the steps a sweep takes.
const STRAYED: f64 = 0.05;

/// The contacts to check, set up once per sweep.
pub(super) struct Cuts {
    watches: Vec<Watch>,
    /// 1e-8 L: the least depth that is a cut.
    tolerance: f64,
}

/// What a sweep does at one position: the curve parameters' columns moved
/// to a new contact, and the contacts still cut (joint, depth in m).
#[derive(Default)]
pub(super) struct Settled {
    pub moved: Vec<usize>,
    pub cut: Vec<(usize, f64)>,
}

struct Watch {
    joint: usize,
    /// The tool's side (0 the joint's first body, 1 its second) and body.
    tool: (usize, BodyId),
    profile: (usize, BodyId),
    shape: Tool,
    /// (u_k, s_k) along the profile.
    samples: Vec<(f64, [f64; 2])>,
    period: Option<f64>,
    rolling: bool,
    /// A disk on a closed profile: whether its centre was inside the
    /// profile as drawn (a disk in a track) — it must stay on that side.
    centre_inside: Option<bool>,
}

/// The tool in its body's reference coordinates.
#[derive(Clone, Copy)]
enum Tool {
    Face { a: [f64; 2], d: [f64; 2], sigma: f64 },
    Disk { c: [f64; 2], r: f64, track: bool },
}

impl Cuts {
    pub fn new(m: &Mechanism) -> Self {
        let watches = (m.joints.iter().enumerate()).filter_map(|(k, j)| watch(m, k, &j.kind, j.bodies)).collect();
        Self { watches, tolerance: 1e-8 * m.size() }
    }

    pub fn is_empty(&self) -> bool {
        self.watches.is_empty()
    }

    /// After Newton assembled q: every watched contact whole. A cut contact
    /// (not rolling: its arc lengths forbid a jump) is moved to its deepest
    /// point and assembled again, up to [`ROUNDS`] times, from Newton's q
    /// and then from the continuation's `predicted` q (where the tool has
    /// not yet been carried across a fold: the flank it is to rest on cuts
    /// into it there). Newton's q clear of every cut but far from the
    /// prediction (a roller that bridged a hollow and was carried by the
    /// tangency to the cam's far side: clear there, yet no follower moves
    /// so) is tried against the prediction's own contact too. Kept: of the
    /// q clear of every cut, the nearest the prediction; else the least cut
    /// — Newton's (iterations, |Φ|∞) there in `assembled` and Φ_q there in `ws`.
    pub fn settle(
        &self,
        m: &Mechanism,
        ws: &mut Workspace,
        (q, predicted): (&mut Vec<f64>, Option<&[f64]>),
        (inputs, step): (&[[f64; 3]], usize),
        assembled: &mut (usize, f64),
    ) -> Settled {
        let mut out = Settled::default();
        let depth = |q: &[f64]| self.worst(m, q).map_or(0.0, |w| w.2);
        let away = |x: &[f64]| predicted.map_or(0.0, |p| strayed(m, x, p));
        let first = depth(q);
        if first <= self.tolerance && away(q) <= STRAYED {
            return out;
        }
        // The best q so far: its depth, distance from the prediction, q, Newton's figures, the watches moved.
        let mut best = (first, away(q), q.clone(), *assembled, Vec::new());
        let starts = (first > self.tolerance).then_some(&q[..]).into_iter().chain(predicted);
        for (k, start) in starts.enumerate() {
            let (mut x, mut path) = (start.to_vec(), Vec::new());
            for round in 0..=ROUNDS {
                match self.worst(m, &x).filter(|&(w, ..)| !self.watches[w].rolling) {
                    Some((w, u, d)) if d > self.tolerance && round < ROUNDS => {
                        self.watches[w].move_to(m, &mut x, u);
                        path.push(w);
                    }
                    // The prediction clear of every cut: each contact moved to
                    // the profile's point nearest its tool (the prediction's
                    // curve parameters can be far off where the contact
                    // sped along the profile) and assembled from there.
                    _ if round == 0 && (k > 0 || first <= self.tolerance) => {
                        for (j, w) in self.watches.iter().enumerate().filter(|(_, w)| !w.rolling) {
                            let u = w.nearest(m, &x);
                            w.move_to(m, &mut x, u);
                            path.push(j);
                        }
                    }
                    _ => break,
                }
                let Ok(newton) = ws.assemble(m, &mut x, inputs, step) else { break };
                let found = (depth(&x), away(&x), x.clone(), newton, path.clone());
                if better((found.0, found.1), (best.0, best.1), self.tolerance) {
                    best = found;
                }
            }
        }
        let (_, _, kept, newton, moved) = best;
        // Φ and Φ_q at the q kept (Newton, converged there, stops at once).
        q.clone_from(&kept);
        let _ = ws.assemble(m, q, inputs, step);
        *assembled = newton;
        for w in moved.into_iter().map(|w| &self.watches[w]) {
            out.moved.extend([w.profile.0, w.tool.0].into_iter().filter_map(|side| m.contact_column(w.joint, side)));
        }
        out.moved.sort_unstable();
        out.moved.dedup();
        let cut = self.watches.iter().filter_map(|w| w.depth(m, q).map(|(_, d)| (w.joint, d)));
        out.cut.extend(cut.filter(|&(_, d)| d > self.tolerance));
        out
    }

    /// The watched contact cut deepest at q: (watch, its profile's u there, δ).
    fn worst(&self, m: &Mechanism, q: &[f64]) -> Option<(usize, f64, f64)> {
        (self.watches.iter().enumerate())
            .filter_map(|(k, w)| w.depth(m, q).map(|(u, d)| (k, u, d)))
            .max_by(|a, b| a.2.total_cmp(&b.2))
    }
}

/// How far q strayed from the prediction p: the largest move of a body's
/// centre over the mechanism's size, or of its angle in radians.
fn strayed(m: &Mechanism, q: &[f64], p: &[f64]) -> f64 {
    let size = m.size().max(f64::MIN_POSITIVE);
    (0..m.n_body_coordinates())
        .map(|c| {
            let d = q[c] - p[c];
            if c % 3 == 2 { (d + PI).rem_euclid(TAU) - PI } else { d / size }.abs()
        })
        .fold(0.0, f64::max)
}

/// Whether (depth, strayed) `a` is better than `b`: clear of every cut
/// (within `tolerance`) before cut, then the nearer the prediction; both
/// cut, the shallower.
fn better(a: (f64, f64), b: (f64, f64), tolerance: f64) -> bool {
    match (a.0 <= tolerance, b.0 <= tolerance) {
        (true, true) => a.1 < b.1,
        (clear, other) if clear != other => clear,
        _ => a.0 < b.0,
    }
}

/// The watch of contact joint k, where one curve is a line or a circle and
/// the other a profile (None otherwise).
fn watch(m: &Mechanism, k: usize, kind: &JointKind, bodies: [BodyId; 2]) -> Option<Watch> {
    let JointKind::Contact(c) = kind else { return None };
    let simple = |c: &Curve| matches!(c, Curve::Line { .. } | Curve::Circle { .. });
    let profiled = |c: &Curve| matches!(c, Curve::Polar { .. } | Curve::Cam { .. } | Curve::Spline(_));
    let tool = (0..2).find(|&s| simple(&c.curves[s]) && profiled(&c.curves[1 - s]))?;
    let (curve, other) = (&c.curves[1 - tool], &c.curves[tool]);
    let (period, (from, to)) = match curve.domain() {
        Domain::Periodic(p) => (Some(p), (0.0, p)),
        Domain::Interval(a, b) => (None, (a, b)),
        _ => return None,
    };
    let g = m.bodies[bodies[1 - tool]].cg;
    let last = if period.is_some() { SAMPLES } else { SAMPLES - 1 };
    let samples: Vec<(f64, [f64; 2])> = (0..SAMPLES)
        .map(|i| {
            let u = from + (to - from) * i as f64 / last as f64;
            let r = curve.at(u).r;
            (u, [r[0] - g[0], r[1] - g[1]])
        })
        .collect();
    let shape = match other {
        Curve::Line { at, direction } => {
            // The face's material faces away from the profile where they touch as drawn:
            // along a closed profile's outward normal, else away from its points.
            let n = perp(*direction);
            let sigma = match curve.orientation() {
                Some(o) => -o * dot(n, perp(curve.at(c.drawn[1 - tool]).d1)),
                None => -samples.iter().map(|(_, s)| dot([s[0] + g[0] - at[0], s[1] + g[1] - at[1]], n)).sum::<f64>(),
            };
            Tool::Face { a: *at, d: *direction, sigma: if sigma >= 0.0 { 1.0 } else { -1.0 } }
        }
        Curve::Circle { centre, radius, inside } => Tool::Disk { c: *centre, r: *radius, track: *inside },
        _ => return None,
    };
    let mut w = Watch {
        joint: k,
        tool: (tool, bodies[tool]),
        profile: (1 - tool, bodies[1 - tool]),
        shape,
        samples,
        period,
        rolling: c.rolling,
        centre_inside: None,
    };
    if let (Tool::Disk { track: false, .. }, Some(_)) = (shape, period) {
        w.centre_inside = Some(w.centre_in_profile(m, &m.reference_q()));
    }
    Some(w)
}

/// A body's pose at q: its centre of mass and angle (the ground's as drawn).
fn pose(m: &Mechanism, b: BodyId, q: &[f64]) -> ([f64; 2], f64) {
    match m.column(b) {
        Some(c) => ([q[c], q[c + 1]], q[c + 2]),
        None => (m.bodies[b].cg, 0.0),
    }
}

impl Watch {
    /// A point of the tool's body (reference coordinates) in the profile
    /// body's frame (relative to its centre of mass), and a direction.
    fn to_profile(&self, m: &Mechanism, q: &[f64]) -> impl Fn([f64; 2], bool) -> [f64; 2] {
        let ((rt, tt), (rp, tp)) = (pose(m, self.tool.1, q), pose(m, self.profile.1, q));
        let g = m.bodies[self.tool.1].cg;
        move |p, direction| {
            if direction {
                return rotate(tt - tp, p);
            }
            let s = rotate(tt, [p[0] - g[0], p[1] - g[1]]);
            rotate(-tp, [rt[0] + s[0] - rp[0], rt[1] + s[1] - rp[1]])
        }
    }

    /// δ of the sample s (profile frame) and a function of u giving (δ, δ′, δ″).
    fn depth_fn(&self, m: &Mechanism, q: &[f64]) -> (impl Fn([f64; 2]) -> f64, impl Fn(f64) -> [f64; 3]) {
        let to = self.to_profile(m, q);
        let g = m.bodies[self.profile.1].cg;
        let curve = self.curve(m);
        // Face: ν and a·ν; disk: c and ±1 (−1 a track).
        let (face, nu, offset, c, r, sign) = match self.shape {
            Tool::Face { a, d, sigma } => {
                let n = to(perp(d), true);
                let nu = [sigma * n[0], sigma * n[1]];
                (true, nu, dot(to(a, false), nu), [0.0; 2], 0.0, 1.0)
            }
            Tool::Disk { c, r, track } => (false, [0.0; 2], 0.0, to(c, false), r, if track { -1.0 } else { 1.0 }),
        };
        let at_sample = move |s: [f64; 2]| {
            if face { dot(s, nu) - offset } else { sign * (r - (s[0] - c[0]).hypot(s[1] - c[1])) }
        };
        let along = move |u: f64| {
            let l = curve.at(u);
            let s = [l.r[0] - g[0], l.r[1] - g[1]];
            if face {
                return [dot(s, nu) - offset, dot(l.d1, nu), dot(l.d2, nu)];
            }
            let w = [s[0] - c[0], s[1] - c[1]];
            let rho = w[0].hypot(w[1]);
            let rho1 = dot(w, l.d1) / rho;
            let rho2 = (dot(l.d1, l.d1) + dot(w, l.d2)) / rho - rho1 * rho1 / rho;
            [sign * (r - rho), -sign * rho1, -sign * rho2]
        };
        (at_sample, along)
    }

    fn curve<'a>(&self, m: &'a Mechanism) -> &'a Curve {
        let JointKind::Contact(c) = &m.joints[self.joint].kind else { unreachable!("a watch is of a contact") };
        &c.curves[self.profile.0]
    }

    /// The profile's point cut deepest into the tool at q (u, δ), among the
    /// samples' local maxima that may hide a cut, each refined; a disk
    /// crossed to the profile's other side counts R + its distance to the
    /// profile. None where nothing is near a cut.
    fn depth(&self, m: &Mechanism, q: &[f64]) -> Option<(f64, f64)> {
        let (at_sample, along) = self.depth_fn(m, q);
        let delta: Vec<f64> = self.samples.iter().map(|(_, s)| at_sample(*s)).collect();
        let n = delta.len();
        let closed = self.period.is_some();
        let neighbours = |k: usize| match (k, k + 1 == n) {
            (0, _) => closed.then_some((n - 1, 1)),
            (_, true) => closed.then_some((k - 1, 0)),
            _ => Some((k - 1, k + 1)),
        };
        // The contact itself: δ′ = 0 there (the equations hold the curves
        // tangent), so where δ″ < 0 it is the local maximum, δ its value.
        let h = self.samples[1].0 - self.samples[0].0;
        let uc = m.contact_parameter(self.joint, self.profile.0, q).unwrap_or(f64::NAN);
        let at_contact = along(uc);
        let near_contact = |u: f64| {
            let gap = self.period.map_or((u - uc).abs(), |p| (u - uc).rem_euclid(p).min((uc - u).rem_euclid(p)));
            gap <= 1.5 * h && at_contact[2] < 0.0
        };
        let mut worst: Option<(f64, f64)> = None;
        for k in 0..n {
            // A sampled local maximum that may hide δ > 0 between its neighbours:
            // δ_k + |Δ²δ_k| bounds the parabola through the three.
            let (a, b) = neighbours(k).unwrap_or((k, k));
            let (da, dk, db) = (delta[a], delta[k], delta[b]);
            if dk < da || dk < db || dk + (da - 2.0 * dk + db).abs() < 0.0 {
                continue;
            }
            let (u, value) =
                if near_contact(self.samples[k].0) { (uc, at_contact[0]) } else { self.refine(k, &along, delta[k]) };
            if worst.is_none_or(|w| value > w.1) {
                worst = Some((u, value));
            }
        }
        if self.centre_inside.is_some_and(|drawn| drawn != self.centre_in_profile(m, q)) {
            let Tool::Disk { r, .. } = self.shape else { return worst };
            let (k, least) = (delta.iter().enumerate())
                .fold((0, f64::INFINITY), |a, (k, v)| if r - v < a.1 { (k, r - v) } else { a });
            return Some((self.samples[k].0, r + least));
        }
        worst
    }

    /// The profile's parameter nearest the tool at q (largest δ, refined).
    fn nearest(&self, m: &Mechanism, q: &[f64]) -> f64 {
        let (at_sample, along) = self.depth_fn(m, q);
        let (k, best) = (self.samples.iter().map(|(_, s)| at_sample(*s)).enumerate())
            .fold((0, f64::NEG_INFINITY), |a, (k, d)| if d > a.1 { (k, d) } else { a });
        self.refine(k, &along, best).0
    }

    /// Newton on δ′(u) = 0 from sample k, kept between its neighbours'
    /// parameters: (u, δ) at the local maximum, or sample k's where Newton
    /// leaves or meets no maximum.
    fn refine(&self, k: usize, along: &impl Fn(f64) -> [f64; 3], sampled: f64) -> (f64, f64) {
        let u0 = self.samples[k].0;
        let h = self.samples[1].0 - self.samples[0].0;
        let (lo, hi) = (u0 - h, u0 + h);
        let mut u = u0;
        for _ in 0..8 {
            let [_, d1, d2] = along(u);
            if d2 >= 0.0 || !(d1 / d2).is_finite() {
                break;
            }
            let next = u - d1 / d2;
            if !(lo..=hi).contains(&next) {
                break;
            }
            let done = (next - u).abs() <= 1e-14 * (1.0 + u.abs());
            u = next;
            if done {
                break;
            }
        }
        let value = along(u)[0];
        if value >= sampled { (u, value) } else { (u0, sampled) }
    }

    /// Whether the disk's centre is inside the closed profile at q (the
    /// samples' polygon, by the crossings of a ray from it: no
    /// trigonometry at every position of a roller's sweep).
    fn centre_in_profile(&self, m: &Mechanism, q: &[f64]) -> bool {
        let Tool::Disk { c, .. } = self.shape else { return false };
        let c = self.to_profile(m, q)(c, false);
        let points = self.samples.iter().map(|(_, s)| *s);
        let crosses = |(a, b): ([f64; 2], [f64; 2])| {
            (a[1] > c[1]) != (b[1] > c[1]) && c[0] < a[0] + (c[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
        };
        points.clone().zip(points.cycle().skip(1)).filter(|&e| crosses(e)).count() % 2 == 1
    }

    /// Moves the contact to the profile's parameter u: that column to u
    /// (the nearest turn to where it was), the tool's to its point nearest
    /// the profile's point there.
    fn move_to(&self, m: &Mechanism, q: &mut [f64], u: f64) {
        let (Some(pc), Some(tc)) =
            (m.contact_column(self.joint, self.profile.0), m.contact_column(self.joint, self.tool.0))
        else {
            return;
        };
        let near =
            |from: f64, to: f64, period: f64| from + (to - from + 0.5 * period).rem_euclid(period) - 0.5 * period;
        q[pc] = self.period.map_or(u, |p| near(q[pc], u, p));
        // The profile's point in the tool's reference coordinates.
        let ((rt, tt), (rp, tp)) = (pose(m, self.tool.1, q), pose(m, self.profile.1, q));
        let (gp, gt) = (m.bodies[self.profile.1].cg, m.bodies[self.tool.1].cg);
        let r = self.curve(m).at(u).r;
        let s = rotate(tp, [r[0] - gp[0], r[1] - gp[1]]);
        let local = rotate(-tt, [rp[0] + s[0] - rt[0], rp[1] + s[1] - rt[1]]);
        let p = [local[0] + gt[0], local[1] + gt[1]];
        q[tc] = match self.shape {
            Tool::Face { a, d, .. } => dot([p[0] - a[0], p[1] - a[1]], d),
            Tool::Disk { c, .. } => near(q[tc], (p[1] - c[1]).atan2(p[0] - c[0]), TAU),
        };
    }
}
