//! Seeded variants of a problem: the same seed gives the same parameters on
//! every machine and every version, so a student's variant is named by a
//! number alone.
//!
//! The generator, written down so anyone can reproduce it:
//! 1. SplitMix64 (Steele, Lea & Flood 2014, the constants of Vigna's
//!    `splitmix64.c`), its state set to the variant's seed `v`;
//! 2. one 64-bit draw `x` per parameter, the parameters in byte order of
//!    their names;
//! 3. `x` onto the parameter's range by multiply-shift,
//!    `i = ⌊x·n / 2^64⌋` (no modulo bias beyond 2^-64·n):
//!    - `choices` (n of them): the i-th;
//!    - `min`, `max`, `step`: the grid min + i·step, i < n = ⌊(max − min)/step⌋ + 1,
//!      rounded to 12 significant digits (0.1·3 is 0.3).
//!
//!    A parameter with neither (`min` and `max` alone only bound what a
//!    user may ask) keeps its default, and still takes its draw.

/// SplitMix64: a 64-bit state advanced by the golden gamma, then mixed.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}

/// Where a parameter's values are drawn from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Range {
    /// One of n listed values.
    Choices(usize),
    /// min + i·step, i = 0 … count − 1.
    Grid { min: f64, step: f64, count: u64 },
}

impl Range {
    /// The grid of `min`, `max`, `step` (None when the step is not positive or max < min).
    pub fn grid(min: f64, max: f64, step: f64) -> Option<Self> {
        if !(step > 0.0 && max >= min) {
            return None;
        }
        let count = ((max - min) / step + 1e-9).floor() as u64 + 1;
        Some(Self::Grid { min, step, count })
    }
}

/// A drawn value: the index of a choice, or a number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Draw {
    Choice(usize),
    Value(f64),
}

/// ⌊x·n / 2^64⌋: a draw onto 0 … n − 1.
pub fn index(x: u64, n: u64) -> u64 {
    ((u128::from(x) * u128::from(n)) >> 64) as u64
}

/// `x` rounded to `digits` significant digits.
pub fn round_sig(x: f64, digits: usize) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    format!("{x:.*e}", digits - 1).parse().unwrap_or(x)
}

/// The value `x` (one draw) gives in `range`.
pub fn draw(range: Range, x: u64) -> Draw {
    match range {
        Range::Choices(n) => Draw::Choice(index(x, n as u64) as usize),
        Range::Grid { min, step, count } => Draw::Value(round_sig(min + index(x, count) as f64 * step, 12)),
    }
}

/// Variant `seed`: one draw per range, in the order given (the caller sorts
/// the parameters by name).
pub fn variant(seed: u64, ranges: &[Range]) -> Vec<Draw> {
    let mut g = SplitMix64::new(seed);
    ranges.iter().map(|r| draw(*r, g.next_u64())).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix64_matches_the_reference_outputs() {
        // Vigna's splitmix64.c with x = 0: the first output 0xe220a8397b1dcdaf.
        assert_eq!(SplitMix64::new(0).next_u64(), 0xE220_A839_7B1D_CDAF);
        // Java's SplittableRandom(1234567).nextLong() (the same mix): its first three.
        let mut g = SplitMix64::new(1_234_567);
        let first: Vec<u64> = (0..3).map(|_| g.next_u64()).collect();
        assert_eq!(first, [6_457_827_717_110_365_317, 3_203_168_211_198_807_973, 9_817_491_932_198_370_423]);
    }

    #[test]
    fn draws_stay_on_their_grid_and_in_range() {
        let grid = Range::grid(400.0, 800.0, 50.0).unwrap();
        assert_eq!(grid, Range::Grid { min: 400.0, step: 50.0, count: 9 });
        assert_eq!(Range::grid(0.1, 0.3, 0.1), Some(Range::Grid { min: 0.1, step: 0.1, count: 3 }));
        assert_eq!(draw(grid, 0), Draw::Value(400.0));
        assert_eq!(draw(grid, u64::MAX), Draw::Value(800.0));
        assert_eq!(draw(Range::grid(0.1, 0.3, 0.1).unwrap(), u64::MAX), Draw::Value(0.3));
        assert_eq!(draw(Range::Choices(3), u64::MAX / 2), Draw::Choice(1));
        assert_eq!(draw(Range::grid(1.0, 2.0, 0.5).unwrap(), 1 << 63), Draw::Value(1.5));
        for seed in 0..2000 {
            let Draw::Value(v) = variant(seed, &[grid])[0] else { panic!("a grid gives values") };
            assert!((400.0..=800.0).contains(&v) && v % 50.0 == 0.0, "{v}");
        }
    }
}
