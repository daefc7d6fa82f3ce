//! `normalise`: the inverse-square-root normaliser every pipeline shares. Three S10 components in (any common
//! scale: the bump vector's Q8.0, the light's Sq7.2) → a unit vector in Sq1.10 (S12, 1024 = 1.0).
//!
//! exact (the rtl has `TABLE_BITS` = 10, `NEWTON` = 0):
//! 1. `s = x² + y² + z²` (U20: at most 3·512² < 2^20);
//! 2. `e` = the largest shift with `s·4^e < 2^20`, `sn = s·4^e` ∈ [2^18, 2^20) (mantissa m = sn/2^18 ∈ [1, 4));
//! 3. `r = table[sn >> (20 − T)]`, the table holding `round(2^12/√m)` at each bin's midpoint (U13);
//!    optionally refined by Newton steps `r ← r·(3 − m·r²)/2`, each product one 16 × 16 multiply (`newton_step`);
//! 4. `n = round_half_away(c·2^e · r, 11)` per component: c·2^e fits S11 because |c|·2^e ≤ √sn < 2^10.
//!
//! A zero vector (s = 0: opposite vertex lights interpolated through their midpoint) gives (0, 0, 0), so that the
//! dot product, and the shade, are 0: no light direction, no light. Defined and tested.

use crate::fixed::{round_half_away, truncate};
use crate::unit::UnitModel;

pub const TABLE_BITS: u32 = 10;
pub const NEWTON: u32 = 0;

/// Fraction bits of the table entries (2^12/√m, m ∈ [1, 4) → 2049..4096, U13).
pub const R_FRAC: u32 = 12;

crate::ports! {
    inputs: [
        vec_x: s 10, vec_y: s 10, vec_z: s 10,
    ],
    outputs: [
        norm_x: s 12, norm_y: s 12, norm_z: s 12,
    ],
}

/// Table entry `idx` of a `t`-bit seed table: 2^12/√m at the midpoint of the bin (entries below 2^(t−2) unused, 0).
pub fn table_entry(idx: u64, t: u32) -> u64 {
    if idx < (1 << (t - 2)) {
        return 0;
    }
    let m = (idx as f64 + 0.5) / (1u64 << (t - 2)) as f64; // bin midpoint, [1, 4)
    ((1u64 << R_FRAC) as f64 / m.sqrt()).round() as u64
}

/// Leading-zero pairs of a nonzero U20: the largest e with s·4^e < 2^20.
pub fn norm_shift(s: u64) -> u32 {
    // s·4^e < 2^20 holds while 2e + 1 + ⌊log2 s⌋ < 20, i.e. 2e < 19 − ⌊log2 s⌋ (s ≥ 1)
    (19 - (63 - s.leading_zeros())) / 2
}

/// The seed table at the rtl's size, built once: `table_entry` for every index.
fn seed_table() -> &'static [u64] {
    static T: std::sync::OnceLock<Vec<u64>> = std::sync::OnceLock::new();
    T.get_or_init(|| (0..1u64 << TABLE_BITS).map(|i| table_entry(i, TABLE_BITS)).collect())
}

pub fn exact(v: [i64; 3]) -> [i64; 3] {
    exact_with(v, TABLE_BITS, NEWTON)
}

pub fn exact_with(v: [i64; 3], t: u32, newton: u32) -> [i64; 3] {
    let s = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) as u64; // U20
    if s == 0 {
        return [0, 0, 0];
    }
    let e = norm_shift(s);
    let sn = s << (2 * e); // U20, [2^18, 2^20)
    let idx = truncate(sn as i64, 20 - t) as u64; // the top t bits of U20 (floor) index a U13, Q1.12
    let mut r = if t == TABLE_BITS { seed_table()[idx as usize] } else { table_entry(idx, t) } as i64;
    for _ in 0..newton {
        r = newton_step(r, sn);
    }
    v.map(|c| round_half_away((c << e) * r, 11)) // S11 × U13 → S24 → Sq1.10
}

/// One Newton step on the seed, `r ← r·(3 − m·r²)/2`, as the rtl computes it: three products, each of operands of
/// at most 16 bits (rust-hdl's one multiply, one DSP each), each truncated (floor) to the next one's operand.
/// r: Uq1.12 (U13); sn: the U20 mantissa s·4^e, m = sn/2^18 ∈ [1, 4).
pub fn newton_step(r: i64, sn: u64) -> i64 {
    let m = truncate(sn as i64, 8); // U20 → Uq2.10 (floor), < 2^12
    let q = truncate(r * r, 10); // Uq1.12² = Uq2.24 → Uq2.14 (floor), ≤ 2^14
    let t = truncate(m * q, 10); // Uq2.10 × Uq2.14 = Uq4.24 → Uq2.14 (floor), m·r² ≈ 1: t ≈ 2^14, < 2^16
    let d = NEWTON_THREE - t; // Uq2.14: 3 − m·r², ≥ 0 while m·r² ≤ 3 (every seed table here: ≤ 1.25)
    truncate(r * d, 15) // Uq1.12 × Uq2.14 = Uq3.26 → Uq1.12 (floor, the halving included)
}

/// 3 in Uq2.14.
pub const NEWTON_THREE: i64 = 3 << 14;

/// The unit vector in reals, in Sq1.10 units.
pub fn ideal(v: [i64; 3]) -> [f64; 3] {
    let l = ((v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) as f64).sqrt();
    if l == 0.0 {
        return [0.0; 3];
    }
    v.map(|c| 1024.0 * c as f64 / l)
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    exact([i[0], i[1], i[2]]).to_vec()
}

fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    use rand::Rng;
    // scale spread over every exponent: short vectors are the hard ones
    let bits = rng.gen_range(1..=10u32);
    (0..3).map(|_| rng.gen_range(-(1i64 << (bits - 1))..(1i64 << (bits - 1)))).collect()
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    vec![
        vec![0, 0, 0],          // zero length
        vec![-512, -512, -512], // the most negative everywhere, the largest s
        vec![511, 511, 511],
        vec![-512, 0, 0],
        vec![511, 0, 0],
        vec![0, 1, 0],
        vec![0, -1, 0],
        vec![1, 1, 1],
        vec![-1, 0, 0],
        vec![254, 1, 0],
        vec![0, 255, 0],
        vec![127, 1, 127], // decoded bumps: horizon, pole, guarded edge
        vec![2, 254, 0],
        vec![1, 127, 0],  // the seed's minimal step near the pole
        vec![85, 85, 85], // the shortest L1-scaled bump, |v| = 1/3 of its L1 length
    ]
}

pub static MODEL: UnitModel =
    UnitModel::new("normalise", (INPUTS, OUTPUTS), exact_ports, random, hard_cases).with_accuracy(accuracy);

/// The normaliser with a `t`-bit seed table and `newton` steps against the ideal, over `samples` random vectors
/// of every scale (the zero vector skipped): the worst component error per vector (Sq1.10 LSB) and the angle.
pub fn error(t: u32, newton: u32, samples: usize, seed: u64) -> (crate::stats::ErrorStats, crate::stats::ErrorStats) {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let (mut comp, mut angle) = (crate::stats::ErrorStats::default(), crate::stats::ErrorStats::default());
    for _ in 0..samples {
        let v = random(&mut rng);
        let v = [v[0], v[1], v[2]];
        if v == [0, 0, 0] {
            continue;
        }
        let e = exact_with(v, t, newton).map(|c| c as f64);
        let i = ideal(v);
        comp.add((0..3).map(|k| (e[k] - i[k]).abs()).fold(0.0, f64::max), || format!("{v:?}"));
        angle.add(crate::stats::angle_deg(e, i), || format!("{v:?}"));
    }
    (comp, angle)
}

/// The rtl's table and Newton steps, random vectors of every scale.
fn accuracy(samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
    let (l, a) = error(TABLE_BITS, NEWTON, samples, seed);
    vec![
        crate::unit::Accuracy::new("component error, Sq1.10 LSB (1/1024)", l),
        crate::unit::Accuracy::new("degrees", a),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_mantissa_lands_in_its_range_for_every_length() {
        for s in 1..(1u64 << 20) {
            let sn = s << (2 * norm_shift(s));
            assert!((1 << 18..1 << 20).contains(&sn), "{s}");
        }
    }

    #[test]
    fn shifted_components_fit_s11() {
        for x in (-512i64..512).step_by(3) {
            for y in [-512i64, -3, 0, 1, 77, 511] {
                let s = (x * x + y * y) as u64;
                if s == 0 {
                    continue;
                }
                let e = norm_shift(s);
                assert!((-1024..1024).contains(&(x << e)) && (-1024..1024).contains(&(y << e)), "{x} {y}");
            }
        }
    }

    #[test]
    fn zero_vector_gives_zero() {
        assert_eq!(exact([0, 0, 0]), [0, 0, 0]);
    }

    /// The widths `newton_step` (and the rtl's `NewtonStep`) give its products, over every mantissa and every
    /// table size the unit can be built with (6 to 12 bits, every one the width sweep takes): r² and m·q fit 16-bit
    /// operands, 3 − m·r² stays ≥ 0, the result is at most 2^12 and nearer 2^12/√m.
    #[test]
    fn a_newton_step_fits_its_widths_for_every_mantissa_and_table() {
        for t in 6..=12u32 {
            let (mut before, mut after) = (0.0f64, 0.0f64);
            for sn in (1u64 << 18)..(1 << 20) {
                let r = table_entry(sn >> (20 - t), t) as i64;
                let (m, q) = (truncate(sn as i64, 8), truncate(r * r, 10));
                assert!(r < 1 << 13 && q < 1 << 15 && m < 1 << 12, "T {t} sn {sn}");
                let tt = truncate(m * q, 10);
                assert!((0..=NEWTON_THREE).contains(&tt), "T {t} sn {sn}: m·r² = {tt}/2^14");
                let r1 = newton_step(r, sn);
                // r·(3 − m·r²)/2 is at most 1/√m (its maximum over r) ≤ 1: the products after it keep their widths
                assert!((0..=1 << R_FRAC).contains(&r1), "T {t} sn {sn}: {r1}");
                let ideal = 4096.0 / (sn as f64 / (1u64 << 18) as f64).sqrt();
                before = before.max((r as f64 - ideal).abs());
                after = after.max((r1 as f64 - ideal).abs());
            }
            assert!(after < before || after <= 2.0, "T {t}: a step leaves {after} LSB from {before}");
        }
    }

    #[test]
    fn a_newton_step_beats_the_bare_table() {
        let err = |t, n| {
            let mut worst = 0.0f64;
            for x in (-512i64..512).step_by(5) {
                for y in (-512i64..512).step_by(37) {
                    let v = [x, y, 100];
                    let e = exact_with(v, t, n);
                    let i = ideal(v);
                    for c in 0..3 {
                        worst = worst.max((e[c] as f64 - i[c]).abs());
                    }
                }
            }
            worst
        };
        assert!(err(6, 1) < err(6, 0));
        assert!(err(10, 0) < err(6, 0));
    }
}

#[cfg(test)]
mod shift_tests {
    #[test]
    fn norm_shift_is_the_largest_e_with_s_times_4_to_the_e_below_2_to_the_20() {
        for s in 1u64..(1 << 20) {
            let e = super::norm_shift(s);
            assert!(s << (2 * e) < (1 << 20) && s << (2 * (e + 1)) >= (1 << 20), "s = {s}, e = {e}");
        }
    }
}
