//! The report's points: every pipeline of the table that renders a scene, the width knobs on the Cartesian
//! pipeline with one light per surface, the polar elevation table's sizes; each with its id.

use sim::pipeline::Pipeline;
use sim::pipelines::{self, Family, Row, Settings, PIPELINES};
use sim::scene::Scene;
use std::path::Path;
use vectors::cart_pipeline::Decode;
use vectors::cart_surface::{Knobs, Variant, UNIT_KNOBS};
use vectors::polar_encode::Scale;

/// A pipeline of the table, as a report point builds it: the row, and the height map's bits (8, or 4 read doubled:
/// the same block; a point of its own). The polar pipelines are built at a scene's default power and weight, the
/// palette ones at their largest palette.
pub(super) fn build(p: &Point, scene: &Scene) -> Box<dyn Pipeline> {
    sim::pipeline::build(p.row, scene, &settings(p))
}

pub(super) fn settings(p: &Point) -> Settings {
    Settings { height_bits: p.height_bits, ..Settings::default() }
}

/// The scenes a report sweeps when none are named: the demo's torus and the quad.
pub const DEFAULT_SCENES: [&str; 2] = ["demo", "quad"];

/// A scene by the name a point carries: `demo` and `quad` are the embedded ones, anything else a scene file.
pub fn scene(name: &str) -> Result<Scene, String> {
    match name {
        "demo" => Ok(sim::scene_file::demo()?.scene),
        "quad" => Ok(sim::scene_file::quad()?.scene),
        path => Ok(sim::scene_file::load(Path::new(path))?.scene),
    }
}

/// The knob settings swept on the Cartesian pipeline with one light per surface, beside its own.
pub(super) fn knob_settings() -> Vec<Knobs> {
    let n = |table_bits, newton| Knobs { table_bits, newton, ..UNIT_KNOBS };
    let b = |blend_bits, drop| Knobs { blend_bits, drop, ..UNIT_KNOBS };
    vec![n(6, 0), n(6, 1), n(8, 0), n(12, 0), b(6, 0), b(4, 0), b(8, 4)]
}

pub(super) fn knob_text(k: Knobs) -> String {
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

pub(super) fn knob_id(k: Knobs) -> String {
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
pub(super) const LUT_SETTINGS: [u32; 1] = [6];
pub(super) const OWN_LUT: u32 = vectors::sincos::TABLE_BITS;

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

pub(super) fn scene_key(name: &str) -> String {
    Path::new(name).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| name.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
