//! `bumprtl demo`: the embedded default scene through both of seed 000's pipelines — Cartesian (second
//! embodiment) and polar (first embodiment, FIG. 3) — each through four paths (f64 ideal, bit-exact model,
//! rust-hdl, Verilator), with pictures, waveforms, the Verilog, the seed's polar shortcomings shown, and one table
//! of speed, hardware cost and error.

use indicatif::{ProgressBar, ProgressStyle};
use rtl::StreamUnit;
use sim::render::{self, Image};
use std::path::Path;
use std::time::Instant;
use vectors::polar_encode::Scale;
use vectors::scene::Scene;
use vectors::stats::{angle_deg, ErrorStats};
use vectors::UnitModel;

/// The polar surface of the demo: h = 1 (a pure dot product, k1 = 0) and p = 4.
pub const POLAR_H: f64 = 1.0;
pub const POLAR_PW: i64 = 16;

fn bar(len: u64, what: &str) -> ProgressBar {
    let b = ProgressBar::new(len);
    b.set_style(ProgressStyle::with_template("{msg:<30} [{bar:40}] {pos}/{len} px {eta}").unwrap().progress_chars("=> "));
    b.set_message(what.to_string());
    b
}

/// One pipeline through the three bit-exact paths (rust-hdl's only when asked for, Verilator's only where it is
/// installed).
struct Paths {
    model: Image,
    hdl: Option<Image>,
    vl: Option<render::VerilatorRun>,
    mism_hdl: usize,
    mism_vl: usize,
}

fn three_paths<U: StreamUnit>(m: &UnitModel, size: usize, inputs: &[Vec<i64>], out: &Path, rust_hdl: bool, verilator: bool) -> Result<Paths, String> {
    let model = render::model(m, size, inputs);
    let hdl = rust_hdl.then(|| {
        let b = bar(inputs.len() as u64, &format!("rust-hdl: {}", m.name));
        let hdl = render::rust_hdl::<U>(m, size, inputs, &|k| b.set_position(k as u64));
        b.finish_and_clear();
        hdl
    });
    let vl = if verilator {
        let b = ProgressBar::new_spinner();
        b.set_message(format!("Verilator: building and running {}", m.name));
        b.enable_steady_tick(std::time::Duration::from_millis(200));
        let vl = render::verilator::<U>(m, size, inputs, &out.join("verilator").join(m.name), 2);
        b.finish_and_clear();
        Some(vl?)
    } else {
        None
    };
    let mism = |a: &Image| (0..inputs.len()).filter(|&k| a.p[k] != model.p[k] || a.rgb[k] != model.rgb[k]).count();
    // both Verilator runs, the one-thread and the split one, against the model
    let mism_vl = vl.as_ref().map(|r| mism(&r.image) + mism(&r.single)).unwrap_or(0);
    let mism_hdl = hdl.as_ref().map(mism).unwrap_or(0);
    Ok(Paths { model, hdl, vl, mism_hdl, mism_vl })
}

/// Worst channel error of a blended colour against the ideal, 8-bit LSB.
fn colour_err(a: [i64; 3], ideal: [f64; 3]) -> f64 {
    (0..3).map(|c| (a[c] as f64 - ideal[c]).abs()).fold(0.0, f64::max)
}

fn at(size: usize) -> impl Fn(usize) -> String {
    move |k| format!("pixel ({}, {})", k % size, k / size)
}

pub fn run(out: &Path, size: usize, scale: Scale, synth: bool) -> Result<(), String> {
    let wall = Instant::now();
    std::fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    let probe = out.join(".write-test");
    std::fs::write(&probe, b"").map_err(|e| format!("cannot write into {}: {e}", out.display()))?;
    let _ = std::fs::remove_file(&probe);
    let scene = Scene { size, ..Scene::default() };
    let n = size * size;
    let where_ = at(size);
    // the paths that need external tools run where the tools are; the demo says what it skipped and why
    let no_vl = synth::tools::missing(&["verilator", "make", "g++"]);
    let no_pnr = if synth { synth::tools::missing(&["yosys", "nextpnr-ice40"]) } else { vec![] };
    let no_ecp5 = synth::tools::nextpnr_ecp5().is_none().then(synth::tools::nextpnr_ecp5_missing);
    let synth = synth && no_pnr.is_empty();

    // Cartesian
    let t = Instant::now();
    let prep = scene.prepare();
    let cart_ideal_s = t.elapsed().as_secs_f64();
    let cart = three_paths::<rtl::cart_pipeline::CartPipeline>(&vectors::cart_pipeline::MODEL, size, &prep.inputs, out, true, no_vl.is_empty())?;
    // the same scene, its normals hemi-octahedrally encoded, through the pipeline built with that decode (rust-hdl
    // is left to the tests here: the model and Verilator are the two fast paths)
    let t = Instant::now();
    let prep_h = Scene { encoder: vectors::cart_encode::Encoder::HemiOct, ..scene.clone() }.prepare();
    let hemi_ideal_s = t.elapsed().as_secs_f64();
    let hm = &vectors::cart_pipeline::MODEL_HEMI_OCT;
    let hemi = three_paths::<rtl::cart_pipeline::CartPipelineHemiOct>(hm, size, &prep_h.inputs, out, false, no_vl.is_empty())?;
    // polar
    let t = Instant::now();
    let pol = scene.prepare_polar(scale, POLAR_PW, POLAR_H);
    let polar_ideal_s = t.elapsed().as_secs_f64();
    let pm = vectors::polar_pipeline::MODEL_FOR[scale as usize];
    let polar = match scale {
        Scale::Seed => three_paths::<rtl::polar_pipeline::PolarPipelineSeed>(pm, size, &pol.inputs, out, true, no_vl.is_empty())?,
        Scale::Dc255 => three_paths::<rtl::polar_pipeline::PolarPipelineDc>(pm, size, &pol.inputs, out, true, no_vl.is_empty())?,
    };

    // error of each model against the scene's ideal
    let cart_errors = |paths: &Paths, prep: &vectors::scene::Prepared, decode: vectors::cart_pipeline::Decode| {
        let (mut shade, mut colour, mut normal) = (ErrorStats::default(), ErrorStats::default(), ErrorStats::default());
        for k in 0..n {
            shade.add((paths.model.p[k] as f64 / 4.0 - prep.ideal_p[k] / 1023.0 * 255.0).abs(), || where_(k));
            colour.add(colour_err(paths.model.rgb[k], prep.ideal_rgb[k]), || where_(k));
            let tr = vectors::cart_pipeline::exact_trace_with(decode, &prep.inputs[k]);
            normal.add(angle_deg(tr.normal.map(|c| c as f64), prep.ideal_normal[k]), || where_(k));
        }
        (shade, colour, normal)
    };
    let (c_shade, c_colour, c_normal) = cart_errors(&cart, &prep, vectors::cart_pipeline::Decode::Seed);
    let (h_shade, h_colour, h_normal) = cart_errors(&hemi, &prep_h, vectors::cart_pipeline::Decode::HemiOct);
    // the polar path against the scene's ideal; against an ideal lit by the surface's one light (what remains is
    // the normal's encoding and filtering, and the arithmetic); against its own codes (the arithmetic alone)
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let pw_real = POLAR_PW as f64 / 4.0;
    let surface_ideal: Vec<f64> = (0..n)
        .map(|k| 255.0 * ((1.0 - POLAR_H) + POLAR_H * dot(pol.normal[k], pol.surface_dir)).clamp(0.0, 1.0).powf(pw_real))
        .collect();
    let (mut p_shade, mut p_colour, mut p_surf, mut p_own) = (ErrorStats::default(), ErrorStats::default(), ErrorStats::default(), ErrorStats::default());
    let (mut wrap_p, mut wrap_c, mut rest_p) = (ErrorStats::default(), ErrorStats::default(), ErrorStats::default());
    for k in 0..n {
        let a = polar.model.p[k] as f64;
        p_shade.add((a - pol.ideal_alpha[k]).abs(), || where_(k));
        p_colour.add(colour_err(polar.model.rgb[k], pol.ideal_rgb[k]), || where_(k));
        let e = (a - surface_ideal[k]).abs();
        p_surf.add(e, || where_(k));
        let v = &pol.inputs[k];
        let own = vectors::polar_shade::ideal(scale, v[0], v[1], v[2], v[3], v[4], v[5]).clamp(0.0, 255.0);
        p_own.add((a - vectors::power::ideal_real(own, v[6])).abs(), || where_(k));
        if pol.straddles[k] {
            wrap_p.add(e, || where_(k));
            wrap_c.add((cart.model.p[k] as f64 / 4.0 - prep.ideal_p[k] / 1023.0 * 255.0).abs(), || where_(k));
        } else {
            rest_p.add(e, || where_(k));
        }
    }

    // shortcoming (a): a light below the horizon. Both pipelines' N·L before their shading curves (Cartesian: dot3's
    // X; polar: the clamped shade with h = 1), 8-bit, against 255·max(0, N·L) with the pixel's true light
    let low = Scene { light_pos: [-0.6, -0.12, 0.5], ..scene.clone() };
    let low_c = low.prepare();
    let low_p = low.prepare_polar(scale, POLAR_PW, POLAR_H);
    let (mut low_ce, mut low_pe) = (ErrorStats::default(), ErrorStats::default());
    let (mut low_cx, mut low_px, mut low_ideal) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    for k in 0..n {
        low_ideal[k] = 255.0 * dot(low_p.normal[k], low_p.light_dir[k]).max(0.0);
        low_cx[k] = vectors::cart_pipeline::exact_trace(&low_c.inputs[k]).x as f64 / 1023.0 * 255.0;
        low_px[k] = vectors::polar_pipeline::exact_trace(scale, &low_p.inputs[k]).shade as f64;
        low_ce.add((low_cx[k] - low_ideal[k]).abs(), || where_(k));
        low_pe.add((low_px[k] - low_ideal[k]).abs(), || where_(k));
    }

    // pictures
    let to8 = |x: f64| x.round().clamp(0.0, 255.0) as u8;
    let png = |name: &str, f: &dyn Fn(usize) -> [u8; 3]| render::write_png(&out.join(name), size, f);
    png("ideal.png", &|k| prep.ideal_rgb[k].map(to8))?;
    png("model.png", &|k| cart.model.rgb[k].map(|c| c as u8))?;
    if let Some(hdl) = &cart.hdl {
        png("rust_hdl.png", &|k| hdl.rgb[k].map(|c| c as u8))?;
    }
    if let Some(vl) = &cart.vl {
        png("verilator.png", &|k| vl.image.rgb[k].map(|c| c as u8))?;
    }
    png("shade_model.png", &|k| [(cart.model.p[k] >> 2) as u8; 3])?;
    let hmax = c_colour.max.max(1.0);
    png("error_heat.png", &|k| render::heat(colour_err(cart.model.rgb[k], prep.ideal_rgb[k]), hmax))?;
    png("polar_ideal.png", &|k| pol.ideal_rgb[k].map(to8))?;
    png("polar_model.png", &|k| polar.model.rgb[k].map(|c| c as u8))?;
    if let Some(hdl) = &polar.hdl {
        png("polar_rust_hdl.png", &|k| hdl.rgb[k].map(|c| c as u8))?;
    }
    png("hemi_oct_model.png", &|k| hemi.model.rgb[k].map(|c| c as u8))?;
    if let Some(vl) = &polar.vl {
        png("polar_verilator.png", &|k| vl.image.rgb[k].map(|c| c as u8))?;
    }
    let pmax = p_shade.max.max(1.0);
    png("polar_error_heat.png", &|k| render::heat((polar.model.p[k] as f64 - pol.ideal_alpha[k]).abs(), pmax))?;
    let smax = p_surf.max.max(1.0);
    png("polar_surface_light_error_heat.png", &|k| render::heat((polar.model.p[k] as f64 - surface_ideal[k]).abs(), smax))?;
    // (b): where the four texels' R straddle the 255 → 0 wrap, over the polar shade error
    png("polar_wrap_pixels.png", &|k| if pol.straddles[k] { [255, 64, 255] } else { [(polar.model.p[k] / 3) as u8; 3] })?;
    // (a): shade of each pipeline and of each ideal with the light below the horizon
    png("below_horizon_ideal.png", &|k| [to8(low_ideal[k]); 3])?;
    png("below_horizon_cartesian.png", &|k| [to8(low_cx[k]); 3])?;
    png("below_horizon_polar.png", &|k| [to8(low_px[k]); 3])?;

    // waveforms of the first pixels, and the Verilog
    let first = |v: &[Vec<i64>]| v.iter().take(64).cloned().collect::<Vec<_>>();
    sim::wave::write_vcd::<rtl::cart_pipeline::CartPipeline>(&vectors::cart_pipeline::MODEL, &first(&prep.inputs), &out.join("cart_pipeline.vcd"))?;
    match scale {
        Scale::Seed => sim::wave::write_vcd::<rtl::polar_pipeline::PolarPipelineSeed>(pm, &first(&pol.inputs), &out.join("polar_pipeline.vcd"))?,
        Scale::Dc255 => sim::wave::write_vcd::<rtl::polar_pipeline::PolarPipelineDc>(pm, &first(&pol.inputs), &out.join("polar_pipeline.vcd"))?,
    };
    let vdir = out.join("verilog");
    synth::export::<rtl::cart_pipeline::CartPipeline>().write(&vdir)?;
    synth::export::<rtl::cart_pipeline::CartPipelineHemiOct>().write(&vdir)?;
    match scale {
        Scale::Seed => synth::export::<rtl::polar_pipeline::PolarPipelineSeed>().write(&vdir)?,
        Scale::Dc255 => synth::export::<rtl::polar_pipeline::PolarPipelineDc>().write(&vdir)?,
    };

    // hardware cost, cached beside the output: each pipeline on the UP5K and the ECP5-45F, on two threads
    let hw = if synth {
        let hdir = out.join("synth");
        let parts: Vec<synth::fpga::Part> = crate::hardware::DEMO_PARTS.iter().copied().filter(|p| p.family == synth::fpga::Family::Ice40 || no_ecp5.is_none()).collect();
        let (hd, ps) = (&hdir, &parts);
        let jobs: Vec<crate::hardware::Job> = vec![
            Box::new(move |say| crate::hardware::measure::<rtl::cart_pipeline::CartPipeline>(hd, ps, say)),
            Box::new(move |say| crate::hardware::measure::<rtl::cart_pipeline::CartPipelineHemiOct>(hd, ps, say)),
            match scale {
                Scale::Seed => Box::new(move |say| crate::hardware::measure::<rtl::polar_pipeline::PolarPipelineSeed>(hd, ps, say)),
                Scale::Dc255 => Box::new(move |say| crate::hardware::measure::<rtl::polar_pipeline::PolarPipelineDc>(hd, ps, say)),
            },
        ];
        Some(crate::hardware::run_jobs(jobs)?)
    } else {
        None
    };

    println!("scene: {size}x{size} quad, 128x128 height map, 4 vertex lights towards a point light");
    println!("  Cartesian: seed-encoded texels, bilinear, lights interpolated per pixel, gloss C = {}", scene.conc);
    println!("  hemi-oct: the same, its normals hemi-octahedrally encoded, through cart_pipeline_hemi_oct");
    println!(
        "  polar ({}): S, R bilinear as numbers, one light per surface (T {:.1}°, Q {}, k = {}, {}, {}), p = {}",
        scale.name(), pol.light.t.to_degrees(), pol.light.q, pol.light.k1, pol.light.k2, pol.light.k3, POLAR_PW as f64 / 4.0
    );
    println!();
    let cols = [&cart, &hemi, &polar];
    let line = |label: &str, f: &dyn Fn(&Paths) -> String| {
        let cells: String = cols.iter().map(|p| format!(" {:>14}", f(p))).collect();
        println!("{label:<34}{cells}");
    };
    println!("{:<34} {:>14} {:>14} {:>14}", "pixels/s (mismatches vs model)", "Cartesian", "hemi-oct", "polar");
    let pps = |i: &Image, m: usize| format!("{:.0} ({m})", i.pixels_per_second());
    let ideal_s = [cart_ideal_s, hemi_ideal_s, polar_ideal_s];
    println!("{:<34} {:>14.0} {:>14.0} {:>14.0}", "f64 ideal (scene set-up included)", n as f64 / ideal_s[0], n as f64 / ideal_s[1], n as f64 / ideal_s[2]);
    line("bit-exact model", &|p| pps(&p.model, 0));
    line("rust-hdl (loop-driven)", &|p| p.hdl.as_ref().map(|h| pps(h, p.mism_hdl)).unwrap_or("in the tests".into()));
    if let Some(c) = &cart.vl {
        line("Verilator, whole frame, 1 thread", &|p| p.vl.as_ref().map(|v| pps(&v.single, p.mism_vl)).unwrap_or_default());
        line(&format!("Verilator, whole frame, {} threads", c.threads), &|p| p.vl.as_ref().map(|v| pps(&v.image, p.mism_vl)).unwrap_or_default());
        line("Verilator bare loop (cycles/s)", &|p| p.vl.as_ref().map(|v| format!("{:.0}", v.bare_cycles_per_second)).unwrap_or_default());
        line("  1 thread against the bare loop", &|p| {
            p.vl.as_ref()
                .map(|v| format!("{:.2}", (v.single.size * v.single.size) as f64 / v.single.seconds / v.bare_cycles_per_second))
                .unwrap_or_default()
        });
    } else {
        println!("Verilator path skipped: {} not installed (`bash .ci/run` installs the tools)", no_vl.join(", "));
    }
    println!();
    if !no_pnr.is_empty() {
        println!("UP5K and ECP5 figures skipped: {} not installed (`bash .ci/run` installs the tools)\n", no_pnr.join(", "));
    } else if let Some(e) = &no_ecp5 {
        println!("ECP5 figures skipped: {e}\n");
    }
    if let Some(hw) = &hw {
        hardware_table(&["Cartesian", "hemi-oct", "polar"], hw);
    }
    println!("{:<52} {:>9} {:>9}   {}", "error of the bit-exact models vs the scene's ideal", "mean", "max", "max at");
    let row = |name: &str, s: &ErrorStats| println!("{name:<52} {:>9.3} {:>9.3}   {}", s.mean(), s.max, s.argmax);
    row("Cartesian shade, 8-bit LSB (P/4)", &c_shade);
    row("Cartesian blended colour, 8-bit LSB", &c_colour);
    row("Cartesian normal angle, degrees", &c_normal);
    row("hemi-oct texels: shade, 8-bit LSB (P/4)", &h_shade);
    row("hemi-oct texels: blended colour, 8-bit LSB", &h_colour);
    row("hemi-oct texels: normal angle, degrees", &h_normal);
    row("polar shade, 8-bit LSB (α)", &p_shade);
    row("polar blended colour, 8-bit LSB", &p_colour);
    row("polar shade vs an ideal lit by the surface's light", &p_surf);
    row("polar shade vs equation 3 + powf on its own codes", &p_own);
    println!();
    println!("the seed's polar shortcomings");
    row(&format!("(b) polar, {} px filtered across R's wrap", wrap_p.count), &wrap_p);
    row("    the other pixels (both vs the surface light)", &rest_p);
    row("    Cartesian shade on the wrap pixels", &wrap_c);
    row(&format!("(a) light {:.1}° below the horizon: Cartesian N·L", -low_p.light_dir[n / 2][1].asin().to_degrees()), &low_ce);
    row(&format!("    polar N·L, the light moved onto it: {}", low_p.light.moved), &low_pe);
    println!();
    let vl_png = if cart.vl.is_some() { " verilator," } else { "" };
    println!("wrote {}: ideal, model, rust_hdl,{vl_png} shade_model, error_heat, hemi_oct_model, polar_*, below_horizon_* .png;", out.display());
    println!("      cart_pipeline.vcd, polar_pipeline.vcd; verilog/{}", if synth { "; synth/" } else { "" });
    println!("wall time {:.1} s", wall.elapsed().as_secs_f64());
    let bad = cols.iter().map(|p| p.mism_hdl + p.mism_vl).sum::<usize>();
    if bad != 0 {
        return Err(format!(
            "the bit-exact paths disagree: Cartesian rust-hdl {} / Verilator {}, hemi-oct Verilator {}, polar rust-hdl {} / Verilator {} pixels differ from the model",
            cart.mism_hdl, cart.mism_vl, hemi.mism_vl, polar.mism_hdl, polar.mism_vl
        ));
    }
    Ok(())
}

/// Hardware cost, one column per pipeline, one block of rows per part.
fn hardware_table(names: &[&str], hw: &[Vec<(synth::fpga::Part, crate::hardware::Fit)>]) {
    use crate::hardware::Fit;
    let Some(first) = hw.first() else { return };
    let row = |label: &str, f: &dyn Fn(&Fit, &synth::fpga::Part) -> String, k: usize| {
        let cells: String = hw.iter().map(|h| format!(" {:>22}", f(&h[k].1, &h[k].0))).collect();
        println!("{label:<34}{cells}");
    };
    for (k, (part, _)) in first.iter().enumerate() {
        let header: String = names.iter().map(|n| format!(" {n:>22}")).collect();
        println!("{:<34}{header}", format!("{} ({})", part.name, if part.family == synth::fpga::Family::Ice40 { "yosys -dsp" } else { "yosys synth_ecp5" }));
        let placed = |f: &Fit, g: &dyn Fn(&synth::fpga::SynthReport) -> String| match f {
            Fit::Placed(r) => g(r),
            Fit::DoesNotFit(_) => "-".to_string(),
        };
        let pct = |n: u64, of: u64| format!("{n} ({:.0}%)", 100.0 * n as f64 / of as f64);
        row("LUT4 / FF", &|f, _| placed(f, &|r| format!("{} / {}", r.cells.lut4, r.cells.ff)), k);
        row(&format!("DSP of {} / BRAM of {}", part.dsp, part.bram), &|f, p| placed(f, &|r| format!("{} / {}", pct(r.cells.dsp, p.dsp), r.cells.bram)), k);
        row(&format!("logic cells of {} (placed)", part.lut4), &|f, p| placed(f, &|r| r.lc.map(|x| pct(x, p.lut4)).unwrap_or("-".into())), k);
        row("fmax, 1 pixel/clock", &|f, _| match f {
            Fit::Placed(r) => match (&r.place_error, r.fmax_mhz) {
                (Some(_), _) => "does not place".into(),
                (None, Some(x)) => format!("{x:.1} MHz"),
                _ => "-".into(),
            },
            Fit::DoesNotFit(_) => "does not fit".into(),
        }, k);
        row("latency (clocks)", &|f, _| placed(f, &|r| r.latency.to_string()), k);
        for (n, h) in names.iter().zip(hw) {
            match &h[k].1 {
                Fit::DoesNotFit(why) => println!("  {n} does not fit the {}: {why}", part.title),
                Fit::Placed(r) => {
                    if let Some(e) = &r.place_error {
                        println!("  {n} does not place on the {}: {e}", part.title);
                    }
                }
            }
        }
        println!();
    }
}
