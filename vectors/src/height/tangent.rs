//! `tangent`: US 2004/0207631's tangent construction unit [155]. From the four bilinear units' results (red, green,
//! blue,
//! alpha: the exact `wide` outputs, U25 with 17 fraction bits of a height LSB) and the unadjusted blend factors:
//! `Tang1y = lerp(V, G − R, A − B)`, `Tang2y = lerp(U, B − R, A − G)`. With the adjusted factors these are half the
//! bi-quadratic B-spline's derivatives ∂H/∂u and ∂H/∂v (H in height LSB, u and v in texels), as a test shows
//! against the spline itself.
//!
//! exact: the four results truncated to 12 fraction bits (U20), the differences S21, then
//! `t = floor((d1·256 + (d2 − d1)·f) / 256)` (S30 → S21, 12 fraction bits): a convex combination of two S21 values,
//! so it stays in S21.

use crate::fixed::truncate;
use crate::unit::{Accuracy, UnitModel};

/// Fraction bits of the bilinear results coming in (`BilinearUnit<8, 9, 1>`: 2·9 − 1) and of the tangents going out.
pub const IN_FRAC: u32 = 17;
pub const FRAC: u32 = 12;

crate::ports! {
    inputs: [
        red: u 25, green: u 25, blue: u 25, alpha: u 25, ublend: u 8, vblend: u 8,
    ],
    outputs: [
        t1: s 21, t2: s 21,
    ],
}

/// (Tang1y, Tang2y) in height LSB with `FRAC` fraction bits.
pub fn exact(r: i64, g: i64, b: i64, a: i64, ub: i64, vb: i64) -> (i64, i64) {
    let [r, g, b, a] = [r, g, b, a].map(|x| truncate(x, IN_FRAC - FRAC)); // U25 → U20 (12 fraction bits), floor
    let (d1, d2) = (g - r, a - b); // S21 each, exact
    let (e1, e2) = (b - r, a - g); // S21 each, exact
    let t1 = truncate(d1 * 256 + (d2 - d1) * vb, 8); // S30 → S21, floor
    let t2 = truncate(e1 * 256 + (e2 - e1) * ub, 8); // S30 → S21, floor
    (t1, t2)
}

/// The same in reals: results in height LSB, factors as fractions of 1.
pub fn ideal(r: f64, g: f64, b: f64, a: f64, u: f64, v: f64) -> (f64, f64) {
    ((g - r) + v * ((a - b) - (g - r)), (b - r) + u * ((a - g) - (b - r)))
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    use input::*;
    let (t1, t2) = exact(i[red], i[green], i[blue], i[alpha], i[ublend], i[vblend]);
    vec![t1, t2]
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let top = (1i64 << 25) - 1;
    let mut v = vec![];
    // equal results: zero tangents; the steepest differences both ways, at the factors' ends
    for (ub, vb) in [(0, 0), (255, 255), (0, 255), (128, 128)] {
        v.push(vec![5 << 17, 5 << 17, 5 << 17, 5 << 17, ub, vb]);
        v.push(vec![0, top, top, 0, ub, vb]);
        v.push(vec![top, 0, 0, top, ub, vb]);
        v.push(vec![0, top, 0, top, ub, vb]);
        v.push(vec![top, 0, top, 0, ub, vb]);
    }
    // a result one LSB below a 12-bit step: the truncation shows
    v.push(vec![(1 << 5) - 1, 1 << 5, 0, 0, 0, 0]);
    v
}

/// Random results and factors, both tangents against the reals (12 fraction bits: 1/4096 of a height LSB).
fn accuracy(samples: usize, seed: u64) -> Vec<Accuracy> {
    vec![Accuracy::over_random("1/4096 height LSB, both tangents", samples, seed, random_inputs, |v| {
        use input::*;
        let f = |x: i64| x as f64 / (1 << IN_FRAC) as f64;
        let (e1, e2) = exact(v[red], v[green], v[blue], v[alpha], v[ublend], v[vblend]);
        let (i1, i2) =
            ideal(f(v[red]), f(v[green]), f(v[blue]), f(v[alpha]), v[ublend] as f64 / 256.0, v[vblend] as f64 / 256.0);
        let q = (1 << FRAC) as f64;
        vec![(e1 as f64 / q - i1).abs() * q, (e2 as f64 / q - i2).abs() * q]
    })]
}

pub static MODEL: UnitModel =
    UnitModel::new("tangent", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases).with_accuracy(accuracy);
