//! `bumprtl demo`: the embedded default scene through the four paths, with pictures, a waveform, the Verilog and
//! a table of speed beside error.

use indicatif::{ProgressBar, ProgressStyle};
use std::path::Path;
use std::time::Instant;
use vectors::scene::Scene;
use vectors::stats::{angle_deg, ErrorStats};

fn bar(len: u64, what: &str) -> ProgressBar {
    let b = ProgressBar::new(len);
    b.set_style(ProgressStyle::with_template("{msg:<22} [{bar:40}] {pos}/{len} px {eta}").unwrap().progress_chars("=> "));
    b.set_message(what.to_string());
    b
}

pub fn run(out: &Path, size: usize) -> Result<(), String> {
    let wall = Instant::now();
    std::fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    let probe = out.join(".write-test");
    std::fs::write(&probe, b"").map_err(|e| format!("cannot write into {}: {e}", out.display()))?;
    let _ = std::fs::remove_file(&probe);
    let scene = Scene { size, ..Scene::default() };
    let n = size * size;

    let t = Instant::now();
    let prep = scene.prepare();
    let ideal_s = t.elapsed().as_secs_f64();
    let model = sim::render::model(&prep);

    let b = bar(n as u64, "rust-hdl simulation");
    let hdl = sim::render::rust_hdl(&prep, &|k| b.set_position(k as u64));
    b.finish_and_clear();

    let b = ProgressBar::new_spinner();
    b.set_message("building and running the Verilator model");
    b.enable_steady_tick(std::time::Duration::from_millis(200));
    let vl = sim::render::verilator(&prep, &out.join("verilator"));
    b.finish_and_clear();
    let vl = vl?;

    // the three bit-exact paths must agree
    let mism = |a: &sim::render::Image| (0..n).filter(|&k| a.p[k] != model.p[k] || a.rgb[k] != model.rgb[k]).count();
    let (m_hdl, m_vl) = (mism(&hdl), mism(&vl));

    // error of the model against the ideal
    let mut shade = ErrorStats::default();
    let mut colour = ErrorStats::default();
    let mut normal = ErrorStats::default();
    for k in 0..n {
        let at = || format!("pixel ({}, {})", k % size, k / size);
        shade.add((model.p[k] as f64 / 4.0 - prep.ideal_p[k] / 1023.0 * 255.0).abs(), at);
        let e = (0..3).map(|c| (model.rgb[k][c] as f64 - prep.ideal_rgb[k][c]).abs()).fold(0.0, f64::max);
        colour.add(e, at);
        let tr = vectors::cart_pipeline::exact_trace(&prep.inputs[k]);
        let nv = [tr.normal[0] as f64, tr.normal[1] as f64, tr.normal[2] as f64];
        normal.add(angle_deg(nv, prep.ideal_normal[k]), at);
    }

    // pictures
    let to8 = |x: f64| x.round().clamp(0.0, 255.0) as u8;
    sim::render::write_png(&out.join("ideal.png"), size, |k| prep.ideal_rgb[k].map(to8))?;
    sim::render::write_png(&out.join("model.png"), size, |k| model.rgb[k].map(|c| c as u8))?;
    sim::render::write_png(&out.join("rust_hdl.png"), size, |k| hdl.rgb[k].map(|c| c as u8))?;
    sim::render::write_png(&out.join("verilator.png"), size, |k| vl.rgb[k].map(|c| c as u8))?;
    sim::render::write_png(&out.join("shade_model.png"), size, |k| [(model.p[k] >> 2) as u8; 3])?;
    let hmax = colour.max.max(1.0);
    sim::render::write_png(&out.join("error_heat.png"), size, |k| {
        let e = (0..3).map(|c| (model.rgb[k][c] as f64 - prep.ideal_rgb[k][c]).abs()).fold(0.0, f64::max);
        sim::render::heat(e, hmax)
    })?;
    // waveform of the first pixels, and the Verilog
    let first: Vec<Vec<i64>> = prep.inputs.iter().take(64).cloned().collect();
    sim::wave::write_vcd::<rtl::cart_pipeline::CartPipeline>(&vectors::cart_pipeline::MODEL, &first, &out.join("cart_pipeline.vcd"))?;
    let vdir = out.join("verilog");
    synth::export::<rtl::cart_pipeline::CartPipeline>().write(&vdir)?;

    println!("scene: {size}x{size} quad, 128x128 height map as seed-encoded Cartesian texels, bilinear, 4 vertex lights, C = {}", scene.conc);
    println!();
    println!("{:<26} {:>14} {:>18} {:>22}", "path", "pixels/s", "mismatches vs model", "");
    println!("{:<26} {:>14.0} {:>18} {:>22}", "f64 ideal (with set-up)", n as f64 / ideal_s, "-", "");
    println!("{:<26} {:>14.0} {:>18} {:>22}", "bit-exact model", model.pixels_per_second(), 0, "");
    println!("{:<26} {:>14.0} {:>18} {:>22}", "rust-hdl (loop-driven)", hdl.pixels_per_second(), m_hdl, "");
    println!("{:<26} {:>14.0} {:>18} {:>22}", "Verilator (exported .v)", vl.pixels_per_second(), m_vl, "");
    println!();
    println!("{:<44} {:>9} {:>9}   {}", "error of the bit-exact model vs the ideal", "mean", "max", "max at");
    println!("{:<44} {:>9.3} {:>9.3}   {}", "shade, 8-bit LSB (P/4 vs ideal·255)", shade.mean(), shade.max, shade.argmax);
    println!("{:<44} {:>9.3} {:>9.3}   {}", "blended colour, 8-bit LSB", colour.mean(), colour.max, colour.argmax);
    println!("{:<44} {:>9.3} {:>9.3}   {}", "normal angle, degrees", normal.mean(), normal.max, normal.argmax);
    println!();
    println!("hardware cost: `bumprtl synth cart_pipeline` (yosys + nextpnr, minutes)");
    println!("wrote {} (ideal, model, rust_hdl, verilator, shade_model, error_heat .png; cart_pipeline.vcd; verilog/)", out.display());
    println!("wall time {:.1} s", wall.elapsed().as_secs_f64());
    if m_hdl != 0 || m_vl != 0 {
        return Err(format!("the bit-exact paths disagree: rust-hdl {m_hdl}, Verilator {m_vl} pixels differ from the model"));
    }
    Ok(())
}
