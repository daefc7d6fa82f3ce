//! `gloss`: the seed's quadratic glossiness, the exact integer recipe (US 6,819,319, second embodiment):
//! `k = C + 8` (U9, 3 fraction bits); `L = max(0, 1023 − ((k·(1023 − X)) >> 3))`; `Q = (L·L) >> 10`;
//! `P = L + ((C·(Q − L)) >> 8)` with `>>` arithmetic (Q ≤ L, so C·(Q − L) ≤ 0 and the shift floors it).
//! X, L, Q, P are 10-bit fractions (Uq0.10); C = 0 gives P = X.

use crate::fixed::truncate;
use crate::unit::UnitModel;

crate::ports! {
    inputs: [
        conc: u 8, x: u 10,
    ],
    outputs: [
        p: u 10,
    ],
}

#[inline]
pub fn exact(c: i64, x: i64) -> i64 {
    let k = c + 8; // U9, Q6.3
    let l = (1023 - truncate(k * (1023 - x), 3)).max(0); // U19 >> 3 (floor) → U16; 1023 − that, ≥ 0: U10
    let q = truncate(l * l, 10); // U20 >> 10 (floor): U10
    l + truncate(c * (q - l), 8) // S19 >> 8 (floor, arithmetic): S11; L + that ∈ 0..1023: U10
}

/// The recipe in reals (1023 = 1.0 as the seed's integers read it): the curve the integers approximate.
pub fn ideal(c: i64, x: i64) -> f64 {
    ideal_real(c, x as f64)
}

/// The same curve on a real-valued X (in 10-bit units), as a float pipeline feeds it.
pub fn ideal_real(c: i64, x: f64) -> f64 {
    let (cf, xf) = (c as f64 / 256.0, x / 1023.0);
    let k = (c as f64 + 8.0) / 8.0;
    let l = (1.0 - k * (1.0 - xf)).max(0.0);
    1023.0 * (l + cf * (l * l - l))
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    vec![exact(i[0], i[1])]
}

fn exhaustive() -> Vec<Vec<i64>> {
    (0..1i64 << 18).map(|t| vec![t >> 10, t & 1023]).collect()
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let mut v = vec![];
    for c in [0, 1, 128, 254, 255] {
        for x in [0, 1, 511, 512, 1000, 1022, 1023] {
            v.push(vec![c, x]);
        }
    }
    v
}

pub static MODEL: UnitModel = UnitModel::new("gloss", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases)
    .with_exhaustive(exhaustive)
    .with_accuracy(accuracy);

/// Every (C, X) against the recipe in reals.
fn accuracy(_samples: usize, _seed: u64) -> Vec<crate::unit::Accuracy> {
    let mut s = crate::stats::ErrorStats::default();
    for cc in 0..256 {
        for x in 0..1024 {
            s.add((exact(cc, x) as f64 - ideal(cc, x)).abs(), || format!("C={cc} X={x}"));
        }
    }
    vec![crate::unit::Accuracy::new("10-bit LSB vs the recipe in reals, all 2^18", s)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_concentration_is_the_identity() {
        for x in 0..1024 {
            assert_eq!(exact(0, x), x);
        }
    }

    #[test]
    fn output_stays_a_10_bit_fraction_and_is_monotonic_in_x() {
        for c in 0..256 {
            let mut prev = 0;
            for x in 0..1024 {
                let p = exact(c, x);
                assert!((0..=1023).contains(&p), "C={c} X={x}: {p}");
                assert!(p >= prev, "not monotonic at C={c} X={x}");
                prev = p;
            }
        }
    }

    #[test]
    fn full_light_loses_one_lsb_for_any_concentration() {
        // The seed's recipe: L = 1023, Q = (1023·1023) >> 10 = 1022, so C·(Q − L) = −C and its arithmetic shift
        // is −1 for every C > 0: full light reads 1022, one LSB short. A property of the recipe, kept as it is.
        assert_eq!(exact(0, 1023), 1023);
        for c in 1..256 {
            assert_eq!(exact(c, 1023), 1022, "C={c}");
        }
    }
}
