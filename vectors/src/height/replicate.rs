//! `replicate`: US 2004/0207631's replicate unit [152]. The fetched 3×3 heights `a b c / d e f / g h k` go out as four
//! overlapping 2×2 grids, one per bilinear unit: red `[a b; d e]`, green `[b c; e f]`, blue `[d e; g h]`, alpha
//! `[e f; h k]`, each in the bilinear unit's texel order (t00, t10, t01, t11). Wiring only: exact by construction.

use crate::unit::{Accuracy, UnitModel};

crate::ports! {
    inputs: [
        a: u 8, b: u 8, c: u 8, d: u 8, e: u 8, f: u 8, g: u 8, h: u 8, k: u 8,
    ],
    outputs: [
        r00: u 8, r10: u 8, r01: u 8, r11: u 8, g00: u 8, g10: u 8, g01: u 8, g11: u 8,
        b00: u 8, b10: u 8, b01: u 8, b11: u 8, a00: u 8, a10: u 8, a01: u 8, a11: u 8,
    ],
}

/// The four grids of a 3×3 window `w` (row-major `a b c d e f g h k`): red, green, blue, alpha, each (t00, t10,
/// t01, t11).
pub fn grids<T: Copy>(w: &[T; 9]) -> [[T; 4]; 4] {
    let at = |col: usize, row: usize| w[3 * row + col];
    std::array::from_fn(|unit| {
        let (c, r) = (unit % 2, unit / 2); // red (0, 0), green (1, 0), blue (0, 1), alpha (1, 1)
        [at(c, r), at(c + 1, r), at(c, r + 1), at(c + 1, r + 1)]
    })
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    let w: [i64; 9] = std::array::from_fn(|k| i[k]);
    grids(&w).concat()
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    // every position distinct, so a crossed wire shows; the extremes
    vec![(1..=9).collect(), vec![0; 9], vec![255; 9], vec![255, 0, 255, 0, 255, 0, 255, 0, 255]]
}

/// Wiring: every output is one input, by construction; counted over random windows as a check.
fn accuracy(samples: usize, seed: u64) -> Vec<Accuracy> {
    vec![Accuracy::over_random("8-bit LSB (wiring, exact)", samples, seed, random_inputs, |v| {
        let out = exact_ports(v);
        let want =
            [[v[0], v[1], v[3], v[4]], [v[1], v[2], v[4], v[5]], [v[3], v[4], v[6], v[7]], [v[4], v[5], v[7], v[8]]];
        out.iter().zip(want.concat()).map(|(o, w)| (o - w).abs() as f64).collect()
    })]
}

pub static MODEL: UnitModel =
    UnitModel::new("replicate", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases).with_accuracy(accuracy);
