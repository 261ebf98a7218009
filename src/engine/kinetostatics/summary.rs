//! Statistics over the sampled positions.

use super::Step;

/// Φ_q counts as near-singular beyond this condition number (reported, not an error).
pub const NEAR_SINGULAR: f64 = 1e4;

/// Means and RMS are over the regular sampled steps (not weighted by time).
#[derive(Clone, Debug, PartialEq)]
pub struct Summary {
    pub max_abs_driving: Vec<f64>,
    pub mean_driving: Vec<f64>,
    pub rms_driving: Vec<f64>,
    /// Largest reaction force magnitude per joint (None: not computed or indeterminate).
    pub max_reaction: Vec<Option<f64>>,
    /// max over the inputs of max |T_multipliers − T_virtual_power| / max |T| (where both are computed).
    pub virtual_power_residual: Option<f64>,
    /// Inputs where Φ_q is near-singular (condition number above [`NEAR_SINGULAR`]).
    pub near_singular: Vec<Vec<f64>>,
    /// Inputs at singular positions (no forces computed there).
    pub singular: Vec<Vec<f64>>,
    pub max_condition: f64,
}

impl Summary {
    pub fn new(all: &[Step], joints: usize) -> Self {
        let regular: Vec<&Step> = all.iter().filter(|s| !s.singular).collect();
        let steps = &regular[..];
        let n_inputs = steps.first().map_or(0, |s| s.driving.len());
        let count = steps.len().max(1) as f64;
        let column = |d: usize| steps.iter().map(move |s| s.driving[d]);
        let max_abs_driving: Vec<f64> = (0..n_inputs).map(|d| column(d).fold(0.0f64, |m, v| m.max(v.abs()))).collect();
        let mean_driving = (0..n_inputs).map(|d| column(d).sum::<f64>() / count).collect();
        let rms_driving = (0..n_inputs).map(|d| (column(d).map(|v| v * v).sum::<f64>() / count).sqrt()).collect();
        let max_reaction = (0..joints)
            .map(|j| {
                let rs: Vec<_> = steps.iter().filter_map(|s| s.reactions.get(j)).collect();
                (!rs.is_empty() && rs.iter().all(|r| r.determinate))
                    .then(|| rs.iter().map(|r| r.fx.hypot(r.fy)).fold(0.0, f64::max))
            })
            .collect();
        // Per input, against that input's largest driving action.
        let compared: Vec<&Step> = steps
            .iter()
            .copied()
            .filter(|s| {
                s.driving_virtual_power.len() == s.driving.len() && (s.driving.len() > 1 || !s.reactions.is_empty())
            })
            .collect();
        let virtual_power_residual = (!compared.is_empty()).then(|| {
            (0..n_inputs)
                .map(|d| {
                    let scale = if max_abs_driving[d] > 0.0 { max_abs_driving[d] } else { 1.0 };
                    compared
                        .iter()
                        .map(|s| (s.driving_virtual_power[d] - s.driving[d]).abs() / scale)
                        .fold(0.0, f64::max)
                })
                .fold(0.0, f64::max)
        });
        Self {
            max_abs_driving,
            mean_driving,
            rms_driving,
            max_reaction,
            virtual_power_residual,
            near_singular: all.iter().filter(|s| s.condition > NEAR_SINGULAR).map(|s| s.input.clone()).collect(),
            singular: all.iter().filter(|s| s.singular).map(|s| s.input.clone()).collect(),
            max_condition: steps.iter().map(|s| s.condition).fold(0.0, f64::max),
        }
    }
}
