//! `bumprtl widths <unit>`: every signal of the unit's rtl block, by its VCD name, with the fixed-point format its
//! source declares and the range it takes over the unit's vectors in rust-hdl (every input when the unit has at most
//! 2^20, else its hard cases and `--count` random vectors): the bits that range needs, the spare bits at the top,
//! and a flag where two or more of them go unused. See `sim::widths`.

use indicatif::{ProgressBar, ProgressStyle};
use rtl::StreamUnit;
use sim::widths::{bits_needed, seen_ticking, Formats};
use vectors::UnitModel;

/// One signal's row.
pub struct Row {
    pub name: String,
    pub format: String,
    pub q: String,
    pub bits: usize,
    pub signed: bool,
    pub min: i64,
    pub max: i64,
    pub needed: usize,
}

impl Row {
    pub fn spare(&self) -> usize {
        self.bits.saturating_sub(self.needed)
    }
    /// two or more bits at the top never used by the data seen
    pub fn unused_flag(&self) -> bool {
        self.spare() >= 2
    }
}

/// The unit's signals and their seen ranges; (rows, vectors, what the vectors were, clocks probed).
pub fn measure<U: StreamUnit>(m: &UnitModel, count: usize, seed: u64) -> Result<(Vec<Row>, usize, String, u64), String> {
    let exhaustive = m.exhaustive.is_some();
    let inputs = vectors::unit::generate(m, exhaustive, count, seed)?;
    let what = if exhaustive {
        format!("every input ({})", inputs.len())
    } else {
        format!("{} hard cases and {count} random vectors (seed {seed})", inputs.len() - count)
    };
    let bar = ProgressBar::new(inputs.len() as u64);
    bar.set_style(ProgressStyle::with_template("{msg:<24} [{bar:40}] {pos}/{len} vectors {eta}").unwrap().progress_chars("=> "));
    bar.set_message(format!("rust-hdl: {}", m.name));
    let ranges = seen_ticking::<U>(m, &inputs, &|k| bar.set_position(k as u64));
    bar.finish_and_clear();
    let f = Formats::of::<U>();
    let mut rows = vec![];
    for s in &ranges.signals {
        let Some(fmt) = f.format(&s.name) else { continue }; // clocks: no value to range
        let (min, max) = if fmt.signed { (s.smin, s.smax) } else { (s.umin as i64, s.umax as i64) };
        rows.push(Row { needed: bits_needed(fmt.signed, min, max), name: s.name.clone(), q: fmt.q(), format: fmt.name, bits: fmt.bits, signed: fmt.signed, min, max });
    }
    Ok((rows, inputs.len(), what, ranges.clocks))
}

pub fn csv(rows: &[Row]) -> String {
    let mut t = String::from("signal,format,q,bits,signed,seen_min,seen_max,bits_needed,spare,unused_flag\n");
    for r in rows {
        t.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{}\n",
            r.name, r.format.replace(',', ";"), r.q, r.bits, r.signed as u8, r.min, r.max, r.needed, r.spare(), r.unused_flag() as u8
        ));
    }
    t
}

pub fn run<U: StreamUnit>(m: &UnitModel, count: usize, seed: u64, csv_out: Option<&std::path::Path>) -> Result<(), String> {
    let t = std::time::Instant::now();
    let (rows, n, what, clocks) = measure::<U>(m, count, seed)?;
    let secs = t.elapsed().as_secs_f64();
    if let Some(p) = csv_out {
        synth::export::write_atomic(p, csv(&rows).as_bytes())?;
    }
    println!("widths of `{}`: {what}; {clocks} clocks in rust-hdl, every signal probed ({:.0} vectors/s)", m.name, n as f64 / secs);
    println!("ranges seen in simulation: bits needed by the data, spare bits at the top; ! marks two or more unused");
    let w = rows.iter().map(|r| r.name.len()).max().unwrap_or(6).max(6);
    println!("{:<w$} {:>10} {:>9} {:>5} {:>24} {:>6} {:>6}", "signal", "format", "Q", "bits", "seen min .. max", "needs", "spare");
    for r in &rows {
        println!(
            "{:<w$} {:>10} {:>9} {:>5} {:>24} {:>6} {:>6} {}",
            r.name, r.format, r.q, r.bits, format!("{} .. {}", r.min, r.max), r.needed, r.spare(), if r.unused_flag() { "!" } else { "" }
        );
    }
    let flagged = rows.iter().filter(|r| r.unused_flag()).count();
    let spare: usize = rows.iter().map(Row::spare).sum();
    println!("{} signals, {spare} spare bits in all, {flagged} with two or more unused", rows.len());
    if let Some(p) = csv_out {
        println!("wrote {}", p.display());
    }
    Ok(())
}
