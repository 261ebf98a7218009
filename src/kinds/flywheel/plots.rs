//! The flywheel's plots, from its stored result: M*(φ) with the lobes of
//! work, W(φ) with ΔE, ω(φ) over the cycle, and Wittenbauer's diagram W
//! against I* with the two tangents that give the exact inertia.

use crate::i18n::{Msg, say};
use crate::kind::chart::{Arrow, Axis, Chart, Fill, Level, Listed, Pen};
use crate::kind::plots::{Drawn, Job, Options, deg, num, rows, sig, xy};
use crate::kinds::mechanism::drawing;
use crate::kinds::mechanism::motion::{self, Still};
use serde_json::Value;

/// Each plot's name and its title's message.
const PLOTS: [(&str, &str); 4] = [
    ("torque", "plot-flywheel-torque"),
    ("work", "plot-flywheel-work"),
    ("speed", "plot-flywheel-speed"),
    ("wittenbauer", "plot-flywheel-wittenbauer"),
];

/// The flywheel's plots: all four when the result has its samples (the
/// default), none with `samples: 0`.
pub fn list(job: &Job) -> Vec<Listed> {
    if rows(job.result, "samples").len() < 2 {
        return Vec::new();
    }
    let varies = varying_inertia(job.result);
    let mut out: Vec<Listed> =
        PLOTS.iter().filter(|(n, _)| varies || *n != "wittenbauer").map(|(n, t)| Listed::new(*n, say(t))).collect();
    if rows(job.result, "machine_poses").len() > 1 && drawing::model(job.request, MECHANISM).is_some() {
        out.push(Listed::new("motion", say("plot-flywheel-motion")));
    }
    out
}

const MECHANISM: &str = "/machine/mechanism";

/// Whether I*(φ) varies over the cycle: with a constant I* Wittenbauer's
/// diagram is a vertical segment (the exact inertia is then I_approx − I*,
/// in closed form), so it is not offered.
fn varying_inertia(r: &Value) -> bool {
    let (lo, hi) = rows(r, "samples")
        .iter()
        .filter_map(|s| num(s, "reduced_inertia"))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
    hi - lo > 1e-9 * (hi.abs() + num(r, "inertia_exact").unwrap_or(0.0).abs())
}

pub fn draw(job: &Job, name: &str, _: &Options) -> Drawn {
    if rows(job.result, "samples").len() < 2 {
        return Ok(None);
    }
    if name == "motion" {
        let title = list(job).into_iter().find(|p| p.name == name).map(|p| p.title);
        return Ok(title.and_then(|t| motion(job, t)));
    }
    // Wittenbauer's diagram only when I* varies (as listed); the others always.
    let offered = name != "wittenbauer" || varying_inertia(job.result);
    let title = PLOTS.iter().find(|p| p.0 == name && offered).map(|p| say(p.1));
    Ok(title.and_then(|title| match name {
        "torque" => Some(torque(job, title)),
        "work" => Some(work(job.result, title)),
        "speed" => Some(speed(job.result, title)),
        _ => wittenbauer(job.result, title),
    }))
}

fn phi() -> Axis {
    Axis::new(say("plot-phi-shaft"), "deg")
}

fn samples(r: &Value, key: &str) -> Vec<(f64, f64)> {
    xy(rows(r, "samples"), |s| num(s, "angle").map(deg), |s| num(s, key))
}

/// M*(φ) and its lobes. With a balance torque M_b (solved, constant), the
/// course's picture: the other torques with their sign changed, M_b − M*,
/// against the line M_b, the lobes between them (the same areas as between
/// M* and zero).
fn torque(job: &Job, title: String) -> Chart {
    let r = job.result;
    let m = samples(r, "reduced_torque");
    let balance = num(r, "balance_torque").map(|b| b * balance_ratio(job.request));
    let level = balance.unwrap_or(0.0);
    let curve: Vec<(f64, f64)> = m.iter().map(|&(x, y)| (x, level - y)).collect();
    let y = Axis::new(say("plot-torque-shaft"), "N·m");
    let mut c = match balance {
        Some(b) => Chart::new(title, phi(), y)
            .line(say("plot-flywheel-other-torques"), curve.clone(), Pen::solid(0))
            .rule(Level::Y(b), Msg::new("plot-flywheel-balance").arg("value", sig(b)).text(), Pen::solid(1)),
        None => {
            Chart::new(title, phi(), y).line("M*(φ)", m.clone(), Pen::solid(0)).rule(Level::Y(0.0), "", Pen::dashed(7))
        }
    };
    let shown = if balance.is_some() { &curve } else { &m };
    for (k, a) in rows(r, "areas").iter().enumerate() {
        let (Some(from), Some(to), Some(w)) = (num(a, "from"), num(a, "to"), num(a, "work")) else { continue };
        let (from, to) = (deg(from), deg(to));
        let inside: Vec<(f64, f64)> = shown.iter().copied().filter(|p| p.0 > from && p.0 < to).collect();
        let mut polygon = vec![(from, level)];
        polygon.extend(inside.iter().copied());
        polygon.push((to, level));
        c.fills.push(Fill { points: polygon, color: if w >= 0.0 { 2 } else { 1 }, opacity: 0.25 });
        let peak = inside.iter().copied().max_by(|p, q| (p.1 - level).abs().total_cmp(&(q.1 - level).abs()));
        let at = peak.map_or(((from + to) / 2.0, level), |p| ((from + to) / 2.0, (p.1 + level) / 2.0));
        c.marks.push(crate::kind::chart::Mark {
            at,
            text: format!("A{} = {}{} J", k + 1, if w > 0.0 { "+" } else { "" }, sig(w)),
            dot: false,
        });
    }
    for x in r.get("crossings").and_then(Value::as_array).into_iter().flatten().filter_map(Value::as_f64) {
        c = c.mark((deg(x), level), "");
    }
    c.subtitle(Msg::new("plot-flywheel-lobes").count("n", rows(r, "areas").len()).text())
}

/// The ratio of the balance torque's shaft to the reference shaft (1 unless the request says).
fn balance_ratio(request: &Value) -> f64 {
    rows(request, "torques")
        .iter()
        .find(|t| t.get("balance").and_then(Value::as_bool) == Some(true))
        .and_then(|t| num(t, "ratio"))
        .unwrap_or(1.0)
}

/// W(φ), its values S_i at the crossings, and ΔE between its extremes.
fn work(r: &Value, title: String) -> Chart {
    let w = samples(r, "work");
    let de = num(r, "energy_fluctuation").unwrap_or(f64::NAN);
    let ends: Vec<f64> = rows(r, "areas").iter().filter_map(|a| num(a, "to")).map(deg).collect();
    // S_n is 0 by the cycle's balance; its rounding error (1e-13 J) would print as such.
    let tiny = |s: f64| if s.abs() < 1e-9 * de.abs() { 0.0 } else { s };
    let sums: Vec<f64> = rows(r, "cumulative").iter().filter_map(Value::as_f64).map(tiny).collect();
    let (lo, hi) = sums.iter().fold((0.0_f64, 0.0_f64), |(a, b), &s| (a.min(s), b.max(s)));
    let mut c = Chart::new(title, phi(), Axis::new(say("plot-work-since"), "J"))
        .line("W(φ) = ∫ M* dφ", w.clone(), Pen::solid(0))
        .rule(Level::Y(hi), format!("S_max = {} J", sig(hi)), Pen::dashed(2))
        .rule(Level::Y(lo), format!("S_min = {} J", sig(lo)), Pen::dashed(1));
    for (k, (x, s)) in ends.iter().zip(&sums).enumerate() {
        c = c.mark((*x, *s), format!("S{} = {}", k + 1, sig(*s)));
    }
    let x_arrow = w.last().map_or(0.0, |p| p.0 * 0.04);
    c.arrows.push(Arrow { from: (x_arrow, lo), to: (x_arrow, hi), color: 6, label: format!("ΔE = {} J", sig(de)) });
    c.subtitle(format!("ΔE = S_max − S_min = {} J", sig(de)))
}

/// ω(φ) with ω_max, ω_min and ω_a = (ω_max + ω_min)/2.
fn speed(r: &Value, title: String) -> Chart {
    let (max, min) = (num(r, "omega_max").unwrap_or(f64::NAN), num(r, "omega_min").unwrap_or(f64::NAN));
    let mean = (max + min) / 2.0;
    let mut c = Chart::new(title, phi(), Axis::new(say("plot-speed-shaft"), "rad/s"))
        .line("ω(φ)", samples(r, "speed"), Pen::solid(0))
        .rule(Level::Y(max), format!("ω_max = {}", sig(max)), Pen::dashed(2))
        .rule(Level::Y(mean), format!("ω_a = {}", sig(mean)), Pen::dashed(7))
        .rule(Level::Y(min), format!("ω_min = {}", sig(min)), Pen::dashed(1));
    if let (Some(a), Some(b)) = (num(r, "phi_at_omega_max"), num(r, "phi_at_omega_min")) {
        c = c.mark((deg(a), max), "").mark((deg(b), min), "");
    }
    let inertia = num(r, "inertia_exact").unwrap_or(f64::NAN);
    let note = Msg::new("plot-flywheel-speed-note").arg("eps", sig((max - min) / mean)).arg("inertia", sig(inertia));
    c.subtitle(note.text())
}

/// W(φ) against I*(φ) with the two tangents of slope ω²/2, for ω_max and
/// ω_min: lines through (−I, −T₀), the origin of the kinetic energy
/// T = T₀ + W = ½(I + I*)ω². Their point of contact is where the speed is
/// extreme; that they touch the curve checks I and T₀.
fn wittenbauer(r: &Value, title: String) -> Option<Chart> {
    let s = rows(r, "samples");
    let curve = xy(s, |x| num(x, "reduced_inertia"), |x| num(x, "work"));
    // Wittenbauer's I, added to I*(φ): the total less I*'s least.
    let inertia = num(r, "inertia_exact")? - num(r, "least_reduced_inertia").unwrap_or(0.0);
    let t0 = num(r, "kinetic_energy_at_start")?;
    let (max, min) = (num(r, "omega_max")?, num(r, "omega_min")?);
    let (x0, x1) = curve.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.0), b.max(p.0)));
    let pad = ((x1 - x0) * 0.15).max(x0.abs().max(1e-3) * 0.02);
    let tangent = |w: f64| {
        let slope = w * w / 2.0;
        let at = |x: f64| slope * (x + inertia) - t0;
        vec![(x0 - pad, at(x0 - pad)), (x1 + pad, at(x1 + pad))]
    };
    let touch = |w: f64, far: fn(f64, f64) -> bool| {
        let gap = |p: &(f64, f64)| p.1 - (w * w / 2.0) * (p.0 + inertia);
        curve.iter().copied().reduce(|a, b| if far(gap(&b), gap(&a)) { b } else { a })
    };
    let mut c =
        Chart::new(title, Axis::new(say("plot-reduced-inertia"), "kg·m²"), Axis::new(say("plot-work-since"), "J"))
            .line(say("plot-wittenbauer-curve"), curve.clone(), Pen::solid(0))
            .line(Msg::new("plot-tangent-max").arg("value", sig(max)).text(), tangent(max), Pen::dashed(2))
            .line(Msg::new("plot-tangent-min").arg("value", sig(min)).text(), tangent(min), Pen::dashed(1));
    if let Some(p) = touch(max, |a, b| a > b) {
        c = c.mark(p, "ω_max");
    }
    if let Some(p) = touch(min, |a, b| a < b) {
        c = c.mark(p, "ω_min");
    }
    let note = Msg::new("plot-wittenbauer-note").arg("x", sig(-inertia)).arg("y", sig(-t0));
    Some(c.subtitle(note.arg("inertia", sig(inertia)).arg("t0", sig(t0)).text()))
}

/// The machine moving over its period, each pose shown at the time the
/// flywheel's speed takes to reach it (t(φ) = ∫dφ/ω over the samples, the
/// cycle played in [`CYCLE_SECONDS`]): its speed's fluctuation, slowed.
fn motion(job: &Job, title: String) -> Option<Chart> {
    let m = drawing::model(job.request, MECHANISM)?;
    let samples = samples(job.result, "speed");
    let time = elapsed(&samples);
    let cycle = time.last().copied().filter(|t| *t > 0.0)?;
    let at = |angle: f64| {
        let k = samples.partition_point(|s| s.0 < angle).clamp(1, samples.len() - 1);
        let (a, b) = (samples[k - 1], samples[k]);
        let f = if b.0 > a.0 { ((angle - a.0) / (b.0 - a.0)).clamp(0.0, 1.0) } else { 0.0 };
        (time[k - 1] + f * (time[k] - time[k - 1]), a.1 + f * (b.1 - a.1))
    };
    let poses = rows(job.result, "machine_poses");
    let stills: Vec<Still> = (poses.iter().enumerate())
        .filter_map(|(k, p)| {
            let angle = deg(num(p, "angle")?);
            let (t, omega) = at(angle);
            Some(Still {
                step: k,
                at: t / cycle,
                caption: Msg::new("plot-flywheel-motion-at").arg("phi", sig(angle)).arg("omega", sig(omega)).text(),
                poses: drawing::poses(&m, rows(p, "bodies")),
                reactions: &[],
                contacts: &[],
            })
        })
        .collect();
    let all: Vec<_> = poses.iter().map(|p| drawing::poses(&m, rows(p, "bodies"))).collect();
    let mut c = motion::motion(&m, &stills, motion::joint_paths(&m, &all), CYCLE_SECONDS, title);
    c.subtitle = Some(Msg::new("plot-motion-note-paths").arg("seconds", CYCLE_SECONDS).text());
    Some(c)
}

/// How long the motion takes to play one cycle, s.
const CYCLE_SECONDS: f64 = 4.0;

/// t at each sample (φ in degrees, ω in rad/s) from the first: the
/// trapezoidal ∫dφ/ω.
fn elapsed(samples: &[(f64, f64)]) -> Vec<f64> {
    let mut t = vec![0.0; samples.len()];
    for k in 1..samples.len() {
        let ((a, wa), (b, wb)) = (samples[k - 1], samples[k]);
        t[k] = t[k - 1] + (b - a).to_radians() * 0.5 * (1.0 / wa + 1.0 / wb);
    }
    t
}
