//! Printed tables: accuracy (error with where its max occurs) and synthesis figures.

use vectors::stats::ErrorStats;

fn stat_line(unit: &str, metric: &str, s: &ErrorStats) {
    println!("{unit:<13} {metric:<52} {:>9.4} {:>9.4}   {}", s.mean(), s.max, s.argmax);
}

pub fn accuracy(directions: usize, samples: usize) {
    println!("{:<13} {:<52} {:>9} {:>9}   {}", "unit", "error (exact against ideal)", "mean", "max", "max at");
    for r in sim::accuracy::units(samples, 1) {
        stat_line(&r.unit, &r.metric, &r.stats);
    }
    for r in sim::accuracy::encoders(directions, 2) {
        stat_line(&r.unit, &r.metric, &r.stats);
    }
    println!("\nnormalise seed table and Newton steps (model; the rtl has 10 table bits, no Newton step):");
    println!("{:>11} {:>7} {:>24} {:>9}", "table bits", "Newton", "mean err (Sq1.10 LSB)", "max");
    for (t, n, s) in sim::accuracy::normaliser_tradeoff(samples, 3) {
        println!("{t:>11} {n:>7} {:>24.4} {:>9.4}", s.mean(), s.max);
    }
}

pub fn synth_row(r: &synth::ice40::SynthReport) {
    println!(
        "{:<14} LUT4 {:>5}  carry {:>4}  FF {:>5}  DSP {:>2}  BRAM {:>2}  LC {:>5}  fmax {:>6}  latency {:>2}{}",
        r.unit,
        r.lut4,
        r.carry,
        r.ff,
        r.dsp,
        r.bram,
        r.lc.map(|x| x.to_string()).unwrap_or("-".into()),
        r.fmax_mhz.map(|x| format!("{x:.1}")).unwrap_or("-".into()),
        r.latency,
        if r.dsp_fallback { "  (more than 8 DSPs: placed with LUT multipliers)" } else { "" }
    );
    if let Some(e) = &r.place_error {
        println!("{:<14} does not place on an UP5K SG48: {e}", "");
    }
}
