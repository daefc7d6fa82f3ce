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

/// One pipeline through the three bit-exact paths (Verilator's only where it is installed).
struct Paths {
    model: Image,
    hdl: Image,
    vl: Option<Image>,
    mism_hdl: usize,
    mism_vl: usize,
}

fn three_paths<U: StreamUnit>(m: &UnitModel, size: usize, inputs: &[Vec<i64>], out: &Path, verilator: bool) -> Result<Paths, String> {
    let model = render::model(m, size, inputs);
    let b = bar(inputs.len() as u64, &format!("rust-hdl: {}", m.name));
    let hdl = render::rust_hdl::<U>(m, size, inputs, &|k| b.set_position(k as u64));
    b.finish_and_clear();
    let vl = if verilator {
        let b = ProgressBar::new_spinner();
        b.set_message(format!("Verilator: building and running {}", m.name));
        b.enable_steady_tick(std::time::Duration::from_millis(200));
        let vl = render::verilator::<U>(m, size, inputs, &out.join("verilator").join(m.name));
        b.finish_and_clear();
        Some(vl?)
    } else {
        None
    };
    let mism = |a: &Image| (0..inputs.len()).filter(|&k| a.p[k] != model.p[k] || a.rgb[k] != model.rgb[k]).count();
    let (mism_hdl, mism_vl) = (mism(&hdl), vl.as_ref().map(mism).unwrap_or(0));
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
    let synth = synth && no_pnr.is_empty();

    // Cartesian
    let t = Instant::now();
    let prep = scene.prepare();
    let cart_ideal_s = t.elapsed().as_secs_f64();
    let cart = three_paths::<rtl::cart_pipeline::CartPipeline>(&vectors::cart_pipeline::MODEL, size, &prep.inputs, out, no_vl.is_empty())?;
    // polar
    let t = Instant::now();
    let pol = scene.prepare_polar(scale, POLAR_PW, POLAR_H);
    let polar_ideal_s = t.elapsed().as_secs_f64();
    let pm = vectors::polar_pipeline::MODEL_FOR[scale as usize];
    let polar = match scale {
        Scale::Seed => three_paths::<rtl::polar_pipeline::PolarPipelineSeed>(pm, size, &pol.inputs, out, no_vl.is_empty())?,
        Scale::Dc255 => three_paths::<rtl::polar_pipeline::PolarPipelineDc>(pm, size, &pol.inputs, out, no_vl.is_empty())?,
    };

    // error of each model against the scene's ideal
    let (mut c_shade, mut c_colour, mut c_normal) = (ErrorStats::default(), ErrorStats::default(), ErrorStats::default());
    for k in 0..n {
        c_shade.add((cart.model.p[k] as f64 / 4.0 - prep.ideal_p[k] / 1023.0 * 255.0).abs(), || where_(k));
        c_colour.add(colour_err(cart.model.rgb[k], prep.ideal_rgb[k]), || where_(k));
        let tr = vectors::cart_pipeline::exact_trace(&prep.inputs[k]);
        c_normal.add(angle_deg(tr.normal.map(|c| c as f64), prep.ideal_normal[k]), || where_(k));
    }
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
    png("rust_hdl.png", &|k| cart.hdl.rgb[k].map(|c| c as u8))?;
    if let Some(vl) = &cart.vl {
        png("verilator.png", &|k| vl.rgb[k].map(|c| c as u8))?;
    }
    png("shade_model.png", &|k| [(cart.model.p[k] >> 2) as u8; 3])?;
    let hmax = c_colour.max.max(1.0);
    png("error_heat.png", &|k| render::heat(colour_err(cart.model.rgb[k], prep.ideal_rgb[k]), hmax))?;
    png("polar_ideal.png", &|k| pol.ideal_rgb[k].map(to8))?;
    png("polar_model.png", &|k| polar.model.rgb[k].map(|c| c as u8))?;
    png("polar_rust_hdl.png", &|k| polar.hdl.rgb[k].map(|c| c as u8))?;
    if let Some(vl) = &polar.vl {
        png("polar_verilator.png", &|k| vl.rgb[k].map(|c| c as u8))?;
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
    match scale {
        Scale::Seed => synth::export::<rtl::polar_pipeline::PolarPipelineSeed>().write(&vdir)?,
        Scale::Dc255 => synth::export::<rtl::polar_pipeline::PolarPipelineDc>().write(&vdir)?,
    };

    // hardware cost, cached beside the output
    let (cs, ps) = if synth {
        let b = ProgressBar::new_spinner();
        b.set_message("yosys + nextpnr-ice40 (UP5K), both pipelines (cached after the first run)");
        b.enable_steady_tick(std::time::Duration::from_millis(200));
        let cs = synth::ice40::synth_and_place_cached::<rtl::cart_pipeline::CartPipeline>(&out.join("synth").join("cart_pipeline"), 50.0);
        let ps = match scale {
            Scale::Seed => synth::ice40::synth_and_place_cached::<rtl::polar_pipeline::PolarPipelineSeed>(&out.join("synth").join(pm.name), 50.0),
            Scale::Dc255 => synth::ice40::synth_and_place_cached::<rtl::polar_pipeline::PolarPipelineDc>(&out.join("synth").join(pm.name), 50.0),
        };
        b.finish_and_clear();
        (Some(cs?), Some(ps?))
    } else {
        (None, None)
    };

    println!("scene: {size}x{size} quad, 128x128 height map, 4 vertex lights towards a point light");
    println!("  Cartesian: seed-encoded texels, bilinear, lights interpolated per pixel, gloss C = {}", scene.conc);
    println!(
        "  polar ({}): S, R bilinear as numbers, one light per surface (T {:.1}°, Q {}, k = {}, {}, {}), p = {}",
        scale.name(), pol.light.t.to_degrees(), pol.light.q, pol.light.k1, pol.light.k2, pol.light.k3, POLAR_PW as f64 / 4.0
    );
    println!();
    println!("{:<34} {:>14} {:>14}", "pixels/s (mismatches vs model)", "Cartesian", "polar");
    let pps = |i: &Image, m: usize| format!("{:.0} ({m})", i.pixels_per_second());
    println!("{:<34} {:>14.0} {:>14.0}", "f64 ideal (scene set-up included)", n as f64 / cart_ideal_s, n as f64 / polar_ideal_s);
    println!("{:<34} {:>14} {:>14}", "bit-exact model", pps(&cart.model, 0), pps(&polar.model, 0));
    println!("{:<34} {:>14} {:>14}", "rust-hdl (loop-driven)", pps(&cart.hdl, cart.mism_hdl), pps(&polar.hdl, polar.mism_hdl));
    match (&cart.vl, &polar.vl) {
        (Some(c), Some(p)) => println!("{:<34} {:>14} {:>14}", "Verilator (exported .v)", pps(c, cart.mism_vl), pps(p, polar.mism_vl)),
        _ => println!("Verilator path skipped: {} not installed (`bash .ci/run` installs the tools)", no_vl.join(", ")),
    }
    println!();
    if !no_pnr.is_empty() {
        println!("UP5K figures skipped: {} not installed (`bash .ci/run` installs the tools)\n", no_pnr.join(", "));
    }
    if let (Some(c), Some(p)) = (&cs, &ps) {
        let fit = |r: &synth::ice40::SynthReport| match (&r.place_error, r.fmax_mhz) {
            (Some(_), _) => "does not fit".to_string(),
            (None, Some(f)) => format!("{f:.1} MHz"),
            (None, None) => "-".to_string(),
        };
        println!("{:<34} {:>14} {:>14}", "UP5K (yosys -dsp; nextpnr)", "Cartesian", "polar");
        println!("{:<34} {:>14} {:>14}", "LUT4 / FF", format!("{} / {}", c.lut4, c.ff), format!("{} / {}", p.lut4, p.ff));
        println!("{:<34} {:>14} {:>14}", "DSP (UP5K has 8) / BRAM", format!("{} / {}", c.dsp, c.bram), format!("{} / {}", p.dsp, p.bram));
        let lc = |r: &synth::ice40::SynthReport| r.lc.map(|x| x.to_string()).unwrap_or("-".into());
        println!("{:<34} {:>14} {:>14}", "LC of 5,280 (with the I/O wrapper)", lc(c), lc(p));
        println!("{:<34} {:>14} {:>14}", "fmax (I/O wrapper, placed)", fit(c), fit(p));
        println!("{:<34} {:>14} {:>14}", "latency (clocks), 1 pixel/clock", c.latency, p.latency);
        for (name, r) in [("Cartesian", c), ("polar", p)] {
            if let Some(e) = &r.place_error {
                let how = if r.dsp_fallback { "with its multipliers in LUTs (it needs more than 8 DSPs)" } else { "" };
                println!("{name} does not place on the UP5K {how}: {e}");
            }
        }
        println!();
    }
    println!("{:<52} {:>9} {:>9}   {}", "error of the bit-exact models vs the scene's ideal", "mean", "max", "max at");
    let row = |name: &str, s: &ErrorStats| println!("{name:<52} {:>9.3} {:>9.3}   {}", s.mean(), s.max, s.argmax);
    row("Cartesian shade, 8-bit LSB (P/4)", &c_shade);
    row("Cartesian blended colour, 8-bit LSB", &c_colour);
    row("Cartesian normal angle, degrees", &c_normal);
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
    println!("wrote {}: ideal, model, rust_hdl,{vl_png} shade_model, error_heat, polar_*, below_horizon_* .png;", out.display());
    println!("      cart_pipeline.vcd, polar_pipeline.vcd; verilog/{}", if synth { "; synth/" } else { "" });
    println!("wall time {:.1} s", wall.elapsed().as_secs_f64());
    let bad = cart.mism_hdl + cart.mism_vl + polar.mism_hdl + polar.mism_vl;
    if bad != 0 {
        return Err(format!(
            "the bit-exact paths disagree: Cartesian rust-hdl {} / Verilator {}, polar rust-hdl {} / Verilator {} pixels differ from the model",
            cart.mism_hdl, cart.mism_vl, polar.mism_hdl, polar.mism_vl
        ));
    }
    Ok(())
}
