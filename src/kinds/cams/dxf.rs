//! A cam's profile as a DXF drawing (ASCII, AutoCAD R12 entities, mm): the
//! profile a closed POLYLINE on layer PROFILE, a roller's pitch curve on
//! PITCH, the base circle a CIRCLE on BASE. Written here rather than with
//! the `dxf` crate: three entities of group-code pairs against a crate of
//! 18 000 lines with chrono, image and uuid among its dependencies.

use serde_json::Value;
use std::fmt::Write;

/// The drawing of a stored cam result (None when it has no samples).
pub fn profile(result: &Value) -> Option<Vec<u8>> {
    let rows = result["samples"].as_array().filter(|r| !r.is_empty())?;
    let points = |key: &str| -> Option<Vec<[f64; 2]>> {
        rows.iter().map(|r| Some([1e3 * r[key][0].as_f64()?, 1e3 * r[key][1].as_f64()?])).collect()
    };
    let mut out = String::new();
    out.push_str("0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1009\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n");
    out.push_str("0\nSECTION\n2\nENTITIES\n");
    polyline(&mut out, "PROFILE", &points("profile_point")?);
    if rows[0].get("pitch_curvature_radius").is_some() {
        polyline(&mut out, "PITCH", &points("pitch_point")?);
    }
    if let Some(base) = result["summary"]["base_radius"].as_f64() {
        let _ = write!(out, "0\nCIRCLE\n8\nBASE\n10\n0.0\n20\n0.0\n30\n0.0\n40\n{}\n", 1e3 * base);
    }
    out.push_str("0\nENDSEC\n0\nEOF\n");
    Some(out.into_bytes())
}

/// A closed 2-D polyline on `layer` through `points` (mm).
fn polyline(out: &mut String, layer: &str, points: &[[f64; 2]]) {
    let _ = write!(out, "0\nPOLYLINE\n8\n{layer}\n66\n1\n70\n1\n10\n0.0\n20\n0.0\n30\n0.0\n");
    for [x, y] in points {
        let _ = write!(out, "0\nVERTEX\n8\n{layer}\n10\n{x}\n20\n{y}\n30\n0.0\n");
    }
    let _ = write!(out, "0\nSEQEND\n8\n{layer}\n");
}
