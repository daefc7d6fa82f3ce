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
    for r in sim::accuracy::encoders(directions, 2).into_iter().chain(sim::accuracy::polar_encoders(directions, 2)) {
        stat_line(&r.unit, &r.metric, &r.stats);
    }
    println!("\nnormalise seed table and Newton steps (model; the rtl has 10 table bits, no Newton step):");
    println!("{:>11} {:>7} {:>24} {:>9}", "table bits", "Newton", "mean err (Sq1.10 LSB)", "max");
    for (t, n, s) in sim::accuracy::normaliser_tradeoff(samples, 3) {
        println!("{t:>11} {n:>7} {:>24.4} {:>9.4}", s.mean(), s.max);
    }
}

/// The LUT-size tables of the sine/cosine unit [10] and the cosine unit with sign [18]: entries and width against
/// error (every input) and, when `cost` is on, against what yosys makes of the rtl block of that size for iCE40.
pub fn lut_sizes(cost: bool) -> Result<(), String> {
    use rtl::cos_sign::CosSign;
    use rtl::sincos::SinCos;
    use synth::ice40::synth_unit;
    let dir = std::env::temp_dir().join(format!("bumprtl-lut-{}", std::process::id()));
    println!("\nsin/cos unit [10]: table size and width (10-bit elevation in; error in 8-bit LSB; the rtl has 256 × 8):");
    lut_header();
    for r in sim::accuracy::sincos_sizes() {
        let (tb, d) = (r.entries.trailing_zeros(), dir.join(format!("sincos_t{}w{}", r.entries, r.width)));
        let c = if !cost {
            None
        } else {
            Some(match (tb, r.width) {
                (6, 8) => synth_unit::<SinCos<6, 8>>(&d),
                (8, 8) => synth_unit::<SinCos<8, 8>>(&d),
                (10, 8) => synth_unit::<SinCos<10, 8>>(&d),
                (6, 10) => synth_unit::<SinCos<6, 10>>(&d),
                (8, 10) => synth_unit::<SinCos<8, 10>>(&d),
                (10, 10) => synth_unit::<SinCos<10, 10>>(&d),
                (6, 12) => synth_unit::<SinCos<6, 12>>(&d),
                (8, 12) => synth_unit::<SinCos<8, 12>>(&d),
                (10, 12) => synth_unit::<SinCos<10, 12>>(&d),
                other => return Err(format!("no rtl sincos of size {other:?}")),
            }?)
        };
        lut_row(&r, c.as_ref());
    }
    println!("\ncosine unit with sign [18]: table size and width (d = R − Q in; error of the signed cosine, 8-bit LSB):");
    lut_header();
    for r in sim::accuracy::cos_sign_sizes() {
        let (tb, d) = (r.entries.trailing_zeros(), dir.join(format!("cos_sign_t{}w{}", r.entries, r.width)));
        let c = if !cost {
            None
        } else {
            Some(match (tb, r.width) {
                (4, 8) => synth_unit::<CosSign<4, 8>>(&d),
                (6, 8) => synth_unit::<CosSign<6, 8>>(&d),
                (8, 8) => synth_unit::<CosSign<8, 8>>(&d),
                (4, 12) => synth_unit::<CosSign<4, 12>>(&d),
                (6, 12) => synth_unit::<CosSign<6, 12>>(&d),
                (8, 12) => synth_unit::<CosSign<8, 12>>(&d),
                other => return Err(format!("no rtl cos_sign of size {other:?}")),
            }?)
        };
        lut_row(&r, c.as_ref());
    }
    let _ = std::fs::remove_dir_all(&dir);
    Ok(())
}

fn lut_header() {
    println!("{:>8} {:>6} {:>10} {:>9} {:>7} {:>6} {:>5} {:>5}", "entries", "width", "mean", "max", "max at", "LUT4", "FF", "BRAM");
}

fn lut_row(r: &vectors::sincos::SizeRow, c: Option<&synth::ice40::SynthReport>) {
    let f = |x: Option<u64>| x.map(|v| v.to_string()).unwrap_or("-".into());
    println!(
        "{:>8} {:>6} {:>10.4} {:>9.4} {:>7} {:>6} {:>5} {:>5}",
        r.entries, r.width, r.mean_lsb8, r.max_lsb8, r.max_at, f(c.map(|c| c.lut4)), f(c.map(|c| c.ff)), f(c.map(|c| c.bram))
    );
}

pub fn synth_row(r: &synth::ice40::SynthReport) {
    println!(
        "{:<18} LUT4 {:>5}  carry {:>4}  FF {:>5}  DSP {:>2}  BRAM {:>2}  LC {:>5}  fmax {:>6}  latency {:>2}{}",
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
        println!("{:<18} does not place on an UP5K SG48: {e}", "");
    }
}
