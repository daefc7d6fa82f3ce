//! `blend_adjust`: US 2004/0207631's blend-factor adjust unit [153]. From the address unit's blend factors (U8, 1/256)
//! it
//! makes the four bilinear units' factors, `U0 = ½ + U/2`, `U1 = U/2` (V likewise), in 1/512 (U9): exact, one more
//! bit rather than a rounding, so `U0 = 256 + U` and `U1 = U`. Red takes (U0, V0), green (U1, V0), blue (U0, V1),
//! alpha (U1, V1). With the replicated 2×2 grids this is de Casteljau's first step on the Bézier points of the
//! bi-quadratic B-spline, without converting the control points (equation 1).

use crate::unit::{Accuracy, UnitModel};

crate::ports! {
    inputs: [
        ublend: u 8, vblend: u 8,
    ],
    outputs: [
        u0: u 9, u1: u 9, v0: u 9, v1: u 9,
    ],
}

/// (U0, U1) of one factor, in 1/512.
pub fn exact_axis(f: i64) -> (i64, i64) {
    (256 + f, f) // U9, exact: ½ + f/2 and f/2 in 1/512
}

/// The same in reals, as fractions of 1.
pub fn ideal_axis(f: i64) -> (f64, f64) {
    let x = f as f64 / 256.0;
    (0.5 + x / 2.0, x / 2.0)
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    let ((u0, u1), (v0, v1)) = (exact_axis(i[input::ublend]), exact_axis(i[input::vblend]));
    vec![u0, u1, v0, v1]
}

fn exhaustive() -> Vec<Vec<i64>> {
    (0..1i64 << 16).map(|t| vec![t & 255, t >> 8]).collect()
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    // factor 0 (the texel's edge: U0 = ½, U1 = 0) and the largest (255/256: U0 = 511/512)
    vec![vec![0, 0], vec![255, 255], vec![0, 255], vec![255, 0], vec![128, 128]]
}

/// Every factor against ½ + f/2 and f/2 in reals (the step is exact: this is a check).
fn accuracy(_samples: usize, _seed: u64) -> Vec<Accuracy> {
    let mut s = crate::stats::ErrorStats::default();
    for f in 0..256 {
        let ((e0, e1), (i0, i1)) = (exact_axis(f), ideal_axis(f));
        s.add((e0 as f64 / 512.0 - i0).abs().max((e1 as f64 / 512.0 - i1).abs()) * 512.0, || format!("factor {f}"));
    }
    vec![Accuracy::new("1/512 LSB, every factor", s)]
}

pub static MODEL: UnitModel = UnitModel::new("blend_adjust", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases)
    .with_exhaustive(exhaustive)
    .with_accuracy(accuracy);
