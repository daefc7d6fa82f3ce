//! `bumprtl report`: the design knobs swept over scenes, each point's error beside its cost.
//!
//! A point is one configuration on one scene: a pipeline the project builds (the encoding, the light per vertex or
//! per surface, the gloss unit or none, bilinear or the nearest texel, the palette's size), or a Cartesian
//! pipeline with one of its units at another of its swept widths (the normaliser's table and Newton steps, the
//! bilinear units' blend-factor bits). For each point:
//! - the error against the scene's f64 ideal: the blended colour and the shade in 8-bit LSB, the normal's angle;
//!   split three ways (a palette texel's code is its index: the quantization is its encoding; a height map's
//!   parts are taken through its B-spline, see `height_parts`), each the mean (and max) of a shade difference, 8-bit LSB:
//!   **encoding** (the texel codes read as the directions they mean, filtered as the ideal filters, against the
//!   ideal), **method** (the pipeline's own method in reals on those codes, against the codes read as directions:
//!   filtering codes rather than normals, one light per surface, the nearest texel) and **datapath** (the bit-exact
//!   model against that float run: the hardware's arithmetic);
//! - the cost: yosys cells for the iCE40 family (products beyond the UP5K's 8 SB_MAC16 in logic) and, unless
//!   skipped, placement on the part the unit fits (logic cells, fmax); a width knob's cost is the pipeline's own
//!   plus the swept unit's difference in cells (marked `est.`), since the pipeline is built at the units' own
//!   widths; the model's pixels per second.
//!
//! Every point is independent: `--point ID` computes one and saves it, `--merge DIR` reads the saved points and
//! writes the report, and `--plan` writes both as commands (GNU parallel, ssh, a Slurm job array).

use sim::pipeline::{Height, Pipeline, Prepared};
use sim::pipelines::{self, Family, Row, Settings, PIPELINES};
use sim::scene::Scene;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;
use vectors::cart_pipeline::Decode;
use vectors::cart_surface::{Knobs, Variant, UNIT_KNOBS};
use vectors::polar_encode::Scale;
use vectors::stats::ErrorStats;

/// The cost scalar the Pareto set and the budgets rank by: iCE40 SB_LUT4 plus this many per SB_MAC16. Measured on
/// this flow: moving ten of cart_surface_matte's products from SB_MAC16 blocks into logic added 2,648 SB_LUT4.
pub const LUT4_PER_MAC16: u64 = 265;

/// A pipeline of the table, as a report point builds it: the row, and the height map's bits (8, or 4 read doubled:
/// the same block; a point of its own). The polar pipelines are built at a scene's default power and weight, the
/// palette ones at their largest palette.
fn build(p: &Point, scene: &Scene) -> Box<dyn Pipeline> {
    sim::pipeline::build(p.row, scene, &settings(p))
}

fn settings(p: &Point) -> Settings {
    Settings { height_bits: p.height_bits, ..Settings::default() }
}

/// The scenes a report sweeps when none are named: the demo's torus and the quad.
pub const DEFAULT_SCENES: [&str; 2] = ["demo", "quad"];

/// A scene by the name a point carries: `demo` and `quad` are the embedded ones, anything else a scene file.
pub fn scene(name: &str) -> Result<Scene, String> {
    match name {
        "demo" => crate::demo::demo_scene(),
        "quad" => crate::demo::quad_scene(),
        path => Ok(sim::scene_file::load(Path::new(path))?.scene),
    }
}

/// The knob settings swept on the Cartesian pipeline with one light per surface, beside its own.
fn knob_settings() -> Vec<Knobs> {
    let n = |table_bits, newton| Knobs { table_bits, newton, ..UNIT_KNOBS };
    let b = |blend_bits, drop| Knobs { blend_bits, drop, ..UNIT_KNOBS };
    vec![n(6, 0), n(6, 1), n(8, 0), n(12, 0), b(6, 0), b(4, 0), b(8, 4)]
}

fn knob_text(k: Knobs) -> String {
    if k == UNIT_KNOBS {
        return "-".into();
    }
    let mut s = vec![];
    if (k.table_bits, k.newton) != (UNIT_KNOBS.table_bits, UNIT_KNOBS.newton) {
        s.push(format!("normalise 2^{} table, {} Newton", k.table_bits, k.newton));
    }
    if (k.blend_bits, k.drop) != (UNIT_KNOBS.blend_bits, UNIT_KNOBS.drop) {
        s.push(format!("bilinear {} blend bits, {} dropped", k.blend_bits, k.drop));
    }
    s.join("; ")
}

fn knob_id(k: Knobs) -> String {
    format!("t{}n{}f{}d{}", k.table_bits, k.newton, k.blend_bits, k.drop)
}

/// One point of the sweep.
#[derive(Clone, Debug)]
pub struct Point {
    pub id: String,
    pub scene: String,
    pub row: &'static Row,
    /// the height map's bits (8 but on the 4-bit point)
    pub height_bits: u32,
    pub knobs: Knobs,
    /// the polar shading unit's elevation table, 2^lut entries (the unit's own: `sincos::TABLE_BITS`)
    pub lut: u32,
}

/// The polar elevation table sizes swept beside the unit's 2^8 (those `SinCos<tb, 8>` is built at).
const LUT_SETTINGS: [u32; 1] = [6];
const OWN_LUT: u32 = vectors::sincos::TABLE_BITS;

/// Every point for these scenes, in the report's order.
pub fn points(scenes: &[String]) -> Result<Vec<Point>, String> {
    let mut out = vec![];
    for name in scenes {
        let s = scene(name)?;
        let key = scene_key(name);
        for row in PIPELINES.iter().filter(|r| r.renders(&s)) {
            // the 4-bit map runs on the same block: its own point, its own id
            let heights: &[u32] = if row.family == Family::Height { &[8, 4] } else { &[8] };
            for &height_bits in heights {
                let bits = if height_bits == 4 { ".h4" } else { "" };
                out.push(Point {
                    id: format!("{key}.{}{bits}", row.name),
                    scene: name.clone(),
                    row,
                    height_bits,
                    knobs: UNIT_KNOBS,
                    lut: OWN_LUT,
                });
            }
        }
        // the width knobs, on the smallest bilinear pipeline the material allows
        let v = Variant { decode: Decode::Seed, nearest: false, gloss: s.conc != 0 };
        for k in knob_settings() {
            out.push(Point {
                id: format!("{key}.{}.{}", v.model().name, knob_id(k)),
                scene: name.clone(),
                row: surface_row(v),
                height_bits: 8,
                knobs: k,
                lut: OWN_LUT,
            });
        }
        // the sin/cos table's size, on the polar pipeline
        for tb in LUT_SETTINGS {
            out.push(Point {
                id: format!("{key}.polar_pipeline.lut{tb}"),
                scene: name.clone(),
                row: polar_row(),
                height_bits: 8,
                knobs: UNIT_KNOBS,
                lut: tb,
            });
        }
    }
    Ok(out)
}

/// The row of the Cartesian pipeline with one light per surface of this variant.
fn surface_row(v: Variant) -> &'static Row {
    pipelines::choose(&pipelines::surface(v)).expect("every surface variant has its pipeline")
}

/// The row of the seed's polar pipeline.
fn polar_row() -> &'static Row {
    pipelines::choose(&pipelines::polar(Scale::Seed)).expect("the polar pipeline is in the table")
}

fn scene_key(name: &str) -> String {
    Path::new(name).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| name.to_string())
}

/// What a point measured: everything the report prints, saved as `key=value` lines.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Result_ {
    pub id: String,
    pub scene: String,
    pub pipeline: String,
    pub units: String,
    pub knob: String,
    pub pixels: usize,
    /// (mean, max): blended colour, shade, normal angle (degrees), and the shade split three ways
    pub colour: (f64, f64),
    pub shade: (f64, f64),
    pub angle: Option<(f64, f64)>,
    pub encoding: Option<(f64, f64)>,
    pub method: Option<(f64, f64)>,
    pub datapath: Option<(f64, f64)>,
    pub model_mpx: f64,
    pub part: String,
    pub lut4: u64,
    pub ff: u64,
    pub dsp: u64,
    pub bram: u64,
    pub soft: u64,
    pub estimated: bool,
    pub lc: Option<u64>,
    pub fmax: Option<f64>,
    pub latency: usize,
}

impl Result_ {
    pub fn cost(&self) -> u64 {
        self.lut4 + LUT4_PER_MAC16 * self.dsp
    }

    pub fn to_text(&self) -> String {
        let p = |x: Option<(f64, f64)>| x.map(|(a, b)| format!("{a} {b}")).unwrap_or_default();
        let o = |x: Option<String>| x.unwrap_or_default();
        let mut s = String::new();
        for (k, v) in [
            ("id", self.id.clone()),
            ("scene", self.scene.clone()),
            ("pipeline", self.pipeline.clone()),
            ("units", self.units.clone()),
            ("knob", self.knob.clone()),
            ("pixels", self.pixels.to_string()),
            ("colour", p(Some(self.colour))),
            ("shade", p(Some(self.shade))),
            ("angle", p(self.angle)),
            ("encoding", p(self.encoding)),
            ("method", p(self.method)),
            ("datapath", p(self.datapath)),
            ("model_mpx", self.model_mpx.to_string()),
            ("part", self.part.clone()),
            ("lut4", self.lut4.to_string()),
            ("ff", self.ff.to_string()),
            ("dsp", self.dsp.to_string()),
            ("bram", self.bram.to_string()),
            ("soft", self.soft.to_string()),
            ("estimated", self.estimated.to_string()),
            ("lc", o(self.lc.map(|x| x.to_string()))),
            ("fmax", o(self.fmax.map(|x| x.to_string()))),
            ("latency", self.latency.to_string()),
        ] {
            let _ = writeln!(s, "{k}={v}");
        }
        s
    }

    pub fn from_text(text: &str) -> Option<Result_> {
        let get = |k: &str| text.lines().find_map(|l| l.strip_prefix(k).and_then(|r| r.strip_prefix('=')));
        let pair = |k: &str| -> Option<Option<(f64, f64)>> {
            let v = get(k)?;
            if v.is_empty() {
                return Some(None);
            }
            let mut f = v.split(' ').map(|x| x.parse::<f64>());
            Some(Some((f.next()?.ok()?, f.next()?.ok()?)))
        };
        let num = |k: &str| get(k)?.parse::<u64>().ok();
        Some(Result_ {
            id: get("id")?.into(),
            scene: get("scene")?.into(),
            pipeline: get("pipeline")?.into(),
            units: get("units")?.into(),
            knob: get("knob")?.into(),
            pixels: get("pixels")?.parse().ok()?,
            colour: pair("colour")??,
            shade: pair("shade")??,
            angle: pair("angle")?,
            encoding: pair("encoding")?,
            method: pair("method")?,
            datapath: pair("datapath")?,
            model_mpx: get("model_mpx")?.parse().ok()?,
            part: get("part")?.into(),
            lut4: num("lut4")?,
            ff: num("ff")?,
            dsp: num("dsp")?,
            bram: num("bram")?,
            soft: num("soft")?,
            estimated: get("estimated")? == "true",
            lc: get("lc").filter(|v| !v.is_empty()).and_then(|v| v.parse().ok()),
            fmax: get("fmax").filter(|v| !v.is_empty()).and_then(|v| v.parse().ok()),
            latency: get("latency")?.parse().ok()?,
        })
    }
}

fn stats(s: &ErrorStats) -> (f64, f64) {
    (s.mean(), s.max)
}

/// The split of a pipeline's shade error (8-bit units): encoding (the codes read as the directions they mean,
/// filtered as the ideal filters, shaded by the ideal's own curve `curve(n, l)`, against the ideal), method (the
/// pipeline's method in reals on those codes, `float(input)`, against the codes' meaning) and datapath (the model
/// against that float run).
fn split(
    scene: &Scene,
    meaning: &[[f64; 3]],
    prep: &Prepared,
    exact_shade: &[f64],
    curve: &dyn Fn([f64; 3], [f64; 3]) -> f64,
    float: &dyn Fn(&[i64]) -> f64,
) -> [(f64, f64); 3] {
    let frame = sim::raster::frame(scene, meaning);
    let (mut e, mut m, mut d) = (ErrorStats::default(), ErrorStats::default(), ErrorStats::default());
    for (k, px) in frame.pixels.iter().enumerate() {
        let s_enc = curve(px.normal, px.light);
        let s_float = float(&prep.pixels()[k]);
        e.add((s_enc - prep.ideal[k].shade).abs(), || format!("pixel {k}"));
        m.add((s_float - s_enc).abs(), || format!("pixel {k}"));
        d.add((exact_shade[k] - s_float).abs(), || format!("pixel {k}"));
    }
    [stats(&e), stats(&m), stats(&d)]
}

/// What each texel's Cartesian code means, as a unit vector.
fn cartesian_meaning(scene: &Scene, decode: Decode) -> Vec<[f64; 3]> {
    use vectors::cart_encode::{self, Encoder};
    let enc = if decode == Decode::Seed { Encoder::Seed } else { Encoder::HemiOct };
    scene
        .normals()
        .iter()
        .map(|&n| {
            let t = cart_encode::encode(enc, n);
            match decode {
                Decode::Seed => vectors::cart_decode::ideal(t.0, t.1),
                Decode::HemiOct => vectors::cart_decode_hemi_oct::ideal(t.0, t.1),
            }
        })
        .collect()
}

/// The three parts for the pipelines that have a float run of their method: the Cartesian ones (N·L through the
/// gloss curve) and the polar one (equation 3 on its own codes, then p's power, both in reals).
fn three_parts(p: &Point, scene: &Scene, prep: &Prepared, exact_shade: &[f64]) -> Option<[(f64, f64); 3]> {
    let gloss = |n: [f64; 3], l: [f64; 3]| sim::pipeline::gloss_shade(scene.conc, n, l);
    let p10 = |p: f64| p / 1023.0 * 255.0;
    let own = settings(p);
    match p.row.family {
        Family::Cartesian(d) => {
            let g = p.row.serves.gloss;
            // a matte pipeline's vectors are the full one's without C (which is 0)
            let float = |i: &[i64]| {
                let full = if g { i.to_vec() } else { vectors::cart_pipeline::with_zero_conc(i) };
                p10(vectors::cart_pipeline::float_p(d, &full))
            };
            Some(split(scene, &cartesian_meaning(scene, d), prep, exact_shade, &gloss, &float))
        }
        Family::CartSurface(v) => {
            Some(split(scene, &cartesian_meaning(scene, v.decode), prep, exact_shade, &gloss, &|i| {
                p10(vectors::cart_surface::float_p(v, i))
            }))
        }
        Family::Polar(sc) => {
            use vectors::polar_encode;
            use vectors::polar_pipeline::input;
            let meaning: Vec<[f64; 3]> = scene
                .normals()
                .iter()
                .map(|&n| {
                    let (s, r) = polar_encode::encode_normal(sc, n);
                    polar_encode::decode_normal(sc, s, r)
                })
                .collect();
            let (h, p) = (own.h, own.pw as f64 / 4.0);
            let curve = |n: [f64; 3], l: [f64; 3]| {
                255.0 * ((1.0 - h) + h * (n[0] * l[0] + n[1] * l[1] + n[2] * l[2])).clamp(0.0, 1.0).powf(p)
            };
            let float = |i: &[i64]| {
                let own = vectors::polar_shade::ideal(
                    sc,
                    i[input::s],
                    i[input::r],
                    i[input::q],
                    i[input::k1],
                    i[input::k2],
                    i[input::k3],
                )
                .clamp(0.0, 255.0);
                vectors::power::ideal_real(own, i[input::pw])
            };
            Some(split(scene, &meaning, prep, exact_shade, &curve, &float))
        }
        Family::Height => Some(height_parts(scene, own.height_bits, prep, exact_shade)),
        Family::Palette => {
            let s_n = own.palette.unwrap_or(1 << p.row.serves.index_bits);
            // a texel's index means its entry: the S10 code the table builder takes, as a unit vector
            let normals = scene.normals();
            let q = vectors::palette::quantize::quantize(&normals, s_n);
            let entry: Vec<[f64; 3]> = q
                .palette
                .iter()
                .map(|n| vectors::stats::unit(n.map(|c| ((c * 511.0).round()).clamp(-512.0, 511.0))))
                .collect();
            let meaning: Vec<[f64; 3]> = q.index.iter().map(|&k| entry[k as usize]).collect();
            let l = vectors::table_builder::sq1_10(scene.light_dir(0.5, 0.5)).map(|c| c as f64 / 1024.0);
            let float = |i: &[i64]| {
                sim::pipeline::gloss_shade(scene.conc, entry[i[vectors::palette_pipeline::input::idx] as usize], l)
            };
            Some(split(scene, &meaning, prep, exact_shade, &gloss, &float))
        }
    }
}

/// The height pipeline's three parts. Its texel codes are heights, whose normal needs a method, so the parts are
/// taken through the method: encoding (the B-spline in reals on the codes against the B-spline in reals on the
/// true heights), method (the B-spline in reals on the true heights against the ideal, the true surface's normal)
/// and datapath (the model against the B-spline in reals on the codes).
fn height_parts(scene: &Scene, bits: u32, prep: &Prepared, exact_shade: &[f64]) -> [(f64, f64); 3] {
    let (t, n) = (scene.tex, scene.size);
    let h = Height::heights(scene);
    let lo = h.iter().copied().fold(f64::MAX, f64::min);
    let (codes, k) = Height::codes_in(scene, bits);
    // the true heights in the codes' units (UQ6.2 steps: 4·m per texel of height, m = 16/k)
    let m = 16.0 / k as f64;
    let real: Vec<f64> = h.iter().map(|x| (x - lo) * 4.0 * m).collect();
    let pipe = Height::with_bits(scene, bits);
    let size_log2 = t.trailing_zeros() as i64;
    let kf = k as f64 / 16.0;
    let normal = |w: [f64; 9], ub: i64, vb: i64| {
        let (_, hu, hv) = vectors::height_pipeline::bspline(&w, ub as f64 / 256.0, vb as f64 / 256.0);
        vectors::height_normal::ideal(hu / 2.0, hv / 2.0, kf)
    };
    let (mut e, mut me, mut d) = (ErrorStats::default(), ErrorStats::default(), ErrorStats::default());
    for py in 0..n {
        for px in 0..n {
            let k_ = py * n + px;
            let (i, ub, j, vb) = Height::sample(px, py, n, t);
            let (xs, ys) =
                (vectors::height_fetch::axis(i, size_log2, false), vectors::height_fetch::axis(j, size_log2, false));
            let at = |q: usize| ys[q / 3] as usize * t + xs[q % 3] as usize;
            let (wt, wc): ([f64; 9], [f64; 9]) =
                (std::array::from_fn(|q| real[at(q)]), std::array::from_fn(|q| codes[at(q)] as f64));
            // the same window the pipeline was given
            assert_eq!(wc.map(|c| c as i64).to_vec(), prep.pixels()[k_][..9].to_vec(), "pixel ({px}, {py})");
            let (s_true, s_codes) = (pipe.shade_of(normal(wt, ub, vb)), pipe.shade_of(normal(wc, ub, vb)));
            e.add((s_codes - s_true).abs(), || format!("pixel ({px}, {py})"));
            me.add((s_true - prep.ideal[k_].shade).abs(), || format!("pixel ({px}, {py})"));
            d.add((exact_shade[k_] - s_codes).abs(), || format!("pixel ({px}, {py})"));
        }
    }
    [stats(&e), stats(&me), stats(&d)]
}

/// The unit whose width a knob changes, and its cells at the knob and at the pipeline's own setting (the pipeline
/// holds one normaliser in its bump path and two of the four channels of `Bilinear`).
fn knob_delta(k: Knobs, dir: &Path) -> Result<[i64; 5], String> {
    let fam = synth::fpga::Family::Ice40;
    let cells = |c: synth::fpga::Cells| [c.lut4 as i64, c.ff as i64, c.dsp as i64, c.bram as i64, c.soft as i64];
    let diff = |a: [i64; 5], b: [i64; 5], div: i64| -> [i64; 5] { std::array::from_fn(|i| (a[i] - b[i]) / div) };
    let mut total = [0i64; 5];
    if (k.table_bits, k.newton) != (UNIT_KNOBS.table_bits, UNIT_KNOBS.newton) {
        let f = crate::widths::normalise_block(k.table_bits, k.newton)
            .ok_or(format!("no Normalise<{}, {}>", k.table_bits, k.newton))?;
        let own =
            crate::widths::normalise_block(UNIT_KNOBS.table_bits, UNIT_KNOBS.newton).ok_or("no Normalise<10, 0>")?;
        let d = diff(
            cells(f(&dir.join(format!("normalise_t{}n{}", k.table_bits, k.newton)), fam)?),
            cells(own(&dir.join("normalise_t10n0"), fam)?),
            1,
        );
        total = std::array::from_fn(|i| total[i] + d[i]);
    }
    if (k.blend_bits, k.drop) != (UNIT_KNOBS.blend_bits, UNIT_KNOBS.drop) {
        let f = crate::widths::bilinear_block(k.blend_bits, k.drop)
            .ok_or(format!("no Bilinear<{}, {}>", k.blend_bits, k.drop))?;
        let own = crate::widths::bilinear_block(UNIT_KNOBS.blend_bits, UNIT_KNOBS.drop).ok_or("no Bilinear<8, 0>")?;
        let d = diff(
            cells(f(&dir.join(format!("bilinear_f{}d{}", k.blend_bits, k.drop)), fam)?),
            cells(own(&dir.join("bilinear_f8d0"), fam)?),
            2,
        );
        total = std::array::from_fn(|i| total[i] + d[i]);
    }
    Ok(total)
}

/// Compute one point: its errors on its scene, the model's speed, and its cost (`place`: also nextpnr).
pub fn run_point(p: &Point, dir: &Path, place: bool) -> Result<Result_, String> {
    let scene = scene(&p.scene)?;
    let pipe = build(p, &scene);
    let m = pipe.model();
    let prep = pipe.prepare(&scene);
    let t = Instant::now();
    // a knob's pixels through the model at that knob (the rtl block is built at the units' own widths)
    let image = |f: &dyn Fn(&[i64]) -> Vec<i64>| sim::render::Image {
        size: prep.size,
        outs: prep.pixels().iter().map(|i| f(i)).collect(),
        seconds: t.elapsed().as_secs_f64(),
    };
    let model = if p.lut != OWN_LUT {
        let Family::Polar(sc) = p.row.family else {
            return Err(format!("{}: the table size is swept on the polar pipeline only", p.id));
        };
        image(&|i| {
            let tr = vectors::polar_pipeline::exact_trace_sized(sc, p.lut, i);
            vec![tr.alpha, tr.out[0], tr.out[1], tr.out[2]]
        })
    } else if p.knobs == UNIT_KNOBS {
        sim::render::model(m, &prep)
    } else {
        let Family::CartSurface(v) = p.row.family else {
            return Err(format!("{}: width knobs are swept on cart_surface only", p.id));
        };
        image(&|i| {
            let tr = vectors::cart_surface::exact_trace_knobs(v, p.knobs, i);
            vec![tr.p, tr.out[0], tr.out[1], tr.out[2]]
        })
    };
    let secs = t.elapsed().as_secs_f64();
    let errs = sim::pipeline::errors(pipe.as_ref(), &scene, &prep, &model);
    // a knob's normal is the model's at the knob
    let angle = if p.knobs == UNIT_KNOBS {
        errs.normal.as_ref().map(stats)
    } else {
        let Family::CartSurface(v) = p.row.family else { unreachable!() };
        let mut s = ErrorStats::default();
        for (k, i) in prep.pixels().iter().enumerate() {
            let n = vectors::cart_surface::exact_trace_knobs(v, p.knobs, i).normal.map(|c| c as f64);
            s.add(vectors::stats::angle_deg(n, prep.ideal[k].normal), || format!("pixel {k}"));
        }
        Some(stats(&s))
    };
    let exact_shade: Vec<f64> = model.outs.iter().map(|o| pipe.shade(o)).collect();
    let three = three_parts(p, &scene, &prep, &exact_shade);
    let n = prep.pixels().len();
    let mut r = Result_ {
        id: p.id.clone(),
        scene: p.scene.clone(),
        pipeline: m.name.to_string(),
        units: pipe.units().join(" → "),
        knob: if p.height_bits == 4 {
            "4-bit heights (UQ3.1), read doubled".into()
        } else if p.lut != OWN_LUT {
            format!("sin/cos table 2^{} × 8 (S's top {0} bits)", p.lut)
        } else {
            knob_text(p.knobs)
        },
        pixels: n,
        colour: stats(&errs.colour),
        shade: stats(&errs.shade),
        angle,
        encoding: three.map(|t| t[0]),
        method: three.map(|t| t[1]),
        datapath: three.map(|t| t[2]),
        model_mpx: n as f64 / secs / 1e6,
        latency: pipe.rtl().latency(),
        ..Default::default()
    };
    // cost: the pipeline's own rtl block; a knob adds the swept unit's difference
    let udir = dir.join("synth").join(m.name);
    let c = crate::cli::synth_cells(m.name, &udir)?;
    let [mut lut4, mut ff, mut dsp, mut bram, mut soft] = [c.lut4, c.ff, c.dsp, c.bram, c.soft].map(|x| x as i64);
    if p.lut != OWN_LUT {
        // the pipeline's SinCos<8, 8> against SinCos<lut, 8>
        let f = |tb: u32| {
            crate::report::SINCOS_BLOCKS
                .iter()
                .find(|b| (b.0, b.1) == (tb, 8))
                .map(|b| b.2)
                .ok_or(format!("no SinCos<{tb}, 8>"))
        };
        let kd = dir.join("synth").join("knobs");
        let (a, b) = (
            f(p.lut)?(&kd.join(format!("sincos_t{}w8", p.lut)), synth::fpga::Family::Ice40)?,
            f(OWN_LUT)?(&kd.join("sincos_t8w8"), synth::fpga::Family::Ice40)?,
        );
        (lut4, ff, dsp, bram) = (
            lut4 + a.lut4 as i64 - b.lut4 as i64,
            ff + a.ff as i64 - b.ff as i64,
            dsp + a.dsp as i64 - b.dsp as i64,
            bram + a.bram as i64 - b.bram as i64,
        );
        r.estimated = true;
    } else if p.knobs != UNIT_KNOBS {
        let d = knob_delta(p.knobs, &dir.join("synth").join("knobs"))?;
        (lut4, ff, dsp, bram, soft) = (lut4 + d[0], ff + d[1], dsp + d[2], bram + d[3], soft + d[4]);
        r.estimated = true;
    }
    (r.lut4, r.ff, r.dsp, r.bram, r.soft) =
        (lut4.max(0) as u64, ff.max(0) as u64, dsp.max(0) as u64, bram.max(0) as u64, soft.max(0) as u64);
    r.part = "-".into();
    if place && !r.estimated {
        if let Some(rep) = crate::cli::place_cached(m.name, &udir)? {
            // a design whose cells fit the part but whose placement fails says so where its figures would be
            r.part =
                if rep.place_error.is_some() { format!("{} (does not place)", rep.part) } else { rep.part.clone() };
            r.lc = rep.lc;
            r.fmax = rep.fmax_mhz;
        }
    }
    Ok(r)
}

/// The points of a result set on the Pareto front of their scene: no other point of the scene is as cheap and as
/// accurate (mean colour error) and better in one.
pub fn pareto(rs: &[Result_]) -> Vec<bool> {
    rs.iter()
        .map(|a| {
            !rs.iter().any(|b| {
                b.scene == a.scene
                    && b.cost() <= a.cost()
                    && b.colour.0 <= a.colour.0
                    && (b.cost() < a.cost() || b.colour.0 < a.colour.0)
            })
        })
        .collect()
}

/// The cheapest point of each scene whose mean colour error is within the budget.
pub fn cheapest<'a>(rs: &'a [Result_], budget: f64) -> Vec<(&'a str, Option<&'a Result_>)> {
    let mut scenes: Vec<&str> = vec![];
    for r in rs {
        if !scenes.contains(&r.scene.as_str()) {
            scenes.push(&r.scene);
        }
    }
    scenes
        .into_iter()
        .map(|s| {
            (s, rs.iter().filter(|r| r.scene == s && r.colour.0 <= budget).min_by_key(|r| (r.cost(), r.id.clone())))
        })
        .collect()
}

/// The report as Markdown: one table (the model's speed in its own column, the only figure a rerun changes), the
/// budgets' answers.
pub fn markdown(rs: &[Result_], budgets: &[f64]) -> String {
    let on = pareto(rs);
    let f2 = |x: Option<(f64, f64)>| x.map(|(a, b)| format!("{a:.3} / {b:.2}")).unwrap_or("-".into());
    let mut s = String::new();
    let _ = writeln!(s, "# bumprtl report\n");
    let _ = writeln!(
        s,
        "Error against each scene's f64 ideal, 8-bit LSB (mean / max; angle in degrees). The shade's error split: encoding, method, datapath \
         (a palette's quantization is its encoding; a height map's parts are taken through its B-spline). Cost: iCE40 yosys cells (products beyond the UP5K's 8 SB_MAC16 in logic); \
         `cost` = SB_LUT4 + {LUT4_PER_MAC16}·SB_MAC16; `est.`: the pipeline plus the swept unit's difference. P: on the scene's Pareto set of cost \
         against mean colour error.\n"
    );
    let _ = writeln!(s, "| point | pipeline | knob | colour | shade | angle ° | encoding | method | datapath | LUT4 | FF | MAC16 | RAM40 | in logic | cost | part | LC | fmax MHz | latency | P | model Mpx/s |");
    let _ = writeln!(s, "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    for (r, p) in rs.iter().zip(&on) {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {}{} | {} | {} | {} | {} | {} | {:.2} |",
            r.id, r.pipeline, r.knob, f2(Some(r.colour)), f2(Some(r.shade)), f2(r.angle), f2(r.encoding), f2(r.method), f2(r.datapath),
            r.lut4, r.ff, r.dsp, r.bram, r.soft, r.cost(), if r.estimated { " est." } else { "" }, r.part,
            r.lc.map(|x| x.to_string()).unwrap_or("-".into()), r.fmax.map(|x| format!("{x:.1}")).unwrap_or("-".into()), r.latency,
            if *p { "P" } else { "" }, r.model_mpx
        );
    }
    for b in budgets {
        let _ = writeln!(s, "\nBudget {b} 8-bit LSB mean colour error:");
        for (scene, c) in cheapest(rs, *b) {
            match c {
                Some(r) => {
                    let _ = writeln!(
                        s,
                        "- {scene}: {} ({}{}), cost {}{}, colour {:.3} / {:.2}",
                        r.id,
                        r.units,
                        if r.knob == "-" { String::new() } else { format!("; {}", r.knob) },
                        r.cost(),
                        if r.estimated { " est." } else { "" },
                        r.colour.0,
                        r.colour.1
                    );
                }
                None => {
                    let _ = writeln!(s, "- {scene}: no configuration meets it");
                }
            }
        }
    }
    s
}

/// The Pareto plot: mean colour error against cost, one colour per scene, the Pareto set joined.
pub fn plot(rs: &[Result_], path: &Path) -> Result<(), String> {
    use plotters::prelude::*;
    let font = crate::fonts::sans()?;
    // drawn beside its place and moved there whole (the encoder picks the format by the name's extension)
    let tmp = path.with_extension("partial.png");
    {
        let root = BitMapBackend::new(&tmp, (1000, 640)).into_drawing_area();
        let e = |x: String| x;
        root.fill(&WHITE).map_err(|x| e(x.to_string()))?;
        let xmax = rs.iter().map(|r| r.cost()).max().unwrap_or(1) as f64 * 1.08;
        // the errors span two orders of magnitude (a quantized palette against one light for a whole surface):
        // a logarithmic axis
        let ymax = rs.iter().map(|r| r.colour.0).fold(0.1f64, f64::max) * 1.3;
        let ymin = rs.iter().map(|r| r.colour.0).filter(|e| *e > 0.0).fold(ymax, f64::min) * 0.7;
        let mut chart = ChartBuilder::on(&root)
            .caption("bumprtl: mean colour error against cost", (font, 22))
            .margin(16)
            .x_label_area_size(44)
            .y_label_area_size(60)
            .build_cartesian_2d(0f64..xmax, (ymin..ymax).log_scale())
            .map_err(|x| e(x.to_string()))?;
        chart
            .configure_mesh()
            .x_desc(format!("cost: iCE40 SB_LUT4 + {LUT4_PER_MAC16}·SB_MAC16"))
            .y_desc("mean colour error, 8-bit LSB (log scale)")
            .label_style((font, 14))
            .draw()
            .map_err(|x| e(x.to_string()))?;
        let on = pareto(rs);
        let mut scenes: Vec<&str> = vec![];
        for r in rs {
            if !scenes.contains(&r.scene.as_str()) {
                scenes.push(&r.scene);
            }
        }
        let palette = [RGBColor(31, 119, 180), RGBColor(214, 39, 40), RGBColor(44, 160, 44), RGBColor(148, 103, 189)];
        // (the point in pixels, its label, its scene's colour)
        let mut labels: Vec<((i32, i32), String, RGBColor)> = vec![];
        for (k, sc) in scenes.iter().enumerate() {
            let col = palette[k % palette.len()];
            let pts: Vec<(f64, f64, bool, &str)> = rs
                .iter()
                .zip(&on)
                .filter(|(r, _)| r.scene == *sc)
                .map(|(r, p)| (r.cost() as f64, r.colour.0, *p, r.id.as_str()))
                .collect();
            chart
                .draw_series(pts.iter().map(|&(x, y, p, _)| {
                    Circle::new((x, y), if p { 6 } else { 4 }, if p { col.filled() } else { col.stroke_width(1) })
                }))
                .map_err(|x| e(x.to_string()))?
                .label(format!("scene {sc}"))
                .legend(move |(x, y)| Circle::new((x + 8, y), 5, col.filled()));
            let mut front: Vec<(f64, f64)> = pts.iter().filter(|p| p.2).map(|p| (p.0, p.1)).collect();
            front.sort_by(|a, b| a.0.total_cmp(&b.0));
            chart.draw_series(LineSeries::new(front, col.stroke_width(2))).map_err(|x| e(x.to_string()))?;
            for &(x, y, p, id) in &pts {
                if p {
                    let label = id.split_once('.').map_or(id, |(_, rest)| rest).to_string();
                    labels.push((chart.backend_coord(&(x, y)), label, col));
                }
            }
        }
        // the Pareto points' labels, each beside its point where it overlaps no label placed before it (nearest
        // first, up or down a line at a time), joined to its point by a thin line when moved
        let style = (font, 12).into_font().color(&BLACK);
        let area = chart.plotting_area().get_pixel_range();
        labels.sort_by_key(|l| (l.0 .0, l.0 .1));
        let mut placed: Vec<(i32, i32, i32, i32)> = vec![];
        for ((px, py), label, col) in labels {
            let (w, h) = root.estimate_text_size(&label, &style).map_err(|x| e(x.to_string()))?;
            let (w, h) = (w as i32, h as i32 + 2);
            // right of the point, or left of it where the right runs off the plot
            let x0 = if px + 8 + w <= area.0.end { px + 8 } else { px - 8 - w };
            let clear = |y0: i32| {
                y0 >= area.1.start
                    && y0 + h <= area.1.end
                    && placed.iter().all(|b| x0 + w <= b.0 || b.2 <= x0 || y0 + h <= b.1 || b.3 <= y0)
            };
            let y0 =
                (0..40).flat_map(|k| [k, -k]).map(|k| py - h / 2 + k * h).find(|&y| clear(y)).unwrap_or(py - h / 2);
            placed.push((x0, y0, x0 + w, y0 + h));
            if (y0 + h / 2 - py).abs() > h / 2 {
                let end = (if x0 > px { x0 - 1 } else { x0 + w + 1 }, y0 + h / 2);
                root.draw(&PathElement::new(vec![(px, py), end], col.mix(0.5))).map_err(|x| e(x.to_string()))?;
            }
            root.draw(&Text::new(label, (x0, y0), style.clone())).map_err(|x| e(x.to_string()))?;
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .label_font((font, 14))
            .draw()
            .map_err(|x| e(x.to_string()))?;
        root.present().map_err(|x| e(x.to_string()))?;
    }
    std::fs::rename(&tmp, path).map_err(|e| format!("{}: {e}", path.display()))
}

/// `bumprtl report`: every point in this process, then the report.
pub fn run(scenes: &[String], out: &Path, budgets: &[f64], place: bool, only: Option<&str>) -> Result<(), String> {
    let pts: Vec<Point> = points(scenes)?.into_iter().filter(|p| only.is_none_or(|o| p.id.contains(o))).collect();
    if pts.is_empty() {
        return Err(format!("report: no point matches --only {}", only.unwrap_or("")));
    }
    crate::cli::writable_folder(out)?;
    let dir = out.join("points");
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let wall = Instant::now();
    let mut rs = vec![];
    for (k, p) in pts.iter().enumerate() {
        eprintln!("[{}/{}] {}", k + 1, pts.len(), p.id);
        let r = run_point(p, out, place)?;
        synth::export::write_atomic(&dir.join(format!("{}.txt", p.id)), r.to_text().as_bytes())?;
        rs.push(r);
    }
    finish(&rs, out, budgets)?;
    println!("{} points in {:.1} s", rs.len(), wall.elapsed().as_secs_f64());
    Ok(())
}

/// The report from saved points: Markdown and the Pareto plot into `out`, the table on standard output.
pub fn finish(rs: &[Result_], out: &Path, budgets: &[f64]) -> Result<(), String> {
    let md = markdown(rs, budgets);
    synth::export::write_atomic(&out.join("report.md"), md.as_bytes())?;
    plot(rs, &out.join("pareto.png"))?;
    print!("{md}");
    println!("\nwrote {}, {}", out.join("report.md").display(), out.join("pareto.png").display());
    Ok(())
}

/// `bumprtl report --merge DIR`: the saved points of a plan, in the plan's order.
pub fn merge(scenes: &[String], out: &Path, budgets: &[f64], only: Option<&str>) -> Result<(), String> {
    let pts: Vec<Point> = points(scenes)?.into_iter().filter(|p| only.is_none_or(|o| p.id.contains(o))).collect();
    let dir = out.join("points");
    let mut rs = vec![];
    let mut missing = vec![];
    for p in &pts {
        let f = dir.join(format!("{}.txt", p.id));
        match std::fs::read_to_string(&f).ok().and_then(|t| Result_::from_text(&t)) {
            Some(r) => rs.push(r),
            None => missing.push(p.id.clone()),
        }
    }
    if !missing.is_empty() {
        return Err(format!(
            "report --merge: {} of {} points not computed or unreadable under {}: {}",
            missing.len(),
            pts.len(),
            dir.display(),
            missing.join(", ")
        ));
    }
    finish(&rs, out, budgets)
}

/// `bumprtl report --point ID`: one point, saved under `out/points/ID.txt`.
pub fn one(scenes: &[String], id: &str, out: &Path, place: bool) -> Result<(), String> {
    let pts = points(scenes)?;
    let p = pts
        .iter()
        .find(|p| p.id == id)
        .ok_or_else(|| format!("report --point {id}: no such point (`bumprtl report --plan FILE` lists them)"))?;
    let dir = out.join("points");
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let r = run_point(p, out, place)?;
    synth::export::write_atomic(&dir.join(format!("{id}.txt")), r.to_text().as_bytes())?;
    println!("{id}: colour {:.3} / {:.2}, cost {}", r.colour.0, r.colour.1, r.cost());
    Ok(())
}

/// `bumprtl report --plan FILE`: one command per point in FILE (for `parallel < FILE`, or over ssh with
/// `parallel -S`), the merge step in FILE.merge, and a Slurm job array in FILE.slurm that runs line
/// `$SLURM_ARRAY_TASK_ID` of FILE.
pub fn plan(
    scenes: &[String],
    file: &Path,
    out: &Path,
    budgets: &[f64],
    place: bool,
    only: Option<&str>,
) -> Result<(), String> {
    let pts: Vec<Point> = points(scenes)?.into_iter().filter(|p| only.is_none_or(|o| p.id.contains(o))).collect();
    let exe = std::env::current_exe().map_err(|e| format!("cannot name this program: {e}"))?;
    let q = |p: &Path| shell_quote(&p.to_string_lossy());
    let common = {
        let mut c = String::new();
        for s in scenes {
            let _ = write!(c, " --scene {}", shell_quote(s));
        }
        let _ = write!(c, " --out {}", q(out));
        c
    };
    let mut lines = String::new();
    for p in &pts {
        let _ = writeln!(
            lines,
            "{} report{common} --point {}{}",
            q(&exe),
            shell_quote(&p.id),
            if place { "" } else { " --no-place" }
        );
    }
    let mut merge = format!("{} report{common} --merge", q(&exe));
    if let Some(o) = only {
        let _ = write!(merge, " --only {}", shell_quote(o));
    }
    for b in budgets {
        let _ = write!(merge, " --budget {b}");
    }
    merge.push('\n');
    let with = |ext: &str| PathBuf::from(format!("{}.{ext}", file.display()));
    let slurm = format!(
        "#!/usr/bin/env bash\n#SBATCH --job-name=bumprtl-report\n#SBATCH --array=1-{}\n# then, once the array is done: bash {}\nsed -n \"${{SLURM_ARRAY_TASK_ID}}p\" {} | bash\n",
        pts.len(), q(&with("merge")), q(file)
    );
    synth::export::write_atomic(file, lines.as_bytes())?;
    synth::export::write_atomic(&with("merge"), merge.as_bytes())?;
    synth::export::write_atomic(&with("slurm"), slurm.as_bytes())?;
    println!(
        "{} points: {} (parallel < {0}), then {}; a Slurm array: sbatch {}",
        pts.len(),
        file.display(),
        with("merge").display(),
        with("slurm").display()
    );
    Ok(())
}

fn shell_quote(s: &str) -> String {
    if !s.is_empty() && s.chars().all(|c| c.is_ascii_alphanumeric() || "-_./=:,+".contains(c)) {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', "'\\''"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(id: &str, scene: &str, lut4: u64, dsp: u64, err: f64) -> Result_ {
        Result_ { id: id.into(), scene: scene.into(), lut4, dsp, colour: (err, err * 10.0), ..Default::default() }
    }

    #[test]
    fn the_pareto_set_and_the_cheapest_within_a_budget_are_per_scene() {
        let rs = vec![
            r("a", "s", 1000, 0, 1.0),
            r("b", "s", 500, 2, 2.0),
            r("c", "s", 2000, 0, 0.5),
            r("d", "s", 3000, 0, 0.9),
            r("e", "t", 9000, 0, 9.0),
        ];
        // b costs 500 + 530 = 1030 > a's 1000 with more error: off; d is beaten by c
        assert_eq!(pareto(&rs), [true, false, true, false, true]);
        let c = cheapest(&rs, 1.0);
        assert_eq!(
            c.iter().map(|(s, r)| (*s, r.map(|r| r.id.as_str()))).collect::<Vec<_>>(),
            [("s", Some("a")), ("t", None)]
        );
        assert_eq!(cheapest(&rs, 0.6)[0].1.map(|r| r.id.as_str()), Some("c"));
    }

    #[test]
    fn a_saved_point_reads_back_whole() {
        let mut a = r("quad.cart_surface.t6n1f8d0", "quad", 1234, 6, 0.75);
        (a.angle, a.encoding, a.method, a.datapath, a.fmax, a.lc, a.estimated) =
            (Some((0.1, 2.0)), Some((0.2, 3.0)), None, Some((0.5, 1.5)), Some(37.5), Some(3082), true);
        (a.units, a.knob, a.pipeline, a.part, a.model_mpx) =
            ("x → y".into(), "normalise 2^6 table, 1 Newton".into(), "cart_surface".into(), "up5k".into(), 12.5);
        assert_eq!(Result_::from_text(&a.to_text()), Some(a));
        assert_eq!(Result_::from_text("id=x\n"), None);
    }

    #[test]
    fn every_point_has_its_own_id_and_the_knobs_only_the_surface_pipeline() {
        let pts = points(&DEFAULT_SCENES.map(String::from)).unwrap();
        let ids: std::collections::BTreeSet<&str> = pts.iter().map(|p| p.id.as_str()).collect();
        assert_eq!(ids.len(), pts.len());
        assert!(pts.iter().all(|p| p.knobs == UNIT_KNOBS || matches!(p.row.family, Family::CartSurface(_))));
        assert!(pts.iter().all(|p| p.lut == OWN_LUT || p.row.name == "polar_pipeline"));
        // the torus is matte and curved: no height or palette pipeline on it, the matte variants on it
        assert!(!ids.iter().any(|i| i.starts_with("demo.height") || i.starts_with("demo.palette")));
        assert!(ids.contains("demo.cart_surface_nearest_matte") && !ids.contains("quad.cart_surface_nearest_matte"));
        assert!(ids.contains("quad.height_pipeline") && ids.contains("quad.palette_pipeline_12"));
    }

    #[test]
    fn plan_arguments_are_quoted_for_the_shell() {
        assert_eq!(shell_quote("scenes/up5k.toml"), "scenes/up5k.toml");
        assert_eq!(shell_quote("my scene's.toml"), "'my scene'\\''s.toml'");
    }
}
