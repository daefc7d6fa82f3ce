//! `bumprtl widths <unit>`: every signal of the unit's rtl block, by its VCD name, with the fixed-point format its
//! source declares and the range it takes over the unit's vectors in rust-hdl (every input when the unit has at most
//! 2^20, else its hard cases and `--count` random vectors): the bits that range needs, the spare bits at the top,
//! and a flag where two or more of them go unused. See `sim::widths`.

use indicatif::{ProgressBar, ProgressStyle};
use rtl::StreamUnit;
use sim::widths::{bits_needed, bounds, mismatches, seen_ticking, sites, wraps::Waived, Formats};
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
    /// the proven range in the same reading (every input sequence), the bits it needs
    pub proven: (i128, i128),
    pub proven_needed: usize,
    /// the step that writes it may wrap: the exact hull of what it computes, which the declared range does not hold
    pub wrap: Option<(i128, i128)>,
    /// that step's entry in `sim::widths::wraps` (deliberate, or argued in range), if it is listed
    pub listed: Option<&'static Waived>,
}

impl Row {
    pub fn spare(&self) -> usize {
        self.bits.saturating_sub(self.needed)
    }
    /// two or more bits at the top never used by the data seen
    pub fn unused_flag(&self) -> bool {
        self.spare() >= 2
    }
    /// spare bits at the top over every input
    pub fn proven_spare(&self) -> usize {
        self.bits.saturating_sub(self.proven_needed)
    }
    /// `W` a step that may wrap and is not listed (a risk), `w` one that wraps on purpose, `a` one argued in range
    pub fn wrap_flag(&self) -> Option<char> {
        self.wrap.map(|_| self.listed.map_or('W', |l| l.kind.flag()))
    }
}

/// What the width report measured: the rows, the vectors run, what they were, the clocks probed, and the vectors
/// whose rtl outputs differ from the model's.
pub struct Measured {
    pub rows: Vec<Row>,
    pub vectors: usize,
    pub what: String,
    pub clocks: u64,
    pub mismatches: usize,
}

/// The unit's signals, their seen and proven ranges, and the rtl against the model on the same vectors.
pub fn measure<U: StreamUnit>(m: &UnitModel, count: usize, seed: u64) -> Result<Measured, String> {
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
    let ports: Vec<(&str, i64, i64)> = m.inputs.iter().map(|p| (p.name, p.range().0, p.range().1)).collect();
    let signed = |n: &str| f.format(n).is_some_and(|x| x.signed);
    let proof = bounds::prove(&U::build(), &ports, &signed);
    let proven = &proof.values;
    let sites = sites(&f, &proof);
    let mut rows = vec![];
    for s in &ranges.signals {
        let Some(fmt) = f.format(&s.name) else { continue }; // clocks: no value to range
        let (min, max) = if fmt.signed { (s.smin, s.smax) } else { (s.umin as i64, s.umax as i64) };
        let p = proven.get(&s.name).copied().unwrap_or(bounds::V::full(fmt.bits as u32));
        let pr = p.range(fmt.signed);
        rows.push(Row {
            needed: bits_needed(fmt.signed, min, max),
            proven_needed: bits_needed(fmt.signed, pr.0 as i64, pr.1 as i64),
            proven: pr,
            wrap: sites.iter().filter(|w| w.name == s.name).map(|w| w.exact).reduce(|a, b| (a.0.min(b.0), a.1.max(b.1))),
            // a signal written by a listed step and an unlisted one counts as unlisted
            listed: {
                let at: Vec<_> = sites.iter().filter(|w| w.name == s.name).map(|w| w.listed).collect();
                if at.iter().all(Option::is_some) { at.first().copied().flatten() } else { None }
            },
            name: s.name.clone(),
            q: fmt.q(),
            format: fmt.name,
            bits: fmt.bits,
            signed: fmt.signed,
            min,
            max,
        });
    }
    let mismatches = mismatches(m, &inputs, &ranges.outputs);
    Ok(Measured { rows, vectors: inputs.len(), what, clocks: ranges.clocks, mismatches })
}

pub fn csv(rows: &[Row]) -> String {
    let mut t = String::from("signal,format,q,bits,signed,seen_min,seen_max,bits_needed,spare,unused_flag,proven_min,proven_max,proven_bits_needed,proven_spare,may_wrap,exact_min,exact_max,listed_as\n");
    for r in rows {
        t.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
            r.name, r.format.replace(',', ";"), r.q, r.bits, r.signed as u8, r.min, r.max, r.needed, r.spare(), r.unused_flag() as u8,
            r.proven.0, r.proven.1, r.proven_needed, r.proven_spare(), r.wrap.is_some() as u8,
            r.wrap.map(|w| w.0.to_string()).unwrap_or_default(), r.wrap.map(|w| w.1.to_string()).unwrap_or_default(),
            r.wrap.and(r.listed).map(|l| l.kind.name()).unwrap_or_default()
        ));
    }
    t
}

pub fn run<U: StreamUnit>(m: &UnitModel, count: usize, seed: u64, csv_out: Option<&std::path::Path>) -> Result<(), String> {
    let t = std::time::Instant::now();
    let Measured { rows, vectors: n, what, clocks, mismatches } = measure::<U>(m, count, seed)?;
    let secs = t.elapsed().as_secs_f64();
    if let Some(p) = csv_out {
        synth::export::write_atomic(p, csv(&rows).as_bytes())?;
    }
    println!("widths of `{}`: {what}; {clocks} clocks in rust-hdl, every signal probed ({:.0} vectors/s)", m.name, n as f64 / secs);
    let stateless_all = m.exhaustive.is_some() && m.stream.is_none();
    if stateless_all {
        // a unit without state, every input applied: each signal took every value it can take
        println!("proven by exhaustion: every input applied to a unit without state, so the seen ranges are the exact ones");
    }
    println!("rtl against the model on the same vectors: {mismatches} of {n} differ");
    println!("seen: the range over those vectors in simulation; proven: over every input sequence (interval analysis of");
    println!("the block's hdl); needs / spare: bits that range needs, and the declared bits it leaves at the top;");
    println!("! two or more bits never used by the data seen; where the step writing a signal computes, with each operand read");
    println!("in its declared format, more than the declared range holds: W a risk (not listed), w a wrap on purpose (a split or");
    println!("modular arithmetic), a in range for a reason intervals do not carry (argued): each listed below with its reason");
    let w = rows.iter().map(|r| r.name.len()).max().unwrap_or(6).max(6);
    println!(
        "{:<w$} {:>10} {:>9} {:>5} {:>24} {:>5} {:>5} {:>28} {:>5} {:>5}",
        "signal", "format", "Q", "bits", "seen min .. max", "needs", "spare", "proven min .. max", "needs", "spare"
    );
    for r in &rows {
        println!(
            "{:<w$} {:>10} {:>9} {:>5} {:>24} {:>5} {:>5} {:>28} {:>5} {:>5} {}{}",
            r.name, r.format, r.q, r.bits, format!("{} .. {}", r.min, r.max), r.needed, r.spare(),
            format!("{} .. {}", r.proven.0, r.proven.1), r.proven_needed, r.proven_spare(),
            if r.unused_flag() { "!" } else { "" }, r.wrap_flag().map(String::from).unwrap_or_default()
        );
    }
    let flagged = rows.iter().filter(|r| r.unused_flag()).count();
    let count = |c: char| rows.iter().filter(|r| r.wrap_flag() == Some(c)).count();
    let spare: usize = rows.iter().map(Row::spare).sum();
    let proven_spare: usize = rows.iter().map(Row::proven_spare).sum();
    println!(
        "{} signals: {spare} spare bits seen, {proven_spare} proven; {flagged} with two or more unused (!); steps beyond their \
         format: {} risks (W), {} wraps on purpose (w), {} argued (a)",
        rows.len(),
        count('W'),
        count('w'),
        count('a')
    );
    let evidence = if stateless_all {
        format!("every input applied, rtl = model on all {n}")
    } else if mismatches == 0 {
        format!("rtl = model (which does not wrap) on all {n} vectors")
    } else {
        format!("rtl differs from the model on {mismatches} of {n} vectors")
    };
    for r in rows.iter().filter(|r| r.wrap.is_some()) {
        let (a, b) = r.wrap.unwrap_or_default();
        let (lo, hi) = if r.signed { (-(1i128 << (r.bits - 1)), (1i128 << (r.bits - 1)) - 1) } else { (0, (1i128 << r.bits) - 1) };
        let flag = r.wrap_flag().unwrap_or('W');
        println!("  {flag} {}: computes {a} .. {b}, {} holds {lo} .. {hi}", r.name, r.q);
        match r.listed {
            Some(l) if flag == 'a' => println!("      argued: {}; {evidence}", l.why),
            Some(l) => println!("      {}: {}", l.kind.name(), l.why),
            None => println!("      not listed in sim::widths::wraps: a risk until shown otherwise"),
        }
    }
    if let Some(p) = csv_out {
        println!("wrote {}", p.display());
    }
    Ok(())
}
