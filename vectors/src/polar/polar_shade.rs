//! `polar_shade`: US 6,819,319, FIG. 3 and equation 3 up to the clamp: `k1 + k2·sin S + k3·cos S·cos(R − Q)`.
//! All U8 in, 255 = 1.0 for the k's and the tables (UNORM8, see `sincos`):
//! - sin/cos unit [10] on S: `sin_s`, `cos_s` (U8);
//! - multipliers [12] `t12 = div255(k2·sin_s)` and [14] `t14 = div255(k3·cos_s)`: U16 products, /255 rounded to
//!   nearest (U8);
//! - subtractor [16]: `d = (R − Q) mod 256` (U8, wraps);
//! - cosine unit [18]: `|cos d|` (U8) and its sign bit [26];
//! - multiplier [20]: `t20 = div255(t14·|cos d|)` (U8);
//! - adder [22]: `a22 = k1 + t12` (U9, ≤ 510);
//! - add/subtract [24], chosen by the sign bit: `sum = a22 ∓ t20` — S11; reachable −255 ..= 616 (255 + 255·√2);
//! - clamp [28] to U8: `shade = min(max(sum, 0), 255)`.
//!
//! The power unit [30] is its own unit (`power`); the pipeline chains them.

use crate::blend::div255;
use crate::fixed::saturate;
use crate::polar_encode::Scale;
use crate::sincos::{cos_sign_table, elevation_entry, elevation_table, TABLE_BITS, WIDTH};
use crate::unit::UnitModel;
use std::sync::OnceLock;

crate::ports! {
    inputs: [s: u 8, r: u 8, q: u 8, k1: u 8, k2: u 8, k3: u 8],
    outputs: [sum: s 11, shade: u 8],
}

/// The two tables of one scale.
pub struct Tables {
    pub elevation: Vec<(i64, i64)>,
    pub cos_sign: Vec<(i64, bool)>,
}

pub fn tables(sc: Scale) -> &'static Tables {
    static SEED: OnceLock<Tables> = OnceLock::new();
    static DC: OnceLock<Tables> = OnceLock::new();
    let cell = match sc {
        Scale::Seed => &SEED,
        Scale::Dc255 => &DC,
    };
    cell.get_or_init(|| Tables {
        elevation: elevation_table(sc, TABLE_BITS, WIDTH),
        cos_sign: cos_sign_table(sc, WIDTH),
    })
}

/// Every intermediate of FIG. 3, for tests and the waveform reader.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Trace {
    pub d: i64,
    pub t12: i64,
    pub t14: i64,
    pub t20: i64,
    pub a22: i64,
    pub negative: bool,
    pub sum: i64,
    pub shade: i64,
}

pub fn exact_trace(sc: Scale, s: i64, r: i64, q: i64, k1: i64, k2: i64, k3: i64) -> Trace {
    exact_trace_sized(sc, TABLE_BITS, s, r, q, k1, k2, k3)
}

/// The same with an elevation table of 2^tb entries (tb ≤ 8), read at S's top tb bits (truncation): the sin/cos
/// unit's swept table sizes in the shading unit. At tb = TABLE_BITS this is the unit.
#[allow(clippy::too_many_arguments)]
pub fn exact_trace_sized(sc: Scale, tb: u32, s: i64, r: i64, q: i64, k1: i64, k2: i64, k3: i64) -> Trace {
    let t = tables(sc);
    let (sin_s, cos_s) =
        if tb == TABLE_BITS { t.elevation[s as usize] } else { elevation_entry(sc, tb, WIDTH, s >> (8 - tb)) };
    let t12 = div255(k2 * sin_s); // U16 / 255, rounded: U8
    let t14 = div255(k3 * cos_s); // U16 / 255, rounded: U8
    let d = (r - q).rem_euclid(256); // U8, modulo-256 wrap
    let (cd, negative) = t.cos_sign[d as usize];
    let t20 = div255(t14 * cd); // U16 / 255, rounded: U8
    let a22 = k1 + t12; // U9
    let sum = if negative { a22 - t20 } else { a22 + t20 }; // S11
    let shade = saturate(sum, 0, 255); // U8
    Trace { d, t12, t14, t20, a22, negative, sum, shade }
}

pub fn exact(sc: Scale, s: i64, r: i64, q: i64, k1: i64, k2: i64, k3: i64) -> (i64, i64) {
    let t = exact_trace(sc, s, r, q, k1, k2, k3);
    (t.sum, t.shade)
}

/// Equation 3 in reals on the angles the codes stand for, ×255, before the clamp.
pub fn ideal(sc: Scale, s: i64, r: i64, q: i64, k1: i64, k2: i64, k3: i64) -> f64 {
    let (es, dr) = (sc.elevation(s), sc.rotation(r) - sc.rotation(q));
    k1 as f64 + k2 as f64 * es.sin() + k3 as f64 * es.cos() * dr.cos()
}

fn exact_ports_in(scale: Scale, i: &[i64]) -> Vec<i64> {
    let (sum, shade) = exact(scale, i[input::s], i[input::r], i[input::q], i[input::k1], i[input::k2], i[input::k3]);
    vec![sum, shade]
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    exact_ports_in(Scale::Seed, i)
}

fn exact_ports_dc(i: &[i64]) -> Vec<i64> {
    exact_ports_in(Scale::Dc255, i)
}

/// The k sweep of the exhaustive set: every (S, R − Q) pair is run under each of these (k1, k2, k3).
pub const K_SWEEP: &[(i64, i64, i64)] = &[
    (0, 0, 255),
    (0, 255, 255),
    (255, 255, 255),
    (128, 90, 90),
    (0, 180, 180),
    (255, 0, 0),
    (64, 1, 254),
    (17, 200, 73),
];

/// All 2^16 (S, R) pairs with Q = 0 (R − Q takes every value), under each k triple of the sweep: 2^19 vectors.
fn exhaustive() -> Vec<Vec<i64>> {
    let mut v = Vec::with_capacity(K_SWEEP.len() << 16);
    for &(k1, k2, k3) in K_SWEEP {
        for sr in 0..1i64 << 16 {
            v.push(vec![sr >> 8, sr & 255, 0, k1, k2, k3]);
        }
    }
    v
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let mut v = vec![
        // R − Q wraps: R = 1, Q = 255 is +2 steps; R = 255, Q = 1 is −2 steps; R = Q
        vec![100, 1, 255, 0, 128, 255],
        vec![100, 255, 1, 0, 128, 255],
        vec![100, 77, 77, 0, 128, 255],
        // S at both ends, cos(R − Q) at 0°, 90°, 180°
        vec![0, 0, 0, 0, 255, 255],
        vec![255, 0, 0, 0, 255, 255],
        vec![0, 64, 0, 0, 255, 255],
        vec![0, 128, 0, 0, 255, 255],
        // the S11 extremes before the clamp: 255 + 255·(sin 45° + cos 45°) = 616 and 0 + 0 − 255 = −255
        // (765 would need sin S = cos S = 1)
        vec![128, 0, 0, 255, 255, 255],
        vec![0, 0, 0, 255, 255, 255],
        vec![0, 128, 0, 0, 0, 255],
        // k's at 0 and at max
        vec![200, 30, 40, 0, 0, 0],
        vec![200, 30, 40, 255, 255, 255],
        // a light on the horizon (T = 0: k2 = 0, k3 = h) lighting a texel facing it and one facing away
        vec![40, 64, 64, 0, 0, 255],
        vec![40, 192, 64, 0, 0, 255],
    ];
    for s in [0, 1, 254, 255] {
        v.push(vec![s, 200, 10, 30, 200, 200]);
    }
    v
}

pub static MODEL: UnitModel = UnitModel::new("polar_shade", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases)
    .with_exhaustive(exhaustive)
    .with_accuracy(accuracy);

/// The same unit with the Dreamcast toolchains' angle scale in its tables (the block `PolarShade<true>`, inside
/// `polar_pipeline_dc`).
pub static MODEL_DC: UnitModel =
    UnitModel::new("polar_shade_dc", (INPUTS, OUTPUTS), exact_ports_dc, random_inputs, hard_cases)
        .with_exhaustive(exhaustive)
        .with_accuracy(accuracy_dc);

/// Random vectors against equation 3 on the angles the codes stand for: the S11 before the clamp and the shade.
fn accuracy_in(scale: Scale, samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let (mut pre, mut clamped) = (crate::stats::ErrorStats::default(), crate::stats::ErrorStats::default());
    for _ in 0..samples {
        let v = random_inputs(&mut rng);
        let (sum, shade) = exact(scale, v[0], v[1], v[2], v[3], v[4], v[5]);
        let i = ideal(scale, v[0], v[1], v[2], v[3], v[4], v[5]);
        pre.add((sum as f64 - i).abs(), || format!("{v:?}"));
        clamped.add((shade as f64 - i.clamp(0.0, 255.0)).abs(), || format!("{v:?}"));
    }
    vec![
        crate::unit::Accuracy::new("8-bit LSB, S11 before the clamp", pre),
        crate::unit::Accuracy::new("8-bit LSB, clamped shade", clamped),
    ]
}

fn accuracy(samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
    accuracy_in(Scale::Seed, samples, seed)
}

fn accuracy_dc(samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
    accuracy_in(Scale::Dc255, samples, seed)
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_sized_table_path_reads_the_units_own_table_at_its_size_and_coarser_ones_at_the_top_bits() {
        for sc in [Scale::Seed, Scale::Dc255] {
            for s in 0..256 {
                assert_eq!(elevation_entry(sc, TABLE_BITS, WIDTH, s), tables(sc).elevation[s as usize]);
                // 64 entries: S and S with its two low bits cleared read the same entry
                let a = exact_trace_sized(sc, 6, s, 40, 7, 30, 200, 180);
                let b = exact_trace_sized(sc, 6, s & !3, 40, 7, 30, 200, 180);
                assert_eq!(a, b);
            }
        }
        let moved = (0..256).filter(|&s| {
            exact_trace_sized(Scale::Seed, 6, s, 40, 7, 30, 200, 180)
                != exact_trace(Scale::Seed, s, 40, 7, 30, 200, 180)
        });
        assert!(moved.count() > 64);
    }

    use super::*;

    #[test]
    fn the_s11_reaches_both_of_its_extremes() {
        assert_eq!(exact(Scale::Seed, 0, 0, 0, 255, 255, 255).0, 255 + 0 + 255);
        assert_eq!(exact(Scale::Seed, 255, 0, 0, 255, 255, 255).0, 255 + 255 + 2); // cos S = 2/255 at S = 255
        assert_eq!(exact(Scale::Seed, 0, 128, 0, 0, 0, 255), (-255, 0));
        let (mut lo, mut hi) = (i64::MAX, i64::MIN);
        for i in exhaustive() {
            let (sum, shade) = exact(Scale::Seed, i[0], i[1], i[2], i[3], i[4], i[5]);
            assert_eq!(shade, sum.clamp(0, 255));
            lo = lo.min(sum);
            hi = hi.max(sum);
        }
        assert!(lo >= -1024 && hi <= 1023, "S11 holds it: {lo}..{hi}");
        // the reachable extremes: −k3 and k1 + k2·sin S + k3·cos S at its best, 255 + 255·√2
        assert_eq!((lo, hi), (-255, (255.0 + 255.0 * 2f64.sqrt()).round() as i64));
    }

    #[test]
    fn r_minus_q_wraps_modulo_256() {
        let a = exact_trace(Scale::Seed, 100, 1, 255, 0, 128, 255);
        let b = exact_trace(Scale::Seed, 100, 3, 1, 0, 128, 255);
        assert_eq!(a.d, 2);
        assert_eq!(a, b);
        let c = exact_trace(Scale::Seed, 100, 255, 1, 0, 128, 255);
        assert_eq!(c.d, 254);
        assert_eq!(c.sum, a.sum); // cos is even
    }

    #[test]
    fn exact_stays_within_a_few_lsb_of_equation_3() {
        let mut worst: f64 = 0.0;
        for i in exhaustive() {
            let (sum, _) = exact(Scale::Seed, i[0], i[1], i[2], i[3], i[4], i[5]);
            worst = worst.max((sum as f64 - ideal(Scale::Seed, i[0], i[1], i[2], i[3], i[4], i[5])).abs());
        }
        // four roundings of ±0.5 LSB and the table entries' own ±0.5: bounded well under 3 LSB
        assert!(worst < 3.0, "{worst}");
    }
}
