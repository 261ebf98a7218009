//! A cam's profile as a DXF drawing (ASCII, AutoCAD R12 entities, mm): the
//! profile a closed POLYLINE on layer PROFILE, a roller's pitch curve on
//! PITCH, the base circle a CIRCLE on BASE. Written here rather than with
//! the `dxf` crate: three entities of group-code pairs against a crate of
//! 18 000 lines with chrono, image and uuid among its dependencies.

use serde_json::Value;
use std::fmt::Write;

/// The drawing of a stored cam result (None when it has no samples).
pub fn profile(result: &Value) -> Option<Vec<u8>> {
    let (profile, pitch) = curves(result)?;
    let mut out = String::new();
    out.push_str("0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1009\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n");
    out.push_str("0\nSECTION\n2\nENTITIES\n");
    polyline(&mut out, "PROFILE", &profile);
    if let Some(pitch) = pitch {
        polyline(&mut out, "PITCH", &pitch);
    }
    if let Some(base) = result["summary"]["base_radius"].as_f64() {
        let _ = write!(out, "0\nCIRCLE\n8\nBASE\n10\n0.0\n20\n0.0\n30\n0.0\n40\n{}\n", 1e3 * base);
    }
    out.push_str("0\nENDSEC\n0\nEOF\n");
    Some(out.into_bytes())
}

/// Whether the result has a drawing ([`curves`] would find them), without
/// gathering its points (a page links it).
pub fn has_profile(result: &Value) -> bool {
    let Some(rows) = samples(result) else { return false };
    let every = |key: &str| rows.iter().all(|r| r[key][0].is_f64() && r[key][1].is_f64());
    every("profile_point") && (rows[0].get("pitch_curvature_radius").is_none() || every("pitch_point"))
}

fn samples(result: &Value) -> Option<&Vec<Value>> {
    result["samples"].as_array().filter(|r| !r.is_empty())
}

/// The profile's points and a roller's pitch curve's (mm).
type Curves = (Vec<[f64; 2]>, Option<Vec<[f64; 2]>>);

/// The result's [`Curves`], None where it has no samples or a sample lacks them.
fn curves(result: &Value) -> Option<Curves> {
    let rows = samples(result)?;
    let points = |key: &str| -> Option<Vec<[f64; 2]>> {
        rows.iter().map(|r| Some([1e3 * r[key][0].as_f64()?, 1e3 * r[key][1].as_f64()?])).collect()
    };
    let pitch = match rows[0].get("pitch_curvature_radius") {
        Some(_) => Some(points("pitch_point")?),
        None => None,
    };
    Some((points("profile_point")?, pitch))
}

/// A closed 2-D polyline on `layer` through `points` (mm).
fn polyline(out: &mut String, layer: &str, points: &[[f64; 2]]) {
    let _ = write!(out, "0\nPOLYLINE\n8\n{layer}\n66\n1\n70\n1\n10\n0.0\n20\n0.0\n30\n0.0\n");
    for [x, y] in points {
        let _ = write!(out, "0\nVERTEX\n8\n{layer}\n10\n{x}\n20\n{y}\n30\n0.0\n");
    }
    let _ = write!(out, "0\nSEQEND\n8\n{layer}\n");
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    /// The check a page links by agrees with the drawing: a roller's
    /// result has one, not without its pitch points, nor with a profile
    /// point missing, nor with no samples; a flat face's needs no pitch.
    #[test]
    fn has_profile_is_whether_a_profile_is_drawn() {
        let sample = |pitch: bool| {
            let mut s =
                json!({"profile_point": [0.04, 0.0], "pitch_point": [0.05, 0.0], "pitch_curvature_radius": 0.05});
            if !pitch {
                let s = s.as_object_mut().unwrap();
                s.remove("pitch_point");
                s.remove("pitch_curvature_radius");
            }
            s
        };
        let roller = json!({"samples": [sample(true), sample(true)], "summary": {"base_radius": 0.04}});
        let mut no_pitch = roller.clone();
        no_pitch["samples"][1].as_object_mut().unwrap().remove("pitch_point");
        let mut no_point = roller.clone();
        no_point["samples"][0]["profile_point"] = json!(null);
        let flat = json!({"samples": [sample(false)]});
        for (result, drawn) in
            [(roller, true), (no_pitch, false), (no_point, false), (flat, true), (json!({"samples": []}), false)]
        {
            assert_eq!(has_profile(&result), drawn, "{result}");
            assert_eq!(profile(&result).is_some(), drawn, "{result}");
        }
    }
}
