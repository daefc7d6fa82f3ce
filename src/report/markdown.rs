//! The report as Markdown.

use super::figures::{PointFigures, LUT4_PER_MAC16};
use super::pareto::{cheapest, pareto};
use std::fmt::Write as _;

/// The report as Markdown: one table (the model's speed in its own column, the only figure a rerun changes), the
/// budgets' answers.
pub fn markdown(rs: &[PointFigures], budgets: &[f64]) -> String {
    let on = pareto(rs);
    let fmax = |r: &PointFigures| match (r.fmax, r.fmax_range) {
        (Some(m), Some((lo, hi))) => format!("{m:.1} ({lo:.1}–{hi:.1}, {})", r.placements),
        (Some(m), None) => format!("{m:.1} ({})", r.placements),
        (None, _) => "-".into(),
    };
    let f2 = |x: Option<(f64, f64)>| x.map(|(a, b)| format!("{a:.3} / {b:.2}")).unwrap_or("-".into());
    let mut s = String::new();
    let _ = writeln!(s, "# bumprtl report\n");
    let _ = writeln!(
        s,
        "Error against each scene's f64 ideal, 8-bit LSB (mean / max; angle in degrees). The shade's error split: encoding, method, datapath \
         (a palette's quantization is its encoding; a height map's parts are taken through its B-spline). Cost: iCE40 yosys cells (products beyond the UP5K's 8 SB_MAC16 in logic); \
         `cost` = SB_LUT4 + {LUT4_PER_MAC16}·SB_MAC16; `est.`: the pipeline plus the swept unit's difference. P: on the scene's Pareto set of cost \
         against mean colour error. fmax: the median of nextpnr's placements at seeds 1 … n that place, with the slowest and the fastest (the part column names seeds that did not).\n"
    );
    let _ = writeln!(s, "| point | pipeline | knob | colour | shade | angle ° | encoding | method | datapath | LUT4 | FF | MAC16 | RAM40 | SPRAM | in logic | cost | part | LC | fmax MHz (min–max, placements) | latency | P | model Mpx/s |");
    let _ = writeln!(s, "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    for (r, p) in rs.iter().zip(&on) {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {}{} | {} | {} | {} | {} | {} | {:.2} |",
            r.id, r.pipeline, r.knob, f2(Some(r.colour)), f2(Some(r.shade)), f2(r.angle), f2(r.encoding), f2(r.method), f2(r.datapath),
            r.lut4, r.ff, r.dsp, r.bram, r.spram, r.soft, r.cost(), if r.estimated { " est." } else { "" }, r.part,
            r.lc.map(|x| x.to_string()).unwrap_or("-".into()), fmax(r),
            if r.clocks() == 1 { r.latency.to_string() } else { format!("{}, {} clocks a pixel", r.latency, r.clocks()) },
            if *p { "P" } else { "" }, r.model_mpx
        );
    }
    let _ = writeln!(
        s,
        "\nThe AXI4-Stream wrapper (`bumprtl verilog` writes `<pipeline>_axis.v`): its output FIFO holds latency + 2 \
         words, the fewest that keep one beat a clock; what it adds, its control and FIFO synthesised alone in iCE40 \
         cells, and that as a share of the pipeline's own.\n"
    );
    let _ = writeln!(
        s,
        "| pipeline | latency | FIFO places | RAM words × bits | LUT4 | FF | RAM40 | LUT4 share | FF share |"
    );
    let _ = writeln!(s, "| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    let mut seen = std::collections::BTreeSet::new();
    for r in rs.iter().filter(|r| !r.estimated && seen.insert(r.pipeline.clone())) {
        let Some(a) = r.axis else { continue };
        let share =
            |x: u64, of: u64| if of == 0 { "-".to_string() } else { format!("{:.1} %", 100.0 * x as f64 / of as f64) };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} × {} | {} | {} | {} | {} | {} |",
            r.pipeline,
            r.latency,
            a.depth,
            a.words,
            a.bits,
            a.lut4,
            a.ff,
            a.bram,
            share(a.lut4, r.lut4),
            share(a.ff, r.ff)
        );
    }
    for b in budgets {
        let _ = writeln!(s, "\nBudget {b} 8-bit LSB mean colour error:");
        for (scene, c) in cheapest(rs, *b) {
            match c {
                Some(r) => {
                    let _ = writeln!(
                        s,
                        "- {scene}: {} ({}{}), cost {}{}, colour {:.3} / {:.2}",
                        r.id,
                        r.units,
                        if r.knob == "-" { String::new() } else { format!("; {}", r.knob) },
                        r.cost(),
                        if r.estimated { " est." } else { "" },
                        r.colour.0,
                        r.colour.1
                    );
                }
                None => {
                    let _ = writeln!(s, "- {scene}: no configuration meets it");
                }
            }
        }
    }
    s
}
