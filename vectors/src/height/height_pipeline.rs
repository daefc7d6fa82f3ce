//! `height_pipeline`: US 2004/0207631's normal generation end to end (FIG. 7), from the fetched 3×3 heights on:
//! replicate [152] → blend adjust [153] → the four bilinear units [65–68] (9 blend bits, one dropped between their
//! stages: `BilinearUnit<8, 9, 1>`, the colour filter's own units) → tangent [155] → normal [156] → `normalise`.
//! Every stage is the unit of the same name; this file only wires them. The ideal is the same method in reals,
//! which a test shows to be the bi-quadratic B-spline's own normal.

use crate::height::{blend_adjust, height_normal, replicate, tangent};
use crate::{bilinear, normalise};

/// The shared bilinear units in height mode: 9 blend bits, one bit dropped between their stages.
pub const BLEND_BITS: u32 = 9;
pub const DROPPED: u32 = 1;

crate::ports! {
    inputs: [
        a: u 8, b: u 8, c: u 8, d: u 8, e: u 8, f: u 8, g: u 8, h: u 8, k: u 8, ublend: u 8, vblend: u 8,
        scale: u 8,
    ],
    outputs: [
        norm_x: s 12, norm_y: s 12, norm_z: s 12,
    ],
}

/// Every stage's result for one input vector.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Trace {
    /// red, green, blue, alpha: the bilinear units' exact results (17 fraction bits of a height LSB)
    pub rgba: [i64; 4],
    pub t1: i64,
    pub t2: i64,
    /// N as S10 for the normaliser, and the unit normal (Sq1.10)
    pub n: [i64; 3],
    pub normal: [i64; 3],
}

pub fn exact_trace(i: &[i64]) -> Trace {
    use input::*;
    let w: [i64; 9] = std::array::from_fn(|x| i[x]);
    let grids = replicate::grids(&w);
    let (u0, u1) = blend_adjust::exact_axis(i[ublend]);
    let (v0, v1) = blend_adjust::exact_axis(i[vblend]);
    let factors = [(u0, v0), (u1, v0), (u0, v1), (u1, v1)]; // red, green, blue, alpha [60]
    let rgba: [i64; 4] = std::array::from_fn(|unit| {
        let (t, (u, v)) = (grids[unit], factors[unit]);
        bilinear::exact_wide(t[0], t[1], t[2], t[3], u, v, BLEND_BITS, DROPPED)
    });
    let (t1, t2) = tangent::exact(rgba[0], rgba[1], rgba[2], rgba[3], i[ublend], i[vblend]);
    let n = height_normal::exact(t1, t2, i[scale]);
    Trace { rgba, t1, t2, n, normal: normalise::exact(n) }
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    exact_trace(i).normal.to_vec()
}

/// The same method in reals on the same codes: the four bilinear blends with ½ + u/2 and u/2, the tangents, the
/// normal with k = scale/16, normalised.
pub fn ideal(i: &[i64]) -> [f64; 3] {
    use input::*;
    let w: [f64; 9] = std::array::from_fn(|x| i[x] as f64);
    let grids = replicate::grids(&w);
    let (u, v) = (i[ublend] as f64 / 256.0, i[vblend] as f64 / 256.0);
    let (u0, u1) = (0.5 + u / 2.0, u / 2.0);
    let (v0, v1) = (0.5 + v / 2.0, v / 2.0);
    let factors = [(u0, v0), (u1, v0), (u0, v1), (u1, v1)];
    let rgba: [f64; 4] = std::array::from_fn(|unit| {
        let (t, (fu, fv)) = (grids[unit], factors[unit]);
        bilinear::ideal_channel(t[0], t[1], t[2], t[3], fu, fv)
    });
    let (t1, t2) = tangent::ideal(rgba[0], rgba[1], rgba[2], rgba[3], u, v);
    height_normal::ideal(t1, t2, i[scale] as f64 / (1 << height_normal::SCALE_FRAC) as f64)
}

/// The bi-quadratic uniform B-spline through a 3×3 window (row-major a..k) at (u, v) ∈ [0, 1)²: its height and its
/// derivatives ∂H/∂u, ∂H/∂v, straight from the basis functions (the reference the method is checked against).
pub fn bspline(w: &[f64; 9], u: f64, v: f64) -> (f64, f64, f64) {
    let basis = |t: f64| [(1.0 - t) * (1.0 - t) / 2.0, (-2.0 * t * t + 2.0 * t + 1.0) / 2.0, t * t / 2.0];
    let slope = |t: f64| [-(1.0 - t), 1.0 - 2.0 * t, t];
    let (bu, bv, du, dv) = (basis(u), basis(v), slope(u), slope(v));
    let (mut h, mut hu, mut hv) = (0.0, 0.0, 0.0);
    for row in 0..3 {
        for col in 0..3 {
            let p = w[3 * row + col];
            h += bu[col] * bv[row] * p;
            hu += du[col] * bv[row] * p;
            hv += bu[col] * dv[row] * p;
        }
    }
    (h, hu, hv)
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let mut v = vec![];
    let with = |w: [i64; 9], ub: i64, vb: i64, s: i64| [w.to_vec(), vec![ub, vb, s]].concat();
    // a flat map at every level: exactly (0, 1024, 0)
    for h in [0, 128, 255] {
        v.push(with([h; 9], 0, 0, 16));
        v.push(with([h; 9], 255, 255, 255));
    }
    // the steepest step, 0 → 255 in one texel, along u and along v, at the blend factors' ends
    for (ub, vb) in [(0, 0), (255, 255), (128, 0)] {
        v.push(with([0, 255, 255, 0, 255, 255, 0, 255, 255], ub, vb, 16));
        v.push(with([0, 0, 0, 255, 255, 255, 255, 255, 255], ub, vb, 16));
        v.push(with([255, 0, 0, 255, 0, 0, 255, 0, 0], ub, vb, 255)); // falling, at the largest scale
    }
    // the largest scale on a gentle slope, and scale 0 on a steep one (flat)
    v.push(with([0, 1, 2, 0, 1, 2, 0, 1, 2], 64, 64, 255));
    v.push(with([0, 255, 0, 255, 0, 255, 0, 255, 0], 64, 192, 0));
    v
}

/// Random windows and factors: the exact normal's angle to the ideal of the same method on the same codes.
fn accuracy(samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
    let smooth = |rng: &mut dyn rand::RngCore| -> Vec<i64> {
        // a plane with a little curvature: what a height map of a smooth surface holds
        let x = random_inputs(rng);
        let (h0, gu, gv, cu) = (x[4] / 2 + 64, (x[0] % 32) - 16, (x[1] % 32) - 16, (x[2] % 7) - 3);
        let mut w: Vec<i64> = (0..9)
            .map(|p| {
                let (col, row) = ((p % 3) as i64 - 1, (p / 3) as i64 - 1);
                (h0 + gu * col + gv * row + cu * col * col).clamp(0, 255)
            })
            .collect();
        w.extend([x[9], x[10], 16]);
        w
    };
    let angle = |v: &[i64]| vec![crate::stats::angle_deg(exact_trace(v).normal.map(|c| c as f64), ideal(v))];
    vec![
        crate::unit::Accuracy::over_random(
            "degrees, random windows, factors and scales",
            samples,
            seed,
            random_inputs,
            angle,
        ),
        crate::unit::Accuracy::over_random(
            "degrees, smooth windows (slopes ≤ 4 LSB/texel·4), k = 1",
            samples,
            seed,
            smooth,
            angle,
        ),
    ]
}

pub static MODEL: crate::unit::UnitModel =
    crate::unit::UnitModel::new("height_pipeline", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases)
        .with_accuracy(accuracy);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_method_is_the_b_spline_derivative() {
        // Tang1y and Tang2y in reals are half of ∂H/∂u and ∂H/∂v of the bi-quadratic B-spline, for any window
        let w = [12.0, 200.0, 37.0, 90.0, 5.0, 255.0, 61.0, 140.0, 33.0];
        for (u, v) in [(0.0, 0.0), (0.25, 0.75), (0.5, 0.5), (0.99, 0.01)] {
            let g = replicate::grids(&w);
            let f = [
                (0.5 + u / 2.0, 0.5 + v / 2.0),
                (u / 2.0, 0.5 + v / 2.0),
                (0.5 + u / 2.0, v / 2.0),
                (u / 2.0, v / 2.0),
            ];
            let r: Vec<f64> =
                (0..4).map(|k| bilinear::ideal_channel(g[k][0], g[k][1], g[k][2], g[k][3], f[k].0, f[k].1)).collect();
            let (t1, t2) = tangent::ideal(r[0], r[1], r[2], r[3], u, v);
            let (_, hu, hv) = bspline(&w, u, v);
            assert!((2.0 * t1 - hu).abs() < 1e-9 && (2.0 * t2 - hv).abs() < 1e-9, "({u}, {v}): {t1} {hu} / {t2} {hv}");
        }
    }

    #[test]
    fn a_flat_map_is_exactly_straight_up() {
        for h in [0, 77, 255] {
            for (ub, vb, s) in [(0, 0, 16), (255, 255, 255), (17, 200, 0)] {
                let t = exact_trace(&[vec![h; 9], vec![ub, vb, s]].concat());
                assert_eq!((t.t1, t.t2, t.normal), (0, 0, [0, 1024, 0]), "height {h}");
            }
        }
    }

    #[test]
    fn a_raised_bump_is_lit_on_the_side_facing_the_light() {
        // heights of a round bump (in quarter texels) on a 16 × 16 grid; a light low from +x
        let bump = |x: f64, z: f64| 200.0 * (-((x - 8.0).powi(2) + (z - 8.0).powi(2)) / 8.0).exp();
        let light = [0.8f64, 0.6, 0.0];
        let shade_at = |cx: i64| {
            let w: Vec<i64> =
                (0..9).map(|p| bump((cx + p % 3 - 1) as f64, (8 + p / 3 - 1) as f64).round() as i64).collect();
            let n = exact_trace(&[w, vec![128, 128, 16]].concat()).normal.map(|c| c as f64 / 1024.0);
            n[0] * light[0] + n[1] * light[1] + n[2] * light[2]
        };
        // the flank facing +x (beyond the top) is brighter than the one facing away, which is brighter than nothing
        let (facing, away) = (shade_at(10), shade_at(6));
        assert!(facing > shade_at(8) && shade_at(8) > away, "facing {facing}, top {}, away {away}", shade_at(8));
        // and on the facing flank the normal leans towards +x: N_x > 0 where H falls along u
        let w: Vec<i64> =
            (0..9).map(|p| bump((10 + p % 3 - 1) as f64, (8 + p / 3 - 1) as f64).round() as i64).collect();
        assert!(exact_trace(&[w, vec![128, 128, 16]].concat()).normal[0] > 0);
    }

    #[test]
    fn the_exact_path_is_close_to_its_own_ideal() {
        let rows = accuracy(20_000, 1);
        for r in &rows {
            assert!(
                r.stats.mean() < 0.1,
                "{}: mean {:.4}°, max {:.4}° at {}",
                r.metric,
                r.stats.mean(),
                r.stats.max,
                r.stats.argmax
            );
        }
    }
}
