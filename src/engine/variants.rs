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
//!
//! A template may ask for its variants without repetition (`distinct`):
//! every combination of its parameters' values is a number in 0 … M − 1
//! (M the product of the counts; the first parameter by name the fastest
//! digit), and variant `v` is combination π(v mod M), π a fixed shuffle of
//! 0 … M − 1 — so any M consecutive variants are all different. π: a
//! four-round Feistel network on h + h bits (2^2h ≥ M, h ≥ 1), round k
//! mixing the right half as SplitMix64 seeded with R + 2^32·k, its first
//! output's low h bits XORed into the left half; a result ≥ M is shuffled
//! again until it is below M (cycle-walking).

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

/// Variant `seed` without repetition ([the module's notes](self)): one
/// draw per range, the combination π(seed mod M); [`variant`]'s where a
/// range is no grid or list (M ≥ 2^62: too many to shuffle).
pub fn distinct(seed: u64, ranges: &[Range]) -> Vec<Draw> {
    let counts: Vec<u64> = ranges
        .iter()
        .map(|r| match *r {
            Range::Choices(n) => n as u64,
            Range::Grid { count, .. } => count,
        })
        .collect();
    let total = counts.iter().try_fold(1u64, |m, &n| m.checked_mul(n).filter(|m| *m < 1 << 62));
    let Some(total) = total.filter(|m| *m > 0) else { return variant(seed, ranges) };
    let mut rest = shuffled(seed % total, total);
    ranges
        .iter()
        .zip(&counts)
        .map(|(r, &n)| {
            let i = rest % n;
            rest /= n;
            match *r {
                Range::Choices(_) => Draw::Choice(i as usize),
                Range::Grid { min, step, .. } => Draw::Value(round_sig(min + i as f64 * step, 12)),
            }
        })
        .collect()
}

/// π(i) of 0 … m − 1: the Feistel network, walked until below m.
fn shuffled(i: u64, m: u64) -> u64 {
    let bits = 64 - (m - 1).leading_zeros().min(63);
    let h = bits.div_ceil(2).max(1);
    let mask = (1u64 << h) - 1;
    let feistel = |x: u64| {
        let (mut left, mut right) = (x >> h, x & mask);
        for k in 0..4u64 {
            let f = SplitMix64::new(right + (k << 32)).next_u64() & mask;
            (left, right) = (right, left ^ f);
        }
        (left << h) | right
    };
    let mut y = feistel(i);
    while y >= m {
        y = feistel(y);
    }
    y
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

    /// The shuffle is a permutation of 0 … M − 1 (every index once), for
    /// the p103-class grid (M = 11·7·4·9 = 2772) and small and odd M; its
    /// draws stay on the grid, and any M consecutive variants differ.
    #[test]
    fn distinct_variants_are_a_shuffle_of_every_combination() {
        for m in [1u64, 2, 3, 7, 64, 65, 2772] {
            let mut seen = vec![false; m as usize];
            for i in 0..m {
                let j = shuffled(i, m) as usize;
                assert!(!seen[j], "M = {m}: {j} twice");
                seen[j] = true;
            }
        }
        let ranges = [
            Range::grid(300.0, 800.0, 50.0).unwrap(),
            Range::grid(2.0, 8.0, 1.0).unwrap(),
            Range::Choices(4),
            Range::grid(40.0, 120.0, 10.0).unwrap(),
        ];
        let from = 1_000_000_007u64;
        let drawn: std::collections::HashSet<String> =
            (from..from + 2772).map(|v| format!("{:?}", distinct(v, &ranges))).collect();
        assert_eq!(drawn.len(), 2772, "2772 consecutive variants, every combination once");
        let Draw::Value(f) = distinct(5, &ranges)[0] else { panic!("a grid gives values") };
        assert!((300.0..=800.0).contains(&f) && f % 50.0 == 0.0, "{f}");
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
