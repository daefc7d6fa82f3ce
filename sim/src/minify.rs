//! Minification, measured: the texture unit's filters on one scene against a supersampled f64 ideal. Each pixel's
//! ideal colour is the mean of `n × n` samples spread over its footprint on the map (the pixel's centre moved by
//! the screen derivatives of its position, on a regular grid), each sample the map's level 0 read bilinearly in f64
//! at that point, made unit length and lit by the pixel's light as the pipelines' ideal is. Against it, the colour
//! each filter's pipeline gives (the bit-exact model, which the rtl equals), over every pixel and over the minified
//! ones, where λ = log2 ρ of the pixel's own derivatives is above ½ (the nearest level is no longer level 0). The
//! MIP filters read λ plus the scene's LOD bias; `sweep` measures them over a range of biases. A polar scene's
//! ideal is lit as the polar pipeline's is (`Shading::Polar`), and its filters are the polar pipelines on the unit;
//! a palette scene's, as the Cartesian one at its C, through the palette pipelines on the unit (nearest, and the
//! nearest level of the index map's §5.2 chain).

use crate::pipeline::{build, gloss_shade, Pipeline};
use crate::pipelines::{self, Filter, Settings};
use crate::scene::Scene;
use vectors::stats::ErrorStats;

/// λ above which a pixel counts as minified.
pub const MINIFIED: f64 = 0.5;

/// The bands of λ the table splits the pixels into: each band's upper end (the last is open).
pub const BANDS: [f64; 4] = [0.5, 1.5, 2.5, f64::INFINITY];

/// The filters on the texture unit, each with the matte per-vertex pipeline that holds it.
pub const FILTERS: [(Filter, &str); 4] = [
    (Filter::Nearest, "cart_tex_nearest_matte"),
    (Filter::NearestMip, "cart_tex_nearest_mip_matte"),
    (Filter::Bilinear, "cart_tex_bilinear_matte"),
    (Filter::Trilinear, "cart_tex_trilinear_matte"),
];

/// The polar filters on the texture unit (US 6,819,319's angle scale: S and R filtered as numbers), each with its
/// pipeline.
pub const POLAR_FILTERS: [(Filter, &str); 2] =
    [(Filter::Bilinear, "polar_tex_bilinear"), (Filter::Trilinear, "polar_tex_trilinear")];

/// The palette filters on the texture unit (an index is never blended: the nearest texel, of level 0 or of the
/// nearest level, §5.2's), each with its pipeline.
pub const PALETTE_FILTERS: [(Filter, &str); 2] =
    [(Filter::Nearest, "palette_tex_nearest"), (Filter::NearestMip, "palette_tex_nearest_mip")];

/// How the ideal lights a normal n under the pixel's light l: the shade α, 0 … 255.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shading {
    /// the Cartesian pipelines': max(0, N·L) through the gloss unit's ideal at C (`gloss_shade`)
    Gloss(i64),
    /// the polar pipelines': max(0, (1 − h) + h·N·L)^p, p = pw / 4
    Polar { pw: i64, h: f64 },
    /// the palette pipelines': the Cartesian ideal at C (the palette's normals, its one light a frame and its
    /// point sampling are what its error counts), through pipelines that quantize to s_N normals
    Palette { conc: i64, s_n: usize },
}

impl Shading {
    /// The shading of a scene's pipeline family: polar for a polar pipeline (its power and weight), else the gloss
    /// unit's at the scene's C.
    pub fn of(spec: &crate::scene_file::SceneSpec) -> Shading {
        match spec.pipeline.family {
            pipelines::Family::Polar(_) => Shading::Polar { pw: spec.settings.pw, h: spec.settings.h },
            pipelines::Family::CartTex { host, .. }
                if matches!(pipelines::named(host).map(|h| h.family), Some(pipelines::Family::Polar(_))) =>
            {
                Shading::Polar { pw: spec.settings.pw, h: spec.settings.h }
            }
            pipelines::Family::Palette => Shading::Palette { conc: spec.scene.conc, s_n: palette_size(spec) },
            pipelines::Family::CartTex { host, .. }
                if pipelines::named(host).map(|h| h.family) == Some(pipelines::Family::Palette) =>
            {
                Shading::Palette { conc: spec.scene.conc, s_n: palette_size(spec) }
            }
            _ => Shading::Gloss(spec.scene.conc),
        }
    }

    pub fn alpha(self, n: [f64; 3], l: [f64; 3]) -> f64 {
        match self {
            Shading::Gloss(conc) | Shading::Palette { conc, .. } => gloss_shade(conc, n, l),
            Shading::Polar { pw, h } => crate::pipeline::polar_ideal(pw, h, n, l),
        }
    }

    /// The filters measured under this shading, each with its pipeline.
    pub fn filters(self) -> &'static [(Filter, &'static str)] {
        match self {
            Shading::Gloss(_) => &FILTERS,
            Shading::Polar { .. } => &POLAR_FILTERS,
            Shading::Palette { .. } => &PALETTE_FILTERS,
        }
    }

    /// What the pipelines are built with: the polar power and weight.
    fn settings(self) -> Settings {
        match self {
            Shading::Gloss(_) => Settings::default(),
            Shading::Polar { pw, h } => Settings { pw, h, ..Settings::default() },
            Shading::Palette { s_n, .. } => Settings { palette: Some(s_n), ..Settings::default() },
        }
    }
}

/// The scene's palette size s_N (256 where it names none: the texture unit's palette pipelines hold 8-bit indices).
fn palette_size(spec: &crate::scene_file::SceneSpec) -> usize {
    spec.settings.palette.unwrap_or(256)
}

/// The supersampled ideal of a frame, pixel by pixel in the pipelines' order.
pub struct Ideal {
    /// how each sample is lit, and so which filters are measured against it
    pub shading: Shading,
    /// the colour, 8-bit units, real
    pub rgb: Vec<[f64; 3]>,
    /// λ = log2 ρ of the pixel's derivatives (unclamped)
    pub lambda: Vec<f64>,
    /// each pixel's place in the frame
    pub at: Vec<usize>,
    /// each filter of `FILTERS` in f64 on the float MIP chain the unit's memory is loaded from (the method alone,
    /// without the texels' encoding or the datapath's widths): the colour, pixel by pixel
    pub method: [Vec<[f64; 3]>; 4],
}

/// The texel of a level of side `t` that holds the point x (texels of that level), repeating or clamped.
fn nearest(x: f64, t: usize, wrap: bool) -> usize {
    let i = x.floor() as i64;
    if wrap {
        i.rem_euclid(t as i64) as usize
    } else {
        i.clamp(0, t as i64 - 1) as usize
    }
}

/// The LOD biases `sweep` measures the MIP filters at, levels.
pub const SWEEP: [f64; 7] = [0.0, -0.25, -0.5, -0.75, -1.0, -1.25, -1.5];

/// The filter's normal in f64 at the pixel's centre: on level 0, or on the level(s) λ (clamped to the chain) names.
fn method(filter: Filter, chain: &[Vec<[f64; 3]>], t: usize, px: &crate::raster::Pixel, lambda: f64) -> [f64; 3] {
    let last = chain.len() - 1;
    let at = |k: usize| (px.pos[0] / (1u64 << k) as f64, px.pos[1] / (1u64 << k) as f64, t >> k);
    let texel = |k: usize| {
        let (x, y, side) = at(k);
        chain[k][nearest(y, side, px.wrap[1]) * side + nearest(x, side, px.wrap[0])]
    };
    let bilinear = |k: usize| {
        let (x, y, side) = at(k);
        sample(&chain[k], side, x, y, px.wrap)
    };
    let l = lambda.clamp(0.0, last as f64);
    match filter {
        Filter::Nearest => texel(0),
        Filter::NearestMip => texel(((l + 0.5).floor() as usize).min(last)),
        Filter::Bilinear => bilinear(0),
        Filter::Trilinear | Filter::TrilinearTwoPass => {
            let (k, f) = (l.floor() as usize, l - l.floor());
            if k >= last {
                return bilinear(last);
            }
            let (a, b) = (bilinear(k), bilinear(k + 1));
            crate::surface::unit(std::array::from_fn(|c| a[c] + (b[c] - a[c]) * f))
        }
    }
}

/// Level 0 of the map read bilinearly in f64 at (x, y) in texels (texel centres at k + ½), each axis repeating or
/// clamped, renormalised.
fn sample(normals: &[[f64; 3]], t: usize, x: f64, y: f64, wrap: [bool; 2]) -> [f64; 3] {
    let axis = |s: f64, wrap: bool| -> (usize, usize, f64) {
        let s = s - 0.5;
        if wrap {
            let f = s.floor();
            let i0 = (f as i64).rem_euclid(t as i64) as usize;
            (i0, (i0 + 1) % t, s - f)
        } else {
            let s = s.clamp(0.0, (t - 1) as f64);
            let i0 = (s.floor() as usize).min(t - 1);
            (i0, (i0 + 1).min(t - 1), s - i0 as f64)
        }
    };
    let ((i0, i1, fu), (j0, j1, fv)) = (axis(x, wrap[0]), axis(y, wrap[1]));
    let n = |i: usize, j: usize| normals[j * t + i];
    let m: [f64; 3] = std::array::from_fn(|c| {
        (1.0 - fv) * ((1.0 - fu) * n(i0, j0)[c] + fu * n(i1, j0)[c])
            + fv * ((1.0 - fu) * n(i0, j1)[c] + fu * n(i1, j1)[c])
    });
    crate::surface::unit(m)
}

/// The scene's supersampled ideal with `n × n` samples a pixel, lit as the Cartesian pipelines are at the scene's C.
pub fn ideal(scene: &Scene, n: usize) -> Ideal {
    ideal_shaded(scene, n, Shading::Gloss(scene.conc))
}

/// The scene's supersampled ideal with `n × n` samples a pixel, each sample lit by `shading`.
pub fn ideal_shaded(scene: &Scene, n: usize, shading: Shading) -> Ideal {
    let normals = scene.normals();
    let t = scene.tex;
    let frame = crate::raster::frame(scene, &normals);
    let chain = crate::pipeline::mip_chain(&normals, t);
    let mut out = Ideal { shading, rgb: vec![], lambda: vec![], at: vec![], method: Default::default() };
    for px in &frame.pixels {
        let d = px.deriv; // du/dx, dv/dx, du/dy, dv/dy in texels of level 0
        let mut rgb = [0.0; 3];
        for sy in 0..n {
            for sx in 0..n {
                let (ox, oy) = ((sx as f64 + 0.5) / n as f64 - 0.5, (sy as f64 + 0.5) / n as f64 - 0.5);
                let (x, y) = (px.pos[0] + d[0] * ox + d[2] * oy, px.pos[1] + d[1] * ox + d[3] * oy);
                let c = scene.blend_ideal(shading.alpha(sample(&normals, t, x, y, px.wrap), px.light));
                for k in 0..3 {
                    rgb[k] += c[k] / (n * n) as f64;
                }
            }
        }
        let rho = (d[0] * d[0] + d[1] * d[1]).sqrt().max((d[2] * d[2] + d[3] * d[3]).sqrt());
        out.rgb.push(rgb);
        out.lambda.push(rho.log2());
        out.at.push(px.at);
    }
    out.method = methods(scene, &frame, &chain, shading);
    out
}

/// Each filter of `FILTERS` in f64 on the float chain, pixel by pixel, the MIP filters at λ plus the scene's bias,
/// lit by `shading`.
fn methods(
    scene: &Scene,
    frame: &crate::raster::Frame,
    chain: &[Vec<[f64; 3]>],
    shading: Shading,
) -> [Vec<[f64; 3]>; 4] {
    std::array::from_fn(|k| {
        let f = FILTERS[k].0;
        let bias = if f.front().mip() { scene.lod_bias } else { 0.0 };
        frame
            .pixels
            .iter()
            .map(|px| {
                let d = px.deriv;
                let rho = (d[0] * d[0] + d[1] * d[1]).sqrt().max((d[2] * d[2] + d[3] * d[3]).sqrt());
                let n = method(f, chain, scene.tex, px, rho.log2() + bias);
                scene.blend_ideal(shading.alpha(n, px.light))
            })
            .collect()
    })
}

/// One bias of the sweep: the MIP filters' mean error on the minified pixels, the pipeline's and the f64 method's,
/// in `FILTERS`' order (None for the filters without a level of detail, or without a pipeline under the ideal's
/// shading).
pub struct Swept {
    pub bias: f64,
    pub hardware: [Option<f64>; 4],
    pub method: [Option<f64>; 4],
}

/// The MIP filters at each bias of `SWEEP`, against the same supersampled ideal (`ideal`, made for `scene`).
pub fn sweep(scene: &Scene, ideal: &Ideal) -> Result<Vec<Swept>, String> {
    let normals = scene.normals();
    let frame = crate::raster::frame(scene, &normals);
    let chain = crate::pipeline::mip_chain(&normals, scene.tex);
    let measured = ideal.shading.filters();
    let mip: Vec<usize> = (0..FILTERS.len())
        .filter(|&k| FILTERS[k].0.front().mip() && measured.iter().any(|f| f.0 == FILTERS[k].0))
        .collect();
    let mut out = vec![];
    for bias in SWEEP {
        let biased = Scene { lod_bias: bias, ..scene.clone() };
        let at = Ideal {
            shading: ideal.shading,
            rgb: ideal.rgb.clone(),
            lambda: ideal.lambda.clone(),
            at: ideal.at.clone(),
            method: methods(&biased, &frame, &chain, ideal.shading),
        };
        let lines = measure_only(&biased, &at, &mip)?;
        let (mut hardware, mut method) = ([None; 4], [None; 4]);
        for (l, &k) in lines.iter().zip(&mip) {
            (hardware[k], method[k]) = (Some(l.minified.mean()), Some(l.method_minified.mean()));
        }
        out.push(Swept { bias, hardware, method });
    }
    Ok(out)
}

/// One filter's colour error against the supersampled ideal.
pub struct Line {
    pub filter: Filter,
    pub pipeline: &'static str,
    pub all: ErrorStats,
    pub minified: ErrorStats,
    /// by band of λ (`BANDS`)
    pub bands: Vec<ErrorStats>,
    /// the filter in f64 (`Ideal::method`) against the same ideal, every pixel and the minified ones
    pub method_all: ErrorStats,
    pub method_minified: ErrorStats,
    /// the frame's colours, place by place (None off the surface)
    pub frame: Vec<Option<[u8; 3]>>,
    /// the worst channel's error against the ideal, place by place
    pub error: Vec<Option<f64>>,
}

/// Every filter of the ideal's shading (`Shading::filters`: for the Cartesian one the scene's gloss must be 0, the
/// filters' pipelines being matte) on the scene against `ideal`.
pub fn measure(scene: &Scene, ideal: &Ideal) -> Result<Vec<Line>, String> {
    let which: Vec<usize> = ideal
        .shading
        .filters()
        .iter()
        .map(|f| FILTERS.iter().position(|g| g.0 == f.0).expect("a filter of FILTERS"))
        .collect();
    measure_only(scene, ideal, &which)
}

/// The filters `FILTERS[k]` for each k of `which` (through the ideal's shading's pipelines), as `measure`.
pub fn measure_only(scene: &Scene, ideal: &Ideal, which: &[usize]) -> Result<Vec<Line>, String> {
    if matches!(ideal.shading, Shading::Gloss(_)) && scene.conc != 0 {
        return Err(format!(
            "the minification table runs the matte pipelines: the scene's gloss is {}, not 0",
            scene.conc
        ));
    }
    let mut lines = vec![];
    for &i in which {
        let filter = FILTERS[i].0;
        let name = ideal
            .shading
            .filters()
            .iter()
            .find(|f| f.0 == filter)
            .map(|f| f.1)
            .ok_or_else(|| format!("no pipeline filters {} under this shading", filter.name()))?;
        let row = pipelines::named(name).ok_or_else(|| format!("no pipeline {name}"))?;
        if !row.renders(scene) {
            return Err(format!("{name} cannot render this scene (the texture unit holds maps of side 1, 2, 4 … 128)"));
        }
        let p: Box<dyn Pipeline> = build(row, scene, &ideal.shading.settings());
        let prep = p.prepare(scene);
        let img = crate::render::model(p.model(), &prep);
        assert_eq!(img.outs.len(), ideal.rgb.len(), "{name}: the pipeline's pixels and the ideal's");
        let (mut all, mut minified) = (ErrorStats::default(), ErrorStats::default());
        let mut bands = vec![ErrorStats::default(); BANDS.len()];
        let (mut method_all, mut method_minified) = (ErrorStats::default(), ErrorStats::default());
        let size = scene.size;
        let (mut frame, mut error) = (vec![None; size * size], vec![None; size * size]);
        for (k, out) in img.outs.iter().enumerate() {
            let c = p.colour(out);
            let e = crate::render::colour_err(c, ideal.rgb[k]);
            let at = ideal.at[k];
            let place = || crate::render::pixel_at(size)(at);
            all.add(e, place);
            if ideal.lambda[k] > MINIFIED {
                minified.add(e, place);
            }
            let m = (0..3).map(|c| (ideal.method[i][k][c] - ideal.rgb[k][c]).abs()).fold(0.0, f64::max);
            method_all.add(m, place);
            if ideal.lambda[k] > MINIFIED {
                method_minified.add(m, place);
            }
            let band = BANDS.iter().position(|&hi| ideal.lambda[k] <= hi).unwrap_or(BANDS.len() - 1);
            bands[band].add(e, place);
            (frame[at], error[at]) = (Some(c), Some(e));
        }
        lines.push(Line { filter, pipeline: name, all, minified, bands, method_all, method_minified, frame, error });
    }
    Ok(lines)
}
