//! `bumprtl render SCENE.toml --out DIR`: a scene file through the pipeline it names, on four paths: the f64 ideal,
//! the bit-exact model, Verilator on the exported Verilog for the whole frame (where it is installed), and rust-hdl
//! for a window, traced to a VCD. The rtl paths must equal the model on every pixel they render; the command fails
//! if they do not. The scene is read (or refused) before anything is written.

use crate::page::{Block, Figure, Page, Section, Table};
use sim::render::{self, Window};
use std::path::Path;
use std::time::Instant;

/// The side of the default window: the centre 8 × 8 pixels.
pub const WINDOW: usize = 8;

/// `x,y,w,h` in pixels.
pub fn parse_window(s: &str) -> Result<Window, String> {
    let v: Vec<usize> = s
        .split(',')
        .map(|p| p.trim().parse::<usize>().map_err(|_| format!("--window `{s}`: four whole numbers x,y,w,h")))
        .collect::<Result<_, _>>()?;
    let [x, y, w, h] = v[..] else {
        return Err(format!("--window `{s}`: four whole numbers x,y,w,h, not {}", v.len()));
    };
    if w == 0 || h == 0 {
        return Err(format!("--window `{s}`: an empty window ({w} × {h})"));
    }
    Ok(Window { x, y, w, h })
}

/// A row of an error table: what, mean, max, where the max is ("none" where nothing was measured).
pub fn error_row(name: String, s: &vectors::stats::ErrorStats) -> Vec<String> {
    match s.count {
        0 => vec![name, "none".into(), "none".into(), String::new()],
        _ => vec![name, format!("{:.3}", s.mean()), format!("{:.3}", s.max), s.argmax.clone()],
    }
}

/// The heat map of the model's colour error against the ideal (the worst channel), written to `dir/file` with its
/// bar ending at the 99th percentile, and its figure for the page (`src` the file as the page links it).
pub fn colour_error_heat(
    pipe: &dyn sim::pipeline::Pipeline,
    prep: &sim::prepared::Prepared,
    model: &render::Image,
    largest: f64,
    dir: &Path,
    file: &str,
    src: String,
) -> Result<Figure, String> {
    let n = prep.ideal.len();
    let err: Vec<f64> = (0..n).map(|k| render::colour_err(pipe.colour(&model.outs[k]), prep.ideal[k].rgb)).collect();
    let hmax = render::heat_scale(err.iter().copied());
    let by = prep.by_place();
    render::write_heat_png(&dir.join(file), prep.size, |at| by[at].map(|k| err[k]), hmax, "LSB")?;
    Ok(Figure {
        src,
        caption: format!(
            "the model's colour error against the ideal, worst channel; white from {hmax:.0} LSB (99% of the pixels \
             are below), the largest {largest:.2} LSB"
        ),
        bar: Some((hmax, "LSB")),
    })
}

pub fn run(path: &Path, out: &Path, window: Option<Window>, verilator: bool) -> Result<(), String> {
    let wall = Instant::now();
    let spec = sim::scene_file::load(path)?;
    let scene = &spec.scene;
    let size = scene.size;
    if let Some(w) = window {
        if w.x + w.w > size || w.y + w.h > size {
            return Err(format!("--window {},{},{},{}: outside the {size} × {size} frame", w.x, w.y, w.w, w.h));
        }
    }
    let no_vl = synth::tools::missing(&["verilator", "make", "g++"]);
    crate::output::writable_folder(out)?;
    for n in &spec.notes {
        println!("{n}");
    }
    let stem = path.file_stem().map_or("scene".into(), |s| s.to_string_lossy().into_owned());
    let pipe = spec.build();
    let (m, rtl) = (pipe.model(), pipe.rtl());
    println!("scene: {} ({}), {size} × {size}", spec.name, path.display());
    println!("pipeline: {} ({}, latency {} clocks): {}", m.name, pipe.label(), rtl.latency(), pipe.describe(scene));
    println!("  units: {}", pipe.units().join(" → "));

    let step = crate::progress::Step::new(&format!("{}: the ideal and the model", m.name), None);
    let t = Instant::now();
    let prep = pipe.prepare(scene);
    let ideal_s = t.elapsed().as_secs_f64();
    let n = prep.ideal.len();
    // the window: the one asked for, or 8 × 8 round the covered pixel nearest the frame's centre
    let win = window.unwrap_or_else(|| {
        let c = (size / 2) as i64;
        let near = (0..n).map(|k| prep.frame_index(k)).min_by_key(|&at| {
            let (x, y) = ((at % size) as i64, (at / size) as i64);
            (x - c).pow(2) + (y - c).pow(2)
        });
        let (x, y) = near.map_or((size / 2, size / 2), |at| (at % size, at / size));
        let corner = |v: usize| v.saturating_sub(WINDOW / 2).min(size - WINDOW);
        Window { x: corner(x), y: corner(y), w: WINDOW, h: WINDOW }
    });

    // the window's pixels, refused before any simulation when the surface covers none of them
    let wprep = pipe.trim(win.of(&prep));
    if wprep.ideal.is_empty() {
        return Err(format!("--window {},{},{},{}: the surface covers no pixel of it", win.x, win.y, win.w, win.h));
    }
    let threads = render::cores();
    let model = render::fastest(|| render::model_on(m, &prep, threads));
    step.done(&format!("{n} px, {} runs", render::RUNS));
    // Verilator, the whole frame
    let vl = if verilator && no_vl.is_empty() {
        let step = crate::progress::Step::new(&format!("{}: Verilator, built and run", m.name), None);
        let v = rtl.verilator(m, &prep, &out.join("verilator").join(m.name), 2)?;
        step.done(&format!("{n} px, {} runs each way", render::RUNS));
        Some(v)
    } else {
        None
    };
    // rust-hdl, the window, traced
    let vcd = out.join(format!("{stem}_window.vcd"));
    let step = crate::progress::Step::new(&format!("{}: rust-hdl, the window traced", m.name), None);
    let t = Instant::now();
    let hdl = rtl.traced(m, &wprep, &vcd)?;
    let hdl_s = t.elapsed().as_secs_f64();
    step.done(&format!("{} vectors", wprep.inputs.len()));
    let wpx = win.pixels(&prep);
    let mism_hdl = wpx.iter().zip(&hdl).filter(|(&k, o)| model.outs[k] != **o).count() + wpx.len().abs_diff(hdl.len());
    let mism_vl = vl.as_ref().map(|v| v.image.mismatches(&model) + v.single.mismatches(&model));

    // pictures
    let to8 = |x: f64| x.round().clamp(0.0, 255.0) as u8;
    let by = prep.by_place();
    // each place of the frame: its pixel's colour, or the background
    let png = |what: &str, f: &dyn Fn(usize) -> [u8; 3]| {
        render::write_png(&out.join(format!("{stem}_{what}.png")), size, |at| by[at].map_or(render::BACKGROUND, f))
    };
    png("ideal", &|k| prep.ideal[k].rgb.map(to8))?;
    png("model", &|k| pipe.colour(&model.outs[k]))?;
    if let Some(v) = &vl {
        png("verilator", &|k| pipe.colour(&v.image.outs[k]))?;
    }
    png("shade", &|k| [to8(pipe.shade(&model.outs[k])); 3])?;
    let e = sim::pipeline::errors(pipe.as_ref(), scene, &prep, &model);
    let file = format!("{stem}_error_heat.png");
    let heat = colour_error_heat(pipe.as_ref(), &prep, &model, e.colour.max, out, &file, file.clone())?;

    println!();
    println!("{n} pixels of the surface in the {size} × {size} frame");
    println!("{:<44} {:>14} {:>12}", "path", "pixels/s", "mismatches");
    println!("{:<44} {:>14.0} {:>12}", "f64 ideal (set-up included)", n as f64 / ideal_s.max(1e-9), "-");
    println!("{:<44} {:>14.0} {:>12}", render::on_threads("bit-exact model", threads), model.pixels_per_second(), "-");
    match &vl {
        Some(v) => println!(
            "{:<44} {:>14.0} {:>12}",
            render::on_threads("Verilator, whole frame", v.threads),
            v.image.pixels_per_second(),
            mism_vl.unwrap_or(0)
        ),
        None if !verilator => println!("Verilator: skipped (--no-verilator)"),
        None => println!("Verilator: skipped, {} not installed (`bash .ci/run` installs the tools)", no_vl.join(", ")),
    }
    println!(
        "{:<44} {:>14.0} {:>12}",
        format!("rust-hdl, window {}×{} at ({}, {}), traced", win.w, win.h, win.x, win.y),
        wpx.len() as f64 / hdl_s.max(1e-9),
        mism_hdl
    );
    println!();
    let row = |name: &str, s: &vectors::stats::ErrorStats| {
        println!("{name:<44} {:>9.3} {:>9.3}   {}", s.mean(), s.max, s.argmax)
    };
    println!("{:<44} {:>9} {:>9}   max at", "the model against the scene's ideal", "mean", "max");
    row(&format!("shade, 8-bit LSB ({})", pipe.shade_name()), &e.shade);
    row("blended colour, 8-bit LSB", &e.colour);
    if let Some(s) = &e.normal {
        row("normal angle, degrees", s);
    }
    if let Some(s) = &e.surface {
        row("shade vs the ideal under its one light", s);
    }
    println!();
    let vl_png = if vl.is_some() { format!("{stem}_verilator.png, ") } else { String::new() };
    println!("wrote {}: {stem}_{{ideal,model,shade,error_heat}}.png, {vl_png}{stem}_window.vcd", out.display());
    // the page: the pictures, the paths and the error, the files
    let fig = |what: &str, caption: String| Figure { src: format!("{stem}_{what}.png"), caption, bar: None };
    let mut figs = vec![fig("ideal", "the f64 ideal".into()), fig("model", "the bit-exact model".into())];
    if let (Some(v), Some(m)) = (&vl, mism_vl) {
        figs.push(fig(
            "verilator",
            format!("Verilator on the exported Verilog, {} threads ({m} pixels differ)", v.threads),
        ));
    }
    figs.push(fig("shade", format!("the shade alone ({})", pipe.shade_name())));
    figs.push(heat);
    let mut paths = Table::new(
        &format!("{n} pixels of the surface in the {size} × {size} frame"),
        &["path", "pixels/s", "pixels that differ from the model"],
    );
    paths.rows.push(vec![
        "f64 ideal (set-up included)".into(),
        format!("{:.0}", n as f64 / ideal_s.max(1e-9)),
        "-".into(),
    ]);
    paths.rows.push(vec![
        render::on_threads("bit-exact model", threads),
        format!("{:.0}", model.pixels_per_second()),
        "-".into(),
    ]);
    if let Some(v) = &vl {
        paths.rows.push(vec![
            render::on_threads("Verilator, whole frame", v.threads),
            format!("{:.0}", v.image.pixels_per_second()),
            mism_vl.unwrap_or(0).to_string(),
        ]);
    }
    paths.rows.push(vec![
        format!("rust-hdl, window {}×{} at ({}, {}), traced", win.w, win.h, win.x, win.y),
        format!("{:.0}", wpx.len() as f64 / hdl_s.max(1e-9)),
        mism_hdl.to_string(),
    ]);
    let mut errors = Table::new("The model against the scene's ideal", &["what", "mean", "max", "max at"]);
    let mut erow = |name: String, s: &vectors::stats::ErrorStats| errors.rows.push(error_row(name, s));
    erow(format!("shade, 8-bit LSB ({})", pipe.shade_name()), &e.shade);
    erow("blended colour, 8-bit LSB".into(), &e.colour);
    if let Some(s) = &e.normal {
        erow("normal angle, degrees".into(), s);
    }
    if let Some(s) = &e.surface {
        erow("shade vs the ideal under its one light".into(), s);
    }
    let page = Page {
        title: format!("bumprtl render: {}", spec.name),
        intro: vec![
            format!(
                "{} through {} ({}, latency {} clocks): {}.",
                path.display(),
                m.name,
                pipe.label(),
                rtl.latency(),
                pipe.describe(scene)
            ),
            format!("Its units, in order: {}.", pipe.units().join(" → ")),
        ],
        sections: vec![
            Section { title: "Pictures".into(), blocks: vec![Block::Figures(figs)] },
            Section { title: "Paths".into(), blocks: vec![Block::Table(paths)] },
            Section { title: "Error".into(), blocks: vec![Block::Table(errors)] },
            Section {
                title: "Waveform".into(),
                blocks: vec![Block::Links(vec![
                    (format!("{stem}_window.vcd"), format!("{stem}_window.vcd")),
                    (format!("{stem}_window.gtkw (GTKWave)"), format!("{stem}_window.gtkw")),
                ])],
            },
        ],
    };
    // named for the scene, as its pictures are: several scenes can share a folder
    let (index, _) = page.write_as(out, &format!("{stem}.html"), &format!("{stem}.md"))?;
    println!("wall time {:.1} s", wall.elapsed().as_secs_f64());
    println!("the page: {}", index.display());
    let bad = mism_hdl + mism_vl.unwrap_or(0);
    if bad != 0 {
        return Err(format!(
            "the rtl disagrees with the model: rust-hdl {mism_hdl} of {} window pixels, Verilator {} of {n} (each of two runs)",
            wpx.len(),
            mism_vl.map_or("-".into(), |v| v.to_string())
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_window_is_four_whole_numbers_and_not_empty() {
        assert_eq!(parse_window("1,2,3,4"), Ok(Window { x: 1, y: 2, w: 3, h: 4 }));
        assert_eq!(parse_window(" 0, 0 ,8,8"), Ok(Window { x: 0, y: 0, w: 8, h: 8 }));
        for bad in ["1,2,3", "1,2,3,4,5", "a,b,c,d", "1,2,0,4", "-1,0,4,4", ""] {
            let e = parse_window(bad).unwrap_err();
            assert!(e.contains("--window") && !e.contains('\n'), "{e}");
        }
    }
}
