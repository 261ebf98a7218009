//! The spur gear's plot: its teeth drawn from the computed geometry (base,
//! pitch, tip and root circles and the tooth thickness).
//!
//! Symbols of the tooth: r_b the base radius, r the pitch radius, r_a the
//! tip's, r_f the root's, s the tooth thickness on the pitch circle, α the
//! pressure angle there (cos α = r_b/r), inv α = tan α − α; a flank is at
//! the half angle ψ(ρ) = s/(2r) + inv α − inv α_ρ from the tooth's axis,
//! cos α_ρ = r_b/ρ.

use crate::i18n::{Msg, say};
use crate::kind::chart::{Axis, Chart, Listed, Pen};
use crate::kind::plots::{Drawn, Job, Options, num, sig};
use std::f64::consts::FRAC_PI_2;

pub fn list(job: &Job) -> Vec<Listed> {
    match tooth_geometry(job) {
        Some(_) => vec![Listed::new("tooth", say("plot-gear-tooth"))],
        None => Vec::new(),
    }
}

/// (r_b, r, r_a, r_f, s, z) in m, m, m, m, m and teeth.
fn tooth_geometry(job: &Job) -> Option<[f64; 6]> {
    let r = job.result;
    let g = [
        num(r, "base_radius")?,
        num(r, "pitch_radius")?,
        num(r, "tip_radius")?,
        num(r, "root_radius")?,
        num(r, "thickness_at_pitch")?,
        num(job.request, "teeth")?,
    ];
    g.iter().all(|v| v.is_finite() && *v > 0.0).then_some(g).filter(|g| g[0] < g[2] && g[3] < g[2])
}

fn inv(a: f64) -> f64 {
    a.tan() - a
}

/// ψ(ρ): the flank's angle from the tooth's axis at radius ρ ≥ r_b.
fn half_angle(rb: f64, r: f64, s: f64, rho: f64) -> f64 {
    let alpha = (rb / r).clamp(-1.0, 1.0).acos();
    s / (2.0 * r) + inv(alpha) - inv((rb / rho.max(rb)).clamp(-1.0, 1.0).acos())
}

pub fn draw(job: &Job, name: &str, _: &Options) -> Drawn {
    let Some([rb, r, ra, rf, s, z]) = tooth_geometry(job).filter(|_| name == "tooth") else { return Ok(None) };
    let mm = |rho: f64, th: f64| (1e3 * rho * th.cos(), 1e3 * rho * th.sin());
    let alpha = (rb / r).clamp(-1.0, 1.0).acos();
    let psi = |rho: f64| half_angle(rb, r, s, rho);
    let pitch = 2.0 * std::f64::consts::PI / z;
    let top = (0..=200)
        .map(|k| rb.max(rf) + (ra - rb.max(rf)) * f64::from(k) / 200.0)
        .take_while(|&rho| psi(rho) > 0.0)
        .last()
        .unwrap_or(ra);
    let flank: Vec<f64> = (0..=60).map(|k| rb.max(rf) + (top - rb.max(rf)) * f64::from(k) / 60.0).collect();
    let mut outline = Vec::new();
    let teeth: Vec<f64> = if z >= 3.0 { vec![-1.0, 0.0, 1.0] } else { (0..z as usize).map(|k| k as f64).collect() };
    for (i, k) in teeth.iter().enumerate() {
        let axis = FRAC_PI_2 + k * pitch;
        if i == 0 {
            outline.extend(arc(rf, axis - pitch / 2.0, axis - psi(rb.max(rf)), &mm));
        }
        outline.push(mm(rf, axis - psi(rb.max(rf))));
        outline.extend(flank.iter().map(|&rho| mm(rho, axis - psi(rho))));
        outline.extend(arc(top, axis - psi(top), axis + psi(top), &mm));
        outline.extend(flank.iter().rev().map(|&rho| mm(rho, axis + psi(rho))));
        outline.push(mm(rf, axis + psi(rb.max(rf))));
        let next = if i + 1 < teeth.len() { axis + pitch - psi(rb.max(rf)) } else { axis + pitch / 2.0 };
        outline.extend(arc(rf, axis + psi(rb.max(rf)), next, &mm));
    }
    let span = (teeth.len() as f64 / 2.0 + 0.2) * pitch;
    let circle = |rho: f64| arc(rho, FRAC_PI_2 - span, FRAC_PI_2 + span, &mm);
    let tip = Msg::new("plot-gear-tip").arg("tip", sig(1e3 * ra)).arg("root", sig(1e3 * rf)).text();
    let c = Chart::new(say("plot-gear-tooth"), Axis::new("x", "mm"), Axis::new("y", "mm"))
        .line(say("plot-gear-profile"), outline, Pen::solid(0))
        .line(Msg::new("plot-gear-pitch").arg("value", sig(1e3 * r)).text(), circle(r), Pen::dashed(1))
        .line(Msg::new("plot-gear-base").arg("value", sig(1e3 * rb)).text(), circle(rb), Pen::dashed(2))
        .line(tip, circle(ra), Pen::dashed(7))
        .line("", circle(rf), Pen::dashed(7));
    let thickness = Msg::new("plot-gear-thickness").arg("value", sig(1e3 * s)).text();
    let mut c = c.mark(mm(r, FRAC_PI_2 + s / (2.0 * r)), thickness);
    c.equal = true;
    let note = Msg::new(if top < ra { "plot-gear-note-pointed" } else { "plot-gear-note" });
    Ok(Some(c.subtitle(note.arg("z", z).arg("alpha", sig(alpha.to_degrees())).text())))
}

fn arc(rho: f64, from: f64, to: f64, mm: &impl Fn(f64, f64) -> (f64, f64)) -> Vec<(f64, f64)> {
    let n = 24;
    (0..=n).map(|k| mm(rho, from + (to - from) * f64::from(k) / f64::from(n))).collect()
}

#[cfg(test)]
mod tests {
    use super::half_angle;

    /// The drawn flank agrees with the engine's tooth thickness: module
    /// 4 mm, z = 30, α = 20° (the OpenAPI example of `POST
    /// /v1/gears/geometry`): the engine gives s_a = 2.9495998320114066 mm on
    /// the tip circle r_a = 64 mm; the drawing's chord angle 2ψ(r_a) times
    /// r_a is that arc (1e-12, the rounding of a few operations).
    #[test]
    fn the_drawn_flank_has_the_engines_thickness_at_the_tip() {
        let (rb, r, s, ra) = (0.056381557247154504, 0.06, 0.006283185307179587, 0.064);
        assert!((2.0 * ra * half_angle(rb, r, s, ra) - 0.0029495998320114066).abs() < 1e-12);
        assert!((2.0 * r * half_angle(rb, r, s, r) - s).abs() < 1e-15, "s on the pitch circle");
    }
}
