//! `blend`: the shade becomes an alpha (U8) and is combined with colours, US 6,819,319's "alpha output to the blending
//! unit ... combined with the existing colour". Two modes, per channel, both exact round-to-nearest of a /255:
//! - `mode = 0`, modulate: `out = round(src·α / 255)`;
//! - `mode = 1`, alpha-lerp: `out = round((src·α + dst·(255 − α)) / 255)`.
//!
//! The division: `t = num + 128`, `out = (t + (t >> 8)) >> 8`, which equals round-half-up(num/255) for every
//! num ≤ 255·255 (checked exhaustively below).

use crate::fixed::truncate;
use crate::unit::UnitModel;

crate::ports! {
    inputs: [
        alpha: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
    ],
    outputs: [
        out_r: u 8, out_g: u 8, out_b: u 8,
    ],
}

/// num/255 rounded half up, by shifts and adds only (U16 in, U8 out).
pub fn div255(num: i64) -> i64 {
    let t = num + 128; // U16
    truncate(t + truncate(t, 8), 8) // U16 + U8 = U17 → U8 (floor)
}

pub fn exact_channel(alpha: i64, mode: i64, src: i64, dst: i64) -> i64 {
    if mode == 0 {
        div255(src * alpha)
    } else {
        div255(src * alpha + dst * (255 - alpha))
    }
}

pub fn ideal_channel(alpha: i64, mode: i64, src: i64, dst: i64) -> f64 {
    let a = alpha as f64 / 255.0;
    if mode == 0 {
        src as f64 * a
    } else {
        src as f64 * a + dst as f64 * (1.0 - a)
    }
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    (0..3).map(|c| exact_channel(i[0], i[1], i[2 + c], i[5 + c])).collect()
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let mut v = vec![];
    for a in [0, 1, 127, 128, 254, 255] {
        for m in [0, 1] {
            v.push(vec![a, m, 255, 0, 128, 0, 255, 127]);
        }
    }
    v
}

pub static MODEL: UnitModel =
    UnitModel::new("blend", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases).with_accuracy(accuracy);

/// Random vectors against the reals, the red channel.
fn accuracy(samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
    vec![crate::unit::Accuracy::over_random("8-bit LSB", samples, seed, random_inputs, |v| {
        let (a, m, s, d) = (v[input::alpha], v[input::mode], v[input::src_r], v[input::dst_r]);
        vec![(exact_channel(a, m, s, d) as f64 - ideal_channel(a, m, s, d)).abs()]
    })]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn div255_is_round_half_up_over_the_whole_range() {
        for num in 0..=255 * 255 {
            assert_eq!(div255(num), (2 * num + 255) / 510, "{num}");
        }
    }

    #[test]
    fn both_modes_are_within_half_an_lsb_of_ideal_on_every_channel_value() {
        for a in 0..256 {
            for s in 0..256 {
                for d in [0, 1, 127, 254, 255] {
                    for m in [0, 1] {
                        let e = exact_channel(a, m, s, d) as f64;
                        assert!((e - ideal_channel(a, m, s, d)).abs() <= 0.5, "{a} {m} {s} {d}");
                    }
                }
            }
        }
    }
}
