//! `bilinear`: the colour filter's bilinear unit, four 8-bit channels, `F` blend-factor bits (the rtl has F = 8).
//! The same unit serves the height-map pipeline later (US 2004/0207631, units 65–68).
//!
//! exact: `a = t00·(2^F − u) + t10·u`, `b = t01·(2^F − u) + t11·u` (U(8+F), no rounding), then
//! `r = round_half_up((a·(2^F − v) + b·v), 2F)` (U8). The rtl computes the same value as `a·2^F + (b − a)·v`.

use crate::fixed::{round_half_up, truncate};
use crate::unit::UnitModel;

pub const F: u32 = 8;

crate::ports! {
    inputs: [
        t00_r: u 8, t00_g: u 8, t00_b: u 8, t00_a: u 8, t10_r: u 8, t10_g: u 8, t10_b: u 8, t10_a: u 8, t01_r: u 8,
        t01_g: u 8, t01_b: u 8, t01_a: u 8, t11_r: u 8, t11_g: u 8, t11_b: u 8, t11_a: u 8, ublend: u 8,
        vblend: u 8,
    ],
    outputs: [
        out_r: u 8, out_g: u 8, out_b: u 8, out_a: u 8,
    ],
}

/// One channel with `f` blend-factor bits; `u`, `v` in 0..2^f (weight of the second texel is u/2^f).
pub fn exact_channel(t00: i64, t10: i64, t01: i64, t11: i64, u: i64, v: i64, f: u32) -> i64 {
    exact_channel_with(t00, t10, t01, t11, u, v, f, 0)
}

/// The unit's value before its rounding, with `d` bits dropped between its two stages: `a' = a >> d`,
/// `b' = b >> d` (truncate), `a'·2^f + (b' − a')·v` = `a'·(2^f − v) + b'·v` (U(8 + 2f − d), 2f − d fraction bits).
/// The rtl's `BilinearUnit<W, F, D>` output `wide`.
pub fn exact_wide(t00: i64, t10: i64, t01: i64, t11: i64, u: i64, v: i64, f: u32, d: u32) -> i64 {
    let one = 1i64 << f;
    let a = truncate(t00 * (one - u) + t10 * u, d); // U(8+f) → U(8+f−d), floor
    let b = truncate(t01 * (one - u) + t11 * u, d); // U(8+f) → U(8+f−d), floor
    a * (one - v) + b * v // U(8+2f−d), exact
}

/// The unit's output `out`: `exact_wide` rounded half up to the texels' integer scale (U8).
pub fn exact_channel_with(t00: i64, t10: i64, t01: i64, t11: i64, u: i64, v: i64, f: u32, d: u32) -> i64 {
    round_half_up(exact_wide(t00, t10, t01, t11, u, v, f, d), 2 * f - d) // U(8+2f−d) → U8, round half up
}

pub fn ideal_channel(t00: f64, t10: f64, t01: f64, t11: f64, u: f64, v: f64) -> f64 {
    let a = t00 * (1.0 - u) + t10 * u;
    let b = t01 * (1.0 - u) + t11 * u;
    a * (1.0 - v) + b * v
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    (0..4).map(|c| exact_channel(i[c], i[4 + c], i[8 + c], i[12 + c], i[16], i[17], F)).collect()
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let mut v = vec![];
    for (t, u, w) in [(0, 0, 0), (255, 255, 255), (255, 0, 0), (255, 128, 128), (255, 255, 0), (0, 255, 255)] {
        let mut x = vec![0; 18];
        for c in 0..4 {
            x[c] = t;
            x[4 + c] = 255 - t;
            x[8 + c] = 255 - t;
            x[12 + c] = t;
        }
        x[16] = u;
        x[17] = w;
        v.push(x);
    }
    // all-255 texels at the largest blend factors must stay 255; half-way rounds up
    v.push([vec![255; 16], vec![255, 255]].concat());
    v.push([vec![0, 0, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 1], vec![128, 0]].concat());
    v
}

pub static MODEL: UnitModel =
    UnitModel::new("bilinear", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases).with_accuracy(accuracy);

/// The unit with `f` blend bits and `d` dropped: each 8-bit position keeps its top `f` bits (floor), every channel
/// `exact_channel_with`. At (8, 0) this is the unit's own `exact`.
pub fn exact_sized(i: &[i64], f: u32, d: u32) -> Vec<i64> {
    let (u, v) = (i[input::ublend] >> (8 - f), i[input::vblend] >> (8 - f)); // U8 → U(f), floor
    (0..4).map(|c| exact_channel_with(i[c], i[4 + c], i[8 + c], i[12 + c], u, v, f, d)).collect()
}

/// The sized unit against the reals at the 8-bit positions it was given (u/256, v/256): every channel of `samples`
/// random vectors, 8-bit LSB.
pub fn error_sized(f: u32, d: u32, samples: usize, seed: u64) -> crate::stats::ErrorStats {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut s = crate::stats::ErrorStats::default();
    for _ in 0..samples {
        let i = random_inputs(&mut rng);
        let e = exact_sized(&i, f, d);
        let (u, v) = (i[input::ublend] as f64 / 256.0, i[input::vblend] as f64 / 256.0);
        for c in 0..4 {
            let want = ideal_channel(i[c] as f64, i[4 + c] as f64, i[8 + c] as f64, i[12 + c] as f64, u, v);
            s.add((e[c] as f64 - want).abs(), || format!("{i:?}"));
        }
    }
    s
}

/// Random vectors against the reals, the red channel.
fn accuracy(samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
    let one = (1i64 << F) as f64;
    vec![crate::unit::Accuracy::over_random("8-bit LSB", samples, seed, random_inputs, |v| {
        let (t00, t10, t01, t11) = (v[input::t00_r], v[input::t10_r], v[input::t01_r], v[input::t11_r]);
        let (u, w) = (v[input::ublend], v[input::vblend]);
        let e = exact_channel(t00, t10, t01, t11, u, w, F) as f64;
        vec![(e - ideal_channel(t00 as f64, t10 as f64, t01 as f64, t11 as f64, u as f64 / one, w as f64 / one)).abs()]
    })]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_unit_s_own_size_is_the_unit() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        for _ in 0..2000 {
            let i = random_inputs(&mut rng);
            assert_eq!(exact_sized(&i, 8, 0), exact_ports(&i));
        }
        // fewer blend bits cost accuracy: at 4 bits the position's dropped half texel shows
        let (e8, e4) = (error_sized(8, 0, 20_000, 1), error_sized(4, 0, 20_000, 1));
        assert!(e8.max <= 0.5 + 1e-9 && e4.mean() > 4.0 * e8.mean(), "{} / {}", e8.mean(), e4.mean());
    }

    #[test]
    fn exact_is_the_ideal_rounded_half_up_for_every_f() {
        let mut worst = 0.0f64;
        for f in [4u32, 6, 8] {
            let one = 1i64 << f;
            for (t00, t10, t01, t11) in [(0, 255, 17, 200), (255, 255, 255, 255), (3, 250, 128, 0)] {
                for u in 0..one {
                    for v in 0..one {
                        let e = exact_channel(t00, t10, t01, t11, u, v, f) as f64;
                        let i = ideal_channel(
                            t00 as f64,
                            t10 as f64,
                            t01 as f64,
                            t11 as f64,
                            u as f64 / one as f64,
                            v as f64 / one as f64,
                        );
                        worst = worst.max((e - i).abs());
                    }
                }
            }
        }
        assert!(worst <= 0.5, "{worst}");
    }
}
