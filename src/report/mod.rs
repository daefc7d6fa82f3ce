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

//!
//! The module by concern: `points` (which points, their ids), `measure` (one point computed), `split` (the shade
//! error's three parts), `figures` (what a point measured, saved and read back), `pareto` (the Pareto set, the
//! cheapest within a budget), `markdown` and `plot` (the report's two outputs), `plan` (the points as commands).

mod figures;
mod markdown;
mod measure;
mod pareto;
mod plan;
mod plot;
mod points;
mod split;

use self::figures::PointFigures;
use self::markdown::markdown;
use self::measure::run_point;
pub use self::plan::plan;
use self::plot::plot;
pub use self::points::DEFAULT_SCENES;
use self::points::{points, Point};
use std::path::Path;
use std::time::Instant;

/// `bumprtl report`: every point in this process, then the report.
pub fn run(
    scenes: &[String],
    out: &Path,
    budgets: &[f64],
    place: Option<u32>,
    only: Option<&str>,
) -> Result<(), String> {
    let pts: Vec<Point> = points(scenes)?.into_iter().filter(|p| only.is_none_or(|o| p.id.contains(o))).collect();
    if pts.is_empty() {
        return Err(format!("report: no point matches --only {}", only.unwrap_or("")));
    }
    crate::output::writable_folder(out)?;
    let dir = out.join("points");
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let wall = Instant::now();
    let mut rs = vec![];
    for (k, p) in pts.iter().enumerate() {
        let step = crate::progress::Step::new(&format!("[{}/{}] {}", k + 1, pts.len(), p.id), None);
        let r = run_point(p, out, place)?;
        step.done("a point");
        synth::export::write_atomic(&dir.join(format!("{}.txt", p.id)), r.to_text().as_bytes())?;
        rs.push(r);
    }
    finish(&rs, out, budgets)?;
    println!("{} points in {:.1} s", rs.len(), wall.elapsed().as_secs_f64());
    Ok(())
}

/// The report from saved points: Markdown and the Pareto plot into `out`, the table on standard output.
pub fn finish(rs: &[PointFigures], out: &Path, budgets: &[f64]) -> Result<(), String> {
    let md = markdown(rs, budgets);
    synth::export::write_atomic(&out.join("report.md"), md.as_bytes())?;
    plot(rs, &out.join("pareto.png"))?;
    // the same as a page, the Pareto plot first
    let plot = crate::page::Section {
        title: "Error against cost".into(),
        blocks: vec![crate::page::Block::Figures(vec![crate::page::Figure {
            src: "pareto.png".into(),
            caption: "each point's colour error against its cost; the Pareto front joined".into(),
            bar: None,
        }])],
    };
    let (index, _) = crate::page::Page::from_markdown(&md, plot).write(out)?;
    print!("{md}");
    println!("\nwrote {}, {}, {}", out.join("report.md").display(), out.join("pareto.png").display(), index.display());
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
        match std::fs::read_to_string(&f).ok().and_then(|t| PointFigures::from_text(&t)) {
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
pub fn one(scenes: &[String], id: &str, out: &Path, place: Option<u32>) -> Result<(), String> {
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
