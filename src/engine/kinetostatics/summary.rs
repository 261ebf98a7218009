//! Statistics over the sampled positions.

use super::Step;

/// Φ_q counts as near-singular beyond this condition number of its scaled
/// form (reported, not an error).
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
    pub max_scaled_condition: f64,
}

/// A [`Summary`] gathered one step at a time, as a sweep hands them over.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    /// Regular steps so far.
    count: usize,
    max_abs_driving: Vec<f64>,
    sum: Vec<f64>,
    sum_of_squares: Vec<f64>,
    /// Per joint: the largest force's square while every reaction so far
    /// was determinate (None once one was not), and whether any was computed.
    max_reaction: Vec<(Option<f64>, bool)>,
    /// Per input, the largest |T_multipliers − T_virtual_power| of the steps
    /// where both are computed (None: no such step).
    max_gap: Option<Vec<f64>>,
    near_singular: Vec<Vec<f64>>,
    singular: Vec<Vec<f64>>,
    max_condition: f64,
    max_scaled_condition: f64,
    max_friction_iterations: usize,
}

impl Tally {
    pub fn new(joints: usize) -> Self {
        Self { max_reaction: vec![(Some(0.0), false); joints], ..Self::default() }
    }

    /// Counts a step in.
    pub fn add(&mut self, s: &Step) {
        if s.scaled_condition > NEAR_SINGULAR {
            self.near_singular.push(s.input.clone());
        }
        self.max_friction_iterations = self.max_friction_iterations.max(s.friction_iterations);
        if s.singular {
            self.singular.push(s.input.clone());
            return;
        }
        if self.count == 0 {
            let n = s.driving.len();
            (self.max_abs_driving, self.sum, self.sum_of_squares) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        }
        self.count += 1;
        self.max_condition = self.max_condition.max(s.condition);
        self.max_scaled_condition = self.max_scaled_condition.max(s.scaled_condition);
        for (d, &t) in s.driving.iter().enumerate().take(self.sum.len()) {
            self.max_abs_driving[d] = self.max_abs_driving[d].max(t.abs());
            self.sum[d] += t;
            self.sum_of_squares[d] += t * t;
        }
        for (largest, r) in self.max_reaction.iter_mut().zip(&s.reactions) {
            largest.1 = true;
            largest.0 = largest.0.filter(|_| r.determinate).map(|m| m.max(r.fx * r.fx + r.fy * r.fy));
        }
        let compared =
            s.driving_virtual_power.len() == s.driving.len() && (s.driving.len() > 1 || !s.reactions.is_empty());
        if compared {
            let gaps = self.max_gap.get_or_insert_with(|| vec![0.0; s.driving.len()]);
            for ((gap, a), b) in gaps.iter_mut().zip(&s.driving_virtual_power).zip(&s.driving) {
                *gap = gap.max((a - b).abs());
            }
        }
    }

    /// Largest fixed-point iteration count of joint friction so far.
    pub fn max_friction_iterations(&self) -> usize {
        self.max_friction_iterations
    }

    /// The summary of the steps counted.
    pub fn summary(self) -> Summary {
        let count = self.count.max(1) as f64;
        // Per input, against that input's largest driving action.
        let virtual_power_residual = self.max_gap.map(|gaps| {
            gaps.iter()
                .zip(&self.max_abs_driving)
                .map(|(gap, &largest)| gap / if largest > 0.0 { largest } else { 1.0 })
                .fold(0.0, f64::max)
        });
        Summary {
            mean_driving: self.sum.iter().map(|s| s / count).collect(),
            rms_driving: self.sum_of_squares.iter().map(|s| (s / count).sqrt()).collect(),
            max_abs_driving: self.max_abs_driving,
            max_reaction: self
                .max_reaction
                .into_iter()
                .map(|(largest, any)| largest.filter(|_| any).map(f64::sqrt))
                .collect(),
            virtual_power_residual,
            near_singular: self.near_singular,
            singular: self.singular,
            max_condition: self.max_condition,
            max_scaled_condition: self.max_scaled_condition,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::kinetostatics::Reaction;

    fn step(input: f64, driving: [f64; 2], virtual_power: [f64; 2], determinate: bool, condition: f64) -> Step {
        let reaction =
            |fx: f64, fy: f64| Reaction { joint: 0, on: 1, by: 0, fx, fy, moment: 0.0, ends: None, determinate };
        Step {
            input: vec![input],
            driving: driving.to_vec(),
            driving_virtual_power: virtual_power.to_vec(),
            reactions: vec![reaction(3.0 * input, 4.0 * input), reaction(1.0, 0.0)],
            condition: 3.0 * condition,
            scaled_condition: condition,
            ..Step::default()
        }
    }

    /// Three hand-made steps of two inputs (one singular, one near-singular,
    /// one with an indeterminate reaction): every field against its value
    /// worked by hand.
    #[test]
    fn the_tally_gives_each_statistic() {
        let singular = Step { input: vec![9.0], scaled_condition: 1e9, singular: true, ..Step::default() };
        let mut second = step(2.0, [-4.0, 1.0], [-4.0, 1.5], true, 2e4);
        second.reactions[1].determinate = false;
        let steps = [step(1.0, [2.0, 1.0], [2.5, 1.0], true, 10.0), singular, second];
        let mut tally = Tally::new(2);
        steps.iter().for_each(|s| tally.add(s));
        let s = tally.summary();
        assert_eq!(s.max_abs_driving, [4.0, 1.0]);
        assert_eq!(s.mean_driving, [-1.0, 1.0], "(2 − 4)/2, (1 + 1)/2 over the regular steps");
        assert_eq!(s.rms_driving, [10f64.sqrt(), 1.0], "√((4 + 16)/2), √((1 + 1)/2)");
        assert_eq!(s.max_reaction, [Some(10.0), None], "|(6, 8)| = 10; the second joint indeterminate once");
        assert_eq!(s.virtual_power_residual, Some(0.5), "max(0.5/4, 0.5/1)");
        assert_eq!(s.singular, [vec![9.0]]);
        assert_eq!(s.near_singular, [vec![9.0], vec![2.0]], "κ above 1e4, singular steps included");
        assert_eq!(s.max_condition, 6e4, "over the regular steps");
        assert_eq!(s.max_scaled_condition, 2e4, "over the regular steps");
    }
}
