//! `dot3`: N·L of two Sq1.10 unit vectors (S12 each) → the seed's X, a 10-bit fraction (Uq0.10, 1023 ≈ 1.0).
//! exact: `d = Σ n_i·l_i` (S25, Q2.20), `truncate` 10 bits (floor) to Q.10, `saturate` to 0..1023: a light behind
//! the bump gives 0; a dot of 1.0 (1024) reads as 1023, the seed's 1.0.

use crate::fixed::{saturate, truncate};
use crate::unit::UnitModel;

crate::ports! {
    inputs: [
        n_x: s 12, n_y: s 12, n_z: s 12, l_x: s 12, l_y: s 12, l_z: s 12,
    ],
    outputs: [
        x: u 10,
    ],
}

#[inline]
pub fn exact(n: [i64; 3], l: [i64; 3]) -> i64 {
    let d = n[0] * l[0] + n[1] * l[1] + n[2] * l[2]; // S25, Q2.20
    saturate(truncate(d, 10), 0, 1023) // floor to Q.10, then 0..1023
}

/// The dot in reals, in X units, clamped the same way.
pub fn ideal(n: [i64; 3], l: [i64; 3]) -> f64 {
    let d = (n[0] * l[0] + n[1] * l[1] + n[2] * l[2]) as f64 / 1024.0;
    d.clamp(0.0, 1023.0)
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    vec![exact([i[0], i[1], i[2]], [i[3], i[4], i[5]])]
}

fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    use rand::Rng;
    if rng.gen_range(0..2) == 0 {
        INPUTS.iter().map(|p| crate::unit::draw(rng, p)).collect()
    } else {
        // unit-length pairs, as the normalisers deliver them
        let mut v = vec![];
        for _ in 0..2 {
            let d = crate::cart_encode::random_hemisphere(rng);
            v.extend(d.map(|c| (c * 1024.0).round() as i64));
        }
        v
    }
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    vec![
        vec![0, 1024, 0, 0, 1024, 0],                   // N = L: 1024 → 1023
        vec![0, 1024, 0, 0, -1024, 0],                  // opposite: 0
        vec![-2048, -2048, -2048, -2048, -2048, -2048], // the most negative: largest positive sum
        vec![-2048, -2048, -2048, 2047, 2047, 2047],    // the most negative sum
        vec![1024, 0, 0, 0, 1024, 0],                   // light on the horizon of the normal: 0
        vec![0, 0, 0, 0, 0, 0],                         // zero light from the normaliser
        vec![1, 0, 0, 1023, 0, 0],
        vec![1, 0, 0, 1024, 0, 0],
    ]
}

pub static MODEL: UnitModel =
    UnitModel::new("dot3", (INPUTS, OUTPUTS), exact_ports, random, hard_cases).with_accuracy(accuracy);

/// Random vectors against the reals (the ideal clamped to the output's 1023).
fn accuracy(samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
    vec![crate::unit::Accuracy::over_random("10-bit LSB", samples, seed, random, |v| {
        let (n, l) = ([v[0], v[1], v[2]], [v[3], v[4], v[5]]);
        vec![(exact(n, l) as f64 - ideal(n, l).min(1023.0)).abs()]
    })]
}
