//! What a point measured, and its cost scalar; saved and read back as `key=value` lines.

use std::fmt::Write as _;
use vectors::stats::ErrorStats;

/// The cost scalar the Pareto set and the budgets rank by: iCE40 SB_LUT4 plus this many per SB_MAC16. Measured on
/// this flow: moving ten of cart_surface_matte's products from SB_MAC16 blocks into logic added 2,648 SB_LUT4.
pub const LUT4_PER_MAC16: u64 = 265;

/// What a point measured: everything the report prints, saved as `key=value` lines.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PointFigures {
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
    /// the UP5K's single-port RAM blocks (a texture unit's map)
    pub spram: u64,
    pub soft: u64,
    pub estimated: bool,
    pub lc: Option<u64>,
    /// the median placement's fmax, the slowest and fastest placement's, and how many placements (nextpnr seeds)
    pub fmax: Option<f64>,
    pub fmax_range: Option<(f64, f64)>,
    pub placements: u32,
    pub latency: usize,
    /// clocks a pixel (2 for a two-clock variant; 0 read as 1: `clocks`)
    pub interval: usize,
    /// the AXI4-Stream wrapper around the pipeline: its FIFO and what it adds in iCE40 cells
    pub axis: Option<AxisCost>,
}

/// What the AXI4-Stream wrapper adds to a pipeline: its output FIFO (places, RAM words, bits a word) and the iCE40
/// cells of its control and FIFO, synthesised alone.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AxisCost {
    pub depth: usize,
    pub words: usize,
    pub bits: usize,
    pub lut4: u64,
    pub ff: u64,
    pub bram: u64,
}

impl PointFigures {
    /// Clocks a pixel: 1, or k for a k-clock variant.
    pub fn clocks(&self) -> usize {
        self.interval.max(1)
    }

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
            ("spram", self.spram.to_string()),
            ("soft", self.soft.to_string()),
            ("estimated", self.estimated.to_string()),
            ("lc", o(self.lc.map(|x| x.to_string()))),
            ("fmax", o(self.fmax.map(|x| x.to_string()))),
            ("fmax_range", o(self.fmax_range.map(|(a, b)| format!("{a} {b}")))),
            ("placements", self.placements.to_string()),
            ("latency", self.latency.to_string()),
            ("interval", self.interval.to_string()),
            (
                "axis",
                o(self.axis.map(|a| format!("{} {} {} {} {} {}", a.depth, a.words, a.bits, a.lut4, a.ff, a.bram))),
            ),
        ] {
            let _ = writeln!(s, "{k}={v}");
        }
        s
    }

    pub fn from_text(text: &str) -> Option<PointFigures> {
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
        Some(PointFigures {
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
            spram: num("spram").unwrap_or(0),
            soft: num("soft")?,
            estimated: get("estimated")? == "true",
            lc: get("lc").filter(|v| !v.is_empty()).and_then(|v| v.parse().ok()),
            fmax: get("fmax").filter(|v| !v.is_empty()).and_then(|v| v.parse().ok()),
            fmax_range: get("fmax_range").and_then(|v| {
                let (a, b) = v.split_once(' ')?;
                Some((a.parse().ok()?, b.parse().ok()?))
            }),
            placements: get("placements").and_then(|v| v.parse().ok()).unwrap_or(0),
            latency: get("latency")?.parse().ok()?,
            interval: get("interval").and_then(|v| v.parse().ok()).unwrap_or(1),
            axis: get("axis").and_then(|v| {
                match v.split(' ').filter_map(|x| x.parse::<u64>().ok()).collect::<Vec<_>>()[..] {
                    [depth, words, bits, lut4, ff, bram] => Some(AxisCost {
                        depth: depth as usize,
                        words: words as usize,
                        bits: bits as usize,
                        lut4,
                        ff,
                        bram,
                    }),
                    _ => None,
                }
            }),
        })
    }
}

pub(super) fn stats(s: &ErrorStats) -> (f64, f64) {
    (s.mean(), s.max)
}

#[cfg(test)]
mod tests {
    use super::*;
    fn r(id: &str, scene: &str, lut4: u64, dsp: u64, err: f64) -> PointFigures {
        PointFigures { id: id.into(), scene: scene.into(), lut4, dsp, colour: (err, err * 10.0), ..Default::default() }
    }

    #[test]
    fn a_saved_point_reads_back_whole() {
        let mut a = r("quad.cart_surface.t6n1f8d0", "quad", 1234, 6, 0.75);
        (a.angle, a.encoding, a.method, a.datapath, a.fmax, a.lc, a.estimated, a.spram) =
            (Some((0.1, 2.0)), Some((0.2, 3.0)), None, Some((0.5, 1.5)), Some(37.5), Some(3082), true, 4);
        (a.fmax_range, a.placements, a.interval) = (Some((36.25, 39.0)), 5, 2);
        (a.units, a.knob, a.pipeline, a.part, a.model_mpx) =
            ("x → y".into(), "normalise 2^6 table, 1 Newton".into(), "cart_surface".into(), "up5k".into(), 12.5);
        assert_eq!(PointFigures::from_text(&a.to_text()), Some(a.clone()));
        a.axis = Some(AxisCost { depth: 50, words: 64, bits: 24, lut4: 95, ff: 27, bram: 1 });
        assert_eq!(PointFigures::from_text(&a.to_text()), Some(a));
        assert_eq!(PointFigures::from_text("id=x\n"), None);
    }
}
