//! Engine timings: `cargo bench --bench engine [-- flywheel|kinetostatics]`.
//! Prints wall time per job or per step (the fastest of several runs: this
//! shared machine adds ±30 % of noise, never removes time) on this machine;
//! no assertions (benchmarks are not tests). Shows what computing only what
//! is asked buys.

use mechdyn::engine::Deadline;
use mechdyn::engine::expr::Expr;
use mechdyn::engine::flywheel::{FlywheelProblem, Load as TorqueLoad, TorqueItem, solve as flywheel};
use mechdyn::engine::function::{Function, Segment};
use mechdyn::engine::kinetostatics::{Load, Outputs, solve};
use mechdyn::engine::samples::offset_slider_crank;
use std::f64::consts::PI;
use std::hint::black_box;
use std::time::Instant;

/// Fastest wall time of `runs` calls, in microseconds.
fn best_us(runs: usize, mut f: impl FnMut()) -> f64 {
    (0..runs)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64() * 1e6
        })
        .fold(f64::INFINITY, f64::min)
}

/// Whether the command line (after `--`) selects this group; none selects all.
fn selected(group: &str) -> bool {
    let args: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with('-')).collect();
    args.is_empty() || args.iter().any(|a| group.contains(a.as_str()))
}

fn p103(check: bool, inertia: Function) -> FlywheelProblem {
    let load = Function::Segments(vec![Segment {
        from: 0.0,
        to: PI,
        expr: Expr::compile("-500*sin(phi)", &["phi"]).unwrap(),
    }]);
    FlywheelProblem {
        period: 2.0 * PI,
        mean_speed: 2.0 * PI,
        irregularity: 0.04,
        torques: vec![
            TorqueItem { name: "load".into(), load: TorqueLoad::Given(load), ratio: 1.0, label: "load".into() },
            TorqueItem { name: "motor".into(), load: TorqueLoad::Balance, ratio: 1.0, label: "motor".into() },
        ],
        reduced_inertia: inertia,
        reduced_inertia_label: "I*".into(),
        existing_inertia: 0.0,
        flywheel_ratio: 1.0,
        disk: None,
        tolerance: 1e-9,
        check,
        samples: 0,
        deadline: Deadline::none(),
    }
}

fn main() {
    println!("| job | what | time |");
    println!("|---|---|---|");
    if selected("flywheel") {
        flywheels();
    }
    if selected("kinetostatics") {
        kinetostatics();
    }
}

fn flywheels() {
    let variable = || Function::Expr(Expr::compile("5*sin(phi)^2", &["phi"]).unwrap());
    for (what, p) in [
        ("P.103, I* = 5 sin²φ, exact + time check", p103(true, variable())),
        ("P.103, I* = 5 sin²φ, exact, no check", p103(false, variable())),
        ("P.103, I* constant (closed form), no check", p103(false, Function::Constant(5.0))),
    ] {
        let t = best_us(51, || {
            black_box(flywheel(&p).unwrap());
        });
        println!("| flywheel | {what} | {t:.0} µs/job |");
    }
}

fn kinetostatics() {
    let m = offset_slider_crank();
    let b = m.joints[2].at;
    let gas = Function::Expr(Expr::compile("-8000*exp(3*(cos(phi - 0.35) - 1))", &["phi"]).unwrap());
    let loads = vec![Load::Force { body: 3, at: b, direction: [1.0, 0.0], magnitude: gas }];
    let n = 3600;
    let positions: Vec<Vec<[f64; 3]>> = (0..n).map(|k| vec![[2.0 * PI * k as f64 / n as f64, 150.0, 0.0]]).collect();
    for (what, outputs) in [
        (
            "all reactions + I*, M* + virtual-power check",
            Outputs { driving: true, reactions: true, reduced: true, kinematics: false, condition: false },
        ),
        (
            "driving torque only (virtual power)",
            Outputs { driving: true, reactions: false, reduced: false, kinematics: false, condition: false },
        ),
    ] {
        let t = best_us(15, || {
            black_box(solve(&m, &loads, &positions, outputs, &Deadline::none()).unwrap());
        });
        println!("| kinetostatics | slider-crank, 3600 steps, {what} | {:.2} µs/step |", t / n as f64);
    }
}
