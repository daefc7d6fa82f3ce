//! `power`: the power unit [30] of US 6,819,319's FIG. 3, `y = 255·(x/255)^p` for the clamped U8 shade x and an
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
//!
//! Those are the unit's table sizes (`LOG_FRAC` = 12, `EXP_BITS` = 8). The width sweep varies both (`exact_with`):
//! L with `lf` fraction bits (Uq3.lf), e = pw·L with 2 + lf, g rounded (half up) to `eb` fraction bits, and an
//! exp table of 2^eb entries.

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

/// The unit's fraction bits of L and of g (the exp table's index bits).
pub const LOG_FRAC: u32 = 12;
pub const EXP_BITS: u32 = 8;

// L fits its U15 for lf ≤ 12, and rounding g needs eb < 2 + lf: the width sweep's settings (`sim::units::SETTINGS`)
// stay inside both.

/// L(x) with `lf` fraction bits, entry 0 unused (0).
pub fn log_entry(x: u64, lf: u32) -> i64 {
    if x == 0 {
        0
    } else {
        (-(x as f64 / 255.0).log2() * (1u64 << lf) as f64).round() as i64
    }
}

/// E(f) of a 2^eb-entry table: 255·2^(−f/2^eb)·2^7, rounded (U15).
pub fn exp_entry(f: u64, eb: u32) -> i64 {
    (255.0 * (-(f as f64) / (1u64 << eb) as f64).exp2() * 128.0).round() as i64
}

/// L(x) at the unit's size.
pub fn log_table() -> &'static [i64] {
    static T: OnceLock<Vec<i64>> = OnceLock::new();
    T.get_or_init(|| (0..256).map(|x| log_entry(x, LOG_FRAC)).collect())
}

/// E(f) at the unit's size.
pub fn exp_table() -> &'static [i64] {
    static T: OnceLock<Vec<i64>> = OnceLock::new();
    T.get_or_init(|| (0..1 << EXP_BITS).map(|f| exp_entry(f, EXP_BITS)).collect())
}

pub fn exact(x: i64, pw: i64) -> i64 {
    if x == 0 {
        return if pw == 0 { 255 } else { 0 };
    }
    pow_of(pw, log_table()[x as usize], LOG_FRAC, EXP_BITS, |f| exp_table()[f as usize])
}

/// The power unit with L to `lf` fraction bits and an exp table of 2^eb entries.
pub fn exact_with(x: i64, pw: i64, lf: u32, eb: u32) -> i64 {
    if (lf, eb) == (LOG_FRAC, EXP_BITS) {
        return exact(x, pw);
    }
    if x == 0 {
        return if pw == 0 { 255 } else { 0 };
    }
    pow_of(pw, log_entry(x as u64, lf), lf, eb, |f| exp_entry(f as u64, eb))
}

/// 2^(−p·L) from L = `l` (Uq3.lf): e = pw·l (Uq9.(2 + lf), U23 at most), g = e rounded half up to `eb` fraction
/// bits (Uq9.eb), n = min(g >> eb, 9), f = g mod 2^eb, y = (E(f) + 2^(n+6)) >> (n + 7) (rounded half up: U8).
fn pow_of(pw: i64, l: i64, lf: u32, eb: u32, e_of: impl Fn(i64) -> i64) -> i64 {
    let k = 2 + lf - eb; // fraction bits dropped from e
    let e = pw * l; // U23, Uq9.(2+lf)
    let g = (e + (1 << (k - 1))) >> k; // round half up to eb fraction bits: Uq9.eb
    let n = (g >> eb).min(9); // U4, saturated
    let f = g & ((1 << eb) - 1); // U(eb)
    (e_of(f) + (1 << (n + 6))) >> (n + 7) // U16 >> 7..16, rounded: U8
}

/// Mean and max |error| in 8-bit LSB against `powf` over every (x, p), at L fraction bits `lf` and 2^eb exp entries.
pub fn size_error(lf: u32, eb: u32) -> crate::stats::ErrorStats {
    let mut s = crate::stats::ErrorStats::default();
    for x in 0..256 {
        for p in 0..256 {
            s.add((exact_with(x, p, lf, eb) as f64 - ideal(x, p)).abs(), || format!("x={x} p={}", p as f64 / 4.0));
        }
    }
    s
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

pub static MODEL: UnitModel = UnitModel::new("power", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases)
    .with_exhaustive(exhaustive)
    .with_accuracy(accuracy);

/// Every (x, p) against `powf`.
fn accuracy(_samples: usize, _seed: u64) -> Vec<crate::unit::Accuracy> {
    vec![crate::unit::Accuracy::new("8-bit LSB against powf, all 2^16 (x, p)", size_error(LOG_FRAC, EXP_BITS))]
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
    fn every_size_keeps_its_ends_and_its_widths() {
        // every size the width sweep can take: L of 8 to 12 fraction bits, E of 64 to 512 entries
        for (lf, eb) in (8..=LOG_FRAC).flat_map(|lf| (6..=9).map(move |eb| (lf, eb))) {
            assert!(eb < 2 + lf, "({lf}, {eb})");
            // L fits U15 and e + the rounding half fits U23
            assert!(
                (1..256).all(|x| log_entry(x, lf) < 1 << 15) && 255 * log_entry(1, lf) + (1 << (1 + lf - eb)) < 1 << 23
            );
            for pw in 0..256 {
                assert_eq!(exact_with(255, pw, lf, eb), 255, "({lf}, {eb}): 1^p");
                assert_eq!(exact_with(0, pw, lf, eb), if pw == 0 { 255 } else { 0 }, "({lf}, {eb}): 0^p");
            }
            for x in 1..256 {
                assert_eq!(exact_with(x, 0, lf, eb), 255, "({lf}, {eb}): x^0");
            }
        }
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
