//! `tex_addr`: the texture unit's address unit (US 2004/0207631's [150], both axes at once), in front of the fetch.
//! It takes what a rasteriser gives, the sample position (u, v) in texels of level 0, and the MIP level n to read
//! (from `lod`), and gives the level's two columns and two rows of the bilinear footprint and its two blend factors.
//!
//! For a map of side 2^s (s = min(log_side, 8)) the level read is n' = min(n, s), of side 2^m with m = s − n'
//! (`level_log2`). Per axis, in 1/256 texel of level n':
//! - a = ⌊u·2^8 / 2^n'⌋: u (Sq11.8, S20) shifted right by n', the bits below the 8th fraction bit dropped (a floor,
//!   the only rounding in the unit: u has 8 fraction bits at level 0, so every level keeps at least 8 for the blend);
//! - bilinear (`linear` = 1): c = a − 128, half a texel back, so that the footprint's first texel is the one whose
//!   centre is at or below the position (texel centres sit at i + ½); nearest (`linear` = 0): c = a, the texel that
//!   holds the position;
//! - repeat (`uwrap` = 1): r = c mod 256·2^m; clamp: r = clamp(c, 0, top), top = 256·(2^m − 1) (the last texel's
//!   centre, blend 0) for bilinear, 256·2^m − 1 for nearest;
//! - x0 = r >> 8; bilinear: x1 = x0 + 1, modulo 2^m (repeat) or at most 2^m − 1 (clamp), ublend = r mod 256;
//!   nearest: x1 = x0 and ublend = 0, so a bilinear filter after it returns texel (x0, y0) itself.
//!
//! Clamping the position and then taking x0 + 1 is the same footprint as OpenGL's clamp-to-edge, which clamps each
//! texel: past either end both give the edge texel with all of the weight.

use crate::fixed::saturate;
use crate::unit::{Accuracy, UnitModel};

crate::ports! {
    inputs: [
        u: s 20, v: s 20, level: u 4, log_side: u 4, uwrap: u 1, vwrap: u 1, linear: u 1,
    ],
    outputs: [
        level_log2: u 4, x0: u 8, x1: u 8, y0: u 8, y1: u 8, ublend: u 8, vblend: u 8,
    ],
}

/// Fraction bits of u and v (Sq11.8).
pub const FRAC: u32 = 8;
/// The largest map the unit addresses: side 2^8 (a larger `log_side` is read as 8).
pub const MAX_LOG_SIDE: i64 = 8;

/// (n', m): the level read and its side's log2, for a requested level and a map of side 2^log_side.
pub fn level_read(level: i64, log_side: i64) -> (i64, i64) {
    let s = saturate(log_side, 0, MAX_LOG_SIDE);
    let n = level.min(s);
    (n, s - n)
}

/// One axis: (t0, t1, blend) of coordinate `coord` (Sq11.8) at level n of side 2^m.
pub fn axis(coord: i64, n: i64, m: i64, wrap: bool, linear: bool) -> [i64; 3] {
    let a = coord >> n; // Sq11.8 >> n: floor (arithmetic shift), 1/256 texel of level n
    let c = if linear { a - 128 } else { a }; // S21: half a texel back for bilinear, exact
    let span = 256i64 << m; // the level along the axis, 1/256 texel (≤ 2^16)
    let r = if wrap {
        c.rem_euclid(span) // modulo the level: U16
    } else if linear {
        saturate(c, 0, span - 256) // up to the last texel's centre
    } else {
        saturate(c, 0, span - 1) // up to the last texel's end
    };
    let (side, t0) = (1i64 << m, r >> 8); // the integer part: a split
    match (linear, wrap) {
        (false, _) => [t0, t0, 0],
        (true, true) => [t0, (t0 + 1) & (side - 1), r & 255],
        (true, false) => [t0, (t0 + 1).min(side - 1), r & 255],
    }
}

/// The unit's outputs, in port order.
pub fn exact(i: &[i64]) -> Vec<i64> {
    use input::*;
    let (n, m) = level_read(i[level], i[log_side]);
    let lin = i[linear] == 1;
    let x = axis(i[u], n, m, i[uwrap] == 1, lin);
    let y = axis(i[v], n, m, i[vwrap] == 1, lin);
    vec![m, x[0], x[1], y[0], y[1], x[2], y[2]]
}

/// One axis in reals: the footprint's first texel and the blend weight of the second, at position `pos` texels of
/// level 0 read at level n of side 2^m.
pub fn ideal_axis(pos: f64, n: i64, m: i64, wrap: bool, linear: bool) -> (i64, f64) {
    let side = (1i64 << m) as f64;
    let p = pos / (1i64 << n) as f64 - if linear { 0.5 } else { 0.0 };
    let p = if wrap {
        p.rem_euclid(side)
    } else if linear {
        p.clamp(0.0, side - 1.0)
    } else {
        p.clamp(0.0, side - 1.0 / 256.0)
    };
    (p.floor() as i64, if linear { p - p.floor() } else { 0.0 })
}

fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    use rand::Rng;
    // positions mostly within a few repeats of the map, one draw in eight anywhere in the port's range (and its
    // ends); levels and sizes of every map the unit addresses, one draw in sixteen past them
    let coord = |rng: &mut dyn rand::RngCore| {
        if rng.gen_range(0..8) == 0 {
            crate::unit::draw(rng, &INPUTS[0])
        } else {
            rng.gen_range(-(1i64 << 17)..1 << 17)
        }
    };
    let (u, v) = (coord(rng), coord(rng));
    let past = |rng: &mut dyn rand::RngCore| {
        if rng.gen_range(0..16) == 0 {
            rng.gen_range(9..16)
        } else {
            rng.gen_range(0..=MAX_LOG_SIDE)
        }
    };
    let (level, log_side) = (past(rng), past(rng));
    vec![u, v, level, log_side, rng.gen_range(0..2), rng.gen_range(0..2), rng.gen_range(0..2)]
}

/// Every level of the map sizes 1 × 1, 2 × 2, 8 × 8, 128 × 128 and 256 × 256 (and one past them), in both border
/// modes and both filters, at the coordinates where the footprint changes: the wrap seam (the level's last texel
/// and its first, a step either side of the level's end), the clamp edges (the first and the last texel centre, a
/// step either side), zero and the ends of the port's range; the two axes take different coordinates, so a crossed
/// axis shows.
pub fn hard_cases() -> Vec<Vec<i64>> {
    let (lo, hi) = (-(1i64 << 19), (1i64 << 19) - 1);
    let mut v = vec![];
    for log_side in [0, 1, 3, 7, 8, 12] {
        let s = log_side.min(MAX_LOG_SIDE);
        for lvl in 0..=s + 1 {
            let (n, m) = level_read(lvl, log_side);
            let unit = 1i64 << n; // one 1/256 texel of level n, at level 0
            let end = (256i64 << m) * unit; // the level's span at level 0
            let half = 128 * unit;
            let at = [
                0,
                -1,
                unit - 1,
                half - unit,
                half,
                half + unit,
                end - half - unit,
                end - half,
                end - half + unit,
                end - unit,
                end,
                end + unit,
                -end,
                2 * end + half,
                lo,
                hi,
            ];
            for (wrap, linear) in [(1, 1), (0, 1), (1, 0), (0, 0)] {
                for (k, &c) in at.iter().enumerate() {
                    let other = at[(k + 7) % at.len()];
                    v.push(vec![c.clamp(lo, hi), other.clamp(lo, hi), lvl, log_side, wrap, 1 - wrap, linear]);
                    v.push(vec![other.clamp(lo, hi), c.clamp(lo, hi), lvl, log_side, wrap, wrap, linear]);
                }
            }
        }
    }
    v
}

/// The footprint against the reals over random positions, levels and sizes: the blend factor's error (1/256 of a
/// texel; it comes only from the floor of u / 2^n) and whether the first texel agrees.
fn accuracy(samples: usize, seed: u64) -> Vec<Accuracy> {
    let errors = |i: &[i64], blend: bool| -> Vec<f64> {
        use input::*;
        let (n, m) = level_read(i[level], i[log_side]);
        let lin = i[linear] == 1;
        let e = exact(i);
        let (ex, ey) = ((e[output::x0], e[output::ublend]), (e[output::y0], e[output::vblend]));
        let f = |c: i64, w: i64| ideal_axis(c as f64 / 256.0, n, m, w == 1, lin);
        let (ix, iy) = (f(i[u], i[uwrap]), f(i[v], i[vwrap]));
        if blend {
            vec![(ex.1 as f64 / 256.0 - ix.1).abs() * 256.0, (ey.1 as f64 / 256.0 - iy.1).abs() * 256.0]
        } else {
            vec![(ex.0 != ix.0) as i64 as f64, (ey.0 != iy.0) as i64 as f64]
        }
    };
    vec![
        Accuracy::over_random("blend, 1/256 LSB, vs the position in reals", samples, seed, random, |i| errors(i, true)),
        Accuracy::over_random("first texel differs (0 or 1)", samples, seed, random, |i| errors(i, false)),
    ]
}

pub static MODEL: UnitModel =
    UnitModel::new("tex_addr", (INPUTS, OUTPUTS), exact, random, hard_cases).with_accuracy(accuracy);

#[cfg(test)]
mod tests {
    use super::*;

    fn at(u: i64, v: i64, level: i64, log_side: i64, wrap: i64, linear: i64) -> Vec<i64> {
        exact(&[u, v, level, log_side, wrap, wrap, linear])
    }

    #[test]
    fn a_position_between_centres_blends_the_two_texels_around_it() {
        // u = 3.25 texels on a 16-texel map, level 0: 2.75 after the half texel, texels 2 and 3, ¾ of the second
        assert_eq!(at(3 * 256 + 64, 0, 0, 4, 1, 1)[..7], [4, 2, 3, 15, 0, 192, 128]);
        // level 1 (8 texels): 1.625 − ½ = 1.125
        assert_eq!(at(3 * 256 + 64, 0, 1, 4, 1, 1)[1..3], [1, 2]);
        assert_eq!(at(3 * 256 + 64, 0, 1, 4, 1, 1)[5], 32);
        // nearest: the texel holding the position, no blend
        assert_eq!(at(3 * 256 + 64, 0, 0, 4, 1, 0)[1..7], [3, 3, 0, 0, 0, 0]);
    }

    #[test]
    fn the_wrap_seam_and_the_clamp_edge() {
        // 0.25 texels on 16: repeat blends the last texel into the first; clamp stays on the first
        assert_eq!(at(64, 64, 0, 4, 1, 1)[1..], [15, 0, 15, 0, 192, 192]);
        assert_eq!(at(64, 64, 0, 4, 0, 1)[1..], [0, 1, 0, 1, 0, 0]);
        // past the end (17.5 texels): repeat is texel 1 exactly; clamp is the last texel, all of its weight
        assert_eq!(at(17 * 256 + 128, 0, 0, 4, 1, 1)[1..3], [1, 2]);
        assert_eq!(at(17 * 256 + 128, 0, 0, 4, 0, 1)[1..3], [15, 15]);
        assert_eq!(at(17 * 256 + 128, 0, 0, 4, 0, 1)[5], 0);
        // a negative position repeats from the end
        assert_eq!(at(-256, 0, 0, 4, 1, 0)[1], 15);
    }

    #[test]
    fn the_level_is_clamped_to_the_map_and_a_one_texel_level_is_texel_zero() {
        for lvl in [4, 5, 15] {
            for c in [-(1 << 19), -1, 0, 77, (1 << 19) - 1] {
                for wrap in [0, 1] {
                    for linear in [0, 1] {
                        let e = at(c, c, lvl, 4, wrap, linear);
                        assert_eq!(e[0], 0, "level_log2");
                        assert_eq!(e[1..5], [0, 0, 0, 0], "u {c} level {lvl}");
                        // repeat on one texel still blends (texel 0 with itself); clamp has no weight to give
                        assert!(wrap == 1 && linear == 1 || e[5] == 0, "{e:?}");
                    }
                }
            }
        }
        assert_eq!(level_read(3, 15), (3, 5));
        assert_eq!(level_read(9, 8), (8, 0));
    }

    #[test]
    fn the_blend_is_within_one_lsb_of_the_reals() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        for _ in 0..100_000 {
            let i = random(&mut rng);
            let (n, m) = level_read(i[2], i[3]);
            let e = exact(&i);
            let (t, b) = ideal_axis(i[0] as f64 / 256.0, n, m, i[4] == 1, i[6] == 1);
            assert!((e[5] as f64 / 256.0 - b).abs() < 1.0 / 256.0, "{i:?} {e:?} {b}");
            // the floor of u / 2^n can move the position down one LSB across a texel boundary only where the blend
            // is within one LSB of it
            assert!(e[1] == t || e[5] == 255 || b < 1.0 / 256.0, "{i:?} {e:?} {t}");
        }
    }
}
