//! `table_builder`: Tarini et al.'s per-frame colour table (§5.1, §7.1) built by the shading hardware the project
//! already
//! has, one palette normal a clock: the normal (S10, as a palette stores it) through the shared `normalise`, N·L and
//! N·H through two `dot3`s, the specular power through `gloss` (concentration C), then the entry of equation (1):
//! alpha the Lambert shade, the colour the reflected light (the specular colour times P). No new arithmetic besides
//! the last scaling. The entry leaves with its palette index, for the table RAM (`palette_lookup`).
//!
//! exact: N = normalise(n) (Sq1.10); X = dot3(N, L), Y = dot3(N, H) (Uq0.10); P = gloss(C, Y) (Uq0.10);
//! α = X >> 2 (U8, floor); r, g, b = (P·s + 512) >> 10 (U8, rounded half up).

use crate::unit::{Accuracy, UnitModel};
use crate::{dot3, gloss, normalise};

crate::ports! {
    inputs: [
        idx: u 14, n_x: s 10, n_y: s 10, n_z: s 10, l_x: s 12, l_y: s 12, l_z: s 12, h_x: s 12, h_y: s 12, h_z: s 12,
        conc: u 8, spec_r: u 8, spec_g: u 8, spec_b: u 8,
    ],
    outputs: [
        addr: u 14, r: u 8, g: u 8, b: u 8, a: u 8,
    ],
}

/// The entry (r, g, b, α) of a normal.
pub fn exact(n: [i64; 3], l: [i64; 3], h: [i64; 3], conc: i64, spec: [i64; 3]) -> [i64; 4] {
    exact_normalised(normalise::exact(n), l, h, conc, spec)
}

/// The entry from the normaliser's output `nn` (Sq1.10): what follows the normaliser, for software that keeps a
/// palette's normalised normals from frame to frame (a palette changes per map, not per frame).
#[inline]
pub fn exact_normalised(nn: [i64; 3], l: [i64; 3], h: [i64; 3], conc: i64, spec: [i64; 3]) -> [i64; 4] {
    let x = dot3::exact(nn, l);
    let p = gloss::exact(conc, dot3::exact(nn, h));
    let c = spec.map(|s| (p * s + 512) >> 10); // U18 + 512 → >> 10: U8, rounded half up
    [c[0], c[1], c[2], x >> 2] // α: U10 → U8, floor
}

/// The same in reals: the normal normalised, L and H as given (Sq1.10 / 1024), the gloss curve in reals.
pub fn ideal(n: [i64; 3], l: [i64; 3], h: [i64; 3], conc: i64, spec: [i64; 3]) -> [f64; 4] {
    let len = ((n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) as f64).sqrt();
    let nf = if len > 0.0 { n.map(|c| c as f64 / len) } else { [0.0, 1.0, 0.0] };
    let d = |v: [i64; 3]| (nf[0] * v[0] as f64 + nf[1] * v[1] as f64 + nf[2] * v[2] as f64) / 1024.0;
    let x = d(l).clamp(0.0, 1.0) * 1023.0;
    let p = gloss::ideal_real(conc, d(h).clamp(0.0, 1.0) * 1023.0);
    let c = spec.map(|s| p * s as f64 / 1023.0);
    [c[0], c[1], c[2], x / 1023.0 * 255.0]
}

fn split(i: &[i64]) -> ([i64; 3], [i64; 3], [i64; 3], i64, [i64; 3]) {
    use input::*;
    (
        [i[n_x], i[n_y], i[n_z]],
        [i[l_x], i[l_y], i[l_z]],
        [i[h_x], i[h_y], i[h_z]],
        i[conc],
        [i[spec_r], i[spec_g], i[spec_b]],
    )
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    let (n, l, h, c, s) = split(i);
    [vec![i[input::idx]], exact(n, l, h, c, s).to_vec()].concat()
}

/// A unit vector as Sq1.10, rounded.
pub fn sq1_10(v: [f64; 3]) -> [i64; 3] {
    crate::stats::unit(v).map(|c| (c * 1024.0).round() as i64)
}

/// Any normal (S10, zero included), unit L and H (Sq1.10), any C and specular colour.
fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    use rand::Rng;
    let dir = |rng: &mut dyn rand::RngCore| {
        sq1_10([rng.gen_range(-1.0..1.0), rng.gen_range(-0.2..1.0), rng.gen_range(-1.0..1.0)])
    };
    let (l, h) = (dir(rng), dir(rng));
    let mut v = random_inputs(rng);
    v[input::l_x..input::l_x + 3].copy_from_slice(&l);
    v[input::h_x..input::h_x + 3].copy_from_slice(&h);
    v
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let up = [0, 1024, 0];
    let mut v = vec![];
    let with = |idx: i64, n: [i64; 3], l: [i64; 3], h: [i64; 3], c: i64, s: [i64; 3]| {
        [vec![idx], n.to_vec(), l.to_vec(), h.to_vec(), vec![c], s.to_vec()].concat()
    };
    // a flat normal under the light and the half vector: the brightest entry, at the index's ends
    v.push(with(0, [0, 448, 0], up, up, 255, [255; 3]));
    v.push(with(16_383, [0, 511, 0], up, up, 0, [255, 128, 0]));
    // a zero-length normal (an unused palette slot), a normal on the horizon, one facing away from the light
    v.push(with(1, [0, 0, 0], up, up, 96, [255; 3]));
    v.push(with(2, [511, 0, 0], up, sq1_10([1.0, 1.0, 0.0]), 96, [255; 3]));
    v.push(with(3, [0, -512, 0], up, up, 96, [255; 3]));
    // the light on the horizon, and below it
    v.push(with(4, [100, 400, 0], [1024, 0, 0], sq1_10([1.0, 1.0, 0.0]), 200, [200, 100, 50]));
    v.push(with(5, [100, 400, 0], sq1_10([1.0, -0.2, 0.0]), up, 200, [200, 100, 50]));
    // the most negative components
    v.push(with(6, [-512, -512, -512], sq1_10([-1.0, -1.0, -1.0]), sq1_10([-1.0, -1.0, -1.0]), 255, [255; 3]));
    v
}

/// Random normals and unit light and half vectors: each channel of the entry against the reals, 8-bit LSB.
fn accuracy(samples: usize, seed: u64) -> Vec<Accuracy> {
    vec![Accuracy::over_random("8-bit LSB, every channel, random normals, unit L and H", samples, seed, random, |v| {
        let (n, l, h, c, s) = split(v);
        if n == [0, 0, 0] {
            return vec![];
        }
        let (e, i) = (exact(n, l, h, c, s), ideal(n, l, h, c, s));
        (0..4).map(|k| (e[k] as f64 - i[k]).abs()).collect()
    })]
}

pub static MODEL: UnitModel =
    UnitModel::new("table_builder", (INPUTS, OUTPUTS), exact_ports, random, hard_cases).with_accuracy(accuracy);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_flat_normal_under_the_light_is_the_brightest_entry() {
        let up = [0, 1024, 0];
        assert_eq!(exact([0, 448, 0], up, up, 255, [255; 3]), [255, 255, 255, 255]);
        // facing away: no Lambert shade, no highlight
        assert_eq!(exact([0, -448, 0], up, up, 96, [255; 3]), [0, 0, 0, 0]);
    }

    #[test]
    fn the_entries_are_close_to_the_reals() {
        // the worst entries sit on the steep flank of a tight highlight: at C = 255 the gloss curve turns one LSB of
        // N·H (a rounding of N, a floor of the dot product) into about 32 of P (10 bits), 8 of the 8-bit colour
        let a = accuracy(50_000, 4);
        assert!(
            a[0].stats.mean() < 0.25 && a[0].stats.max < 32.0,
            "{:.3} / {:.3} at {}",
            a[0].stats.mean(),
            a[0].stats.max,
            a[0].stats.argmax
        );
    }
}
