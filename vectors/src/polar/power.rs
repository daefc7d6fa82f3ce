//! `power`: the power unit [30] of seed 000's FIG. 3, `y = 255·(x/255)^p` for the clamped U8 shade x and an
//! exponent p in U6.2 (`pw` = 4p, so p = 0, 0.25, …, 63.75).
//!
//! Method: log and exp tables around one multiplier, y = 2^(−p·L(x)), chosen over the alternatives by cost:
//! repeated squaring needs one multiplier per exponent bit (six for p < 64, and only integer p) and the second
//! embodiment's quadratic (`gloss`) is not a power at all; two 256-entry tables fit one SB_RAM40_4K each and the
//! product p·L one DSP. `bumprtl accuracy` measures it against `powf`.
//! - L(x) = round(−log2(x/255)·2^12) (U3.12, U15, ≤ 32,745), x ≥ 1. x = 0 bypasses the tables: y = 0 for p > 0,
//!   and 255 for p = 0 (0^0 = 1).
//! - e = pw·L (U8 × U15 → U23, 14 fraction bits); rounded to 8 fraction bits: g = (e + 2^5) >> 6 (U17);
//!   n = g >> 8 (the integer part), f = g mod 256.
//! - E(f) = round(255·2^(−f/256)·2^7) (U15, E(0) = 32,640).
//! - y = (E(f) + 2^(n+6)) >> (n + 7), rounded to nearest; n ≥ 9 gives 0 (E < 2^15), so n saturates at 9.

use crate::unit::UnitModel;
use std::sync::OnceLock;

crate::ports! {
    inputs: [
        x: u 8, pw: u 8,
    ],
    outputs: [
        y: u 8,
    ],
}

/// L(x), entry 0 unused (0).
pub fn log_table() -> &'static [i64] {
    static T: OnceLock<Vec<i64>> = OnceLock::new();
    T.get_or_init(|| (0..256).map(|x| if x == 0 { 0 } else { (-(x as f64 / 255.0).log2() * 4096.0).round() as i64 }).collect())
}

/// E(f).
pub fn exp_table() -> &'static [i64] {
    static T: OnceLock<Vec<i64>> = OnceLock::new();
    T.get_or_init(|| (0..256).map(|f| (255.0 * (-(f as f64) / 256.0).exp2() * 128.0).round() as i64).collect())
}

pub fn exact(x: i64, pw: i64) -> i64 {
    if x == 0 {
        return if pw == 0 { 255 } else { 0 };
    }
    let l = log_table()[x as usize]; // U15, Uq3.12
    let e = pw * l; // U23, Uq9.14
    let g = (e + 32) >> 6; // round half up to 8 fraction bits: U17, Uq9.8
    let n = (g >> 8).min(9); // U4, saturated
    let f = g & 255; // U8
    (exp_table()[f as usize] + (1 << (n + 6))) >> (n + 7) // U16 >> 7..16, rounded: U8
}

/// `powf`, ×255.
pub fn ideal(x: i64, pw: i64) -> f64 {
    ideal_real(x as f64, pw)
}

/// `powf` on a real-valued x (8-bit units), as a float pipeline feeds it.
pub fn ideal_real(x: f64, pw: i64) -> f64 {
    255.0 * (x / 255.0).powf(pw as f64 / 4.0)
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    vec![exact(i[0], i[1])]
}

fn exhaustive() -> Vec<Vec<i64>> {
    (0..1i64 << 16).map(|t| vec![t >> 8, t & 255]).collect()
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let mut v = vec![];
    // p = 0, 0.25, 1 and the largest p, against x = 0, 1, 128, 254, 255
    for pw in [0, 1, 4, 8, 255] {
        for x in [0, 1, 128, 254, 255] {
            v.push(vec![x, pw]);
        }
    }
    v
}

pub static MODEL: UnitModel = UnitModel::new("power", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases).with_exhaustive(exhaustive).with_accuracy(accuracy);

/// Every (x, p) against `powf`.
fn accuracy(_samples: usize, _seed: u64) -> Vec<crate::unit::Accuracy> {
    let mut pw = crate::stats::ErrorStats::default();
    for x in 0..256 {
        for p in 0..256 {
            pw.add((exact(x, p) as f64 - ideal(x, p)).abs(), || format!("x={x} p={}", p as f64 / 4.0));
        }
    }
    vec![crate::unit::Accuracy::new("8-bit LSB against powf, all 2^16 (x, p)", pw)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ends_of_the_range() {
        for pw in 0..256 {
            assert_eq!(exact(255, pw), 255, "1^p = 1");
        }
        assert_eq!(exact(0, 0), 255);
        for pw in 1..256 {
            assert_eq!(exact(0, pw), 0);
        }
        for x in 1..256 {
            assert_eq!(exact(x, 0), 255, "x^0 = 1");
        }
    }

    #[test]
    fn p_of_one_gives_x_back_and_every_output_is_within_two_lsb_of_powf() {
        for x in 0..256 {
            assert_eq!(exact(x, 4), x, "p = 1 at x = {x}");
        }
        let mut worst: f64 = 0.0;
        for x in 0..256 {
            for pw in 0..256 {
                worst = worst.max((exact(x, pw) as f64 - ideal(x, pw)).abs());
            }
        }
        assert!(worst < 2.0, "{worst}");
    }

    #[test]
    fn monotonic_in_x_and_falling_in_p() {
        for pw in 0..256 {
            for x in 1..256 {
                assert!(exact(x, pw) >= exact(x - 1, pw), "x {x} pw {pw}");
            }
        }
        for x in 0..255 {
            for pw in 1..256 {
                assert!(exact(x, pw) <= exact(x, pw - 1), "x {x} pw {pw}");
            }
        }
    }
}
