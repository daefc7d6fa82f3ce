//! `texture_filter`: US 2004/0207631's texture filter with its mode input (FIG. 4b and FIG. 7 in one): one set of four
//! bilinear units (`BilinearUnit<8, 9, 1>`) filters RGBA colour or generates normals from a height map.
//!
//! Both modes read the same four fetched words t00, t10, t01, t11 of four bytes (r, g, b, a):
//! - colour (`mode` = 0): each word is a texel; unit c filters channel c with the factors doubled to 9 bits, exactly
//!   the 8-bit colour filter (`bilinear`);
//! - height (`mode` = 1): the map is stored 2×2-interleaved (¶55), each word holding the heights (2X, 2Y),
//!   (2X + 1, 2Y), (2X, 2Y + 1), (2X + 1, 2Y + 1) in r, g, b, a; the four words are a 4 × 4 block, and the 3×3
//!   window a..k starts at (ox, oy) ∈ {0, 1}² inside it (the fetch's select [151]); then replicate [152], blend adjust
//!   [153], the four units, tangent [155], normal [156] and the shared normaliser.
//!
//! Both results leave every clock: the rounded colour (meaningful in colour mode) and the normal (in height mode).

use crate::height::{blend_adjust, height_normal, replicate, tangent};
use crate::{bilinear, normalise};

crate::ports! {
    inputs: [
        t00_r: u 8, t00_g: u 8, t00_b: u 8, t00_a: u 8, t10_r: u 8, t10_g: u 8, t10_b: u 8, t10_a: u 8,
        t01_r: u 8, t01_g: u 8, t01_b: u 8, t01_a: u 8, t11_r: u 8, t11_g: u 8, t11_b: u 8, t11_a: u 8,
        ublend: u 8, vblend: u 8, mode: u 1, ox: u 1, oy: u 1, scale: u 8,
    ],
    outputs: [
        out_r: u 8, out_g: u 8, out_b: u 8, out_a: u 8, norm_x: s 12, norm_y: s 12, norm_z: s 12,
    ],
}

/// The 3×3 window (row-major a..k) at (ox, oy) in the 4 × 4 block of heights that the four words hold.
pub fn window(words: &[[i64; 4]; 4], ox: i64, oy: i64) -> [i64; 9] {
    // words t00, t10, t01, t11; byte (x % 2) + 2·(y % 2) of word (x / 2, y / 2)
    let block = |x: i64, y: i64| words[((x / 2) + 2 * (y / 2)) as usize][((x % 2) + 2 * (y % 2)) as usize];
    std::array::from_fn(|p| block(ox + p as i64 % 3, oy + p as i64 / 3))
}

/// Each unit's texels and factors, in either mode.
pub fn feeds(i: &[i64]) -> [([i64; 4], (i64, i64)); 4] {
    use input::*;
    let words: [[i64; 4]; 4] = std::array::from_fn(|w| std::array::from_fn(|c| i[4 * w + c]));
    if i[mode] == 0 {
        // colour: unit c takes channel c of the four texels, the factors doubled (exact in 9 bits)
        std::array::from_fn(|c| ([words[0][c], words[1][c], words[2][c], words[3][c]], (2 * i[ublend], 2 * i[vblend])))
    } else {
        let grids = replicate::grids(&window(&words, i[ox], i[oy]));
        let (u0, u1) = blend_adjust::exact_axis(i[ublend]);
        let (v0, v1) = blend_adjust::exact_axis(i[vblend]);
        let f = [(u0, v0), (u1, v0), (u0, v1), (u1, v1)];
        std::array::from_fn(|c| (grids[c], f[c]))
    }
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    use input::*;
    let f = feeds(i);
    let (b, d) = (crate::height::height_pipeline::BLEND_BITS, crate::height::height_pipeline::DROPPED);
    let wide: [i64; 4] = std::array::from_fn(|c| {
        bilinear::exact_wide(f[c].0[0], f[c].0[1], f[c].0[2], f[c].0[3], f[c].1 .0, f[c].1 .1, b, d)
    });
    let out: Vec<i64> = (0..4)
        .map(|c| bilinear::exact_channel_with(f[c].0[0], f[c].0[1], f[c].0[2], f[c].0[3], f[c].1 .0, f[c].1 .1, b, d))
        .collect();
    let (t1, t2) = tangent::exact(wide[0], wide[1], wide[2], wide[3], i[ublend], i[vblend]);
    let n = normalise::exact(height_normal::exact(t1, t2, i[scale]));
    [out, n.to_vec()].concat()
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let mut v = vec![];
    let texels: Vec<i64> = (0..16).map(|k| k * 17).collect();
    for (ub, vb) in [(0, 0), (255, 255), (128, 64)] {
        // colour mode: the texels as the colour filter sees them
        v.push([texels.clone(), vec![ub, vb, 0, 0, 0, 16]].concat());
        // height mode, every window offset; a flat block; the steepest step across the block
        for (ox, oy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            v.push([texels.clone(), vec![ub, vb, 1, ox, oy, 16]].concat());
            v.push([vec![200; 16], vec![ub, vb, 1, ox, oy, 255]].concat());
            v.push(
                [vec![0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255], vec![ub, vb, 1, ox, oy, 16]]
                    .concat(),
            );
        }
    }
    v
}

/// Colour mode against the bilinear ideal; height mode against the same method in reals.
fn accuracy(samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
    use crate::unit::Accuracy;
    let colour = |rng: &mut dyn rand::RngCore| {
        let mut x = random_inputs(rng);
        x[input::mode] = 0;
        x
    };
    let height = |rng: &mut dyn rand::RngCore| {
        let mut x = random_inputs(rng);
        x[input::mode] = 1;
        x
    };
    vec![
        Accuracy::over_random("colour mode: 8-bit LSB, every channel", samples, seed, colour, |v| {
            let f = feeds(v);
            let out = exact_ports(v);
            (0..4)
                .map(|c| {
                    let t = f[c].0.map(|x| x as f64);
                    let ideal = bilinear::ideal_channel(
                        t[0],
                        t[1],
                        t[2],
                        t[3],
                        f[c].1 .0 as f64 / 512.0,
                        f[c].1 .1 as f64 / 512.0,
                    );
                    (out[c] as f64 - ideal).abs()
                })
                .collect()
        }),
        Accuracy::over_random("height mode: degrees against the method in reals", samples, seed, height, |v| {
            let w = window(&std::array::from_fn(|q| std::array::from_fn(|c| v[4 * q + c])), v[input::ox], v[input::oy]);
            let hp = [w.to_vec(), vec![v[input::ublend], v[input::vblend], v[input::scale]]].concat();
            let out = exact_ports(v);
            vec![crate::stats::angle_deg(
                [out[4], out[5], out[6]].map(|c| c as f64),
                crate::height::height_pipeline::ideal(&hp),
            )]
        }),
    ]
}

pub static MODEL: crate::unit::UnitModel =
    crate::unit::UnitModel::new("texture_filter", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases)
        .with_accuracy(accuracy);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colour_mode_is_the_colour_filter_and_height_mode_the_height_pipeline() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        for _ in 0..20_000 {
            let mut v = random_inputs(&mut rng);
            v[input::mode] = 0;
            let bil: Vec<i64> = [&v[..16], &v[16..18]].concat();
            assert_eq!(exact_ports(&v)[..4], (bilinear::MODEL.exact)(&bil)[..], "{v:?}");
            v[input::mode] = 1;
            let w = window(&std::array::from_fn(|q| std::array::from_fn(|c| v[4 * q + c])), v[input::ox], v[input::oy]);
            let hp = [w.to_vec(), vec![v[input::ublend], v[input::vblend], v[input::scale]]].concat();
            assert_eq!(exact_ports(&v)[4..], (crate::height::height_pipeline::MODEL.exact)(&hp)[..], "{v:?}");
        }
    }

    #[test]
    fn the_window_is_the_interleaved_block_at_its_offset() {
        // heights numbered by position in the 4 × 4 block: y·4 + x
        let words: [[i64; 4]; 4] = std::array::from_fn(|w| {
            let (bx, by) = (2 * (w as i64 % 2), 2 * (w as i64 / 2));
            [by * 4 + bx, by * 4 + bx + 1, (by + 1) * 4 + bx, (by + 1) * 4 + bx + 1]
        });
        assert_eq!(window(&words, 0, 0), [0, 1, 2, 4, 5, 6, 8, 9, 10]);
        assert_eq!(window(&words, 1, 1), [5, 6, 7, 9, 10, 11, 13, 14, 15]);
    }
}
