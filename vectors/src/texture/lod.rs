//! `lod`: the texture unit's level of detail, OpenGL's isotropic rule (the level the MIP filters of US 2004/0207631
//! ¶76 and ¶81 read) with a LOD bias. From the screen derivatives of u and v, in texels of level 0 per pixel,
//! ρ = max(√(u_x² + v_x²), √(u_y² + v_y²)) and λ = log2 ρ + bias, clamped to [0, n] for a map of side 2^n (levels
//! 0 ..= n). The bias is a signed number of levels (Sq3.8, −8 … +7.996), the sampler setting every texture unit
//! has (OpenGL's `GL_TEXTURE_LOD_BIAS`, Direct3D's `MipLODBias`): the isotropic rule's level, read through
//! trilinear's kernel (a level's texel, a box 2^λ texels wide, under bilinear's tent of the same width), blurs
//! more than the pixel's own footprint, and a negative bias of about a level is what `bumprtl minify` measures
//! closest to a supersampled ideal. Outputs: `level` = ⌊λ⌋ and `frac`, frac(λ) in 8 bits, for trilinear (frac is 0
//! below level 0 and at or past the last level, where there is no second level to blend); `nearest` = ⌊λ + ½⌋ for
//! the nearest texel of the nearest level and for bilinear on one level.
//!
//! The exact recipe:
//! - a = min(|d|, 2^16 − 1) for each derivative d (Sq8.8): its magnitude in Uq8.8 (U16), saturated (only d = −256
//!   exceeds it: ρ ≥ 256 is past every level of a map up to 2^8; a larger `log_side`, which no map has, reads it
//!   0.004 of a level low);
//! - q = ⌊a²/2^8⌋ (Uq16.8, U24: truncated; only the carry of the two squares' dropped bits is lost above ρ = 1,
//!   and below it the truncation is what limits λ: a square below 2^-8 is 0); L_x = q(u_x) + q(v_x),
//!   L_y = q(u_y) + q(v_y) (Uq17.8, U25); m = max(L_x, L_y) ≈ ρ²·2^8;
//! - m = 0 (a footprint below 1/16 of a texel, λ ≤ −4): level 0, frac 0, nearest 0, whatever the bias;
//! - else p, the bit of m's leading one (0 ..= 24), and f, the 8 bits below it (truncated; zeros shifted in below
//!   bit 0); a 256-entry table T(f) = round(log2(1 + (f + ½)/256)·2^9) (U9, the bin's midpoint); then
//!   λ·2^10 = ((p − 8) << 9) + T(f) + (bias << 2) (signed, −12,288 … 16,891, in 16 bits): log2 m − 8 = 2λ, so λ
//!   has one fraction bit more than the table and two more than the bias;
//! - λ < 0: level 0, frac 0, nearest 0; else level = min(λ >> 10, n); frac = (λ mod 2^10) >> 2 (truncated to 8
//!   bits) when λ >> 10 < n, else 0; nearest = min((λ + 2^9) >> 10, n) (rounded half up).
//!
//! Its error against the f64 rule is measured in levels (`bumprtl accuracy`): the table's half bin (at most 0.0014 of
//! a level), its rounding, the squares' truncation (at ρ near 1 at most 2^-7 of ρ², 0.0028 of a level, and more
//! below ρ = ½, which only a positive bias lifts into the levels) and frac's 8-bit truncation.

use crate::fixed::truncate;
use crate::unit::UnitModel;
use std::sync::OnceLock;

crate::ports! {
    inputs: [
        du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, log_side: u 4, bias: s 12,
    ],
    outputs: [
        level: u 4, frac: u 8, nearest: u 4,
    ],
}

/// Fraction bits of the derivatives (Sq8.8), of the bias (Sq3.8) and of the table's entries (log2 m, which is 2λ).
pub const D_FRAC: u32 = 8;
pub const B_FRAC: u32 = 8;
pub const T_FRAC: u32 = 9;
/// The mantissa bits below m's leading one that address the table.
pub const TABLE_BITS: u32 = 8;
/// The largest map this unit is written for: side 2^8, levels 0 ..= 8.
pub const MAX_LOG_SIDE: i64 = 8;

/// T(f): log2 of the midpoint of the mantissa's bin, 9 fraction bits, rounded (≤ 511: U9).
pub fn table_entry(f: u64) -> i64 {
    ((1.0 + (f as f64 + 0.5) / 256.0).log2() * (1u64 << T_FRAC) as f64).round() as i64
}

pub fn table() -> &'static [i64] {
    static T: OnceLock<Vec<i64>> = OnceLock::new();
    T.get_or_init(|| (0..1 << TABLE_BITS).map(table_entry).collect())
}

/// m ≈ ρ²·2^8 (Uq17.8, U25): the larger squared footprint edge, each magnitude saturated to U16 and each square
/// truncated to 8 fraction bits.
pub fn footprint(d: [i64; 4]) -> i64 {
    let a = d.map(|x| x.abs().min((1 << 16) - 1)); // |S17| ≤ 65,536, saturated to U16 (Uq8.8)
    let q = a.map(|x| truncate(x * x, 8)); // U32 >> 8 (floor): Uq16.8, U24
    (q[0] + q[1]).max(q[2] + q[3]) // U24 + U24: U25 each
}

/// log2 ρ·2^10 (signed, −4,096 … 8,703) for m ≥ 1; None for m = 0 (ρ below 1/16 of a texel: −∞ to the rule).
pub fn lambda_q(m: i64) -> Option<i64> {
    if m == 0 {
        return None;
    }
    let p = 63 - m.leading_zeros() as i64; // 0 ..= 24
    let f = ((m << (24 - p)) >> 16) & 0xff; // the 8 bits below the leading one, put at bit 24 (truncated)
    Some(((p - 8) << T_FRAC) + table()[f as usize]) // (−8 ..= 16) << 9 + U9: −4,096 ..= 8,703
}

/// (level, frac, nearest) for the four derivatives (Sq8.8), a map of side 2^n and the bias (Sq3.8, levels).
pub fn exact(d: [i64; 4], n: i64, bias: i64) -> [i64; 3] {
    let Some(l) = lambda_q(footprint(d)) else { return [0, 0, 0] };
    let l = l + (bias << 2); // the bias in 1/1024 of a level: −12,288 ..= 16,891, S16
    if l < 0 {
        return [0, 0, 0];
    }
    let int = l >> 10; // ⌊λ⌋, 0 ..= 16
    let near = ((l + (1 << 9)) >> 10).min(n); // ⌊λ + ½⌋, clamped to the last level
    if int >= n {
        [n, 0, near]
    } else {
        [int, (l & 1023) >> 2, near] // frac(λ) to 8 bits, truncated
    }
}

/// log2 ρ in reals (unclamped, without the bias; −∞ for a zero footprint).
pub fn ideal_lambda(d: [i64; 4]) -> f64 {
    let r = d.map(|x| x as f64 / (1u64 << D_FRAC) as f64);
    let rho = (r[0] * r[0] + r[1] * r[1]).sqrt().max((r[2] * r[2] + r[3] * r[3]).sqrt());
    rho.log2()
}

/// The trilinear position the rule gives, clamp(log2 ρ + bias, 0, n), in levels, for the bias in Sq3.8.
pub fn ideal(d: [i64; 4], n: i64, bias: i64) -> f64 {
    (ideal_lambda(d) + bias as f64 / (1u64 << B_FRAC) as f64).clamp(0.0, n as f64)
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    exact([i[0], i[1], i[2], i[3]], i[4], i[5]).to_vec()
}

/// A random bias: 0 one draw in two (the rule as it is), else uniform over −2 … +2 levels, or an end of the range
/// one draw in eight.
pub fn random_bias(rng: &mut dyn rand::RngCore) -> i64 {
    use rand::Rng;
    match rng.gen_range(0..16) {
        0..=7 => 0,
        8 => -(1 << 11),
        9 => (1 << 11) - 1,
        _ => rng.gen_range(-512..=512),
    }
}

/// One derivative: its magnitude log-uniform from 2^-9 to 2^8.5 texels a pixel (so λ covers every level and both
/// clamps), a random sign; an end of the range one draw in eight.
fn random_derivative(rng: &mut dyn rand::RngCore) -> i64 {
    use rand::Rng;
    if rng.gen_range(0..8) == 0 {
        return crate::unit::draw(rng, &INPUTS[0]);
    }
    let mag = (rng.gen_range(-9.0f64..8.5).exp2() * 256.0).round().min(65_536.0) as i64;
    if rng.gen_bool(0.5) {
        -mag
    } else {
        mag.min(65_535)
    }
}

fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    use rand::Rng;
    let mut v: Vec<i64> = (0..4).map(|_| random_derivative(rng)).collect();
    // the map sizes the unit is written for, and one draw in sixteen past them (λ never reaches them: no clamp)
    v.push(if rng.gen_range(0..16) == 0 { rng.gen_range(9..16) } else { rng.gen_range(0..=MAX_LOG_SIDE) });
    v.push(random_bias(rng));
    v
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let one = 1i64 << D_FRAC; // one texel a pixel
    let mut v = vec![];
    for n in [0, 1, 3, 8] {
        // a zero footprint (log2 0), and the largest and most negative derivatives (the saturation)
        v.push(vec![0, 0, 0, 0, n]);
        v.push(vec![65_535, 65_535, 65_535, 65_535, n]);
        v.push(vec![-65_536, -65_536, -65_536, -65_536, n]);
        v.push(vec![-65_536, 0, 0, 0, n]);
        // ρ exactly 2^k (λ exactly at a level), just below and just above it, on either axis pair
        for k in 0..8 {
            let d = one << k;
            v.push(vec![d, 0, 0, 0, n]);
            v.push(vec![0, 0, 0, -d, n]);
            v.push(vec![d - 1, 0, 0, 0, n]);
            v.push(vec![0, 0, d + 1, 0, n]);
        }
        // ρ just below 1 (the largest footprint with λ < 0), λ = −1, and the ties of nearest: λ = ½ and 1½
        // exactly (ρ = √2 and 2√2, the diagonal of two equal derivatives), and a step below each
        v.push(vec![one - 1, 0, 0, 0, n]);
        v.push(vec![one / 2, 0, 0, one / 2, n]);
        v.push(vec![one, one, 0, 0, n]);
        v.push(vec![0, 0, 2 * one, -2 * one, n]);
        v.push(vec![362, 0, 0, 0, n]);
        v.push(vec![724, 0, 0, 0, n]);
        // a footprint whose two edges are equal; the footprints testbench/tests/lod.rs works by hand
        v.push(vec![3 * one, 4 * one, 4 * one, 3 * one, n]);
        v.push(vec![3 * one, 4 * one, 0, 0, n]);
        v.push(vec![0, 0, 384, 0, n]);
    }
    // log_side past the largest map: λ (at most 8.5) never reaches it
    v.push(vec![65_535, 65_535, 0, 0, 15]);
    v.push(vec![one << 7, 0, 0, 0, 9]);
    for c in &mut v {
        c.push(0); // the rule without a bias
    }
    let b = 1i64 << B_FRAC; // a bias of one level
    for n in [0, 1, 8, 15] {
        // the bias's ends, on a zero footprint (level 0 whatever the bias), at ρ = 1 and at the largest footprint
        for bias in [-(1 << 11), (1 << 11) - 1] {
            v.push(vec![0, 0, 0, 0, n, bias]);
            v.push(vec![one, 0, 0, 0, n, bias]);
            v.push(vec![65_535, 65_535, 65_535, 65_535, n, bias]);
            v.push(vec![-65_536, 0, 0, 0, n, bias]);
        }
        // ρ = 2 brought to λ = 0 exactly by −1, and a step below it (−1 − 1/256); ρ = ½ and ¼ lifted to levels 0
        // and 1 by +1 and +3 (a magnified pixel blurred); the smallest footprint (one square of 2^-8) lifted by the
        // most; ρ = 1 with +½ (nearest's tie) and a step below
        v.push(vec![2 * one, 0, 0, 0, n, -b]);
        v.push(vec![2 * one, 0, 0, 0, n, -b - 1]);
        v.push(vec![one / 2, 0, 0, 0, n, b]);
        v.push(vec![0, one / 4, 0, 0, n, 3 * b]);
        v.push(vec![16, 0, 0, 0, n, (1 << 11) - 1]);
        v.push(vec![15, 0, 0, 0, n, (1 << 11) - 1]);
        v.push(vec![one, 0, 0, 0, n, b / 2]);
        v.push(vec![one, 0, 0, 0, n, b / 2 - 1]);
        // λ past the last level only through the bias: ρ = 2^7 with +2, and the largest λ there is
        v.push(vec![one << 7, 0, 0, 0, n, 2 * b]);
        v.push(vec![65_535, 65_535, 0, 0, n, (1 << 11) - 1]);
    }
    v
}

pub static MODEL: UnitModel =
    UnitModel::new("lod", (INPUTS, OUTPUTS), exact_ports, random, hard_cases).with_accuracy(accuracy);

/// The trilinear position (level + frac/256) against clamp(log2 ρ + bias, 0, n), in levels, and the nearest level
/// against ⌊clamp(λ, 0, n) + ½⌋, over random footprints, map sizes and biases.
fn accuracy(samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
    let at = |i: &[i64]| -> ([i64; 3], f64) {
        let d = [i[0], i[1], i[2], i[3]];
        (exact(d, i[4], i[5]), ideal(d, i[4], i[5]))
    };
    vec![
        crate::unit::Accuracy::over_random(
            "levels, level + frac/256 vs clamp(log2 ρ + bias, 0, n)",
            samples,
            seed,
            random,
            |i| {
                let (e, want) = at(i);
                vec![(e[0] as f64 + e[1] as f64 / 256.0 - want).abs()]
            },
        ),
        crate::unit::Accuracy::over_random(
            "levels, nearest vs ⌊clamp(log2 ρ + bias, 0, n) + ½⌋",
            samples,
            seed,
            random,
            |i| {
                let (e, want) = at(i);
                vec![(e[2] as f64 - (want + 0.5).floor().min(i[4] as f64)).abs()]
            },
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_table_entry_fits_u9_and_rises() {
        let t = table();
        assert!(t.iter().all(|&e| (0..512).contains(&e)), "{t:?}");
        assert!(t.windows(2).all(|w| w[0] <= w[1]));
        assert_eq!(t[0], 1, "log2(1 + 1/512)·512 = 1.44, rounded");
        assert_eq!(t[255], 511);
    }

    #[test]
    fn a_power_of_two_footprint_is_exactly_its_level() {
        for k in 0..8 {
            for n in 0..=8 {
                let d = 256i64 << k;
                let want = if k < n { [k, 0, k] } else { [n, 0, n] };
                // the table's first bin is a little above 0 (its midpoint): frac truncates it to 0
                assert_eq!(exact([d, 0, 0, 0], n, 0), want, "ρ = 2^{k}, n = {n}");
                assert_eq!(exact([0, 0, 0, -d], n, 0), want, "ρ = 2^{k} on the y pair, n = {n}");
            }
        }
    }

    #[test]
    fn magnification_and_a_zero_footprint_read_level_zero() {
        for n in 0..=8 {
            assert_eq!(exact([0, 0, 0, 0], n, 0), [0, 0, 0]);
            assert_eq!(exact([255, 0, 0, 0], n, 0), [0, 0, 0], "ρ just below 1");
            assert_eq!(exact([128, 128, -100, 3], n, 0), [0, 0, 0]);
        }
    }

    #[test]
    fn the_last_level_clamps_and_has_no_fraction() {
        for n in 0..8 {
            // ρ = 2^n·1.5: λ past the last level
            let d = 384i64 << n;
            assert_eq!(exact([d, 0, 0, 0], n, 0), [n, 0, n]);
        }
        // the largest footprint, every map size: λ = ½·log2 2 + log2(65,535/256) = 8.49998, so past a map of 2^8 it
        // reads level 8 and frac 0.49998·256 = 127.99, truncated to 127
        for n in 0..16 {
            let e = exact([-65_536, -65_536, -65_536, -65_536], n, 0);
            assert_eq!((e[0], e[1]), if n <= 8 { (n, 0) } else { (8, 127) }, "n = {n}");
        }
    }

    #[test]
    fn lambda_is_within_a_hundredth_of_a_level_of_the_rule_and_near_rounds_it() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        let (mut worst, mut worst_half) = (0.0f64, 0.0f64);
        for _ in 0..200_000 {
            let i = random(&mut rng);
            let (d, n, b) = ([i[0], i[1], i[2], i[3]], i[4], i[5]);
            let e = exact(d, n, b);
            let pos = e[0] as f64 + e[1] as f64 / 256.0;
            // where ρ ≥ 1, and where only a positive bias brings ½ ≤ ρ < 1 into the levels
            let err = (pos - ideal(d, n, b)).abs();
            if ideal_lambda(d) >= 0.0 {
                worst = worst.max(err);
            } else if ideal_lambda(d) >= -1.0 {
                worst_half = worst_half.max(err);
            }
            assert!(e[0] <= n && e[2] <= n && (e[1] == 0 || e[0] < n), "{i:?}: {e:?}");
            // nearest is the level above exactly where frac is at least one half
            assert_eq!(e[2] - e[0], (e[1] >= 128) as i64, "nearest beside level: {i:?} {e:?}");
        }
        // the table's half bin (0.0014 of a level), its rounding (0.0005), the squares' truncation near ρ = 1
        // (0.0028) and frac's truncation (< 2^-8)
        assert!(worst < 0.009, "{worst}");
        // below ρ = 1 each square's truncation is up to 1/(256ρ²) of ρ², 0.011 of a level at ρ = ½, two of them
        assert!(worst_half < 0.025, "{worst_half}");
    }

    #[test]
    fn a_whole_bias_moves_a_power_of_two_footprint_by_whole_levels() {
        for k in 0..8i64 {
            for j in -8..8i64 {
                for n in [0, 3, 8] {
                    let l = (k + j).clamp(0, n);
                    let want = [l, 0, l];
                    assert_eq!(exact([256 << k, 0, 0, 0], n, j << B_FRAC), want, "ρ = 2^{k}, bias {j}, n = {n}");
                }
            }
        }
        // below ρ = 1: ρ = 2^-3 lifted by +5 levels is level 2; ρ = 2^-4 (m = 1, p = 0, f = 0: λ·2^10 =
        // −8·512 + T(0) = −4,095) lifted by 2,047/256 (+8,188) is 4,093: level 3, frac 1,021 >> 2 = 255, nearest 4
        assert_eq!(exact([32, 0, 0, 0], 8, 5 << B_FRAC), [2, 0, 2]);
        assert_eq!(exact([16, 0, 0, 0], 8, (1 << 11) - 1), [3, 255, 4]);
        // a footprint below 1/16 of a texel squares to 0: level 0 whatever the bias
        assert_eq!(exact([15, 15, 0, 0], 8, (1 << 11) - 1), [0, 0, 0]);
    }
}
