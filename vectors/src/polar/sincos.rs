//! `sincos`: the sine/cosine unit [10] and the cosine-with-sign unit [18] of US 6,819,319's FIG. 3, as tables.
//!
//! Entries are unsigned W-bit fractions with 2^W − 1 = 1.0 (UNORM_W), rounded to nearest: the k's use 255 = 1.0,
//! so with W = 8 a product k·sin is divided by 255 exactly (`blend::div255`) and k = sin = 255 gives 255.
//! - elevation tables, 2^TB entries over a quarter turn: entry i stands for i·90°/D, D = 2^TB (seed scale) or
//!   2^TB − 1 (Dreamcast scale, the last entry is exactly 90°);
//! - the cosine-with-sign table, 256 entries over a full turn indexed by R − Q (mod 256): |cos| as UNORM_W and a
//!   sign bit, set where cos < 0 (the add/subtract unit [24] subtracts then).
//!
//! The rtl unit `sincos` is the elevation unit alone, TB = 8, W = 8, seed scale, on a 10-bit angle (1024 = 90°):
//! the table index is the angle's top TB bits (truncation), so a 10-bit angle resolves finer than a 256-entry
//! table and the LUT-size table (`size_error`) shows what 64, 256 and 1024 entries buy.

use crate::polar_encode::Scale;
use crate::unit::UnitModel;
use std::f64::consts::FRAC_PI_2;

/// Table bits and output width of the rtl units.
pub const TABLE_BITS: u32 = 8;
pub const WIDTH: u32 = 8;
/// Bits of the standalone unit's angle input (a quarter turn).
pub const ANGLE_BITS: u32 = 10;

fn unorm(x: f64, w: u32) -> i64 {
    (x * ((1i64 << w) - 1) as f64).round() as i64
}

/// The elevation a table entry stands for.
pub fn entry_angle(sc: Scale, tb: u32, i: i64) -> f64 {
    let d = match sc {
        Scale::Seed => (1i64 << tb) as f64,
        Scale::Dc255 => ((1i64 << tb) - 1) as f64,
    };
    i as f64 * FRAC_PI_2 / d
}

/// Entry i of a 2^tb-entry elevation table: (sin, cos) of its angle, UNORM_W, rounded to nearest. The one formula
/// of the model's sine/cosine tables.
pub fn elevation_entry(sc: Scale, tb: u32, w: u32, i: i64) -> (i64, i64) {
    let a = entry_angle(sc, tb, i);
    (unorm(a.sin(), w), unorm(a.cos(), w))
}

/// sin and cos tables over a quarter turn: (sin, cos) per entry, UNORM_W.
pub fn elevation_table(sc: Scale, tb: u32, w: u32) -> Vec<(i64, i64)> {
    (0..1i64 << tb).map(|i| elevation_entry(sc, tb, w, i)).collect()
}

/// Entry i of a 2^tb-entry cosine-with-sign table over a full turn: (|cos| UNORM_W rounded to nearest, cos < 0) of
/// the first rotation difference d = i·2^(8 − tb) it covers. The one formula of the model's cosine tables.
pub fn cos_sign_entry(sc: Scale, tb: u32, w: u32, i: i64) -> (i64, bool) {
    let c = sc.rotation(i << (8 - tb)).cos();
    (unorm(c.abs(), w), c < 0.0)
}

/// The cosine-with-sign table over a full turn, 256 entries indexed by (R − Q) mod 256: (|cos| UNORM_W, negative).
pub fn cos_sign_table(sc: Scale, w: u32) -> Vec<(i64, bool)> {
    (0..256).map(|d| cos_sign_entry(sc, 8, w, d)).collect()
}

/// Pack an elevation entry for a ROM word: sin in the low W bits, cos above.
pub fn pack_elevation(e: (i64, i64), w: u32) -> u64 {
    (e.0 as u64) | ((e.1 as u64) << w)
}

/// Pack a cosine-with-sign entry: |cos| in the low W bits, the sign above.
pub fn pack_cos_sign(e: (i64, bool), w: u32) -> u64 {
    (e.0 as u64) | ((e.1 as u64) << w)
}

crate::ports! {
    inputs: [
        angle: u ANGLE_BITS,
    ],
    outputs: [
        sin: u WIDTH, cos: u WIDTH,
    ],
}

/// The standalone unit: 10-bit angle → table entry at its top TB bits.
pub fn exact_with(sc: Scale, tb: u32, w: u32, angle: i64) -> (i64, i64) {
    elevation_entry(sc, tb, w, angle >> (ANGLE_BITS - tb)) // truncate to the table's resolution
}

/// The angle a 10-bit input stands for (seed scale: 1024 = 90°; Dreamcast: 1023 = 90°).
pub fn input_angle(sc: Scale, angle: i64) -> f64 {
    match sc {
        Scale::Seed => angle as f64 * FRAC_PI_2 / (1i64 << ANGLE_BITS) as f64,
        Scale::Dc255 => angle as f64 * FRAC_PI_2 / ((1i64 << ANGLE_BITS) - 1) as f64,
    }
}

pub fn ideal(angle: i64) -> (f64, f64) {
    let a = input_angle(Scale::Seed, angle);
    let full = ((1i64 << WIDTH) - 1) as f64;
    (a.sin() * full, a.cos() * full)
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    let (s, c) = exact_with(Scale::Seed, TABLE_BITS, WIDTH, i[0]);
    vec![s, c]
}

fn exhaustive() -> Vec<Vec<i64>> {
    (0..1i64 << ANGLE_BITS).map(|a| vec![a]).collect()
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    // both ends, the first and last angle of a table bin, 45° and 30°
    [0, 1, 3, 4, 341, 512, 1020, 1022, 1023].iter().map(|&a| vec![a]).collect()
}

pub static MODEL: UnitModel = UnitModel::new("sincos", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases)
    .with_exhaustive(exhaustive)
    .with_accuracy(accuracy);

/// One row of the LUT-size table: max and mean |error| of sin and cos over every 10-bit angle, in LSBs of an
/// 8-bit output (so widths compare), for a table of 2^tb entries of w bits.
#[derive(Clone, Debug)]
pub struct SizeRow {
    pub entries: u32,
    pub width: u32,
    pub mean_lsb8: f64,
    pub max_lsb8: f64,
    pub max_at: i64,
}

pub fn size_error(tb: u32, w: u32) -> SizeRow {
    let full = ((1i64 << w) - 1) as f64;
    let (mut sum, mut max, mut at) = (0.0, -1.0, 0);
    for angle in 0..1i64 << ANGLE_BITS {
        let (s, c) = exact_with(Scale::Seed, tb, w, angle);
        let a = input_angle(Scale::Seed, angle);
        for e in [(s as f64 / full - a.sin()).abs(), (c as f64 / full - a.cos()).abs()] {
            let e = e * 255.0;
            sum += e;
            if e > max {
                max = e;
                at = angle;
            }
        }
    }
    SizeRow { entries: 1 << tb, width: w, mean_lsb8: sum / (2 << ANGLE_BITS) as f64, max_lsb8: max, max_at: at }
}

/// Every 10-bit angle, the worse of sin and cos.
fn accuracy(_samples: usize, _seed: u64) -> Vec<crate::unit::Accuracy> {
    let mut sc = crate::stats::ErrorStats::default();
    for a in 0..1i64 << ANGLE_BITS {
        let (s, c) = exact_with(Scale::Seed, TABLE_BITS, WIDTH, a);
        let (is, ic) = ideal(a);
        sc.add((s as f64 - is).abs().max((c as f64 - ic).abs()), || format!("angle {a}"));
    }
    vec![crate::unit::Accuracy::new("8-bit LSB, every 10-bit angle, 256 entries", sc)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_ends_are_exact_where_the_scale_allows() {
        let t = elevation_table(Scale::Seed, 8, 8);
        assert_eq!(t[0], (0, 255));
        // seed: entry 255 is 255/256 of 90°, sin rounds to 255 but cos is 2 (cos 89.65° = 0.0061)
        assert_eq!(t[255], (255, 2));
        let t = elevation_table(Scale::Dc255, 8, 8);
        assert_eq!(t[255], (255, 0));
    }

    #[test]
    fn cosine_sign_flips_past_a_quarter_turn_both_ways() {
        let t = cos_sign_table(Scale::Seed, 8);
        assert_eq!(t[0], (255, false));
        assert_eq!(t[64].0, 0); // exactly 90°
        assert!(!t[63].1 && t[65].1); // just below and just above 90°
        assert_eq!(t[128], (255, true));
        assert!(t[191].1 && !t[193].1);
        assert_eq!(t[255].0, 255); // −1.4°: cos 0.9997
        assert!(!t[255].1);
    }

    #[test]
    fn bigger_tables_and_wider_entries_cost_less_error() {
        let e64 = size_error(6, 8).max_lsb8;
        let e256 = size_error(8, 8).max_lsb8;
        let e1024 = size_error(10, 8).max_lsb8;
        assert!(e64 > e256 && e256 > e1024, "{e64} {e256} {e1024}");
        assert!(e1024 <= 0.5 + 1e-9); // only the output rounding left
        assert!(size_error(10, 12).max_lsb8 < 0.05);
    }

    #[test]
    fn full_turn_rotation_is_mod_256_in_the_seed_scale() {
        assert!((Scale::Seed.rotation(256) - std::f64::consts::TAU).abs() < 1e-12);
    }
}
