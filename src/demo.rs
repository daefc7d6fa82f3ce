//! `bumprtl demo`: the embedded default scene through every pipeline — US 6,819,319's Cartesian (second embodiment,
//! with the seed's texels and with hemi-octahedral ones) and polar (first embodiment, FIG. 3), each on the texture
//! unit where its memory holds the map, US 2004/0207631's height map, Tarini et al.'s palette at s_N = 256 and
//! 4,096 — each through four paths (f64 ideal, bit-exact model, rust-hdl, Verilator), with pictures, waveforms, the
//! Verilog, US 6,819,319's polar shortcomings shown, and one table of speed, hardware cost and error. The pipelines
//! do the work (`sim::pipeline`); this file is the command's flow and its printing.

use indicatif::{ProgressBar, ProgressStyle};
use sim::pipeline::{Height, Palette, Pipeline, Polar};
use sim::prepared::Prepared;
use sim::render::{self, Image};
use sim::scene::Scene;
use sim::shortcomings::Shortcomings;
use std::path::Path;
use std::time::Instant;
use vectors::polar_encode::Scale;
use vectors::stats::ErrorStats;

fn bar(len: u64, what: &str) -> ProgressBar {
    let b = ProgressBar::new(len);
    b.set_style(
        ProgressStyle::with_template("{msg:<30} [{bar:40}] {pos}/{len} px {eta}").unwrap().progress_chars("=> "),
    );
    b.set_message(what.to_string());
    b
}

/// One pipeline on the scene: its set-up, the three bit-exact paths (rust-hdl's only when asked for, Verilator's
/// only where it is installed) and its errors against the ideal.
struct Run<'a> {
    pipe: &'a dyn Pipeline,
    prep: Prepared,
    ideal_s: f64,
    model: Image,
    /// the model with the frame split across `SPLIT` threads (its pixels must equal `model`'s)
    split: Image,
    hdl: Option<Image>,
    vl: Option<render::VerilatorRun>,
    mism_split: usize,
    mism_hdl: usize,
    mism_vl: usize,
    shade: ErrorStats,
    colour: ErrorStats,
    normal: Option<ErrorStats>,
    /// the shade against the ideal under the pipeline's one light per surface, where it has one
    surface: Option<ErrorStats>,
}

/// The bit-exact model against software as a graphics programmer writes it, on the quad's `cart_pipeline` pixels:
/// each way's speed beside its error against the scene's ideal.
fn peer_table(scene: &Scene) {
    let ways = sim::peer::compare(scene, SPLIT);
    println!(
        "the bit-exact model beside float software on the quad ({} cart_pipeline pixels, the same input vectors)",
        ways[0].image.outs.len()
    );
    println!("{:<40} {:>12} {:>17} {:>17}", "way", "pixels/s", "shade mean / max", "colour mean / max");
    for w in &ways {
        let (s, c) = (&w.errors.shade, &w.errors.colour);
        println!(
            "{:<40} {:>12.0} {:>8.3} / {:>6.2} {:>8.3} / {:>6.2}",
            w.what,
            w.image.pixels_per_second(),
            s.mean(),
            s.max,
            c.mean(),
            c.max
        );
    }
    let (peer, lanes, model) = (&ways[1].image, &ways[2].image, &ways[3].image);
    println!(
        "  the model takes {:.1}× the f32 peer's time on one thread from the same vectors, {:.1}× from its lanes",
        model.seconds / peer.seconds.max(1e-9),
        model.seconds / lanes.seconds.max(1e-9)
    );
}

/// The threads the model's and Verilator's split frames run on, beside their one-thread runs.
const SPLIT: usize = 2;

fn run_pipeline<'a>(
    pipe: &'a dyn Pipeline,
    scene: &Scene,
    out: &Path,
    rust_hdl: bool,
    verilator: bool,
) -> Result<Run<'a>, String> {
    let (m, rtl) = (pipe.model(), pipe.rtl());
    let t = Instant::now();
    let prep = pipe.prepare(scene);
    let ideal_s = t.elapsed().as_secs_f64();
    // each the fastest of its runs, as Verilator's are
    let model = render::fastest(|| render::model(m, &prep));
    let split = render::fastest(|| render::model_on(m, &prep, SPLIT));
    let mism_split = split.mismatches(&model);
    let hdl = rust_hdl.then(|| {
        let b = bar(prep.inputs.len() as u64, &format!("rust-hdl: {}", m.name));
        let hdl = rtl.rust_hdl(m, &prep, &|k| b.set_position(k as u64));
        b.finish_and_clear();
        hdl
    });
    let vl = if verilator {
        let b = ProgressBar::new_spinner();
        b.set_message(format!("Verilator: building and running {}", m.name));
        b.enable_steady_tick(std::time::Duration::from_millis(200));
        let vl = rtl.verilator(m, &prep, &out.join("verilator").join(m.name), SPLIT);
        b.finish_and_clear();
        Some(vl?)
    } else {
        None
    };
    // both Verilator runs, the one-thread and the split one, against the model
    let mism_vl = vl.as_ref().map(|r| r.image.mismatches(&model) + r.single.mismatches(&model)).unwrap_or(0);
    let mism_hdl = hdl.as_ref().map(|h| h.mismatches(&model)).unwrap_or(0);
    let sim::pipeline::Errors { shade, colour, normal, surface } = sim::pipeline::errors(pipe, scene, &prep, &model);
    Ok(Run {
        pipe,
        prep,
        ideal_s,
        model,
        split,
        hdl,
        vl,
        mism_split,
        mism_hdl,
        mism_vl,
        shade,
        colour,
        normal,
        surface,
    })
}

pub fn run(
    out: &Path,
    size: usize,
    scale: Scale,
    synth: bool,
    height_map: Option<&Path>,
    relief: Option<f64>,
) -> Result<(), String> {
    let wall = Instant::now();
    // a user's map is read (or refused) before anything is written
    let mut scene = Scene { size, ..sim::scene_file::quad()?.scene };
    let torus_spec = sim::scene_file::demo()?;
    let mut torus = Scene { size, ..torus_spec.scene.clone() };
    if let Some(path) = height_map {
        let loaded = sim::heightmap::load(path)?;
        for n in &loaded.notes {
            println!("{n}");
        }
        let side = loaded.map.side;
        let map = Some(std::sync::Arc::new(loaded.map));
        let relief = relief.unwrap_or(side as f64 / 16.0);
        scene = Scene { tex: side, relief, map: map.clone(), ..scene };
        torus = Scene { tex: side, relief, map, ..torus };
    }
    crate::output::writable_folder(out)?;
    // the paths that need external tools run where the tools are; the demo says what it skipped and why
    let no_vl = synth::tools::missing(&["verilator", "make", "g++"]);
    let no_pnr = if synth { synth::tools::toolchain().missing() } else { vec![] };
    let no_ecp5 = synth::tools::nextpnr_ecp5().is_none().then(synth::tools::nextpnr_ecp5_missing);
    let synth = synth && no_pnr.is_empty();

    // every pipeline, and whether rust-hdl renders it here (the hemi-oct variant's rust-hdl run is left to the
    // tests: the model and Verilator are the two fast paths)
    // the polar surface: a scene's default (h = 1, p = 4)
    let own = sim::pipelines::Settings::default();
    let polar = Polar::new(scale, own.pw, own.h);
    // the Cartesian pipelines on the texture unit (the map and its MIP chain in its memory, each pixel's u, v); a
    // user's map whose side the memory does not hold (a power of two up to 128) through the host-fed ones
    let cartesian = |on_unit: &str, host: &str| {
        let unit = sim::pipelines::named(on_unit).expect("a row of the table");
        let row = if unit.renders(&scene) { unit } else { sim::pipelines::named(host).expect("a row of the table") };
        sim::pipeline::build(row, &scene, &own)
    };
    let (cart, hemi) = (
        cartesian("cart_tex_bilinear", "cart_pipeline"),
        cartesian("cart_tex_bilinear_hemi_oct", "cart_pipeline_hemi_oct"),
    );
    // the polar pipeline on the texture unit too (S and R filtered as numbers by its bilinear units, so the wrap
    // of R is the hardware's own), the host-fed one for the Dreamcast scale or a map the unit does not hold; on
    // level 0 the two give the same frame (a test), so the shortcomings measured on either are the seed's
    let polar_unit = sim::pipelines::named("polar_tex_bilinear").expect("a row of the table");
    let polar_pipe: Box<dyn Pipeline> = if matches!(scale, Scale::Seed) && polar_unit.renders(&scene) {
        sim::pipeline::build(polar_unit, &scene, &own)
    } else {
        Box::new(polar)
    };
    let height = Height::new(&scene);
    let (pal256, pal4096) = (Palette::new(256, &scene), Palette::new(4096, &scene));
    let pipes: [(&dyn Pipeline, bool); 6] = [
        (cart.as_ref(), true),
        (hemi.as_ref(), false),
        (polar_pipe.as_ref(), true),
        (&height, true),
        (&pal256, true),
        (&pal4096, false),
    ];
    // the demo's own scene first: the torus through the pipeline its file names (the model and Verilator)
    let torus_pipe = torus_spec.build();
    let on_torus = run_pipeline(torus_pipe.as_ref(), &torus, out, false, no_vl.is_empty())?;
    let runs = pipes
        .iter()
        .map(|&(p, hdl)| run_pipeline(p, &scene, out, hdl, no_vl.is_empty()))
        .collect::<Result<Vec<Run>, String>>()?;
    let polar_setup = polar.set_up(&scene);
    let sc = Shortcomings::measure(
        &scene,
        &polar,
        &polar_setup,
        &runs[2].model,
        (cart.as_ref(), &runs[0].prep, &runs[0].model),
    );

    // pictures: per pipeline, then the shortcomings
    let to8 = |x: f64| x.round().clamp(0.0, 255.0) as u8;
    let png = |name: &str, f: &dyn Fn(usize) -> [u8; 3]| render::write_png(&out.join(name), size, f);
    let mut written = vec![];
    for (r, name) in std::iter::once((&on_torus, "torus")).chain(runs.iter().map(|r| (r, r.pipe.model().name))) {
        // pixel k of the run at its place in the frame; places the surface does not cover are background
        let by = r.prep.by_place();
        let mut each = |what: &str, f: &dyn Fn(usize) -> [u8; 3]| -> Result<(), String> {
            written.push(format!("{name}_{what}.png"));
            png(&format!("{name}_{what}.png"), &|at| by[at].map_or(render::BACKGROUND, f))
        };
        each("ideal", &|k| r.prep.ideal[k].rgb.map(to8))?;
        each("model", &|k| r.pipe.colour(&r.model.outs[k]))?;
        if let Some(hdl) = &r.hdl {
            each("rust_hdl", &|k| r.pipe.colour(&hdl.outs[k]))?;
        }
        if let Some(vl) = &r.vl {
            each("verilator", &|k| r.pipe.colour(&vl.image.outs[k]))?;
        }
        each("shade", &|k| [to8(r.pipe.shade(&r.model.outs[k])); 3])?;
        let hmax = r.colour.max.max(1.0);
        each("error_heat", &|k| {
            render::heat(render::colour_err(r.pipe.colour(&r.model.outs[k]), r.prep.ideal[k].rgb), hmax)
        })?;
    }
    let pol = &runs[2];
    let smax = sc.surface.max.max(1.0);
    png("polar_surface_light_error_heat.png", &|k| {
        render::heat((pol.pipe.shade(&pol.model.outs[k]) - sc.surface_ideal[k]).abs(), smax)
    })?;
    // (b): where the four texels' R straddle the 255 → 0 wrap, over the polar shade
    png("polar_wrap_pixels.png", &|k| {
        if polar_setup.straddles[k] {
            [255, 64, 255]
        } else {
            [(pol.pipe.shade(&pol.model.outs[k]) / 3.0) as u8; 3]
        }
    })?;
    // (a): shade of each pipeline and of each ideal with the light below the horizon
    png("below_horizon_ideal.png", &|k| [to8(sc.low_ideal[k]); 3])?;
    png("below_horizon_cartesian.png", &|k| [to8(sc.low_cx[k]); 3])?;
    png("below_horizon_polar.png", &|k| [to8(sc.low_px[k]); 3])?;

    // US 2004/0207631's variants: FIG. 8a/8b on a coarse map of the procedural heights, B-spline colour beside bilinear
    let d = Scene::default();
    let fig8 = sim::variants::fig8(size, d.relief * sim::variants::FIG8_TEXELS as f64 / d.tex as f64); // the same slopes as the scene's
    png("fig8a_blinn.png", &|k| [fig8.blinn[k]; 3])?;
    png("fig8b_bspline.png", &|k| [fig8.bspline[k]; 3])?;
    let colour = sim::variants::colour(size);
    png("colour_reference.png", &|k| colour.reference[k])?;
    png("colour_bilinear.png", &|k| colour.bilinear[k])?;
    png("colour_bspline.png", &|k| colour.bspline[k])?;

    // waveforms of the first pixels, and the Verilog
    let vdir = out.join("verilog");
    for r in std::iter::once(&on_torus).chain(&runs) {
        r.pipe.rtl().write_vcd(
            r.pipe.model(),
            &r.pipe.waveform(&r.prep),
            &out.join(format!("{}.vcd", r.pipe.model().name)),
        )?;
        r.pipe.rtl().export(&vdir)?;
    }

    // hardware cost, cached beside the output: each pipeline on the UP5K and the ECP5-45F, on two threads
    let hw = if synth {
        let hdir = out.join("synth");
        let parts: Vec<synth::fpga::Part> = crate::hardware::DEMO_PARTS
            .iter()
            .copied()
            .filter(|p| p.family == synth::fpga::Family::Ice40 || no_ecp5.is_none())
            .collect();
        let (hd, ps) = (&hdir, &parts);
        let jobs: Vec<crate::hardware::Job> = std::iter::once(&on_torus)
            .chain(&runs)
            .map(|r| -> crate::hardware::Job {
                let rtl = r.pipe.rtl();
                Box::new(move |say| rtl.measure(hd, ps, crate::hardware::DEMO_SEEDS, say))
            })
            .collect();
        Some(crate::hardware::run_jobs(jobs)?)
    } else {
        None
    };

    let source = match height_map {
        Some(p) => {
            format!("{} ({}x{}, white {:.2} texels above black)", p.display(), scene.tex, scene.tex, scene.relief)
        }
        None => format!("procedural {t}x{t} height map", t = scene.tex),
    };
    let covered = on_torus.prep.ideal.len();
    println!("scene: {size}x{size}, a torus ({covered} pixels), {source} repeated 6 × 2 round it, the point light's direction");
    println!(
        "  at each triangle's corners interpolated per pixel: {} ({})",
        on_torus.pipe.model().name,
        on_torus.pipe.describe(&torus)
    );
    let e = &on_torus;
    let vl =
        e.vl.as_ref()
            .map(|v| format!(", Verilator {:.0} px/s ({} mismatches)", v.image.pixels_per_second(), e.mism_vl))
            .unwrap_or_default();
    println!(
        "  model {:.0} px/s{vl}; colour error {:.3} / {:.3} 8-bit LSB mean / max, normal {} ° mean / max",
        e.model.pixels_per_second(),
        e.colour.mean(),
        e.colour.max,
        e.normal.as_ref().map(|n| format!("{:.3} / {:.3}", n.mean(), n.max)).unwrap_or("-".into())
    );
    println!("every pipeline on the quad: {size}x{size}, {source}, 4 vertex lights towards a point light");
    for r in &runs {
        println!("  {} ({}): {}", r.pipe.label(), r.pipe.model().name, r.pipe.describe(&scene));
        println!("    units: {}", r.pipe.units().join(" → "));
    }
    println!();
    let n = size * size;
    let line = |label: &str, f: &dyn Fn(&Run) -> String| {
        let cells: String = runs.iter().map(|r| format!(" {:>14}", f(r))).collect();
        println!("{label:<34}{cells}");
    };
    line("pixels/s (mismatches vs model)", &|r| r.pipe.label().to_string());
    let pps = |i: &Image, m: usize| format!("{:.0} ({m})", i.pixels_per_second());
    line("bits per texel of the bump source", &|r| format!("{}", r.pipe.bits_per_texel()));
    line("f64 ideal (scene set-up included)", &|r| format!("{:.0}", n as f64 / r.ideal_s));
    line(&render::on_threads("bit-exact model", 1), &|r| pps(&r.model, 0));
    line(&render::on_threads("bit-exact model", SPLIT), &|r| pps(&r.split, r.mism_split));
    line("rust-hdl (loop-driven)", &|r| r.hdl.as_ref().map(|h| pps(h, r.mism_hdl)).unwrap_or("in the tests".into()));
    if let Some(c) = &runs[0].vl {
        line(&render::on_threads("Verilator, whole frame", 1), &|r| {
            r.vl.as_ref().map(|v| pps(&v.single, r.mism_vl)).unwrap_or_default()
        });
        line(&render::on_threads("Verilator, whole frame", c.threads), &|r| {
            r.vl.as_ref().map(|v| pps(&v.image, r.mism_vl)).unwrap_or_default()
        });
        line("Verilator bare loop (cycles/s)", &|r| {
            r.vl.as_ref().map(|v| format!("{:.0}", v.bare_cycles_per_second)).unwrap_or_default()
        });
        line("  1 thread against the bare loop", &|r| {
            r.vl.as_ref()
                .map(|v| {
                    format!(
                        "{:.2}",
                        (v.single.size * v.single.size) as f64 / v.single.seconds / v.bare_cycles_per_second
                    )
                })
                .unwrap_or_default()
        });
    } else {
        println!("Verilator path skipped: {} not installed (`bash .ci/run` installs the tools)", no_vl.join(", "));
    }
    println!();
    if !no_pnr.is_empty() {
        println!(
            "UP5K and ECP5 figures skipped: {} not installed (`bash .ci/run` installs the tools)\n",
            no_pnr.join(", ")
        );
    } else if let Some(e) = &no_ecp5 {
        println!("ECP5 figures skipped: {e}\n");
    }
    if let Some(hw) = &hw {
        // the torus's pipeline first, then the quad's
        let names: Vec<&str> = std::iter::once(&on_torus).chain(&runs).map(|r| r.pipe.label()).collect();
        hardware_table(&names, hw);
    }
    println!("{:<52} {:>9} {:>9}   max at", "error of the bit-exact models vs the scene's ideal", "mean", "max");
    let row = |name: &str, s: &ErrorStats| match s.count {
        0 => println!("{name:<52} {:>9} {:>9}", "none", "none"),
        _ => println!("{name:<52} {:>9.3} {:>9.3}   {}", s.mean(), s.max, s.argmax),
    };
    for r in &runs {
        row(&format!("{} shade, 8-bit LSB ({})", r.pipe.label(), r.pipe.shade_name()), &r.shade);
        row(&format!("{} blended colour, 8-bit LSB", r.pipe.label()), &r.colour);
        if let Some(nrm) = &r.normal {
            row(&format!("{} normal angle, degrees", r.pipe.label()), nrm);
        }
        if let Some(s) = &r.surface {
            row(&format!("{} shade vs the ideal under its one light", r.pipe.label()), s);
        }
    }
    row("polar shade vs an ideal lit by the surface's light", &sc.surface);
    row("polar shade vs equation 3 + powf on its own codes", &sc.own);
    println!();
    peer_table(&scene);
    println!();
    println!("US 6,819,319's polar shortcomings");
    row(&format!("(b) polar, {} px filtered across R's wrap", sc.wrap.count), &sc.wrap);
    row("    the other pixels (both vs the surface light)", &sc.rest);
    row("    Cartesian shade on the wrap pixels", &sc.wrap_cartesian);
    row(&format!("(a) light {:.1}° below the horizon: Cartesian N·L", sc.low_below_deg), &sc.low_cartesian);
    row(&format!("    polar N·L, the light moved onto it: {}", sc.low_moved), &sc.low_polar);
    println!();
    let n8 = sim::variants::FIG8_TEXELS;
    println!("US 2004/0207631's variants (bit-exact models; {n8}x{n8} maps magnified to {size}x{size})");
    println!(
        "FIG. 8a/8b, largest jump across a texel edge (methods in reals): N·L derivative Blinn {:.4}, B-spline {:.4}; cross tangent derivative Blinn {:.4}, B-spline {:.4}",
        fig8.jumps.blinn.0, fig8.jumps.bspline.0, fig8.jumps.blinn.1, fig8.jumps.bspline.1
    );
    row("bilinear colour vs the f64 picture, 8-bit LSB", &colour.bilinear_vs_reference);
    row("B-spline colour (¶87) vs the f64 picture, 8-bit LSB", &colour.bspline_vs_reference);
    row("bilinear colour vs its method in reals", &colour.bilinear_vs_own);
    row("B-spline colour vs its method in reals", &colour.bspline_vs_own);
    println!();
    println!("wrote {}: {};", out.display(), written.join(", "));
    println!("      polar_surface_light_error_heat, polar_wrap_pixels, below_horizon_{{ideal,cartesian,polar}} .png;");
    println!("      fig8a_blinn, fig8b_bspline, colour_{{reference,bilinear,bspline}} .png;");
    let vcds: Vec<String> =
        std::iter::once(&on_torus).chain(&runs).map(|r| format!("{}.vcd", r.pipe.model().name)).collect();
    println!("      {}; verilog/{}", vcds.join(", "), if synth { "; synth/" } else { "" });
    println!("wall time {:.1} s", wall.elapsed().as_secs_f64());
    let bad: Vec<String> = std::iter::once(&on_torus)
        .chain(&runs)
        .filter(|r| r.mism_split + r.mism_hdl + r.mism_vl != 0)
        .map(|r| {
            let (name, split) = (r.pipe.model().name, r.mism_split);
            format!("{name} model on {SPLIT} threads {split} / rust-hdl {} / Verilator {}", r.mism_hdl, r.mism_vl)
        })
        .collect();
    if !bad.is_empty() {
        return Err(format!("the bit-exact paths disagree with the model (pixels that differ): {}", bad.join("; ")));
    }
    Ok(())
}

/// Hardware cost, one column per pipeline, one block of rows per part.
fn hardware_table(names: &[&str], hw: &[Vec<(synth::fpga::Part, synth::fpga::Fit)>]) {
    use synth::fpga::Fit;
    let Some(first) = hw.first() else { return };
    let row = |label: &str, f: &dyn Fn(&Fit, &synth::fpga::Part) -> String, k: usize| {
        let cells: String = hw.iter().map(|h| format!(" {:>22}", f(&h[k].1, &h[k].0))).collect();
        println!("{label:<34}{cells}");
    };
    for (k, (part, _)) in first.iter().enumerate() {
        let header: String = names.iter().map(|n| format!(" {n:>22}")).collect();
        println!(
            "{:<34}{header}",
            format!(
                "{} ({})",
                part.name,
                if part.family == synth::fpga::Family::Ice40 { "yosys -dsp" } else { "yosys synth_ecp5" }
            )
        );
        let placed = |f: &Fit, g: &dyn Fn(&synth::fpga::SynthReport) -> String| match f {
            Fit::Placed(r) => g(r),
            Fit::DoesNotFit(_) => "-".to_string(),
        };
        let pct = |n: u64, of: u64| format!("{n} ({:.0}%)", 100.0 * n as f64 / of as f64);
        row("LUT4 / FF", &|f, _| placed(f, &|r| format!("{} / {}", r.cells.lut4, r.cells.ff)), k);
        row(
            &format!("DSP of {} / BRAM of {}", part.dsp, part.bram),
            &|f, p| placed(f, &|r| format!("{} / {}", pct(r.cells.dsp, p.dsp), r.cells.bram)),
            k,
        );
        row(
            &format!("logic cells of {} (placed)", part.lut4),
            &|f, p| placed(f, &|r| r.lc.map(|x| pct(x, p.lut4)).unwrap_or("-".into())),
            k,
        );
        row(
            "fmax, 1 pixel/clock (placements)",
            &|f, _| match f {
                Fit::Placed(r) => match (&r.place_error, r.fmax_mhz) {
                    (Some(_), _) => r.unplaced_text(),
                    (None, Some(x)) => format!("{x:.1} MHz ({})", r.placed_of()),
                    _ => "-".into(),
                },
                Fit::DoesNotFit(_) => "does not fit".into(),
            },
            k,
        );
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
    println!(
        "fmax: the median of the placements in brackets; the demo places nextpnr seed 1 where the cache holds none \
         and reuses any of seeds 1 … 5 it holds (`bumprtl synth` and `report` place all five)"
    );
}
