//! Quantities written as `"VALUE UNIT"` strings, converted to SI with a
//! dimension check.
//!
//! A unit is a product of table units with integer powers: `kg*m^2`,
//! `g/cm^3`, `lbf*ft`, `rev/min`. Dimensions are exponents of
//! (length, mass, time, angle): the angle is its own dimension, so `1/s` is
//! not an angular speed while `rad/s`, `rpm` and `deg/s` are.
//!
//! No crate fits (see ARCHITECTURE.md): the table below holds each unit's
//! exact definition and the tests check every entry against it.

use std::f64::consts::PI;

mod written;
use written::number_length;
pub use written::{number, suggestion, ungrouped};

/// Exponents of (length, mass, time, angle).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Dim(pub [i8; 4]);

impl Dim {
    pub const NONE: Dim = Dim([0, 0, 0, 0]);
    pub const LENGTH: Dim = Dim([1, 0, 0, 0]);
    pub const MASS: Dim = Dim([0, 1, 0, 0]);
    pub const TIME: Dim = Dim([0, 0, 1, 0]);
    pub const ANGLE: Dim = Dim([0, 0, 0, 1]);
    pub const ANGULAR_SPEED: Dim = Dim([0, 0, -1, 1]);
    pub const SPEED: Dim = Dim([1, 0, -1, 0]);
    pub const FORCE: Dim = Dim([1, 1, -2, 0]);
    /// Torque and energy (N·m = J).
    pub const TORQUE: Dim = Dim([2, 1, -2, 0]);
    pub const POWER: Dim = Dim([2, 1, -3, 0]);
    pub const INERTIA: Dim = Dim([2, 1, 0, 0]);
    pub const DENSITY: Dim = Dim([-3, 1, 0, 0]);
    pub const ACCELERATION: Dim = Dim([1, 0, -2, 0]);
    pub const ANGULAR_ACCELERATION: Dim = Dim([0, 0, -2, 1]);
    /// N/m
    pub const STIFFNESS: Dim = Dim([0, 1, -2, 0]);
    /// N·m/rad (a torsional spring).
    pub const TORSIONAL_STIFFNESS: Dim = Dim([2, 1, -2, -1]);
    /// N·s/m
    pub const DAMPING: Dim = Dim([0, 1, -1, 0]);

    fn pow(self, p: i8) -> Dim {
        Dim(self.0.map(|e| e * p))
    }

    fn mul(self, o: Dim) -> Dim {
        Dim([0, 1, 2, 3].map(|i| self.0[i] + o.0[i]))
    }

    /// The SI unit of this dimension, for messages.
    pub fn si_name(self) -> String {
        const NAMED: [(Dim, &str); 16] = [
            (Dim::NONE, "1 (dimensionless)"),
            (Dim::LENGTH, "m"),
            (Dim::MASS, "kg"),
            (Dim::TIME, "s"),
            (Dim::ANGLE, "rad"),
            (Dim::ANGULAR_SPEED, "rad/s"),
            (Dim::SPEED, "m/s"),
            (Dim::FORCE, "N"),
            (Dim::TORQUE, "N*m"),
            (Dim::POWER, "W"),
            (Dim::INERTIA, "kg*m^2"),
            (Dim::DENSITY, "kg/m^3"),
            (Dim::ACCELERATION, "m/s^2"),
            (Dim::ANGULAR_ACCELERATION, "rad/s^2"),
            (Dim::STIFFNESS, "N/m"),
            (Dim::DAMPING, "N*s/m"),
        ];
        if let Some((_, n)) = NAMED.iter().find(|(d, _)| *d == self) {
            return (*n).to_string();
        }
        let parts: Vec<String> = ["m", "kg", "s", "rad"]
            .iter()
            .zip(self.0)
            .filter(|(_, e)| *e != 0)
            .map(|(n, e)| if e == 1 { n.to_string() } else { format!("{n}^{e}") })
            .collect();
        parts.join("*")
    }
}

/// Standard gravity (m/s²), part of the definition of the pound-force.
const G0: f64 = 9.806_65;
/// International pound (kg).
const LB: f64 = 0.453_592_37;
/// International foot (m).
const FT: f64 = 0.3048;
/// Pound-force (N), exact: lb · g₀.
const LBF: f64 = LB * G0;

/// Table of units: name, SI factor, dimension.
const UNITS: &[(&str, f64, Dim)] = &[
    ("m", 1.0, Dim::LENGTH),
    ("mm", 1e-3, Dim::LENGTH),
    ("cm", 1e-2, Dim::LENGTH),
    ("km", 1e3, Dim::LENGTH),
    ("in", 0.0254, Dim::LENGTH),
    ("ft", FT, Dim::LENGTH),
    ("kg", 1.0, Dim::MASS),
    ("g", 1e-3, Dim::MASS),
    ("t", 1e3, Dim::MASS),
    ("lb", LB, Dim::MASS),
    ("slug", LBF / FT, Dim::MASS),
    ("s", 1.0, Dim::TIME),
    ("ms", 1e-3, Dim::TIME),
    ("min", 60.0, Dim::TIME),
    ("h", 3600.0, Dim::TIME),
    ("rad", 1.0, Dim::ANGLE),
    ("deg", PI / 180.0, Dim::ANGLE),
    // The degree sign, and the masculine ordinal a Spanish keyboard puts beside the 1.
    ("°", PI / 180.0, Dim::ANGLE),
    ("º", PI / 180.0, Dim::ANGLE),
    ("rev", 2.0 * PI, Dim::ANGLE),
    ("rpm", 2.0 * PI / 60.0, Dim::ANGULAR_SPEED),
    ("N", 1.0, Dim::FORCE),
    ("kN", 1e3, Dim::FORCE),
    ("MN", 1e6, Dim::FORCE),
    ("lbf", LBF, Dim::FORCE),
    ("Nm", 1.0, Dim::TORQUE),
    ("kNm", 1e3, Dim::TORQUE),
    ("J", 1.0, Dim::TORQUE),
    ("kJ", 1e3, Dim::TORQUE),
    ("MJ", 1e6, Dim::TORQUE),
    ("cal", 4.184, Dim::TORQUE),
    ("kcal", 4184.0, Dim::TORQUE),
    ("W", 1.0, Dim::POWER),
    ("kW", 1e3, Dim::POWER),
    ("MW", 1e6, Dim::POWER),
    ("hp", 550.0 * FT * LBF, Dim::POWER),
    // The metric horsepower (caballo de vapor) of Spanish statements: 75 kgf·m/s.
    ("CV", 75.0 * G0, Dim::POWER),
    ("%", 0.01, Dim::NONE),
];

/// A value converted to SI, with its dimension.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quantity {
    pub si: f64,
    pub dim: Dim,
}

/// Why a quantity string was rejected.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum UnitError {
    #[error("'{0}' is not a number followed by a unit, e.g. \"300 rpm\"")]
    Malformed(String),
    #[error("unknown unit '{0}'{hint}; known units: {known}", hint = hint(.0), known = known_units())]
    Unknown(String),
    #[error("a value in {found} where {expected} is expected")]
    WrongDimension { found: String, expected: String },
}

/// "; did you mean N*m?" where a known unit is close to `name`.
fn hint(name: &str) -> String {
    suggestion(name).map(|s| format!("; did you mean {s}?")).unwrap_or_default()
}

/// The table's units, for messages.
pub fn known_units() -> String {
    UNITS.iter().map(|u| u.0).collect::<Vec<_>>().join(", ")
}

/// Parses a unit expression such as `kg*m^2` or `ft*lbf` into (SI factor, dimension).
pub fn parse_unit(text: &str) -> Result<(f64, Dim), UnitError> {
    let mut factor = 1.0;
    let mut dim = Dim::NONE;
    let mut sign = 1i8;
    let normal = written::normalized(text);
    let mut rest = normal.as_str();
    if rest.is_empty() {
        return Err(UnitError::Malformed(text.into()));
    }
    loop {
        let end = rest.find(['*', '/', '·']).unwrap_or(rest.len());
        let (f, d) = parse_factor(rest[..end].trim())?;
        factor *= if sign > 0 { f } else { 1.0 / f };
        dim = dim.mul(d.pow(sign));
        if end == rest.len() {
            return Ok((factor, dim));
        }
        let op = rest[end..].chars().next().unwrap_or('*');
        sign = if op == '/' { -1 } else { 1 };
        rest = &rest[end + op.len_utf8()..];
    }
}

/// One table unit with an optional integer power: `m^2`, `s^-1`, `1` in `1/s`.
fn parse_factor(text: &str) -> Result<(f64, Dim), UnitError> {
    let (name, power) = match text.split_once('^') {
        Some((n, p)) => {
            let p: i8 = p.trim().parse().map_err(|_| UnitError::Malformed(text.into()))?;
            (n.trim(), p)
        }
        None => (text, 1),
    };
    if name == "1" {
        return Ok((1.0, Dim::NONE));
    }
    // A power written without its caret, as a student writes it (`m2`, `s2`): the table's names have no digits.
    let stem = name.trim_end_matches(|c: char| c.is_ascii_digit());
    if power == 1 && stem.len() + 1 == name.len() && table_unit(stem).is_some() {
        let power: i8 = name[stem.len()..].parse().unwrap_or(1);
        let &(_, f, d) = table_unit(stem).ok_or_else(|| UnitError::Unknown(name.to_string()))?;
        return Ok((f.powi(power.into()), d.pow(power)));
    }
    let &(_, f, d) = table_unit(name).ok_or_else(|| UnitError::Unknown(name.to_string()))?;
    Ok((f.powi(power.into()), d.pow(power)))
}

/// A unit of the table by its name, or by the only name equal to it but for
/// case (`RPM`, `Deg`, `KW`), unless the case of an m is what tells milli
/// from mega (`MM`, `mn`, `MIN`: m or M followed by a unit's name).
fn table_unit(name: &str) -> Option<&'static (&'static str, f64, Dim)> {
    if let Some(u) = UNITS.iter().find(|u| u.0 == name) {
        return Some(u);
    }
    let mut same = UNITS.iter().filter(|u| u.0.eq_ignore_ascii_case(name));
    let found = same.next()?;
    let milli_or_mega = found.0.starts_with(['m', 'M'])
        && !name.starts_with(&found.0[..1])
        && UNITS.iter().any(|u| u.0.eq_ignore_ascii_case(&found.0[1..]));
    (same.next().is_none() && !milli_or_mega).then_some(found)
}

/// Parses `"VALUE"` (SI) or `"VALUE UNIT"`; the space may be left out
/// (`"60rpm"`, `"4%"`).
pub fn parse_quantity(text: &str) -> Result<Quantity, UnitError> {
    let t = text.trim();
    let spaced = t.find(|c: char| c.is_whitespace()).unwrap_or(t.len());
    // "1.200,5": a number with thousands separators, said as such ([`unit_msg`]'s).
    if number(&t[..spaced]).is_none() && written::ungrouped(&t[..spaced]).is_some() {
        return Err(UnitError::Malformed(text.into()));
    }
    let split = match number_length(t) {
        n if n > 0 && n < spaced && number(&t[..spaced]).is_none() => n,
        _ => spaced,
    };
    let (written, unit) = t.split_at(split);
    let value = number(written).ok_or_else(|| UnitError::Malformed(text.into()))?;
    if !value.is_finite() {
        return Err(UnitError::Malformed(text.into()));
    }
    if unit.trim().is_empty() {
        return Ok(Quantity { si: value, dim: Dim::NONE });
    }
    // An operator where a unit's name should start (`20*t`) is no quantity.
    let (factor, dim) = parse_unit(unit).map_err(|e| match e {
        UnitError::Unknown(name) if name.is_empty() => UnitError::Malformed(text.into()),
        e => e,
    })?;
    Ok(Quantity { si: value * factor, dim })
}

/// Parses a quantity and checks its dimension. A bare number is SI in the
/// expected dimension.
pub fn parse_as(text: &str, expected: Dim) -> Result<f64, UnitError> {
    let q = parse_quantity(text)?;
    let bare = number(text).is_some();
    if q.dim == expected || bare {
        Ok(q.si)
    } else {
        Err(UnitError::WrongDimension { found: q.dim.si_name(), expected: expected.si_name() })
    }
}

/// SI factor of a unit, checked against the expected dimension.
pub fn unit_factor(unit: &str, expected: Dim) -> Result<f64, UnitError> {
    let (f, d) = parse_unit(unit)?;
    if d == expected {
        Ok(f)
    } else {
        Err(UnitError::WrongDimension { found: d.si_name(), expected: expected.si_name() })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-15 * b.abs().max(1e-300)
    }

    /// Every unit of the table against its definition (NIST SP 811 / SI brochure):
    /// in = 2.54 cm, ft = 12 in, lb = 0.45359237 kg, lbf = lb·9.80665 m/s²,
    /// slug = lbf·s²/ft, hp = 550 ft·lbf/s, CV = 75 kgf·m/s (DIN 66036's PS),
    /// cal = 4.184 J (thermochemical), rpm = rev/min.
    #[test]
    fn every_unit_matches_its_definition() {
        let expect: &[(&str, f64, Dim)] = &[
            ("m", 1.0, Dim::LENGTH),
            ("mm", 0.001, Dim::LENGTH),
            ("cm", 0.01, Dim::LENGTH),
            ("km", 1000.0, Dim::LENGTH),
            ("in", 0.0254, Dim::LENGTH),
            ("ft", 12.0 * 0.0254, Dim::LENGTH),
            ("kg", 1.0, Dim::MASS),
            ("g", 0.001, Dim::MASS),
            ("t", 1000.0, Dim::MASS),
            ("lb", 0.45359237, Dim::MASS),
            ("slug", 14.593_902_937_206_364, Dim::MASS),
            ("s", 1.0, Dim::TIME),
            ("ms", 0.001, Dim::TIME),
            ("min", 60.0, Dim::TIME),
            ("h", 3600.0, Dim::TIME),
            ("rad", 1.0, Dim::ANGLE),
            ("deg", PI / 180.0, Dim::ANGLE),
            ("°", PI / 180.0, Dim::ANGLE),
            ("º", PI / 180.0, Dim::ANGLE),
            ("rev", 2.0 * PI, Dim::ANGLE),
            ("rpm", PI / 30.0, Dim::ANGULAR_SPEED),
            ("N", 1.0, Dim::FORCE),
            ("kN", 1000.0, Dim::FORCE),
            ("MN", 1e6, Dim::FORCE),
            ("lbf", 4.448_221_615_260_5, Dim::FORCE),
            ("Nm", 1.0, Dim::TORQUE),
            ("kNm", 1000.0, Dim::TORQUE),
            ("J", 1.0, Dim::TORQUE),
            ("kJ", 1000.0, Dim::TORQUE),
            ("MJ", 1e6, Dim::TORQUE),
            ("cal", 4.184, Dim::TORQUE),
            ("kcal", 4184.0, Dim::TORQUE),
            ("W", 1.0, Dim::POWER),
            ("kW", 1000.0, Dim::POWER),
            ("MW", 1e6, Dim::POWER),
            ("hp", 745.699_871_582_270_2, Dim::POWER),
            ("CV", 735.498_75, Dim::POWER),
            ("%", 0.01, Dim::NONE),
        ];
        assert_eq!(expect.len(), UNITS.len(), "every table unit has a test row");
        for &(name, si, dim) in expect {
            let (f, d) = parse_unit(name).unwrap();
            assert!(close(f, si), "{name}: {f} vs {si}");
            assert_eq!(d, dim, "{name}");
        }
    }

    /// The compound units the contract names, against hand-multiplied factors.
    #[test]
    fn compound_units_of_the_contract() {
        let lbf = 4.448_221_615_260_5;
        let cases: &[(&str, f64, Dim)] = &[
            ("300 rpm", 10.0 * PI, Dim::ANGULAR_SPEED),
            ("2 rad/s", 2.0, Dim::ANGULAR_SPEED),
            ("90 deg", PI / 2.0, Dim::ANGLE),
            ("180 deg/s", PI, Dim::ANGULAR_SPEED),
            ("1 rev/min", PI / 30.0, Dim::ANGULAR_SPEED),
            ("3200 ft*lbf", 3200.0 * 0.3048 * lbf, Dim::TORQUE),
            ("509.3 lbf*ft", 509.3 * 0.3048 * lbf, Dim::TORQUE),
            ("12 in*lbf", 0.3048 * lbf, Dim::TORQUE),
            ("2 N*m", 2.0, Dim::TORQUE),
            ("20 slug*ft^2", 20.0 * 14.593_902_937_206_364 * 0.3048 * 0.3048, Dim::INERTIA),
            ("3 kg*m^2", 3.0, Dim::INERTIA),
            ("7.2 g/cm^3", 7200.0, Dim::DENSITY),
            ("7850 kg/m^3", 7850.0, Dim::DENSITY),
            ("1.5 m/s", 1.5, Dim::SPEED),
            ("10 ft/s", 3.048, Dim::SPEED),
            ("4 mm", 0.004, Dim::LENGTH),
            ("29 hp", 29.0 * 745.699_871_582_270_2, Dim::POWER),
            ("2.6 kW", 2600.0, Dim::POWER),
            ("1 kcal", 4184.0, Dim::TORQUE),
            ("5 1/s", 5.0, Dim::TIME.pow(-1)),
            ("1 kg * m / s^2", 1.0, Dim::FORCE),
            ("1 N·m", 1.0, Dim::TORQUE),
        ];
        for &(text, si, dim) in cases {
            let q = parse_quantity(text).unwrap();
            assert!(close(q.si, si), "{text}: {} vs {si}", q.si);
            assert_eq!(q.dim, dim, "{text}");
        }
    }

    /// As people write them: no space, any case where the case tells no
    /// two units apart, and % for ratios (against the table's definitions).
    #[test]
    fn quantities_as_people_write_them() {
        let cases: &[(&str, f64, Dim)] = &[
            ("60rpm", 2.0 * PI, Dim::ANGULAR_SPEED),
            ("60 RPM", 2.0 * PI, Dim::ANGULAR_SPEED),
            ("60 Rpm", 2.0 * PI, Dim::ANGULAR_SPEED),
            ("4 %", 0.04, Dim::NONE),
            ("4%", 0.04, Dim::NONE),
            ("1.5e3N*m", 1500.0, Dim::TORQUE),
            ("-2.5E-1 KW", -250.0, Dim::POWER),
            ("90DEG", PI / 2.0, Dim::ANGLE),
            ("3 KG", 3.0, Dim::MASS),
            ("2 Mn", 2e6, Dim::FORCE),
            ("0,02", 0.02, Dim::NONE),
            ("1,5 m", 1.5, Dim::LENGTH),
            ("-2,5e-1KW", -250.0, Dim::POWER),
            ("20°", PI / 9.0, Dim::ANGLE),
            ("20 °", PI / 9.0, Dim::ANGLE),
            ("20º", PI / 9.0, Dim::ANGLE),
            ("90 °/s", PI / 2.0, Dim::ANGULAR_SPEED),
            ("10 Nm", 10.0, Dim::TORQUE),
            ("1,2 kNm", 1200.0, Dim::TORQUE),
        ];
        for &(text, si, dim) in cases {
            let q = parse_quantity(text).unwrap_or_else(|e| panic!("{text}: {e}"));
            assert!(close(q.si, si), "{text}: {} vs {si}", q.si);
            assert_eq!(q.dim, dim, "{text}");
        }
        // Milli or mega, when only the case of the m says which.
        for text in ["2 mn", "3 MM", "1 MIN", "5 mj"] {
            assert!(matches!(parse_quantity(text), Err(UnitError::Unknown(_))), "{text}");
        }
        assert_eq!(parse_as("4%", Dim::NONE).unwrap(), 0.04);
        assert!(parse_as("4%", Dim::ANGULAR_SPEED).is_err());
    }

    #[test]
    fn dimensions_are_checked() {
        assert_eq!(parse_as("300 rpm", Dim::ANGULAR_SPEED).unwrap(), 10.0 * PI);
        assert_eq!(parse_as("5", Dim::TORQUE).unwrap(), 5.0);
        let err = parse_as("5 1/s", Dim::ANGULAR_SPEED).unwrap_err();
        assert_eq!(err.to_string(), "a value in s^-1 where rad/s is expected");
        assert!(matches!(parse_as("3 kg", Dim::TORQUE), Err(UnitError::WrongDimension { .. })));
        assert!(matches!(unit_factor("ft*lbf", Dim::INERTIA), Err(UnitError::WrongDimension { .. })));
    }

    #[test]
    fn malformed_and_unknown_units_are_errors() {
        assert!(matches!(parse_quantity("fast"), Err(UnitError::Malformed(_))));
        assert!(matches!(parse_quantity("3 furlong"), Err(UnitError::Unknown(u)) if u == "furlong"));
        assert!(matches!(parse_quantity("3 m^x"), Err(UnitError::Malformed(_))));
        assert!(matches!(parse_quantity("inf rpm"), Err(UnitError::Malformed(_))));
        assert!(matches!(parse_quantity("3 m*"), Err(UnitError::Unknown(_) | UnitError::Malformed(_))));
    }
}
