//! The table of a dynamics result (its CSV): one row per sample, and for a
//! mechanism every body's position (a spatial one's motion, a column per
//! component) and every joint's reaction at the sample.

use crate::kind::{Columns, items, names};
use crate::kinds::mechanism::motion3::{MOTION_3, REACTION_3};

/// CSV of a stored dynamics result: one row per sample; for a mechanism
/// also every body's position and every joint's reaction at the sample.
/// The motion's columns carry its first input's unit: rad, or m where it
/// is a length (a slider's travel, a contact's arc length).
pub fn csv_table(result: &serde_json::Value) -> (Vec<String>, Vec<Vec<String>>) {
    let (angle, speed, acceleration) = match result["machine"]["input_units"][0] == "m" {
        true => ("angle_m", "speed_m_s", "acceleration_m_s2"),
        false => ("angle_rad", "speed_rad_s", "acceleration_rad_s2"),
    };
    let columns = [("t", "t_s"), ("angle", angle), ("speed", speed), ("acceleration", acceleration)];
    let mut header: Vec<String> = columns.iter().map(|c| c.1.to_string()).collect();
    let samples: &[serde_json::Value] = result["samples"].as_array().map_or(&[], Vec::as_slice);
    let machine = result["machine"]["samples"].as_array().filter(|m| m.len() == samples.len());
    let rows = machine.map_or(&[][..], Vec::as_slice);
    let (bodies, joints) = (names(rows, "bodies", "body"), names(rows, "reactions", "joint"));
    // A spatial mechanism's bodies and reactions: vectors, a column each component.
    let spatial = result["machine"]["space"] == "spatial";
    let (body, reaction): (Columns, Columns) = match spatial {
        true => (&MOTION_3, &REACTION_3),
        false => (
            &[("/x", "x_m"), ("/y", "y_m"), ("/theta", "theta_rad")],
            &[("/fx", "fx_N"), ("/fy", "fy_N"), ("/moment", "moment_N_m")],
        ),
    };
    header.extend(bodies.iter().flat_map(|b| body.iter().map(move |c| format!("{b}_{}", c.1))));
    header.extend(joints.iter().flat_map(|j| reaction.iter().map(move |c| format!("{j}_{}", c.1))));
    let rows = samples
        .iter()
        .enumerate()
        .map(|(k, row)| {
            let mut cells: Vec<String> = columns.iter().map(|c| row[c.0].to_string()).collect();
            if let Some(m) = machine {
                cells.extend(items(&m[k]["bodies"], bodies.len(), body));
                cells.extend(items(&m[k]["reactions"], joints.len(), reaction));
            }
            cells
        })
        .collect();
    (header, rows)
}
