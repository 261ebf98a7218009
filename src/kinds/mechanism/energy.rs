//! A mechanism's energies as results say them (a kinetostatics step's, a
//! dynamics sample's).

use super::Name;
use crate::engine::kinetostatics::Energy;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use utoipa::ToSchema;

/// The mechanism's energies, J.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct EnergyDto {
    pub kinetic: KineticEnergy,
    pub potential: PotentialEnergy,
}

/// T = Σ ½(m v_G² + I_G ω²), and each moving body's share.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct KineticEnergy {
    pub total: f64,
    #[schema(value_type = BTreeMap<String, f64>)]
    pub bodies: ByName,
}

/// Gravity's −Σ m g·r_G (r_G from the drawing's origin) and the springs' Σ ½k(l − l₀)².
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct PotentialEnergy {
    pub gravity: f64,
    pub springs: f64,
}

impl EnergyDto {
    /// The energies of the engine's at (q, q̇), the moving bodies named by
    /// `names` (ground first) and written in `order` (of `names[1..]`).
    pub fn new(e: Energy, names: &[Name], order: &NameOrder) -> Self {
        let bodies = ByName::ordered(order, &names[1..], &e.bodies);
        EnergyDto {
            kinetic: KineticEnergy { total: e.kinetic, bodies },
            potential: PotentialEnergy { gravity: e.gravity, springs: e.springs },
        }
    }
}

/// A number for each moving body, written as a JSON object in the names'
/// order (as a `BTreeMap` writes it) but kept as a list: a sweep makes one
/// at every position, where a map's nodes cost ~4 % of a cam's position
/// (perf, `cam-flat-follower`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ByName(Vec<(Name, f64)>);

impl ByName {
    /// `values[i]` under `names[i]`; a name given twice keeps its last value, as a map would.
    pub fn new(names: &[Name], values: &[f64]) -> Self {
        Self::ordered(&NameOrder::new(names), names, values)
    }

    /// As [`ByName::new`], in the `order` of these `names` found once (a
    /// sweep writes the same names at every position).
    pub fn ordered(order: &NameOrder, names: &[Name], values: &[f64]) -> Self {
        Self(order.0.iter().map(|&i| (names[i].clone(), values[i])).collect())
    }
}

/// The indices of a list of names in the order [`ByName`] writes them: by
/// name, each name's last index.
#[derive(Clone, Debug, Default)]
pub struct NameOrder(Vec<usize>);

impl NameOrder {
    pub fn new(names: &[Name]) -> Self {
        let mut order: Vec<usize> = (0..names.len()).collect();
        // Stable: a name's indices stay in their order; the last one kept.
        order.sort_by(|&a, &b| names[a].cmp(&names[b]));
        order.dedup_by(|later, kept| {
            let same = names[*later] == names[*kept];
            if same {
                *kept = *later;
            }
            same
        });
        Self(order)
    }
}

impl Serialize for ByName {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_map(self.0.iter().map(|(n, v)| (n, v)))
    }
}

impl<'de> Deserialize<'de> for ByName {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        Ok(Self(BTreeMap::<Name, f64>::deserialize(deserializer)?.into_iter().collect()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Written as the map it replaces writes it (in the names' order, the
    /// last of a repeated name kept), and read back from it.
    #[test]
    fn by_name_is_written_and_read_as_a_map() {
        let names: Vec<Name> = ["rocker", "crank", "coupler", "crank"].map(Name::new).into();
        let values = [1.0, 2.0, 3.0, 4.0];
        let map: BTreeMap<Name, f64> = names.iter().cloned().zip(values).collect();
        let list = ByName::new(&names, &values);
        let written = serde_json::to_string(&list).unwrap();
        assert_eq!(written, serde_json::to_string(&map).unwrap());
        assert_eq!(written, r#"{"coupler":3.0,"crank":4.0,"rocker":1.0}"#);
        assert_eq!(serde_json::from_str::<ByName>(&written).unwrap(), list);
    }
}
