//! `blinn_pipeline`: Blinn's height-map function (US 2004/0207631 ¶31, ¶85) on the shared units, the variant FIG. 8a
//! shows: blend adjust unused, the alpha unit unused, texel k not fetched. The red, green and blue bilinear units
//! (`BilinearUnit<8, 9, 1>`, at the plain factors doubled to 9 bits) blend the top-left [a b; d e], top-right
//! [b c; e f] and bottom-left [d e; g h] grids; the tangent unit shrinks to G − R and B − R; then the normal unit
//! [156] and the shared normaliser, as in `height_pipeline`. See `filters::blinn_exact`.

use crate::height::filters;
use crate::unit::{Accuracy, UnitModel};

crate::ports! {
    inputs: [
        a: u 8, b: u 8, c: u 8, d: u 8, e: u 8, f: u 8, g: u 8, h: u 8, ublend: u 8, vblend: u 8, scale: u 8,
    ],
    outputs: [
        norm_x: s 12, norm_y: s 12, norm_z: s 12,
    ],
}

/// The window a..h with k (unread) as 0.
fn window(i: &[i64]) -> [i64; 9] {
    std::array::from_fn(|p| if p < 8 { i[p] } else { 0 })
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    use input::*;
    filters::blinn_exact(&window(i), i[ublend], i[vblend], i[scale]).to_vec()
}

/// The same method in reals on the same codes.
pub fn ideal(i: &[i64]) -> [f64; 3] {
    let w: Vec<f64> = window(i).iter().map(|&x| x as f64).collect();
    let map = filters::Grid { side: 3, h: &w };
    let (cu, cv) = (1.0 + i[input::ublend] as f64 / 256.0, 1.0 + i[input::vblend] as f64 / 256.0);
    filters::Filter::Blinn.ideal(&map, &map, i[input::scale] as f64, cu, cv)
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let mut v = vec![];
    let with = |w: [i64; 8], ub: i64, vb: i64, s: i64| [w.to_vec(), vec![ub, vb, s]].concat();
    for h in [0, 255] {
        v.push(with([h; 8], 0, 0, 16));
        v.push(with([h; 8], 255, 255, 255));
    }
    // the steepest steps along u and v, both ways, at the factors' ends; the largest scale
    for (ub, vb) in [(0, 0), (255, 255), (128, 0)] {
        v.push(with([0, 255, 255, 0, 255, 255, 0, 255], ub, vb, 16));
        v.push(with([255, 0, 0, 255, 0, 0, 255, 0], ub, vb, 255));
        v.push(with([0, 0, 0, 255, 255, 255, 255, 255], ub, vb, 16));
        v.push(with([255, 255, 255, 0, 0, 0, 0, 0], ub, vb, 255));
    }
    v
}

/// Random windows, factors and scales: the exact normal against the method in reals on the same codes.
fn accuracy(samples: usize, seed: u64) -> Vec<Accuracy> {
    vec![Accuracy::over_random("degrees, random windows, factors and scales", samples, seed, random_inputs, |v| {
        vec![crate::stats::angle_deg(
            exact_ports(v).iter().map(|&c| c as f64).collect::<Vec<_>>().try_into().unwrap_or([0.0; 3]),
            ideal(v),
        )]
    })]
}

pub static MODEL: UnitModel =
    UnitModel::new("blinn_pipeline", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases).with_accuracy(accuracy);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn it_is_the_blinn_filter_on_the_window() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(2);
        for _ in 0..5_000 {
            let v = random_inputs(&mut rng);
            let mut w = window(&v).to_vec();
            w[8] = 200; // texel k: unread
            let map = filters::Grid { side: 3, h: &w };
            let want = filters::Filter::Blinn.exact(
                &map,
                &map,
                v[input::scale],
                256 + v[input::ublend],
                256 + v[input::vblend],
            );
            assert_eq!(exact_ports(&v), want.to_vec());
        }
    }

    #[test]
    fn a_flat_window_is_straight_up() {
        for h in [0, 99, 255] {
            assert_eq!(exact_ports(&[vec![h; 8], vec![17, 240, 200]].concat()), vec![0, 1024, 0]);
        }
    }
}
