//! Grading a number against the engine's: the tolerance rules of course
//! platforms, and the common slips a wrong answer matches.
//!
//! Symbols (all SI): `g` the given answer, `e` the expected value,
//! `d = |g − e|` the difference. The rules, in the order they decide:
//! - zero level `z` (WeBWorK's `zeroLevel`): when |e| ≤ z the item passes
//!   iff d ≤ z (a reaction that passes through zero has no relative error);
//! - absolute `a`: passes when d ≤ a;
//! - relative `r`: passes when d ≤ r·|e|;
//! - significant figures `n` (PrairieLearn's `sigfig`), replacing `r`:
//!   passes when d ≤ 0.51·10^(⌊log10|e|⌋ − n + 1), i.e. g rounds to e's
//!   first n digits with a hair of slack.
//!
//! Every bound is widened by [`SLACK`] (relative) so that an answer exactly
//! at the tolerance, written in decimal, passes despite binary rounding
//! (0.303 against 0.3 at 1 % differs by 0.0030000000000000027).

use std::f64::consts::PI;

/// Relative widening of every bound: far below any tolerance a course uses,
/// far above the rounding of a decimal answer (~1e-16).
pub const SLACK: f64 = 1e-9;

/// How close an answer must be.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    pub relative: f64,
    pub absolute: f64,
    pub sigfigs: Option<u32>,
    pub zero_level: f64,
}

impl Default for Tolerance {
    fn default() -> Self {
        Self { relative: 0.01, absolute: 0.0, sigfigs: None, zero_level: 1e-12 }
    }
}

/// The rule that decided an item.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    ZeroLevel,
    Absolute,
    Relative,
    SigFigs,
}

/// How an answer fared.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Verdict {
    pub pass: bool,
    pub rule: Rule,
    /// The largest difference `rule` allows.
    pub bound: f64,
    /// d/|e|; None when e = 0.
    pub relative_error: Option<f64>,
}

/// The largest difference the significant-figure rule allows for `e`.
pub fn sigfig_bound(e: f64, n: u32) -> f64 {
    let exponent = e.abs().log10().floor() as i32 - n as i32 + 1;
    0.51 * 10f64.powi(exponent)
}

/// Whether `g` passes against `e`, and by which rule.
pub fn judge(g: f64, e: f64, t: &Tolerance) -> Verdict {
    let d = (g - e).abs();
    let relative_error = (e != 0.0).then(|| d / e.abs());
    let within = |bound: f64| d <= bound * (1.0 + SLACK);
    let verdict = |rule, bound| Verdict { pass: within(bound), rule, bound, relative_error };
    if e.abs() <= t.zero_level {
        return verdict(Rule::ZeroLevel, t.zero_level);
    }
    if t.absolute > 0.0 && within(t.absolute) {
        return verdict(Rule::Absolute, t.absolute);
    }
    match t.sigfigs {
        Some(n) => verdict(Rule::SigFigs, sigfig_bound(e, n)),
        None => verdict(Rule::Relative, t.relative * e.abs()),
    }
}

/// A slip a wrong answer matches.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Slip {
    /// Another value of the result (index into the candidates given).
    OtherValue(usize),
    /// −e.
    OppositeSign,
    /// e in degrees where radians are expected (e·180/π).
    Degrees,
    /// An angular speed in rpm where rad/s is expected (e·60/2π).
    Rpm,
    /// e·2π (`times`) or e/2π.
    TwoPi { times: bool },
    /// e·10^k: a unit prefix (mm for m, kN for N).
    PowerOfTen(i32),
}

/// What the expected value is, for the slips that depend on it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Measure {
    /// Its unit has radians to the first power (rad, rad/s, rad/s²).
    pub angular: bool,
    /// It is an angular speed (rad/s).
    pub angular_speed: bool,
}

/// The first slip that `g`, failed against `e`, matches within `t`: the
/// opposite sign, another of `others` (in the order given; those at zero
/// level are skipped), degrees, rpm, 2π, a power of ten.
pub fn slip(g: f64, e: f64, t: &Tolerance, m: Measure, others: &[f64]) -> Option<Slip> {
    let matches = |x: f64| x.abs() > t.zero_level && judge(g, x, t).pass;
    if matches(-e) {
        return Some(Slip::OppositeSign);
    }
    if let Some(i) = others.iter().position(|&x| matches(x)) {
        return Some(Slip::OtherValue(i));
    }
    let scaled = [
        (e.to_degrees(), Slip::Degrees, m.angular),
        (e * 60.0 / (2.0 * PI), Slip::Rpm, m.angular_speed),
        (e * 2.0 * PI, Slip::TwoPi { times: true }, true),
        (e / (2.0 * PI), Slip::TwoPi { times: false }, true),
    ];
    if let Some((_, s, _)) = scaled.iter().find(|(x, _, applies)| *applies && matches(*x)) {
        return Some(*s);
    }
    [-9, -6, -3, 3, 6, 9].into_iter().find(|k| matches(e * 10f64.powi(*k))).map(Slip::PowerOfTen)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(r: f64) -> Tolerance {
        Tolerance { relative: r, ..Tolerance::default() }
    }

    #[test]
    fn exactly_at_the_relative_tolerance_passes_and_just_beyond_fails() {
        // 1 % of 0.3 is 0.003: 0.303 is at the bound (binary rounding makes d 2.7e-18 over it).
        assert!(judge(0.303, 0.3, &rel(0.01)).pass);
        assert!(judge(0.297, 0.3, &rel(0.01)).pass);
        assert!(!judge(0.30301, 0.3, &rel(0.01)).pass);
        // Negative values: the bound is relative to |e|.
        assert!(judge(-101.0, -100.0, &rel(0.01)).pass);
        assert!(!judge(-101.01, -100.0, &rel(0.01)).pass);
        let v = judge(-98.0, -100.0, &rel(0.01));
        assert_eq!((v.pass, v.rule), (false, Rule::Relative));
        assert!((v.relative_error.unwrap() - 0.02).abs() < 1e-15);
    }

    #[test]
    fn absolute_tolerance_passes_what_the_relative_one_would_not() {
        let t = Tolerance { absolute: 0.5, ..rel(0.001) };
        let v = judge(10.5, 10.0, &t);
        assert_eq!((v.pass, v.rule), (true, Rule::Absolute));
        assert!(!judge(10.51, 10.0, &t).pass);
    }

    #[test]
    fn three_significant_figures_of_0_0004567() {
        // PrairieLearn: bound 0.51·10^(⌊log10 0.0004567⌋ − 3 + 1) = 0.51e-6.
        let t = Tolerance { sigfigs: Some(3), ..Tolerance::default() };
        assert!((sigfig_bound(0.0004567, 3) - 0.51e-6).abs() < 1e-21);
        assert!(judge(0.000457, 0.0004567, &t).pass); // d = 0.3e-6
        assert!(judge(0.0004567, 0.0004567, &t).pass);
        assert!(!judge(0.000456, 0.0004567, &t).pass); // d = 0.7e-6
        assert!(!judge(0.00046, 0.0004567, &t).pass); // 2 figures: d = 3.3e-6
        // The rule replaces the relative one: 0.5 % off passes 2 figures of 353.52 even at r = 0.
        let two = Tolerance { sigfigs: Some(2), relative: 0.0, ..Tolerance::default() };
        assert!(judge(350.0, 353.52, &two).pass); // bound 5.1
        assert!(!judge(340.0, 353.52, &two).pass);
    }

    #[test]
    fn below_the_zero_level_the_comparison_is_absolute() {
        let t = Tolerance { zero_level: 1e-3, ..rel(0.01) };
        let v = judge(5e-4, 0.0, &t);
        assert_eq!((v.pass, v.rule, v.relative_error), (true, Rule::ZeroLevel, None));
        assert!(!judge(2e-3, 0.0, &t).pass);
        assert!(judge(-9e-4, 1e-4, &t).pass); // e at zero level: d = 1e-3
        // The default zero level is 1e-12: an exact zero needs a zero (or 1e-12) answer.
        assert!(judge(0.0, 0.0, &Tolerance::default()).pass);
        assert!(!judge(1e-9, 0.0, &Tolerance::default()).pass);
    }

    #[test]
    fn each_slip_is_named() {
        let t = Tolerance::default();
        let none = Measure::default();
        let angular = Measure { angular: true, angular_speed: true };
        // Another value: the approximate inertia (P.103: 359.0) for the exact one (353.52).
        assert_eq!(slip(359.0, 353.52, &t, none, &[0.0, 359.05]), Some(Slip::OtherValue(1)));
        assert_eq!(slip(-42.0, 42.0, &t, none, &[]), Some(Slip::OppositeSign));
        // The sign first: −ΔE is also the work of one lobe, but the slip is the sign.
        assert_eq!(slip(-42.0, 42.0, &t, none, &[-42.0]), Some(Slip::OppositeSign));
        assert_eq!(slip(90.0, PI / 2.0, &t, angular, &[]), Some(Slip::Degrees));
        assert_eq!(slip(90.0, PI / 2.0, &t, none, &[]), None, "degrees only where radians are expected");
        // 60 rpm = 2π rad/s.
        assert_eq!(slip(60.0, 2.0 * PI, &t, angular, &[]), Some(Slip::Rpm));
        assert_eq!(slip(2.0 * PI * 5.0, 5.0, &t, none, &[]), Some(Slip::TwoPi { times: true }));
        assert_eq!(slip(5.0, 2.0 * PI * 5.0, &t, none, &[]), Some(Slip::TwoPi { times: false }));
        assert_eq!(slip(4000.0, 4.0, &t, none, &[]), Some(Slip::PowerOfTen(3)));
        assert_eq!(slip(7.0, 4.0, &t, none, &[]), None);
        // A zero elsewhere in the result is no slip of a zero answer.
        assert_eq!(slip(0.0, 4.0, &t, none, &[0.0]), None);
    }
}
