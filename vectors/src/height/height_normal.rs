//! `height_normal`: US 2004/0207631's normal unit [156]. The tangents T1 = (1, Tang1y, 0) and T2 = (0, Tang2y, 1) in
//! texel
//! units give N = T2 × T1 = (−∂h/∂u, 1, −∂h/∂v). With heights in quarter texels (8-bit UQ6.2) and Tang = ½ ∂H/∂u
//! (H in height LSB), ∂h/∂u = Tang/2, so N ∝ (−k·Tang1y, 2, −k·Tang2y), where k is the per-model scale factor of ¶82
//! (UQ4.4, 16 = 1.0: the map's own relief). The sign is the seed's left open: this one points out of a raised bump,
//! so the side of a bump facing the light is lit (proved on an analytic bump in the tests).
//!
//! exact: N = 7·(−k·t1, 2, −k·t2) with 16 fraction bits (S32; 7 = 8 − 1, a shift and a subtract), then one shift
//! s for all three, the smallest that brings the largest magnitude to ≤ 511 after rounding, magnitudes rounded half up:
//! S10 components
//! for the shared `normalise` unit, which is scale-free. The factor 7 puts a flat map's (0, 14·2^16, 0) at
//! (0, 448, 0), which the normaliser returns as exactly (0, 1024, 0); a power of two such as 256 sits at the bottom
//! of a seed-table bin and comes out as 1023.

use crate::height::tangent::FRAC;
use crate::unit::{Accuracy, UnitModel};

/// Fraction bits of the scale factor.
pub const SCALE_FRAC: u32 = 4;

crate::ports! {
    inputs: [
        t1: s 21, t2: s 21, scale: u 8,
    ],
    outputs: [
        n_x: s 10, n_y: s 10, n_z: s 10,
    ],
}

/// Heights in texel units as 8-bit UQ6.2 codes, and the scale factor k (UQ4.4) that gives their relief back: the
/// codes hold (h − lo)·4·m (rounded, saturated to 8 bits), m the largest power of two up to 16 that keeps the range
/// hi − lo in 8 bits, and k = 16/m.
pub fn encode_heights(h: &[f64], lo: f64, hi: f64) -> (Vec<i64>, i64) {
    encode_heights_in(h, lo, hi, 8)
}

/// The same in `bits` (8 or 4), a quarter of them fraction (¶50): UQ6.2 or UQ3.1. 4-bit codes q enter the 8-bit
/// datapath as 2q, the same height in UQ6.2 (exact), with the same k.
pub fn encode_heights_in(h: &[f64], lo: f64, hi: f64, bits: u32) -> (Vec<i64>, i64) {
    let (top, per_texel) = ((1i64 << bits) - 1, (1i64 << (bits / 4)) as f64);
    let m = (0..=4).rev().map(|p| 1i64 << p).find(|&m| (hi - lo) * per_texel * m as f64 <= top as f64).unwrap_or(1);
    let codes = h.iter().map(|x| ((x - lo) * per_texel * m as f64).round().clamp(0.0, top as f64) as i64).collect();
    (codes, (1 << SCALE_FRAC) / m)
}

/// The unnormalised normal before the shift, 7·N: S32 with FRAC + SCALE_FRAC fraction bits.
pub fn wide(t1: i64, t2: i64, scale: i64) -> [i64; 3] {
    let k7 = 7 * scale; // U11, exact
    [-(k7 * t1), 14 << (FRAC + SCALE_FRAC), -(k7 * t2)] // S21 × U11 → S32, exact; 7·2.0 in the same units
}

/// N as three S10 components: one right shift for all three (the magnitudes rounded), the largest ≤ 511.
pub fn exact(t1: i64, t2: i64, scale: i64) -> [i64; 3] {
    to_s10(wide(t1, t2, scale))
}

/// Any unnormalised vector brought to three S10 components for the scale-free normaliser: the smallest right shift
/// of all three whose rounded largest magnitude is ≤ 511.
pub fn to_s10(n: [i64; 3]) -> [i64; 3] {
    let m = n.iter().map(|x| x.abs()).max().unwrap_or(0);
    // block floating point: the smallest shift whose rounded largest magnitude is ≤ 511
    let s = (0..32).find(|&s| crate::fixed::round_half_up(m, s) <= 511).unwrap_or(31);
    n.map(|x| x.signum() * crate::fixed::round_half_up(x.abs(), s)) // magnitude >> s, rounded half up; sign restored: S10
}

/// The unit normal in reals, from the tangents in height LSB and the scale as a real factor.
pub fn ideal(t1: f64, t2: f64, k: f64) -> [f64; 3] {
    let n = [-k * t1, 2.0, -k * t2];
    let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    n.map(|c| c / l)
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    exact(i[input::t1], i[input::t2], i[input::scale]).to_vec()
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let (lo, hi) = (-(1i64 << 20), (1i64 << 20) - 1);
    let mut v = vec![];
    // flat (zero tangents, any scale; scale 0, any tangents): (0, 448, 0)
    for s in [0, 16, 255] {
        v.push(vec![0, 0, s]);
    }
    v.push(vec![hi, lo, 0]);
    // the largest scale on the largest tangents, both signs: the shift at its largest
    for (t1, t2) in [(hi, hi), (lo, lo), (hi, lo), (lo, 0), (0, hi), (1, -1)] {
        v.push(vec![t1, t2, 255]);
        v.push(vec![t1, t2, 1]);
    }
    // where rounding at the first shift reaches 512 and the shift grows by one: 7k·t in [511.5, 512)·2^s0
    v.push(vec![601_000, 0, 255]);
    v.push(vec![74_836, 0, 16]);
    v
}

/// Random tangents and scales: the S10 vector's angle to the ideal normal (degrees).
fn accuracy(samples: usize, seed: u64) -> Vec<Accuracy> {
    vec![Accuracy::over_random("degrees, random tangents and scales", samples, seed, random_inputs, |v| {
        let (t1, t2, k) = (v[input::t1], v[input::t2], v[input::scale]);
        let q = (1 << FRAC) as f64;
        let e = exact(t1, t2, k).map(|c| c as f64);
        vec![crate::stats::angle_deg(e, ideal(t1 as f64 / q, t2 as f64 / q, k as f64 / (1 << SCALE_FRAC) as f64))]
    })]
}

pub static MODEL: UnitModel =
    UnitModel::new("height_normal", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases).with_accuracy(accuracy);
