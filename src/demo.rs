//! `bumprtl demo`: the embedded default scene through every pipeline — US 6,819,319's Cartesian (second embodiment,
//! with the seed's texels and with hemi-octahedral ones) and polar (first embodiment, FIG. 3), each on the texture
//! unit where its memory holds the map, US 2004/0207631's height map, Tarini et al.'s palette at s_N = 256 and
//! 4,096 — each through four paths (f64 ideal, bit-exact model, rust-hdl, Verilator), with pictures, waveforms, the
//! Verilog and its testbenches, US 6,819,319's polar shortcomings shown, and tables of speed, hardware cost and
//! error, all on one page (`crate::page`: `index.html`, `summary.md`) and a one-screen summary on the terminal. The
//! synthesis runs beside the rendering at a lower priority (`crate::hardware::Pool`). The pipelines do the work
//! (`sim::pipeline`); this file is the command's flow and its printing.

use crate::hardware::Cost;
use crate::page::{Block, Figure, Page, Section, Table};
use crate::progress::Step;
use sim::pipeline::{Height, Palette, Pipeline, Polar};
use sim::prepared::Prepared;
use sim::render::{self, Image};
use sim::scene::Scene;
use sim::shortcomings::Shortcomings;
use std::path::Path;
use std::time::Instant;
use synth::fpga::{Family, ECP5_45F};
use vectors::polar_encode::Scale;
use vectors::stats::ErrorStats;

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
fn peer_table(scene: &Scene) -> Table {
    let ways = crate::progress::step(
        "the model beside float software",
        |w: &Vec<_>| Some(format!("{} ways", w.len())),
        || sim::peer::compare(scene, SPLIT),
    );
    let mut t = Table::new(
        &format!(
            "The bit-exact model beside float software on the quad ({} cart_pipeline pixels, the same input vectors)",
            ways[0].image.outs.len()
        ),
        &["way", "pixels/s", "shade mean", "shade max", "colour mean", "colour max"],
    );
    for w in &ways {
        let (s, c) = (&w.errors.shade, &w.errors.colour);
        t.rows.push(vec![
            w.what.to_string(),
            format!("{:.0}", w.image.pixels_per_second()),
            format!("{:.3}", s.mean()),
            format!("{:.2}", s.max),
            format!("{:.3}", c.mean()),
            format!("{:.2}", c.max),
        ]);
    }
    let (peer, lanes, model) = (&ways[1].image, &ways[2].image, &ways[3].image);
    t.note = Some(format!(
        "The model takes {:.1}× the f32 peer's time on one thread from the same vectors, {:.1}× from its lanes.",
        model.seconds / peer.seconds.max(1e-9),
        model.seconds / lanes.seconds.max(1e-9)
    ));
    t
}

/// rust-hdl's simulation of the runs `which` picks, two at a time (it is one thread each, and the longest path of the
/// demo's rendering), each held to its model.
fn rust_hdl_runs(runs: &mut [Run], which: &[bool]) {
    // taken from the end: the longest (the texture unit's pipelines, first in the demo's order) first
    let mut picked: Vec<&mut Run> = runs.iter_mut().zip(which).filter(|x| *x.1).map(|x| x.0).collect();
    picked.reverse();
    let total: u64 = picked.iter().map(|r| r.prep.inputs.len() as u64).sum();
    let step = Step::new(&format!("rust-hdl, {} pipelines two at a time", picked.len()), Some(total));
    let done = std::sync::atomic::AtomicU64::new(0);
    let queue = std::sync::Mutex::new(picked);
    std::thread::scope(|s| {
        for _ in 0..SPLIT {
            s.spawn(|| loop {
                let Some(r) = queue.lock().unwrap_or_else(|e| e.into_inner()).pop() else { break };
                let (m, rtl) = (r.pipe.model(), r.pipe.rtl());
                let t = Instant::now();
                // the bar counts both threads' vectors: each adds what it ran since its last tick
                let prev = std::cell::Cell::new(0u64);
                let hdl = rtl.rust_hdl(m, &r.prep, &|k| {
                    let d = (k as u64).saturating_sub(prev.replace(k as u64));
                    step.tick(done.fetch_add(d, std::sync::atomic::Ordering::Relaxed) + d);
                });
                if !crate::progress::drawn() {
                    let n = r.prep.inputs.len();
                    eprintln!("{}: rust-hdl: {n} vectors, {:.1} s", m.name, t.elapsed().as_secs_f64());
                }
                r.mism_hdl = hdl.mismatches(&r.model);
                r.hdl = Some(hdl);
            });
        }
    });
    step.done(&format!("{total} vectors"));
}

/// The threads the model's and Verilator's split frames run on, beside their one-thread runs.
const SPLIT: usize = 2;

fn run_pipeline<'a>(pipe: &'a dyn Pipeline, scene: &Scene, out: &Path, verilator: bool) -> Result<Run<'a>, String> {
    let (m, rtl) = (pipe.model(), pipe.rtl());
    let step = Step::new(&format!("{}: the ideal and the model", m.name), None);
    let t = Instant::now();
    let prep = pipe.prepare(scene);
    let ideal_s = t.elapsed().as_secs_f64();
    // each the fastest of its runs, as Verilator's are
    let model = render::fastest(|| render::model(m, &prep));
    let split = render::fastest(|| render::model_on(m, &prep, SPLIT));
    let mism_split = split.mismatches(&model);
    step.done(&format!("{} px, {} runs each way", prep.ideal.len(), render::RUNS));
    let vl = if verilator {
        let step = Step::new(&format!("{}: Verilator, built and run", m.name), None);
        let vl = rtl.verilator(m, &prep, &out.join("verilator").join(m.name), SPLIT)?;
        step.done(&format!("{} px, {} runs each way", prep.ideal.len(), render::RUNS));
        Some(vl)
    } else {
        None
    };
    // both Verilator runs, the one-thread and the split one, against the model
    let mism_vl = vl.as_ref().map(|r| r.image.mismatches(&model) + r.single.mismatches(&model)).unwrap_or(0);
    let sim::pipeline::Errors { shade, colour, normal, surface } = sim::pipeline::errors(pipe, scene, &prep, &model);
    Ok(Run {
        pipe,
        prep,
        ideal_s,
        model,
        split,
        hdl: None,
        vl,
        mism_split,
        mism_hdl: 0,
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
    let no_yosys: Vec<String> = if synth {
        synth::tools::toolchain().missing().into_iter().filter(|p| p.contains("yosys")).collect()
    } else {
        vec![]
    };
    let no_ecp5 = synth::tools::nextpnr_ecp5().is_none().then(synth::tools::nextpnr_ecp5_missing);
    let synth = synth && no_yosys.is_empty();

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
    // the hardware cost, synthesised beside the rendering (at a lower priority, so the speeds it reports are the
    // rendering's own) and cached: the scene's own pipeline placed on the ECP5-45F (the part that holds every
    // pipeline of the demo), and every pipeline's cells there from yosys alone, for the comparison; every part and
    // placement is `report`'s
    let hdir = out.join("synth");
    let place = no_ecp5.is_none();
    let mut jobs: Vec<(String, crate::hardware::Job<'static>)> = vec![];
    for (i, p) in std::iter::once(torus_pipe.as_ref()).chain(pipes.iter().map(|p| p.0)).enumerate() {
        let (rtl, name, hd) = (sim::units::unit(p.model().name)?.rtl, p.model().name, hdir.clone());
        let job: crate::hardware::Job<'static> = if i == 0 && place {
            Box::new(move |say| rtl.measure(&hd, &[ECP5_45F], crate::hardware::DEMO_SEEDS, say).map(Cost::Placed))
        } else {
            Box::new(move |say| {
                say(format!("yosys: {name} on the ECP5"));
                rtl.synth_unit(&hd.join(name).join("cells"), Family::Ecp5).map(Cost::Cells)
            })
        };
        jobs.push((name.to_string(), job));
    }
    let pool = synth.then(|| crate::hardware::Pool::start(jobs));
    let rendered = run_pipeline(torus_pipe.as_ref(), &torus, out, no_vl.is_empty()).and_then(|t| {
        let mut runs = pipes
            .iter()
            .map(|&(p, _)| run_pipeline(p, &scene, out, no_vl.is_empty()))
            .collect::<Result<Vec<Run>, String>>()?;
        rust_hdl_runs(&mut runs, &pipes.map(|p| p.1));
        Ok((t, runs))
    });
    let (on_torus, runs) = match rendered {
        Ok(r) => r,
        Err(e) => {
            if let Some(p) = pool {
                p.cancel();
                let _ = p.join();
            }
            return Err(e);
        }
    };
    let polar_setup = polar.set_up(&scene);
    let sc = Shortcomings::measure(
        &scene,
        &polar,
        &polar_setup,
        &runs[2].model,
        (cart.as_ref(), &runs[0].prep, &runs[0].model),
    );

    // pictures: per pipeline, then the shortcomings; each kind of file in its own folder
    let (img, wave, vdir) = (out.join("img"), out.join("wave"), out.join("verilog"));
    for d in [&img, &wave, &vdir] {
        std::fs::create_dir_all(d).map_err(|e| format!("cannot create {}: {e}", d.display()))?;
    }
    let to8 = |x: f64| x.round().clamp(0.0, 255.0) as u8;
    let png = |name: &str, f: &dyn Fn(usize) -> [u8; 3]| render::write_png(&img.join(name), size, f);
    let mut page = Page {
        title: "bumprtl: bump-mapping hardware from two patents and a paper, checked bit for bit".into(),
        intro: vec![],
        sections: vec![],
    };
    let pictures = Step::new("pictures", None);
    let mut n_png = 0;
    for (r, name, sc_) in
        std::iter::once((&on_torus, "torus", &torus)).chain(runs.iter().map(|r| (r, r.pipe.model().name, &scene)))
    {
        // pixel k of the run at its place in the frame; places the surface does not cover are background
        let by = r.prep.by_place();
        let mut figs = vec![];
        let mut each = |what: &str, caption: String, f: &dyn Fn(usize) -> [u8; 3]| -> Result<(), String> {
            let file = format!("{name}_{what}.png");
            png(&file, &|at| by[at].map_or(render::BACKGROUND, f))?;
            figs.push(Figure { src: format!("img/{file}"), caption, bar: None });
            Ok(())
        };
        each("ideal", "the f64 ideal".into(), &|k| r.prep.ideal[k].rgb.map(to8))?;
        each("model", "the bit-exact model".into(), &|k| r.pipe.colour(&r.model.outs[k]))?;
        if let Some(hdl) = &r.hdl {
            let c = format!("rust-hdl's simulator ({} pixels differ from the model)", r.mism_hdl);
            each("rust_hdl", c, &|k| r.pipe.colour(&hdl.outs[k]))?;
        }
        if let Some(vl) = &r.vl {
            let c = format!("Verilator on the exported Verilog ({} pixels differ)", vl.image.mismatches(&r.model));
            each("verilator", c, &|k| r.pipe.colour(&vl.image.outs[k]))?;
        }
        each("shade", format!("the shade alone ({})", r.pipe.shade_name()), &|k| {
            [to8(r.pipe.shade(&r.model.outs[k])); 3]
        })?;
        let file = format!("{name}_error_heat.png");
        let src = format!("img/{file}");
        figs.push(crate::render::colour_error_heat(r.pipe, &r.prep, &r.model, r.colour.max, &img, &file, src)?);
        n_png += figs.len();
        let m = r.pipe.model().name;
        let title = if name == "torus" {
            format!("The demo's torus: {m}")
        } else {
            format!("{} on the quad: {m}", r.pipe.label())
        };
        page.sections.push(Section {
            title,
            blocks: vec![
                // as the pipeline says it (it may begin with a symbol, s_N, whose case is its meaning)
                Block::Text(r.pipe.describe(sc_)),
                Block::Text(format!("Its units, in order: {}.", r.pipe.units().join(" → "))),
                Block::Figures(figs),
            ],
        });
    }
    let pol = &runs[2];
    let serr: Vec<f64> =
        (0..pol.prep.ideal.len()).map(|k| (pol.pipe.shade(&pol.model.outs[k]) - sc.surface_ideal[k]).abs()).collect();
    let smax = render::heat_scale(serr.iter().copied());
    let pol_by = pol.prep.by_place();
    render::write_heat_png(
        &img.join("polar_surface_light_error_heat.png"),
        size,
        |at| pol_by[at].map(|k| serr[k]),
        smax,
        "LSB",
    )?;
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
    pictures.done(&format!("{} PNG", n_png + 10));

    // waveforms of the first pixels with their GTKWave save files, and the Verilog with a self-checking testbench of
    // those pixels' vectors (the model's outputs expected) and the AXI4-Stream wrapper with its own
    let exports = Step::new("waveforms and Verilog", None);
    let mut wave_links = vec![];
    let mut verilog_links = vec![];
    for r in std::iter::once(&on_torus).chain(&runs) {
        let (m, rtl) = (r.pipe.model(), r.pipe.rtl());
        let vectors = r.pipe.waveform(&r.prep);
        rtl.write_vcd(m, &vectors, &wave.join(format!("{}.vcd", m.name)))?;
        wave_links.push((format!("{}.vcd", m.name), format!("wave/{}.vcd", m.name)));
        wave_links.push((format!("{}.gtkw (GTKWave)", m.name), format!("wave/{}.gtkw", m.name)));
        let ins: Vec<Vec<u64>> = vectors.iter().map(|v| vectors::unit::to_patterns(v, m.inputs)).collect();
        let outs: Vec<Vec<u64>> = m.run(&vectors).iter().map(|v| vectors::unit::to_patterns(v, m.outputs)).collect();
        let source = format!("bumprtl demo, the first {} vectors of {}'s frame", vectors.len(), m.name);
        let unit = sim::units::unit(m.name)?;
        let mut files = rtl.selfcheck(&vdir, &ins, &outs, &source)?;
        files.extend(unit.axis.selfcheck(&vdir, ins.len(), &source)?);
        for f in files {
            let file = f.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
            if file.ends_with(".v") {
                verilog_links.push((file.clone(), format!("verilog/{file}")));
            }
        }
    }
    exports.done(&format!("{} VCD, {} Verilog files", wave_links.len() / 2, verilog_links.len()));

    let hw = pool.map(|p| p.join());
    let source = match height_map {
        Some(p) => {
            format!("{} ({}x{}, white {:.2} texels above black)", p.display(), scene.tex, scene.tex, scene.relief)
        }
        None => format!("a procedural {t}x{t} height map", t = scene.tex),
    };
    let covered = on_torus.prep.ideal.len();
    page.intro = vec![
        format!(
            "Every pipeline below is a synthesizable rust-hdl design. Each frame was computed in f64 (the ideal), by \
             the bit-exact software model and by Verilator on the exported Verilog, and four of the quad's frames \
             also by rust-hdl's simulator (the tests run every pipeline through it); every path must agree with the \
             model on every pixel, and the error heat maps measure the model against the ideal. Frames are {size} × \
             {size}."
        ),
        format!(
            "The torus ({covered} pixels) wears {source} repeated 6 × 2 round it, lit by a point light whose \
             direction is interpolated per pixel from the triangles' corners; the quad shows every pipeline on the \
             same map under four vertex lights towards a point light."
        ),
    ];
    let mut skipped = vec![];
    if !no_vl.is_empty() {
        skipped.push(format!(
            "Verilator path skipped: {} not installed (`bash demo.sh` installs the tools)",
            no_vl.join(", ")
        ));
    }
    if !no_yosys.is_empty() {
        skipped.push(format!(
            "synthesis figures skipped: {} not installed (`bash demo.sh` installs the tools)",
            no_yosys.join(", ")
        ));
    } else if let (true, Some(e)) = (synth, &no_ecp5) {
        skipped.push(format!("the placement on the ECP5 skipped (cells from yosys only): {e}"));
    }
    // a synthesis job that failed leaves its row without figures, and says why here
    let names = std::iter::once(&on_torus).chain(&runs).map(|r| r.pipe.model().name);
    for (name, c) in names.zip(hw.iter().flatten()) {
        if let Cost::Failed(e) = c {
            skipped.push(format!("synthesis of {name} failed: {e}"));
        }
    }

    // the tables: speed, error, hardware, the model beside float software, the shortcomings and the variants
    let all: Vec<&Run> = std::iter::once(&on_torus).chain(&runs).collect();
    let pps = |i: &Image| format!("{:.0}", i.pixels_per_second());
    let mut speed = Table::new(
        "Throughput, pixels a second (pixels that differ from the model in brackets)",
        &[
            "pipeline",
            "unit",
            "bits per texel",
            "f64 ideal (set-up included)",
            &render::on_threads("bit-exact model", 1),
            &render::on_threads("bit-exact model", SPLIT),
            "rust-hdl (loop-driven)",
            "Verilator, 1 thread",
            &format!("Verilator, {SPLIT} threads"),
            "Verilator bare loop, cycles/s",
            "1 thread against the bare loop",
        ],
    );
    for (i, r) in all.iter().enumerate() {
        let n = r.prep.ideal.len();
        let vl = |f: &dyn Fn(&render::VerilatorRun) -> String| r.vl.as_ref().map(f).unwrap_or("skipped".into());
        speed.rows.push(vec![
            if i == 0 { "torus".into() } else { r.pipe.label().to_string() },
            r.pipe.model().name.to_string(),
            r.pipe.bits_per_texel().to_string(),
            format!("{:.0}", n as f64 / r.ideal_s),
            pps(&r.model),
            format!("{} ({})", pps(&r.split), r.mism_split),
            r.hdl.as_ref().map(|h| format!("{} ({})", pps(h), r.mism_hdl)).unwrap_or("in the tests".into()),
            vl(&|v| format!("{} ({})", pps(&v.single), v.single.mismatches(&r.model))),
            vl(&|v| format!("{} ({})", pps(&v.image), v.image.mismatches(&r.model))),
            vl(&|v| format!("{:.0}", v.bare_cycles_per_second)),
            vl(&|v| {
                format!("{:.2}", (v.single.size * v.single.size) as f64 / v.single.seconds / v.bare_cycles_per_second)
            }),
        ]);
    }
    let mut errors =
        Table::new("Error of the bit-exact models against the scene's ideal", &["what", "mean", "max", "max at"]);
    let row = |t: &mut Table, name: String, s: &ErrorStats| t.rows.push(crate::render::error_row(name, s));
    for (i, r) in all.iter().enumerate() {
        let l = if i == 0 { "torus".to_string() } else { r.pipe.label().to_string() };
        row(&mut errors, format!("{l} shade, 8-bit LSB ({})", r.pipe.shade_name()), &r.shade);
        row(&mut errors, format!("{l} blended colour, 8-bit LSB"), &r.colour);
        if let Some(nrm) = &r.normal {
            row(&mut errors, format!("{l} normal angle, degrees"), nrm);
        }
        if let Some(s) = &r.surface {
            row(&mut errors, format!("{l} shade vs the ideal under its one light"), s);
        }
    }
    let peer = peer_table(&scene);
    let mut short =
        Table::new("US 6,819,319's polar shortcomings, shade in 8-bit LSB", &["what", "mean", "max", "max at"]);
    row(&mut short, "polar shade vs an ideal lit by the surface's light".into(), &sc.surface);
    row(&mut short, "polar shade vs equation 3 + powf on its own codes".into(), &sc.own);
    row(&mut short, format!("(b) polar, {} px filtered across R's wrap", sc.wrap.count), &sc.wrap);
    row(&mut short, "    the other pixels (both vs the surface light)".into(), &sc.rest);
    row(&mut short, "    Cartesian shade on the wrap pixels".into(), &sc.wrap_cartesian);
    row(&mut short, format!("(a) light {:.1}° below the horizon: Cartesian N·L", sc.low_below_deg), &sc.low_cartesian);
    row(&mut short, format!("    polar N·L, the light moved onto it: {}", sc.low_moved), &sc.low_polar);
    let n8 = sim::variants::FIG8_TEXELS;
    let mut variants = Table::new(
        &format!("US 2004/0207631's variants (bit-exact models; {n8}x{n8} maps magnified to {size}x{size})"),
        &["what", "mean", "max", "max at"],
    );
    row(&mut variants, "bilinear colour vs the f64 picture, 8-bit LSB".into(), &colour.bilinear_vs_reference);
    row(&mut variants, "B-spline colour (¶87) vs the f64 picture, 8-bit LSB".into(), &colour.bspline_vs_reference);
    row(&mut variants, "bilinear colour vs its method in reals".into(), &colour.bilinear_vs_own);
    row(&mut variants, "B-spline colour vs its method in reals".into(), &colour.bspline_vs_own);
    variants.note = Some(format!(
        "FIG. 8a/8b, largest jump across a texel edge (methods in reals): N·L derivative Blinn {:.4}, B-spline {:.4}; \
         cross tangent derivative Blinn {:.4}, B-spline {:.4}",
        fig8.jumps.blinn.0, fig8.jumps.bspline.0, fig8.jumps.blinn.1, fig8.jumps.bspline.1
    ));
    let fig = |file: &str, caption: &str| Figure { src: format!("img/{file}"), caption: caption.into(), bar: None };
    page.sections
        .insert(0, Section { title: "At a glance".into(), blocks: vec![Block::Table(glance(&all, hw.as_deref()))] });
    page.sections.push(Section { title: "Speed".into(), blocks: vec![Block::Table(speed), Block::Table(peer)] });
    page.sections.push(Section { title: "Error".into(), blocks: vec![Block::Table(errors)] });
    if let Some(hw) = &hw {
        let names: Vec<&str> =
            all.iter().enumerate().map(|(i, r)| if i == 0 { "torus" } else { r.pipe.label() }).collect();
        let units: Vec<&str> = all.iter().map(|r| r.pipe.model().name).collect();
        page.sections.push(Section { title: "Hardware".into(), blocks: hardware_tables(&names, &units, hw) });
    }
    page.sections.push(Section {
        title: "US 6,819,319's polar shortcomings".into(),
        blocks: vec![
            Block::Figures(vec![
                Figure {
                    src: "img/polar_surface_light_error_heat.png".into(),
                    caption: format!(
                        "the polar shade against an ideal lit by the surface's one light: where the polar form's own \
                         approximation shows; white from {smax:.0} LSB, the largest {:.2} LSB",
                        sc.surface.max
                    ),
                    bar: Some((smax, "LSB")),
                },
                fig(
                    "polar_wrap_pixels.png",
                    "(b) magenta: the pixels whose four texels' R straddle the 255 → 0 wrap, \
                     which bilinear filtering of R gets wrong",
                ),
                fig("below_horizon_ideal.png", "(a) the light below the horizon: the ideal shade"),
                fig("below_horizon_cartesian.png", "(a) the Cartesian pipeline's shade: it follows the ideal"),
                fig("below_horizon_polar.png", "(a) the polar pipeline's shade: the light moved onto the horizon"),
            ]),
            Block::Table(short),
        ],
    });
    page.sections.push(Section {
        title: "US 2004/0207631's variants".into(),
        blocks: vec![
            Block::Figures(vec![
                fig("fig8a_blinn.png", "FIG. 8a, Blinn's normals: look for the creases along texel edges"),
                fig("fig8b_bspline.png", "FIG. 8b, the B-spline normals: the same map without the creases"),
                fig("colour_reference.png", "a colour map in f64: the reference"),
                fig("colour_bilinear.png", "bilinear colour: look for the diamonds at texel corners"),
                fig("colour_bspline.png", "B-spline colour (¶87): smoother, a little blurred"),
            ]),
            Block::Table(variants),
        ],
    });
    let mut files = vec![Block::Text(
        "The first pixels of each frame as a waveform (with a GTKWave save file: valid flags, ports, then each \
         block's registers stage by stage), and each pipeline's Verilog with a self-checking testbench of those \
         pixels' vectors, bare and behind its AXI4-Stream wrapper."
            .into(),
    )];
    files.push(Block::Links(wave_links));
    files.push(Block::Links(verilog_links));
    page.sections.push(Section { title: "Waveforms and Verilog".into(), blocks: files });
    if !skipped.is_empty() {
        page.sections.push(Section {
            title: "Skipped".into(),
            blocks: skipped.iter().map(|s| Block::Text(s.clone())).collect(),
        });
    }
    let (index, md) = page.write(out)?;

    // the terminal's summary: one screen, the rest on the page
    for l in wrap(&format!("bumprtl demo: {size}x{size} frames of {source}; every path held to the model"), 100) {
        println!("{l}");
    }
    let e = &on_torus;
    println!("torus ({covered} px) through {}:", e.pipe.model().name);
    for l in wrap(&e.pipe.units().join(" → "), 96) {
        println!("  {l}");
    }
    let vl = e.vl.as_ref().map(|v| format!(", Verilator {}/s", si(v.image.pixels_per_second()))).unwrap_or_default();
    println!(
        "  model {}/s{vl}; colour error {:.3} / {:.3} LSB mean / max",
        si(e.model.pixels_per_second()),
        e.colour.mean(),
        e.colour.max
    );
    println!();
    let w = all.iter().map(|r| r.pipe.model().name.len()).max().unwrap_or(8);
    let head = format!(
        "{:<w$} {:>10} {:>10} {:>6} {:>15}",
        "pipeline", "model px/s", "Verilator", "differ", "colour mean/max"
    );
    match hw {
        Some(_) => println!("{head} {:>6} {:>4} {:>4}", "LUT4", "DSP", "BRAM"),
        None => println!("{head}"),
    }
    for (i, r) in all.iter().enumerate() {
        let line = format!(
            "{:<w$} {:>10} {:>10} {:>6} {:>15}",
            r.pipe.model().name,
            si(r.model.pixels_per_second()),
            r.vl.as_ref().map(|v| si(v.image.pixels_per_second())).unwrap_or("skipped".into()),
            r.mism_split + r.mism_hdl + r.mism_vl,
            format!("{:.2} / {:.2}", r.colour.mean(), r.colour.max)
        );
        match hw.as_ref().and_then(|h| cells_of(&h[i])) {
            Some(c) => println!("{line} {:>6} {:>4} {:>4}", c.lut4, c.dsp, c.bram),
            None => println!("{line}"),
        }
    }
    if let Some(h) = &hw {
        println!("(cells: yosys synth_ecp5 alone, each pipeline on the ECP5)");
        if let Some(r) = placed_of(&h[0]) {
            println!("{} placed on the {}: {}", on_torus.pipe.model().name, ECP5_45F.name, fmax_text(r));
        }
    }
    println!();
    for s in &skipped {
        for l in wrap(s, 100) {
            println!("{l}");
        }
    }
    println!("every table: {}", md.display());
    println!("wall time {:.1} s", wall.elapsed().as_secs_f64());
    println!("the page: {}", index.display());
    let bad: Vec<String> = all
        .iter()
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

/// A synthesis job's cells: yosys's alone, or the placed run's.
fn cells_of(c: &Cost) -> Option<synth::fpga::Cells> {
    match c {
        Cost::Cells(c) => Some(*c),
        _ => placed_of(c).map(|r| r.cells),
    }
}

/// A placed job's report.
fn placed_of(c: &Cost) -> Option<&synth::fpga::SynthReport> {
    match c {
        Cost::Placed(p) => p.first().and_then(|(_, f)| match f {
            synth::fpga::Fit::Placed(r) => Some(r),
            synth::fpga::Fit::DoesNotFit(_) => None,
        }),
        Cost::Cells(_) | Cost::Failed(_) => None,
    }
}

/// A placement's fmax with its count of placements, or why there is none.
fn fmax_text(r: &synth::fpga::SynthReport) -> String {
    match (&r.place_error, r.fmax_mhz) {
        (Some(_), _) => r.unplaced_text(),
        (None, Some(x)) => format!("fmax {x:.1} MHz ({}), latency {} clocks", r.placed_of(), r.latency),
        _ => "no fmax".into(),
    }
}

/// Each pipeline in one row: what it is, its units, its speed through the model and Verilator, the pixels where a
/// path differs from the model, its colour error, and its cells on the ECP5.
fn glance(all: &[&Run], hw: Option<&[Cost]>) -> Table {
    let mut header =
        vec!["pipeline", "units", "model px/s", "Verilator px/s", "pixels that differ", "colour error, LSB mean / max"];
    if hw.is_some() {
        header.extend(["LUT4, ECP5", "DSP", "BRAM"]);
    }
    let mut t = Table::new("Every pipeline of the demo: the torus's first, then the quad's", &header);
    for (i, r) in all.iter().enumerate() {
        let mut row = vec![
            format!("{}{}", if i == 0 { "torus: " } else { "" }, r.pipe.label()),
            r.pipe.units().join(" → "),
            si(r.model.pixels_per_second()),
            r.vl.as_ref().map(|v| si(v.image.pixels_per_second())).unwrap_or("skipped".into()),
            (r.mism_split + r.mism_hdl + r.mism_vl).to_string(),
            format!("{:.2} / {:.2}", r.colour.mean(), r.colour.max),
        ];
        if let Some(h) = hw {
            match cells_of(&h[i]) {
                Some(c) => row.extend([c.lut4, c.dsp, c.bram].map(|x| x.to_string())),
                None => row.extend(["-", "-", "-"].map(String::from)),
            }
        }
        t.rows.push(row);
    }
    let mut note = String::from(
        "Pixels that differ: the model split across threads, rust-hdl and Verilator, each against the model on one \
         thread; the demo fails if any is not 0.",
    );
    if hw.is_some() {
        note.push_str(" Cells: yosys synth_ecp5 on each pipeline alone (the Hardware section places the torus's).");
    }
    t.note = Some(note);
    t
}

/// `text` cut into lines of at most `width` characters, at spaces.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = vec![];
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(l) if l.chars().count() + 1 + word.chars().count() <= width => {
                l.push(' ');
                l.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

/// A rate with an SI prefix: 1234567 → "1.23 M".
fn si(x: f64) -> String {
    match x {
        x if x >= 1e9 => format!("{:.2} G", x / 1e9),
        x if x >= 1e6 => format!("{:.2} M", x / 1e6),
        x if x >= 1e3 => format!("{:.1} k", x / 1e3),
        x => format!("{x:.0}"),
    }
}

/// Hardware cost on the ECP5: every pipeline's cells from yosys alone, then the scene's own pipeline placed.
fn hardware_tables(names: &[&str], units: &[&str], hw: &[Cost]) -> Vec<Block> {
    let p = ECP5_45F;
    let mut cells = Table::new(
        &format!("{}: each pipeline alone, yosys synth_ecp5 (no placement)", p.title),
        &["pipeline", "unit", "LUT4", "FF", &format!("DSP of {}", p.dsp), &format!("BRAM of {}", p.bram), "carry"],
    );
    let pct = |n: u64, of: u64| format!("{n} ({:.0}%)", 100.0 * n as f64 / of as f64);
    for ((n, u), h) in names.iter().zip(units).zip(hw) {
        let mut row = vec![n.to_string(), u.to_string()];
        match cells_of(h) {
            Some(c) => row.extend([
                c.lut4.to_string(),
                c.ff.to_string(),
                pct(c.dsp, p.dsp),
                pct(c.bram, p.bram),
                c.carry.to_string(),
            ]),
            None => row.extend(["-"; 5].map(String::from)),
        }
        cells.rows.push(row);
    }
    cells.note = Some(
        "Every part (the iCE40 UP5K among them), every placement and the error each choice buys: `bumprtl report`; \
         one unit or a scene's pipeline on the part it fits: `bumprtl synth`."
            .into(),
    );
    let mut blocks = vec![Block::Table(cells)];
    if let Some(r) = placed_of(&hw[0]) {
        let mut t = Table::new(
            &format!("{}: the torus's pipeline, {}, placed by nextpnr-ecp5 in a serial I/O wrapper", p.title, units[0]),
            &["logic cells (placed)", "fmax, 1 pixel a clock", "placements", "latency, clocks", "critical path"],
        );
        t.rows.push(vec![
            r.lc.map(|x| pct(x, p.lut4)).unwrap_or("-".into()),
            r.fmax_mhz.filter(|_| r.place_error.is_none()).map_or_else(|| r.unplaced_text(), |x| format!("{x:.1} MHz")),
            r.placed_of(),
            r.latency.to_string(),
            r.critical.clone().unwrap_or_default(),
        ]);
        t.note = Some(
            "fmax: the median of the placements; the demo places nextpnr seed 1 where the cache holds none and reuses \
             any of seeds 1 … 5 it holds (`bumprtl synth` and `report` place all five)."
                .into(),
        );
        blocks.push(Block::Table(t));
    }
    blocks
}
