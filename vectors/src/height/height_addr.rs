//! `height_addr`: US 2004/0207631's address unit [150], one axis (the unit is used once for U and once for V). A
//! texture
//! coordinate in texel units (UQ8.8) → the integer texel coordinate (U8) and the blend factor (U8, 1/256), for a
//! texture of 2^size_log2 texels along the axis (size_log2 ≥ 8 is read as 8), wrapping or clamping at the border.
//!
//! - Colour mode (`height` = 0) subtracts half a texel first [51]: texel centres sit at i + ½, so the coordinate
//!   between centres i and i + 1 is c − ½.
//! - Height mode (`height` = 1) bypasses it: the B-spline segment of control point i spans [i, i + 1), so the blend
//!   factor is the coordinate's own fraction.
//! - Wrap: the coordinate modulo the texture. Clamp: colour mode clamps to [0, size − 1] (the last texel centre,
//!   blend 0), height mode to [0, size) less one LSB (the last segment's end).

use crate::unit::{Accuracy, UnitModel};

crate::ports! {
    inputs: [
        coord: u 16, size_log2: u 4, wrap: u 1, height: u 1,
    ],
    outputs: [
        texel: u 8, blend: u 8,
    ],
}

/// The axis's texel count, log2: size_log2 saturated to 8.
pub fn size_bits(size_log2: i64) -> i64 {
    crate::fixed::saturate(size_log2, 0, 8)
}

/// (texel, blend) of one coordinate.
pub fn exact(coord: i64, size_log2: i64, wrap: bool, height: bool) -> (i64, i64) {
    let span = 256i64 << size_bits(size_log2); // the texture along the axis, in 1/256 texel (≤ 2^16)
    let c = if height { coord } else { coord - 128 }; // S17: the half-texel subtraction [51], bypassed in height mode
    let c = if wrap {
        c.rem_euclid(span) // modulo the texture: 0..span − 1
    } else if height {
        crate::fixed::saturate(c, 0, span - 1)
    } else {
        crate::fixed::saturate(c, 0, span - 256)
    };
    (c >> 8, c & 255) // U16 → the integer part (U8) and the fraction (U8): a split, no rounding
}

/// The same in reals: (texel, fraction) of a coordinate in texel units.
pub fn ideal(coord: f64, size_log2: i64, wrap: bool, height: bool) -> (i64, f64) {
    let size = (1i64 << size_bits(size_log2)) as f64;
    let c = if height { coord } else { coord - 0.5 };
    let c = if wrap {
        c.rem_euclid(size)
    } else if height {
        c.clamp(0.0, size - 1.0 / 256.0)
    } else {
        c.clamp(0.0, size - 1.0)
    };
    (c.floor() as i64, c - c.floor())
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    let (t, b) = exact(i[input::coord], i[input::size_log2], i[input::wrap] == 1, i[input::height] == 1);
    vec![t, b]
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let mut v = vec![];
    for (wrap, height) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
        for size_log2 in [0, 1, 7, 8, 15] {
            // the first texel, the first centre, the last centre, the last texel's end, the top of the range
            for coord in [0, 1, 127, 128, 129, 255, 256, (128 << size_log2.min(8)) - 1, 65_407, 65_408, 65_535] {
                v.push(vec![coord.min(65_535), size_log2, wrap, height]);
            }
        }
    }
    v
}

/// Every coordinate of every size in both modes against the reals: the blend factor's error (1/256) and whether the
/// texel agrees (the split is exact on UQ8.8 inputs: this is a check).
fn accuracy(_samples: usize, _seed: u64) -> Vec<Accuracy> {
    let (mut s, mut t) = (crate::stats::ErrorStats::default(), crate::stats::ErrorStats::default());
    for size_log2 in 0..=8 {
        for (wrap, height) in [(false, false), (false, true), (true, false), (true, true)] {
            for coord in (0..1i64 << 16).step_by(7) {
                let (et, eb) = exact(coord, size_log2, wrap, height);
                let (it, ib) = ideal(coord as f64 / 256.0, size_log2, wrap, height);
                let at = || format!("coord {coord}, 2^{size_log2} texels, wrap {wrap}, height {height}");
                s.add((eb as f64 / 256.0 - ib).abs() * 256.0, at);
                t.add((et != it) as i64 as f64, at);
            }
        }
    }
    vec![
        Accuracy::new("blend, 1/256 LSB, every 7th coordinate, all sizes", s),
        Accuracy::new("texel differs (0 or 1)", t),
    ]
}

pub static MODEL: UnitModel =
    UnitModel::new("height_addr", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases).with_accuracy(accuracy);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colour_mode_subtracts_half_a_texel_and_height_mode_does_not() {
        // coordinate 3.25 texels on a 16-texel axis
        assert_eq!(exact(3 * 256 + 64, 4, false, false), (2, 192)); // 2.75: between centres 2 and 3
        assert_eq!(exact(3 * 256 + 64, 4, false, true), (3, 64)); // segment 3, a quarter in
    }

    #[test]
    fn borders_wrap_or_clamp() {
        // colour mode at 0.25 texels: wraps to the last texel, or clamps to the first centre
        assert_eq!(exact(64, 4, true, false), (15, 192));
        assert_eq!(exact(64, 4, false, false), (0, 0));
        // beyond the texture: 17.5 texels on a 16-texel axis
        assert_eq!(exact(17 * 256 + 128, 4, true, true), (1, 128));
        assert_eq!(exact(17 * 256 + 128, 4, false, true), (15, 255));
        assert_eq!(exact(17 * 256 + 128, 4, false, false), (15, 0));
        // a one-texel axis: always texel 0
        for c in [0, 100, 300, 65_535] {
            assert_eq!(exact(c, 0, true, true).0, 0);
            assert_eq!(exact(c, 0, false, false), (0, 0));
        }
    }

    #[test]
    fn size_log2_above_8_is_8() {
        assert_eq!(exact(65_535, 15, true, true), exact(65_535, 8, true, true));
        assert_eq!(exact(65_535, 8, true, true), (255, 255));
    }
}
