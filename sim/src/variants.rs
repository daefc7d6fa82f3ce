//! US 2004/0207631's variants as pictures: FIG. 8a against 8b (the same coarse height map shaded through Blinn's
//! function
//! and through the B-spline, both bit-exact models), and ¶87's bi-quadratic B-spline colour filtering beside the
//! ordinary bilinear colour filter on the same texture, each against an f64 reference.

use vectors::height::filters::{self, Filter, Grid};
use vectors::stats::{unit, ErrorStats};

/// The FIG. 8 map's side: coarse, so that each method's texel grid shows when magnified.
pub const FIG8_TEXELS: usize = 16;

/// The FIG. 8 light: low, from +x and a little +z.
pub const FIG8_LIGHT: [f64; 3] = [0.77, 0.5, 0.4];

/// The demo's procedural heights on a coarse map: the codes (8-bit) and scale, and the same heights in reals.
pub fn fig8_map(relief: f64) -> (Vec<i64>, i64, Vec<f64>) {
    let n = FIG8_TEXELS;
    let h: Vec<f64> = (0..n * n)
        .map(|k| crate::scene::height(((k % n) as f64 + 0.5) / n as f64, ((k / n) as f64 + 0.5) / n as f64) * relief)
        .collect();
    let (lo, hi) = h.iter().fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
    let (codes, k) = vectors::height_normal::encode_heights(&h, lo, hi);
    let m = 16.0 / k as f64;
    (codes, k, h.iter().map(|x| (x - lo) * 4.0 * m).collect())
}

pub struct Fig8 {
    /// N·L of Blinn's function and of the B-spline, bit-exact models, one value per pixel (0..=255)
    pub blinn: Vec<u8>,
    pub bspline: Vec<u8>,
    /// the methods in reals on the same map: the jumps of `filters::fig8`
    pub jumps: filters::Fig8,
}

/// The coarse map magnified to `size` × `size` pixels through both methods.
pub fn fig8(size: usize, relief: f64) -> Fig8 {
    let (codes, k, real) = fig8_map(relief);
    let n = FIG8_TEXELS;
    let g = Grid { side: n, h: &codes };
    let light = unit(FIG8_LIGHT);
    let shade = |f: Filter| -> Vec<u8> {
        (0..size * size)
            .map(|p| {
                let coord = |q: usize| (((q as f64 + 0.5) / size as f64 * n as f64) * 256.0) as i64; // UQ8.8, truncated
                let nrm = f.exact(&g, &g, k, coord(p % size), coord(p / size)).map(|c| c as f64 / 1024.0);
                (255.0 * (nrm[0] * light[0] + nrm[1] * light[1] + nrm[2] * light[2]).max(0.0)).round() as u8
            })
            .collect()
    };
    Fig8 {
        blinn: shade(Filter::Blinn),
        bspline: shade(Filter::BSpline),
        jumps: filters::fig8(&Grid { side: n, h: &real }, k as f64, light, 1e-4),
    }
}

/// The colour texture's side, texels.
pub const COLOUR_TEXELS: usize = 16;

/// A smooth procedural RGBA picture over [0, 1]²: the f64 reference the texture is sampled from.
pub fn colour_reference(u: f64, v: f64) -> [f64; 4] {
    let t = std::f64::consts::TAU;
    [
        127.5 + 110.0 * (t * (1.3 * u + 0.2 * v)).sin(),
        127.5 + 110.0 * (t * (0.4 * u - 1.1 * v) + 1.0).cos(),
        127.5 + 100.0 * (t * 2.0 * u).sin() * (t * 1.5 * v).sin(),
        255.0,
    ]
}

pub struct Colour {
    pub reference: Vec<[u8; 3]>,
    pub bilinear: Vec<[u8; 3]>,
    pub bspline: Vec<[u8; 3]>,
    /// each exact filter against the reference picture, and against its own method in reals, 8-bit LSB per channel
    pub bilinear_vs_reference: ErrorStats,
    pub bspline_vs_reference: ErrorStats,
    pub bilinear_vs_own: ErrorStats,
    pub bspline_vs_own: ErrorStats,
}

/// A 16 × 16 texture of the reference, magnified to `size` pixels through the colour filter (colour-mode
/// addressing, `bilinear`) and through the B-spline (height-mode addressing, the four units per channel plus the
/// third blend), clamped at the borders.
pub fn colour(size: usize) -> Colour {
    let n = COLOUR_TEXELS;
    let tex: Vec<[i64; 4]> = (0..n * n)
        .map(|q| {
            colour_reference(((q % n) as f64 + 0.5) / n as f64, ((q / n) as f64 + 0.5) / n as f64)
                .map(|c| c.round().clamp(0.0, 255.0) as i64)
        })
        .collect();
    let channel = |c: usize| -> Vec<i64> { tex.iter().map(|t| t[c]).collect() };
    let chans: Vec<Vec<i64>> = (0..3).map(channel).collect();
    let to8 = |x: f64| x.round().clamp(0.0, 255.0) as u8;
    let mut out = Colour {
        reference: vec![],
        bilinear: vec![],
        bspline: vec![],
        bilinear_vs_reference: ErrorStats::default(),
        bspline_vs_reference: ErrorStats::default(),
        bilinear_vs_own: ErrorStats::default(),
        bspline_vs_own: ErrorStats::default(),
    };
    for p in 0..size * size {
        let (x, z) = ((p % size) as f64 + 0.5, (p / size) as f64 + 0.5);
        let (u, v) = (x / size as f64, z / size as f64);
        let (cu, cv) = ((u * n as f64 * 256.0) as i64, (v * n as f64 * 256.0) as i64); // UQ8.8 texels, truncated
        let reference = colour_reference(u, v);
        let (mut bl, mut bs) = ([0u8; 3], [0u8; 3]);
        for c in 0..3 {
            let g = Grid { side: n, h: &chans[c] };
            // the colour filter: half a texel back, the four texels around, clamped
            let (ci, cj) = (cu - 128, cv - 128);
            let (i0, fu, j0, fv) = (ci >> 8, ci & 255, cj >> 8, cj & 255);
            let t = [g.at(i0, j0), g.at(i0 + 1, j0), g.at(i0, j0 + 1), g.at(i0 + 1, j0 + 1)];
            let e = vectors::bilinear::exact_channel(t[0], t[1], t[2], t[3], fu, fv, vectors::bilinear::F);
            let own = vectors::bilinear::ideal_channel(
                t[0] as f64,
                t[1] as f64,
                t[2] as f64,
                t[3] as f64,
                fu as f64 / 256.0,
                fv as f64 / 256.0,
            );
            let at = || format!("pixel ({}, {}), channel {c}", p % size, p / size);
            out.bilinear_vs_reference.add((e as f64 - reference[c]).abs(), at);
            out.bilinear_vs_own.add((e as f64 - own).abs(), at);
            bl[c] = e as u8;
            // the B-spline: the window around (i, j), the factors as they are
            let w = g.window(cu >> 8, cv >> 8);
            let s = filters::bspline_colour_exact(&w, cu & 255, cv & 255);
            let (own, ..) = vectors::height_pipeline::bspline(
                &w.map(|x| x as f64),
                (cu & 255) as f64 / 256.0,
                (cv & 255) as f64 / 256.0,
            );
            out.bspline_vs_reference.add((s as f64 - reference[c]).abs(), at);
            out.bspline_vs_own.add((s as f64 - own).abs(), at);
            bs[c] = s as u8;
        }
        out.reference.push([0, 1, 2].map(|c| to8(reference[c])));
        out.bilinear.push(bl);
        out.bspline.push(bs);
    }
    out
}
