//! `cos_sign`: the cosine unit [18] of US 6,819,319's FIG. 3 on its own: the rotation difference d = (R − Q) mod 256
//! (U8, 256 = a full turn, the seed's scale) → |cos d| as UNORM_W and its sign bit [26] (set where cos d < 0),
//! from a 2^TB-entry table over the full turn addressed by d's top TB bits (truncation). The unit `cos_sign` is
//! TB = 8, W = 8, the table the polar shade unit holds; other sizes go into the LUT-size table.

use crate::unit::UnitModel;
use std::f64::consts::TAU;

pub const TABLE_BITS: u32 = 8;
pub const WIDTH: u32 = 8;

crate::ports! {
    inputs: [
        d: u 8,
    ],
    outputs: [
        mag: u WIDTH, neg: u 1,
    ],
}

/// The table entry for d with a 2^tb-entry table of w-bit magnitudes: (|cos|, negative).
pub fn exact_with(tb: u32, w: u32, d: i64) -> (i64, bool) {
    // truncate to the table's resolution
    crate::sincos::cos_sign_entry(crate::polar_encode::Scale::Seed, tb, w, d >> (8 - tb))
}

/// cos d ×255, signed.
pub fn ideal(d: i64) -> f64 {
    (d as f64 * TAU / 256.0).cos() * 255.0
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    let (m, n) = exact_with(TABLE_BITS, WIDTH, i[0]);
    vec![m, n as i64]
}

fn exhaustive() -> Vec<Vec<i64>> {
    (0..256).map(|d| vec![d]).collect()
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    // 0°, either side of 90°, 180°, either side of 270°, and −1 step
    [0, 63, 64, 65, 128, 191, 192, 193, 255].iter().map(|&d| vec![d]).collect()
}

pub static MODEL: UnitModel = UnitModel::new("cos_sign", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases)
    .with_exhaustive(exhaustive)
    .with_accuracy(accuracy);

/// Mean and max |error| of the signed cosine over every d, in LSBs of an 8-bit output, and where the max is.
pub fn size_error(tb: u32, w: u32) -> crate::sincos::SizeRow {
    let full = ((1i64 << w) - 1) as f64;
    let (mut sum, mut max, mut at) = (0.0, -1.0, 0);
    for d in 0..256 {
        let (m, neg) = exact_with(tb, w, d);
        let v = if neg { -(m as f64) } else { m as f64 } / full * 255.0;
        let e = (v - ideal(d)).abs();
        sum += e;
        if e > max {
            max = e;
            at = d;
        }
    }
    crate::sincos::SizeRow { entries: 1 << tb, width: w, mean_lsb8: sum / 256.0, max_lsb8: max, max_at: at }
}

/// Every d, the signed cosine.
fn accuracy(_samples: usize, _seed: u64) -> Vec<crate::unit::Accuracy> {
    let mut cs = crate::stats::ErrorStats::default();
    for d in 0..256 {
        let (m, neg) = exact_with(TABLE_BITS, WIDTH, d);
        let v = if neg { -m } else { m } as f64;
        cs.add((v - ideal(d)).abs(), || format!("d {d}"));
    }
    vec![crate::unit::Accuracy::new("8-bit LSB, signed cosine, every d, 256 entries", cs)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_unit_is_the_shade_units_table() {
        let t = crate::sincos::cos_sign_table(crate::polar_encode::Scale::Seed, 8);
        for d in 0..256 {
            assert_eq!(exact_with(8, 8, d), t[d as usize], "d = {d}");
        }
    }

    #[test]
    fn fewer_entries_cost_error_and_256_leaves_only_the_rounding() {
        assert!(size_error(8, 8).max_lsb8 <= 0.5 + 1e-9);
        assert!(size_error(6, 8).max_lsb8 > size_error(8, 8).max_lsb8);
        assert!(size_error(4, 8).max_lsb8 > size_error(6, 8).max_lsb8);
    }
}
