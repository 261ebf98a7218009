//! The CSV table of a stored kinetostatics result (`result.csv`), read from
//! the stored JSON: a row per step.

use crate::kind::{Columns, cell, items, names};
use crate::kinds::mechanism::motion3::{MOTION_3, REACTION_3};
use serde_json::Value;

/// The CSV table of a stored result: one row per step; columns input(s),
/// driving action(s), I*, M*, condition number, fx, fy, moment per joint
/// and, where asked, the shaking force and moment (and once balanced) and
/// each body's motion; a singular step's cells are empty.
pub fn csv_table(result: &Value) -> (Vec<String>, Vec<Vec<String>>) {
    let steps = result["steps"].as_array().cloned().unwrap_or_default();
    if steps.is_empty() {
        return (Vec::new(), Vec::new());
    }
    let units = |key: &str| -> Vec<String> {
        result["inputs"]
            .as_array()
            .into_iter()
            .flatten()
            .map(|i| i[key].as_str().unwrap_or("").replace('*', "_"))
            .collect()
    };
    let numbered = |name: &str, units: Vec<String>| -> Vec<String> {
        let n = units.len();
        units
            .iter()
            .enumerate()
            .map(|(k, u)| if n == 1 { format!("{name}_{u}") } else { format!("{name}_{}_{u}", k + 1) })
            .collect()
    };
    let inputs = units("coordinate_unit").len().max(1);
    let driving = steps.iter().any(|s| !s["driving"].is_null());
    let (joints, bodies) = (names(&steps, "reactions", "joint"), names(&steps, "kinematics", "body"));
    // A spatial mechanism's steps: vectors, each component a column.
    let spatial =
        steps.iter().any(|s| s["kinematics"][0].get("position").is_some() || s["reactions"][0].get("force").is_some());
    let (reaction, motion): (Columns, Columns) = if spatial { (&REACTION_3, &MOTION_3) } else { (&REACTION, &MOTION) };
    let mut header = numbered("input", units("coordinate_unit"));
    if driving {
        header.extend(numbered("driving", units("driving_unit")));
    }
    header.extend(["reduced_inertia_kg_m2", "reduced_torque_N_m", "jacobian_condition"].map(String::from));
    for j in &joints {
        header.extend(reaction.iter().map(|(_, column)| format!("{j}_{column}")));
    }
    let has = |key: &str| steps.iter().any(|s| !s["shaking"][key].is_null());
    let (shaking, balanced) = (has("force"), has("balanced_force"));
    if shaking {
        header.extend(["shaking_fx_N", "shaking_fy_N", "shaking_moment_N_m"].map(String::from));
    }
    if balanced {
        header.extend(["balanced_fx_N", "balanced_fy_N"].map(String::from));
    }
    for b in &bodies {
        header.extend(motion.iter().map(|(_, column)| format!("{b}_{column}")));
    }
    let rows = steps
        .iter()
        .map(|s| {
            let mut row = cells(&s["input"], inputs);
            if driving {
                row.extend(cells(&s["driving"], inputs));
            }
            row.extend([cell(&s["reduced_inertia"]), cell(&s["reduced_torque"]), cell(&s["jacobian_condition"])]);
            row.extend(items(&s["reactions"], joints.len(), reaction));
            let f = |key: &str, k: usize| cell(&s["shaking"][key][k]);
            if shaking {
                row.extend([f("force", 0), f("force", 1), cell(&s["shaking"]["moment"])]);
            }
            if balanced {
                row.extend([f("balanced_force", 0), f("balanced_force", 1)]);
            }
            row.extend(items(&s["kinematics"], bodies.len(), motion));
            row
        })
        .collect();
    (header, rows)
}

/// A joint's reaction in the CSV: where in the item, and the column's name.
const REACTION: [(&str, &str); 3] = [("/fx", "fx_N"), ("/fy", "fy_N"), ("/moment", "moment_N_m")];
/// A body's motion in the CSV: where in the item, and the column's name.
const MOTION: [(&str, &str); 9] = [
    ("/x", "x_m"),
    ("/y", "y_m"),
    ("/theta", "theta_rad"),
    ("/vx", "vx_m_s"),
    ("/vy", "vy_m_s"),
    ("/omega", "omega_rad_s"),
    ("/ax", "ax_m_s2"),
    ("/ay", "ay_m_s2"),
    ("/alpha", "alpha_rad_s2"),
];

/// A number or a list of `n` numbers as `n` cells (empty where null).
fn cells(v: &Value, n: usize) -> Vec<String> {
    match v {
        Value::Array(a) => a.iter().map(cell).collect(),
        Value::Null => vec![String::new(); n],
        other => vec![cell(other)],
    }
}
