//! US 2004/0207631's variants beside its preferred B-spline path, each a model path: exact in integers on the widths of
//! the shared units (the bilinear units `BilinearUnit<8, 9, 1>`, the tangent, normal and normaliser units), and
//! the same method in reals. They read a height map through `Grid` (clamped at its borders) at a height-mode
//! coordinate (UQ8.8 texels, control point i of the B-spline at i + ½, no half-texel subtraction).
//!
//! - `BSpline`: the preferred path, `height_pipeline`.
//! - `BSpline4`: the same on 4-bit heights (UQ3.1, ¶50), entering the 8-bit datapath as 2q (exact).
//! - `Bezier`: equation 1 in a modified replicate (¶83): the 3×3 B-spline points turned into Bézier points
//!   (edge midpoints, corner quarter sums, the centre kept), rounded half up to the bilinear units' 8 bits, then the
//!   units at the plain factors (U, V) instead of the adjusted ones. In reals it is the B-spline itself.
//! - `Blinn`: Blinn's function (¶31, ¶85): three bilinear blends at (U, V) of the top-left, top-right and
//!   bottom-left grids (no alpha unit, no texel k, no blend adjust); the tangents are G − R and B − R.
//! - `FourTap`, `Sobel`, `Prewitt` (FIG. 9, ¶86): a derivative filter at each texel centre (the 4-tap central
//!   difference, or the 3×3 Sobel or Prewitt kernels), the four gradients around the point blended bilinearly as a
//!   colour filter blends (colour-mode addressing), then the normal.
//! - `Trilinear` (¶81): the tangents of two adjacent MIP levels blended by the LOD fraction; the coarser level's
//!   tangents halved, since its texels are twice as wide (the seed's 1/Texturesize in N). Measured at LOD ½.
//!
//! Also: the interpolated height (¶84: a third blend of the four units' results) and bi-quadratic B-spline colour
//! filtering (¶87: that height, per colour channel).

use crate::fixed::{round_half_up, truncate};
use crate::height::{height_normal, height_pipeline, replicate, tangent};
use crate::{bilinear, normalise};

/// The bilinear units' blend bits and the bits they drop between their stages (the colour filter's own units).
const B: u32 = height_pipeline::BLEND_BITS;
const D: u32 = height_pipeline::DROPPED;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filter {
    BSpline,
    BSpline4,
    Bezier,
    Blinn,
    FourTap,
    Sobel,
    Prewitt,
    Trilinear,
}

pub const ALL: [Filter; 8] = [
    Filter::BSpline,
    Filter::BSpline4,
    Filter::Bezier,
    Filter::Blinn,
    Filter::FourTap,
    Filter::Sobel,
    Filter::Prewitt,
    Filter::Trilinear,
];

/// The LOD fraction the trilinear path is measured at (U8: 128 = ½).
pub const TRILINEAR_LOD: i64 = 128;

impl Filter {
    pub fn name(self) -> &'static str {
        match self {
            Filter::BSpline => "B-spline (the seed's path)",
            Filter::BSpline4 => "B-spline, 4-bit heights",
            Filter::Bezier => "B-spline via equation-1 Bezier points",
            Filter::Blinn => "Blinn's function",
            Filter::FourTap => "4-tap central difference",
            Filter::Sobel => "Sobel",
            Filter::Prewitt => "Prewitt",
            Filter::Trilinear => "trilinear B-spline, LOD 1/2",
        }
    }

    /// The bits of the map's heights.
    pub fn bits(self) -> u32 {
        if self == Filter::BSpline4 {
            4
        } else {
            8
        }
    }

    /// The unit normal (Sq1.10) at height-mode coordinate (cu, cv) (UQ8.8 texels) of a map of 8-bit UQ6.2 codes
    /// (4-bit codes already doubled), its MIP level 1 beside it, with scale k (UQ4.4).
    pub fn exact(self, map: &Grid<i64>, level1: &Grid<i64>, k: i64, cu: i64, cv: i64) -> [i64; 3] {
        let (i, ub, j, vb) = (cu >> 8, cu & 255, cv >> 8, cv & 255);
        let n = match self {
            Filter::BSpline | Filter::BSpline4 => return bspline_exact(&map.window(i, j), ub, vb, k),
            Filter::Bezier => {
                let net = bezier_points(&map.window(i, j));
                let g = replicate::grids(&net);
                // the plain factors, doubled to the units' 9 bits (exact)
                let r: [i64; 4] = std::array::from_fn(|c| {
                    bilinear::exact_wide(g[c][0], g[c][1], g[c][2], g[c][3], 2 * ub, 2 * vb, B, D)
                });
                let (t1, t2) = tangent::exact(r[0], r[1], r[2], r[3], ub, vb);
                height_normal::exact(t1, t2, k)
            }
            Filter::Blinn => return blinn_exact(&map.window(i, j), ub, vb, k),
            Filter::FourTap | Filter::Sobel | Filter::Prewitt => {
                // colour-mode addressing: the texel centres around the point, half a texel back
                let (cu, cv) = (cu - 128, cv - 128);
                let (i0, fu, j0, fv) = (cu >> 8, cu & 255, cv >> 8, cv & 255);
                let w = [(256 - fu) * (256 - fv), fu * (256 - fv), (256 - fu) * fv, fu * fv]; // U17 each, sum 2^16
                let mut gb = [0i64; 2];
                for (q, (di, dj)) in [(0, 0), (1, 0), (0, 1), (1, 1)].into_iter().enumerate() {
                    let g = gradient(self, &map.window(i0 + di, j0 + dj));
                    gb[0] += w[q] * g[0]; // S12 × U17, summed: S28, exact
                    gb[1] += w[q] * g[1];
                }
                // ∂h/∂u = k/16 · ∂H/∂u / 4 and ∂H/∂u = gb / (2^16·D): N ∝ (−k·gb, 64·D·2^16, −k·gb), times c (7, or 5
                // for Prewitt's D = 6) so that a flat map's (0, 64·D·c·2^16, 0) shifts to 448 or 480, which the
                // normaliser returns as exactly (0, 1024, 0) (as `height_normal`'s factor 7 does)
                let c = if self == Filter::Prewitt { 5 } else { 7 };
                // S42 at most, exact
                height_normal::to_s10([-c * k * gb[0], (64 * c * divisor(self)) << 16, -c * k * gb[1]])
            }
            Filter::Trilinear => {
                let (t1, t2) = trilinear_tangents(map, level1, cu, cv, TRILINEAR_LOD);
                height_normal::exact(t1, t2, k)
            }
        };
        normalise::exact(n)
    }

    /// The same method in reals on real heights (in UQ6.2 code units) with the real scale k.
    pub fn ideal(self, map: &Grid<f64>, level1: &Grid<f64>, k: f64, cu: f64, cv: f64) -> [f64; 3] {
        let (i, j) = (cu.floor() as i64, cv.floor() as i64);
        let (u, v) = (cu - i as f64, cv - j as f64);
        let k = k / (1 << height_normal::SCALE_FRAC) as f64;
        match self {
            Filter::BSpline | Filter::BSpline4 | Filter::Bezier => {
                let (_, hu, hv) = height_pipeline::bspline(&map.window(i, j), u, v);
                height_normal::ideal(hu / 2.0, hv / 2.0, k)
            }
            Filter::Blinn => {
                let g = replicate::grids(&map.window(i, j));
                let r: [f64; 3] =
                    std::array::from_fn(|c| bilinear::ideal_channel(g[c][0], g[c][1], g[c][2], g[c][3], u, v));
                height_normal::ideal((r[1] - r[0]) / 2.0, (r[2] - r[0]) / 2.0, k)
            }
            Filter::FourTap | Filter::Sobel | Filter::Prewitt => {
                let (cu, cv) = (cu - 0.5, cv - 0.5);
                let (i0, j0) = (cu.floor() as i64, cv.floor() as i64);
                let (fu, fv) = (cu - i0 as f64, cv - j0 as f64);
                let w = [(1.0 - fu) * (1.0 - fv), fu * (1.0 - fv), (1.0 - fu) * fv, fu * fv];
                let mut gb = [0.0; 2];
                for (q, (di, dj)) in [(0, 0), (1, 0), (0, 1), (1, 1)].into_iter().enumerate() {
                    let g = gradient(self, &map.window(i0 + di, j0 + dj));
                    gb[0] += w[q] * g[0];
                    gb[1] += w[q] * g[1];
                }
                let d = divisor(self) as f64;
                height_normal::ideal(gb[0] / d / 2.0, gb[1] / d / 2.0, k)
            }
            Filter::Trilinear => {
                let f = TRILINEAR_LOD as f64 / 256.0;
                let t0 = bspline_tangents(map, cu, cv);
                let t1 = bspline_tangents(level1, cu / 2.0, cv / 2.0);
                let t = [0, 1].map(|c| t0[c] + f * (t1[c] / 2.0 - t0[c]));
                height_normal::ideal(t[0], t[1], k)
            }
        }
    }
}

/// The tangents (half the B-spline's derivatives, height LSB) at a real coordinate.
fn bspline_tangents(map: &Grid<f64>, cu: f64, cv: f64) -> [f64; 2] {
    let (i, j) = (cu.floor() as i64, cv.floor() as i64);
    let (_, hu, hv) = height_pipeline::bspline(&map.window(i, j), cu - i as f64, cv - j as f64);
    [hu / 2.0, hv / 2.0]
}

/// Blinn's function on one window (texel k unread): the red, green and blue units at the plain factors (doubled
/// to the units' 9 bits, exact), then G − R and B − R, which are ∂H/∂u and ∂H/∂v with 17 fraction bits; the normal
/// unit takes half of each with 12 fraction bits: one arithmetic shift of 6, floor. `blinn_pipeline`'s model.
pub fn blinn_tangents(w: &[i64; 9], ub: i64, vb: i64) -> ([i64; 3], i64, i64) {
    let g = replicate::grids(w);
    let r: [i64; 3] =
        std::array::from_fn(|c| bilinear::exact_wide(g[c][0], g[c][1], g[c][2], g[c][3], 2 * ub, 2 * vb, B, D));
    let half = tangent::IN_FRAC - tangent::FRAC + 1;
    (r, truncate(r[1] - r[0], half), truncate(r[2] - r[0], half)) // S26 → S20, floor
}

pub fn blinn_exact(w: &[i64; 9], ub: i64, vb: i64, k: i64) -> [i64; 3] {
    let (_, t1, t2) = blinn_tangents(w, ub, vb);
    normalise::exact(height_normal::exact(t1, t2, k))
}

/// The preferred path on one window: `height_pipeline`.
pub fn bspline_exact(w: &[i64; 9], ub: i64, vb: i64, k: i64) -> [i64; 3] {
    height_pipeline::exact_trace(&[w.to_vec(), vec![ub, vb, k]].concat()).normal
}

/// The trilinear path's tangents (S21, 12 fraction bits): level 0's and level 1's (at the coordinate halved, floor;
/// its tangents halved, floor), blended by the LOD fraction `lod` (U8): t0 + (t1/2 − t0)·lod/256, floor.
pub fn trilinear_tangents(map: &Grid<i64>, level1: &Grid<i64>, cu: i64, cv: i64, lod: i64) -> (i64, i64) {
    let t = |g: &Grid<i64>, cu: i64, cv: i64| {
        let x =
            height_pipeline::exact_trace(&[g.window(cu >> 8, cv >> 8).to_vec(), vec![cu & 255, cv & 255, 16]].concat());
        (x.t1, x.t2)
    };
    let (a1, a2) = t(map, cu, cv);
    let (b1, b2) = t(level1, cu >> 1, cv >> 1); // the coordinate in level-1 texels: UQ8.8, floor
    let (b1, b2) = (b1 >> 1, b2 >> 1); // per level-0 texel: halved, floor
    (truncate(a1 * 256 + (b1 - a1) * lod, 8), truncate(a2 * 256 + (b2 - a2) * lod, 8))
    // S30 → S21, floor
}

/// Equation 1: the Bézier points of a 3×3 window of B-spline points, rounded half up to 8 bits.
pub fn bezier_points(w: &[i64; 9]) -> [i64; 9] {
    let at = |c: usize, r: usize| w[3 * r + c];
    // per axis the points (p0 + p1)/2, p1, (p1 + p2)/2: quarter sums at the corners, half sums on the edges
    let pair = |c: usize| [(0, 1), (1, 1), (1, 2)][c];
    std::array::from_fn(|p| {
        let ((c0, c1), (r0, r1)) = (pair(p % 3), pair(p / 3));
        let s = at(c0, r0) + at(c1, r0) + at(c0, r1) + at(c1, r1); // 4 × the point: U10, exact
        round_half_up(s, 2) // U10 → U8, round half up
    })
}

/// The derivative filter's two gradients (∂/∂x, ∂/∂y) at the centre of a 3×3 window, times `divisor`.
pub fn gradient<
    T: Copy + std::ops::Sub<Output = T> + std::ops::Add<Output = T> + std::ops::Mul<Output = T> + From<i32>,
>(
    f: Filter,
    w: &[T; 9],
) -> [T; 2] {
    let k = |c: i32| T::from(c);
    let [a, b, c, d, _, ff, g, h, kk] = *w;
    match f {
        Filter::FourTap => [ff - d, h - b],
        Filter::Sobel => [(c + k(2) * ff + kk) - (a + k(2) * d + g), (g + k(2) * h + kk) - (a + k(2) * b + c)],
        _ => [(c + ff + kk) - (a + d + g), (g + h + kk) - (a + b + c)],
    }
}

/// What the filter's gradient is a multiple of the derivative by.
pub fn divisor(f: Filter) -> i64 {
    match f {
        Filter::FourTap => 2,
        Filter::Sobel => 8,
        _ => 6,
    }
}

/// A square map, row-major, clamped at its borders.
pub struct Grid<'a, T> {
    pub side: usize,
    pub h: &'a [T],
}

impl<T: Copy> Grid<'_, T> {
    pub fn at(&self, x: i64, y: i64) -> T {
        let n = self.side as i64 - 1;
        self.h[(y.clamp(0, n) * (n + 1) + x.clamp(0, n)) as usize]
    }

    /// The 3×3 window a..k around texel (i, j).
    pub fn window(&self, i: i64, j: i64) -> [T; 9] {
        std::array::from_fn(|p| self.at(i + p as i64 % 3 - 1, j + p as i64 / 3 - 1))
    }
}

/// MIP level 1 of 8-bit codes: each 2×2 block's mean, rounded half up, in the same height units.
pub fn mip_exact(h: &[i64], side: usize) -> Vec<i64> {
    let s = side / 2;
    (0..s * s)
        .map(|q| {
            let (x, y) = (2 * (q % s), 2 * (q / s));
            // U10 → U8
            round_half_up(h[y * side + x] + h[y * side + x + 1] + h[(y + 1) * side + x] + h[(y + 1) * side + x + 1], 2)
        })
        .collect()
}

/// The same in reals.
pub fn mip_ideal(h: &[f64], side: usize) -> Vec<f64> {
    let s = side / 2;
    (0..s * s)
        .map(|q| {
            let (x, y) = (2 * (q % s), 2 * (q / s));
            (h[y * side + x] + h[y * side + x + 1] + h[(y + 1) * side + x] + h[(y + 1) * side + x + 1]) / 4.0
        })
        .collect()
}

/// ¶84: the B-spline's height itself, a third blend of the four units' results at the plain factors:
/// lerp(V, lerp(U, R, G), lerp(U, B, A)), each lerp floored back to the results' 17 fraction bits.
pub fn interpolated_height_exact(w: &[i64; 9], ub: i64, vb: i64) -> i64 {
    let rgba = height_pipeline::exact_trace(&[w.to_vec(), vec![ub, vb, 16]].concat()).rgba;
    let x0 = truncate(rgba[0] * 256 + (rgba[1] - rgba[0]) * ub, 8); // U33 → U25, floor
    let x1 = truncate(rgba[2] * 256 + (rgba[3] - rgba[2]) * ub, 8); // U33 → U25, floor
    truncate(x0 * 256 + (x1 - x0) * vb, 8) // U25: the height with 17 fraction bits, floor
}

/// The interpolated height against the B-spline's height in reals, over random windows and factors (height LSB).
pub fn interpolated_height_error(samples: usize, seed: u64) -> crate::stats::ErrorStats {
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut s = crate::stats::ErrorStats::default();
    for _ in 0..samples {
        let w: [i64; 9] = std::array::from_fn(|_| rng.gen_range(0..256));
        let (ub, vb) = (rng.gen_range(0..256), rng.gen_range(0..256));
        let e = interpolated_height_exact(&w, ub, vb) as f64 / (1 << tangent::IN_FRAC) as f64;
        let (h, ..) = height_pipeline::bspline(&w.map(|x| x as f64), ub as f64 / 256.0, vb as f64 / 256.0);
        s.add((e - h).abs(), || format!("{w:?}, ({ub}, {vb})"));
    }
    s
}

/// ¶87: one colour channel filtered by the bi-quadratic B-spline through the same units: the interpolated height of
/// the channel's 3×3 window (height-mode addressing), rounded half up to 8 bits.
pub fn bspline_colour_exact(w: &[i64; 9], ub: i64, vb: i64) -> i64 {
    round_half_up(interpolated_height_exact(w, ub, vb), tangent::IN_FRAC)
}

/// FIG. 8a against 8b on one map, for Blinn's function and the B-spline, each in reals: the largest jump across a
/// texel edge (x = i or z = j) of the shading's derivative across it, and of the cross tangent's derivative across
/// it (∂/∂x of the v tangent at a vertical edge, ∂/∂z of the u tangent at a horizontal one). One-sided differences at
/// `step` texels; a continuous derivative's jump shrinks with the step, a jump does not.
#[derive(Clone, Copy, Debug)]
pub struct Fig8 {
    pub blinn: (f64, f64),
    pub bspline: (f64, f64),
}

pub fn fig8(map: &Grid<f64>, k: f64, light: [f64; 3], step: f64) -> Fig8 {
    let k = k / (1 << height_normal::SCALE_FRAC) as f64;
    let blinn = |x: f64, z: f64| -> [f64; 2] {
        let (i, j) = (x.floor() as i64, z.floor() as i64);
        let g = replicate::grids(&map.window(i, j));
        let (u, v) = (x - i as f64, z - j as f64);
        let r: [f64; 3] = std::array::from_fn(|c| bilinear::ideal_channel(g[c][0], g[c][1], g[c][2], g[c][3], u, v));
        [(r[1] - r[0]) / 2.0, (r[2] - r[0]) / 2.0]
    };
    let spline = |x: f64, z: f64| bspline_tangents(map, x, z);
    let measure = |t: &dyn Fn(f64, f64) -> [f64; 2]| {
        let shade = |x: f64, z: f64| {
            let [t1, t2] = t(x, z);
            let n = height_normal::ideal(t1, t2, k);
            n[0] * light[0] + n[1] * light[1] + n[2] * light[2]
        };
        // the jump of f's derivative along (dx, dz) across the point
        let jump = |f: &dyn Fn(f64, f64) -> f64, x: f64, z: f64, dx: f64, dz: f64| {
            let (l, m, r) = (f(x - dx * step, z - dz * step), f(x, z), f(x + dx * step, z + dz * step));
            (((r - m) - (m - l)) / step).abs()
        };
        let (mut s, mut c) = (0.0f64, 0.0f64);
        let n = map.side as i64;
        for a in 2..n - 2 {
            for b in 3..n - 2 {
                let (along, edge) = (a as f64 + 0.37, b as f64);
                s = s.max(jump(&shade, edge, along, 1.0, 0.0)).max(jump(&shade, along, edge, 0.0, 1.0));
                c = c.max(jump(&|x, z| t(x, z)[1], edge, along, 1.0, 0.0)).max(jump(
                    &|x, z| t(x, z)[0],
                    along,
                    edge,
                    0.0,
                    1.0,
                ));
            }
        }
        (s, c)
    };
    Fig8 { blinn: measure(&blinn), bspline: measure(&spline) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    fn random_map(rng: &mut impl Rng, side: usize) -> Vec<i64> {
        (0..side * side).map(|_| rng.gen_range(0..256)).collect()
    }

    #[test]
    fn equation_1_is_the_b_spline_in_reals_and_its_points_are_the_seeds_matrices() {
        // the Bézier net from the matrices of equation 1, in reals, against the rounded integer one
        let w = [12, 200, 37, 90, 5, 255, 61, 140, 33];
        let m = [[0.5, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.5, 0.5]];
        let net = bezier_points(&w);
        for r in 0..3 {
            for c in 0..3 {
                let mut x = 0.0;
                for p in 0..3 {
                    for q in 0..3 {
                        x += m[r][p] * w[3 * p + q] as f64 * m[c][q]; // M · W · Mᵀ
                    }
                }
                assert!((net[3 * r + c] as f64 - x).abs() <= 0.5, "({r}, {c}): {} vs {x}", net[3 * r + c]);
            }
        }
        // de Casteljau on the real net at the plain factors gives the blend-adjusted results exactly
        let wf = w.map(|x| x as f64);
        let netf: [f64; 9] = std::array::from_fn(|p| {
            let pair = |c: usize| [(0, 1), (1, 1), (1, 2)][c];
            let ((c0, c1), (r0, r1)) = (pair(p % 3), pair(p / 3));
            (wf[3 * r0 + c0] + wf[3 * r0 + c1] + wf[3 * r1 + c0] + wf[3 * r1 + c1]) / 4.0
        });
        let (u, v) = (0.3, 0.8);
        let (gb, ga) = (replicate::grids(&netf), replicate::grids(&wf));
        let f =
            [(0.5 + u / 2.0, 0.5 + v / 2.0), (u / 2.0, 0.5 + v / 2.0), (0.5 + u / 2.0, v / 2.0), (u / 2.0, v / 2.0)];
        for c in 0..4 {
            let bez = bilinear::ideal_channel(gb[c][0], gb[c][1], gb[c][2], gb[c][3], u, v);
            let adj = bilinear::ideal_channel(ga[c][0], ga[c][1], ga[c][2], ga[c][3], f[c].0, f[c].1);
            assert!((bez - adj).abs() < 1e-9, "unit {c}: {bez} vs {adj}");
        }
    }

    #[test]
    fn bezier_agrees_with_blend_adjust_within_rounding() {
        // the count the note reports: how often the rounded Bézier points change the normal, and by how much
        let a = bezier_agreement(200_000, 3);
        assert!(a.same > 0 && a.same < a.samples, "{a:?}");
        assert!(a.mean_deg < 0.5 && a.max_deg < 20.0, "{a:?}");
    }

    #[test]
    fn the_interpolated_height_is_the_b_splines() {
        // two floors after the units' own: under 1/64 of a height LSB
        let s = interpolated_height_error(50_000, 9);
        assert!(s.max < 1.0 / 64.0, "{} at {}", s.max, s.argmax);
        // a flat window is its height exactly, at any factors
        assert_eq!(interpolated_height_exact(&[77; 9], 200, 13), 77 << tangent::IN_FRAC);
        assert_eq!(bspline_colour_exact(&[255; 9], 255, 255), 255);
    }

    #[test]
    fn blinns_tangents_are_the_differences_of_three_blends_and_need_no_k_texel() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(4);
        let map = random_map(&mut rng, 8);
        let g = Grid { side: 8, h: &map };
        let mut other = map.clone();
        other[5 * 8 + 5] = 255 - other[5 * 8 + 5]; // texel k of the window around (4, 4)
        let g2 = Grid { side: 8, h: &other };
        for (ub, vb) in [(0, 0), (255, 255), (17, 230)] {
            let (cu, cv) = (4 * 256 + ub, 4 * 256 + vb);
            assert_eq!(Filter::Blinn.exact(&g, &g, 16, cu, cv), Filter::Blinn.exact(&g2, &g2, 16, cu, cv));
            if ub * vb != 0 {
                // the B-spline's alpha unit weighs k by U/2 · V/2
                assert_ne!(Filter::BSpline.exact(&g, &g, 16, cu, cv), Filter::BSpline.exact(&g2, &g2, 16, cu, cv));
            }
        }
    }

    #[test]
    fn lod_fraction_0_is_the_finer_level_and_the_largest_is_nearly_the_coarser() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(6);
        let map = random_map(&mut rng, 16);
        let l1 = mip_exact(&map, 16);
        let (g0, g1) = (Grid { side: 16, h: &map }, Grid { side: 8, h: &l1 });
        for _ in 0..2_000 {
            let (cu, cv) = (rng.gen_range(256..15 * 256), rng.gen_range(256..15 * 256));
            let t0 = height_pipeline::exact_trace(
                &[g0.window(cu >> 8, cv >> 8).to_vec(), vec![cu & 255, cv & 255, 16]].concat(),
            );
            assert_eq!(trilinear_tangents(&g0, &g1, cu, cv, 0), (t0.t1, t0.t2));
            let t1 = height_pipeline::exact_trace(
                &[g1.window(cu >> 9, cv >> 9).to_vec(), vec![(cu >> 1) & 255, (cv >> 1) & 255, 16]].concat(),
            );
            let (a, b) = trilinear_tangents(&g0, &g1, cu, cv, 255);
            // 255/256 of the way: within 1/256 of the level-0 minus level-1 difference, plus the floors
            let near = |x: i64, lo: i64, hi: i64| (x - (hi >> 1)).abs() <= ((hi >> 1) - lo).abs() / 256 + 2;
            assert!(near(a, t0.t1, t1.t1) && near(b, t0.t2, t1.t2), "{a} {b} vs {} {}", t1.t1 >> 1, t1.t2 >> 1);
        }
    }

    #[test]
    fn every_filter_is_flat_on_a_flat_map_and_leans_away_from_a_slope() {
        let flat = vec![100i64; 64];
        let ramp: Vec<i64> = (0..64).map(|q| 10 * (q % 8) as i64).collect(); // rising along x
        let (gf, gr) = (Grid { side: 8, h: &flat }, Grid { side: 8, h: &ramp });
        let (lf, lr) = (mip_exact(&flat, 8), mip_exact(&ramp, 8));
        for f in ALL {
            assert_eq!(f.exact(&gf, &Grid { side: 4, h: &lf }, 16, 3 * 256 + 77, 4 * 256 + 200), [0, 1024, 0], "{f:?}");
            let n = f.exact(&gr, &Grid { side: 4, h: &lr }, 16, 3 * 256 + 128, 4 * 256 + 128);
            assert!(n[0] < 0 && n[2] == 0, "{f:?}: {n:?}");
        }
    }

    #[test]
    fn the_b_splines_cross_tangent_is_c1_and_blinns_is_not() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(8);
        let map: Vec<f64> = (0..16 * 16).map(|_| rng.gen_range(0.0..64.0)).collect();
        let g = Grid { side: 16, h: &map };
        let l = [0.6, 0.7, 0.3];
        let (a, b) = (fig8(&g, 16.0, l, 1e-3), fig8(&g, 16.0, l, 1e-4));
        // Blinn's cross tangent kinks at the edges (the jump stays as the step shrinks); the B-spline's does not
        assert!(b.blinn.1 > 0.5 * a.blinn.1 && a.blinn.1 > 0.1, "Blinn {a:?} → {b:?}");
        assert!(b.bspline.1 < 0.2 * a.bspline.1.max(1e-9) + 1e-6, "B-spline {a:?} → {b:?}");
        // both normals are only C0 along their own axis (a quadratic's second derivative jumps): the shading
        // derivative jumps for both
        assert!(b.blinn.0 > 0.05 && b.bspline.0 > 0.05, "{b:?}");
    }
}

/// Equation 1 against blend adjust on random windows and factors at the map's own relief (k = 1): how many
/// normals are identical, and the angle between the two where they are not. The Bézier points carry one or two more
/// bits than the 8-bit units take; rounded to 8 they move the normal a little.
#[derive(Clone, Copy, Debug)]
pub struct Agreement {
    pub samples: usize,
    pub same: usize,
    pub mean_deg: f64,
    pub max_deg: f64,
}

pub fn bezier_agreement(samples: usize, seed: u64) -> Agreement {
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut a = Agreement { samples, same: 0, mean_deg: 0.0, max_deg: 0.0 };
    for _ in 0..samples {
        let w: Vec<i64> = (0..9).map(|_| rng.gen_range(0..256)).collect();
        let g = Grid { side: 3, h: &w };
        let (cu, cv) = (256 + rng.gen_range(0..256), 256 + rng.gen_range(0..256));
        let (x, y) = (Filter::BSpline.exact(&g, &g, 16, cu, cv), Filter::Bezier.exact(&g, &g, 16, cu, cv));
        let d = crate::stats::angle_deg(x.map(|c| c as f64), y.map(|c| c as f64));
        a.same += (x == y) as usize;
        a.mean_deg += d / samples as f64;
        a.max_deg = a.max_deg.max(d);
    }
    a
}
