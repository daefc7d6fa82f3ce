//! One point computed: its errors on its scene, the model's speed, and its cost.

use super::figures::{stats, AxisCost, PointFigures};
use super::points::{build, knob_text, scene, Point, OWN_LUT};
use super::split::three_parts;
use sim::pipelines::Family;
use std::path::Path;
use std::time::Instant;
use vectors::cart_surface::{Knobs, UNIT_KNOBS};
use vectors::stats::ErrorStats;

/// The unit whose width a knob changes, and its cells at the knob and at the pipeline's own setting (the pipeline
/// holds one normaliser in its bump path and two of the four channels of `Bilinear`).
fn knob_delta(k: Knobs, dir: &Path) -> Result<[i64; 5], String> {
    let fam = synth::fpga::Family::Ice40;
    let cells = |c: synth::fpga::Cells| [c.lut4 as i64, c.ff as i64, c.dsp as i64, c.bram as i64, c.soft as i64];
    let diff = |a: [i64; 5], b: [i64; 5], div: i64| -> [i64; 5] { std::array::from_fn(|i| (a[i] - b[i]) / div) };
    let mut total = [0i64; 5];
    if (k.table_bits, k.newton) != (UNIT_KNOBS.table_bits, UNIT_KNOBS.newton) {
        let f = crate::units::block("normalise", (k.table_bits, k.newton))?;
        let own = crate::units::block("normalise", (UNIT_KNOBS.table_bits, UNIT_KNOBS.newton))?;
        let d = diff(
            cells(f.synth_unit(&dir.join(format!("normalise_t{}n{}", k.table_bits, k.newton)), fam)?),
            cells(own.synth_unit(&dir.join("normalise_t10n0"), fam)?),
            1,
        );
        total = std::array::from_fn(|i| total[i] + d[i]);
    }
    if (k.blend_bits, k.drop) != (UNIT_KNOBS.blend_bits, UNIT_KNOBS.drop) {
        let f = crate::units::block("bilinear", (k.blend_bits, k.drop))?;
        let own = crate::units::block("bilinear", (UNIT_KNOBS.blend_bits, UNIT_KNOBS.drop))?;
        let d = diff(
            cells(f.synth_unit(&dir.join(format!("bilinear_f{}d{}", k.blend_bits, k.drop)), fam)?),
            cells(own.synth_unit(&dir.join("bilinear_f8d0"), fam)?),
            2,
        );
        total = std::array::from_fn(|i| total[i] + d[i]);
    }
    Ok(total)
}

/// Compute one point: its errors on its scene, the model's speed, and its cost (`place`: also nextpnr, the median of
/// that many placements).
pub fn run_point(p: &Point, dir: &Path, place: Option<u32>) -> Result<PointFigures, String> {
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
    let mut r = PointFigures {
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
        interval: pipe.rtl().interval(),
        ..Default::default()
    };
    // cost: the pipeline's own rtl block; a knob adds the swept unit's difference
    let udir = dir.join("synth").join(m.name);
    let c = crate::units::synth_cells(m.name, &udir)?;
    let [mut lut4, mut ff, mut dsp, mut bram, mut soft] = [c.lut4, c.ff, c.dsp, c.bram, c.soft].map(|x| x as i64);
    if p.lut != OWN_LUT {
        // the pipeline's SinCos<8, 8> against SinCos<lut, 8>
        let f = |tb: u32| crate::units::block("sincos", (tb, 8));
        let kd = dir.join("synth").join("knobs");
        let (a, b) = (
            f(p.lut)?.synth_unit(&kd.join(format!("sincos_t{}w8", p.lut)), synth::fpga::Family::Ice40)?,
            f(OWN_LUT)?.synth_unit(&kd.join("sincos_t8w8"), synth::fpga::Family::Ice40)?,
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
    r.spram = c.spram; // no swept unit holds a single-port memory
                       // the AXI4-Stream wrapper's own cells, the same for every point of a pipeline (cached)
    let axis = sim::units::unit(m.name)?.axis;
    let (depth, words, bits) = axis.fifo();
    let a = axis.ctl_cells(&udir.join("axis_ctl"), synth::fpga::Family::Ice40)?;
    r.axis = Some(AxisCost { depth, words, bits, lut4: a.lut4, ff: a.ff, bram: a.bram });
    r.part = "-".into();
    if let (Some(n), false) = (place, r.estimated) {
        if let Some(rep) = crate::units::place_cached(m.name, &udir, synth::fpga::Seeds::all(n))? {
            // a design whose cells fit the part but whose placement fails says so where its figures would be
            // (and one that fails at some seeds names them)
            r.part = match (&rep.place_error, rep.unplaced.len()) {
                (Some(_), _) => format!("{} ({})", rep.part, rep.unplaced_text()),
                (None, 0) => rep.part.clone(),
                (None, _) => format!("{} (not placed at {})", rep.part, rep.unplaced.join("; ")),
            };
            r.lc = rep.lc;
            r.fmax = rep.fmax_mhz;
            (r.fmax_range, r.placements) = (rep.fmax_range, rep.placements);
        }
    }
    Ok(r)
}
