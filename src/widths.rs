//! `bumprtl widths <unit>`: every signal of the unit's rtl block, by its VCD name, with the fixed-point format its
//! source declares and the range it takes over the unit's vectors in rust-hdl (every input when the unit has at most
//! 2^20, else its hard cases and `--count` random vectors): the bits that range needs, the spare bits at the top,
//! and a flag where two or more of them go unused. See the `widths` crate.

use crate::progress::Step;
use ::widths::{bits_needed, bounds, mismatches, wraps::Waived};

/// One signal's row.
pub struct Row {
    pub name: String,
    pub format: String,
    pub q: String,
    pub bits: usize,
    pub signed: bool,
    pub min: i64,
    pub max: i64,
    /// the seen range is over every clock (a valid flag, or no single stage), not only those holding a vector
    pub every: bool,
    pub needed: usize,
    /// the proven range in the same reading (every input sequence), the bits it needs
    pub proven: (i128, i128),
    pub proven_needed: usize,
    /// the step that writes it may wrap: the exact hull of what it computes, which the declared range does not hold
    pub wrap: Option<(i128, i128)>,
    /// that step's entry in `widths::wraps` (deliberate, or argued in range), if it is listed
    pub listed: Option<&'static Waived>,
    /// the solver's verdict on the signal's claims (its range, the exact value of each step that writes it), with
    /// the refuting trace or why not tried; None where it was not asked or the signal has no claim
    pub solver: Option<(&'static str, String)>,
}

/// The solver's verdict on one signal's claims: refuted if any is, proven if all are, else not tried.
pub fn verdict(p: &sim::prove::Proved, signal: &str) -> Option<(&'static str, String)> {
    use sim::prove::Status;
    let mine: Vec<&sim::prove::Outcome> = p.outcomes.iter().filter(|o| o.prop.signal == signal).collect();
    if mine.is_empty() {
        return None;
    }
    let claims = crate::prove::claim;
    if let Some(o) = mine.iter().find(|o| matches!(o.status, Status::Refuted(_))) {
        let Status::Refuted(trace) = &o.status else { unreachable!() };
        return Some(("refuted", format!("{}: {trace}", claims(o))));
    }
    if let Some(o) = mine.iter().find(|o| matches!(o.status, Status::NotTried(_))) {
        let Status::NotTried(why) = &o.status else { unreachable!() };
        return Some(("not tried", format!("{}: {why}", claims(o))));
    }
    Some(("proven", mine.iter().map(|o| claims(o)).collect::<Vec<_>>().join("; ")))
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
pub fn measure(unit: &sim::units::Unit, count: usize, seed: u64) -> Result<Measured, String> {
    let (m, rtl) = (unit.model, unit.rtl);
    let exhaustive = m.exhaustive.is_some();
    let inputs = vectors::unit::generate(m, exhaustive, count, seed)?;
    let what = if exhaustive {
        format!("every input ({})", inputs.len())
    } else {
        format!("{} hard cases and {count} random vectors (seed {seed})", inputs.len() - count)
    };
    let step = Step::new(&format!("rust-hdl: {}, every signal probed", m.name), Some(inputs.len() as u64));
    let ranges = rtl.seen(m, &inputs, &|k| step.tick(k as u64));
    step.done(&format!("{} vectors, {} clocks", inputs.len(), ranges.clocks));
    let a = crate::progress::step(
        &format!("{}: the formats read and the ranges proven", m.name),
        |_| Some(String::from("the block's statements")),
        || rtl.analyse(m),
    );
    let (f, proven, sites) = (&a.formats, &a.proof.values, a.sites());
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
            wrap: sites
                .iter()
                .filter(|w| w.name == s.name)
                .map(|w| w.exact)
                .reduce(|a, b| (a.0.min(b.0), a.1.max(b.1))),
            // a signal written by a listed step and an unlisted one counts as unlisted
            listed: {
                let at: Vec<_> = sites.iter().filter(|w| w.name == s.name).map(|w| w.listed).collect();
                if at.iter().all(Option::is_some) {
                    at.first().copied().flatten()
                } else {
                    None
                }
            },
            name: s.name.clone(),
            solver: None,
            q: fmt.q(),
            format: fmt.name,
            bits: fmt.bits,
            signed: fmt.signed,
            min,
            max,
            every: s.every,
        });
    }
    let mismatches = mismatches(m, &inputs, &ranges.outputs);
    Ok(Measured { rows, vectors: inputs.len(), what, clocks: ranges.clocks, mismatches })
}

pub fn csv(rows: &[Row]) -> String {
    let mut t = String::from("signal,format,q,bits,signed,seen_min,seen_max,bits_needed,spare,unused_flag,proven_min,proven_max,proven_bits_needed,proven_spare,may_wrap,exact_min,exact_max,listed_as,solver,seen_every_clock\n");
    for r in rows {
        t.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
            r.name,
            r.format.replace(',', ";"),
            r.q,
            r.bits,
            r.signed as u8,
            r.min,
            r.max,
            r.needed,
            r.spare(),
            r.unused_flag() as u8,
            r.proven.0,
            r.proven.1,
            r.proven_needed,
            r.proven_spare(),
            r.wrap.is_some() as u8,
            r.wrap.map(|w| w.0.to_string()).unwrap_or_default(),
            r.wrap.map(|w| w.1.to_string()).unwrap_or_default(),
            r.wrap.and(r.listed).map(|l| l.kind.name()).unwrap_or_default(),
            r.solver.as_ref().map_or("", |s| s.0),
            r.every as u8
        ));
    }
    t
}

pub fn run(
    unit: &sim::units::Unit,
    count: usize,
    seed: u64,
    csv_out: Option<&std::path::Path>,
    solver: Option<&sim::prove::Options>,
) -> Result<(), String> {
    let m = unit.model;
    let t = std::time::Instant::now();
    let Measured { mut rows, vectors: n, what, clocks, mismatches } = measure(unit, count, seed)?;
    let secs = t.elapsed().as_secs_f64();
    let proved = match solver {
        Some(o) => {
            let dir = std::path::Path::new("target/prove").join(unit.rtl.name());
            let p = crate::progress::step(
                &format!("the solver on {}", m.name),
                |p: &Result<sim::prove::Proved, String>| {
                    p.as_ref().ok().map(|p| format!("{} claims", p.outcomes.len()))
                },
                || sim::prove::prove(unit, &dir, o),
            );
            Some(p?)
        }
        None => None,
    };
    if let Some(p) = &proved {
        for r in rows.iter_mut() {
            r.solver = verdict(p, &r.name);
        }
    }
    if let Some(p) = csv_out {
        synth::export::write_atomic(p, csv(&rows).as_bytes())?;
    }
    println!(
        "widths of `{}`: {what}; {clocks} clocks in rust-hdl, every signal probed ({:.0} vectors/s)",
        m.name,
        n as f64 / secs
    );
    let stateless_all = m.exhaustive.is_some() && m.stream.is_none();
    if stateless_all {
        // a unit without state, every input applied: each signal took every value it can take
        println!(
            "proven by exhaustion: every input applied to a unit without state, so the seen ranges are the exact ones \
             over data"
        );
    }
    println!("rtl against the model on the same vectors: {mismatches} of {n} differ");
    println!(
        "seen: the range over those vectors in simulation, on the clocks where the signal's stage holds one (the unit's"
    );
    println!("valid in that many clocks before; ~ on every clock: a valid flag, or a signal with no single stage);");
    println!("proven: over every input sequence and reachable state, idle clocks too (interval analysis of the block's hdl);");
    println!("needs / spare: bits that range needs, and the declared bits it leaves at the top;");
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
            "{:<w$} {:>10} {:>9} {:>5} {:>24} {:>5} {:>5} {:>28} {:>5} {:>5} {}{}{}",
            r.name,
            r.format,
            r.q,
            r.bits,
            format!("{} .. {}{}", r.min, r.max, if r.every { "~" } else { " " }),
            r.needed,
            r.spare(),
            format!("{} .. {}", r.proven.0, r.proven.1),
            r.proven_needed,
            r.proven_spare(),
            if r.unused_flag() { "!" } else { "" },
            r.wrap_flag().map(String::from).unwrap_or_default(),
            r.solver.as_ref().map_or(String::new(), |s| format!(" {}", s.0))
        );
    }
    if let Some(p) = &proved {
        println!(
            "the solver (yosys-smtbmc, z3, depth {} past the latency): {} claims, {} proven, {} refuted, {} not tried, in {:.1} s; \
             a row's verdict is its claims' (its range and each step that writes it)",
            p.depth - unit.rtl.latency(),
            p.outcomes.len(),
            p.count("proven"),
            p.count("refuted"),
            p.count("not tried"),
            p.seconds
        );
        for r in rows.iter().filter(|r| r.solver.as_ref().is_some_and(|s| s.0 != "proven")) {
            let (word, detail) = r.solver.as_ref().unwrap();
            println!("  {word} {}: {detail}", r.name);
        }
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
    if proved.is_some() {
        // the goal: no argued entry the solver has not proven
        let argued: Vec<&Row> = rows.iter().filter(|r| r.wrap_flag() == Some('a')).collect();
        let word = |w: &str| argued.iter().filter(|r| r.solver.as_ref().is_some_and(|s| s.0 == w)).count();
        println!(
            "argued (a) steps: {} proven by the solver, {} refuted, {} not tried, {} without a claim; {} left unproven",
            word("proven"),
            word("refuted"),
            word("not tried"),
            argued.iter().filter(|r| r.solver.is_none()).count(),
            argued.len() - word("proven")
        );
    }
    let evidence = if stateless_all {
        format!("every input applied, rtl = model on all {n}")
    } else if mismatches == 0 {
        format!("rtl = model (which does not wrap) on all {n} vectors")
    } else {
        format!("rtl differs from the model on {mismatches} of {n} vectors")
    };
    for r in rows.iter().filter(|r| r.wrap.is_some()) {
        let (a, b) = r.wrap.unwrap_or_default();
        let (lo, hi) =
            if r.signed { (-(1i128 << (r.bits - 1)), (1i128 << (r.bits - 1)) - 1) } else { (0, (1i128 << r.bits) - 1) };
        let flag = r.wrap_flag().unwrap_or('W');
        println!("  {flag} {}: computes {a} .. {b}, {} holds {lo} .. {hi}", r.name, r.q);
        let solver = r.solver.as_ref().map_or(String::new(), |s| format!("; the solver: {}", s.0));
        match r.listed {
            Some(l) if flag == 'a' => println!("      argued: {}; {evidence}{solver}", l.why),
            Some(l) => println!("      {}: {}", l.kind.name(), l.why),
            None => println!("      not listed in widths::wraps: a risk until shown otherwise"),
        }
    }
    if let Some(p) = csv_out {
        println!("wrote {}", p.display());
    }
    Ok(())
}

/// One setting of a unit's width parameters in the budget sweep: what it is, whether it is the unit's own, its error
/// against the ideal (mean, max, in the sweep's unit; and a second measure where the unit has one), its cost.
pub struct Point {
    pub setting: String,
    pub own: bool,
    pub mean: f64,
    pub max: f64,
    pub also: Option<String>,
    pub cells: synth::fpga::Cells,
}

impl Point {
    /// Every figure at most the other's (error and every resource) and one below it.
    fn dominates(&self, o: &Point) -> bool {
        let (a, b) = (&self.cells, &o.cells);
        let le = self.max <= o.max
            && self.mean <= o.mean
            && a.lut4 <= b.lut4
            && a.ff <= b.ff
            && a.dsp <= b.dsp
            && a.bram <= b.bram;
        let lt = self.max < o.max
            || self.mean < o.mean
            || a.lut4 < b.lut4
            || a.ff < b.ff
            || a.dsp < b.dsp
            || a.bram < b.bram;
        le && lt
    }
    /// Scarce blocks first: DSP, block RAM, then LUT4 and FF.
    fn cost(&self) -> (u64, u64, u64, u64) {
        (self.cells.dsp, self.cells.bram, self.cells.lut4, self.cells.ff)
    }
}

/// The units with width parameters the sweep knows, and the unit of their budget. The normaliser's is the worst
/// component's error (Sq1.10 LSB), not the angle: its table sets the length of the result, hardly its direction
/// (a scale error of 1/√m moves every component alike), and N·L reads the length; the angle is printed beside.
pub const SWEPT: &[(&str, &str)] =
    &[("normalise", "Sq1.10 LSB"), ("sincos", "8-bit LSB"), ("bilinear", "8-bit LSB"), ("power", "8-bit LSB")];

/// Every setting of the unit's width parameters: its error from the model (random vectors, or every input where
/// the unit has few) and its cost from yosys for `family`, each synthesised in its own folder under `dir`.
pub fn sweep(
    unit: &str,
    family: synth::fpga::Family,
    dir: &std::path::Path,
    say: &dyn Fn(&str),
) -> Result<Vec<Point>, String> {
    const SAMPLES: usize = 200_000;
    // every setting in its own folder (one module name for all of them)
    let cost = |s: &sim::units::Setting, name: String| {
        say(&name);
        s.rtl.synth_unit(&dir.join(&name), family)
    };
    let mut points = vec![];
    match unit {
        "normalise" => {
            for f in sim::units::settings("normalise") {
                let (t, n) = f.params;
                let (lsb, deg) = vectors::normalise::error(t, n, SAMPLES, 3);
                points.push(Point {
                    setting: format!("table 2^{t} entries, {n} Newton step{}", if n == 1 { "" } else { "s" }),
                    own: (t, n) == (vectors::normalise::TABLE_BITS, vectors::normalise::NEWTON),
                    mean: lsb.mean(),
                    max: lsb.max,
                    also: Some(format!("{:.4}/{:.4} degrees", deg.mean(), deg.max)),
                    cells: cost(f, format!("normalise_t{t}n{n}"))?,
                });
            }
        }
        "sincos" => {
            for f in sim::units::settings("sincos") {
                let (tb, w) = f.params;
                let e = vectors::sincos::size_error(tb, w);
                points.push(Point {
                    setting: format!("{} entries of {w} bits", 1u32 << tb),
                    own: (tb, w) == (vectors::sincos::TABLE_BITS, vectors::sincos::WIDTH),
                    mean: e.mean_lsb8,
                    max: e.max_lsb8,
                    also: None,
                    cells: cost(f, format!("sincos_t{tb}w{w}"))?,
                });
            }
        }
        "bilinear" => {
            for f in sim::units::settings("bilinear") {
                let (fb, d) = f.params;
                let e = vectors::bilinear::error_sized(fb, d, SAMPLES / 4, 3);
                points.push(Point {
                    setting: format!("{fb} blend bits, {d} dropped"),
                    own: (fb, d) == (vectors::bilinear::F, 0),
                    mean: e.mean(),
                    max: e.max,
                    also: None,
                    cells: cost(f, format!("bilinear_f{fb}d{d}"))?,
                });
            }
        }
        "power" => {
            for f in sim::units::settings("power") {
                let (lf, eb) = f.params;
                let e = vectors::power::size_error(lf, eb);
                points.push(Point {
                    setting: format!("L to 2^-{lf}, {} exp entries", 1u32 << eb),
                    own: (lf, eb) == (vectors::power::LOG_FRAC, vectors::power::EXP_BITS),
                    mean: e.mean(),
                    max: e.max,
                    also: None,
                    cells: cost(f, format!("power_l{lf}e{eb}"))?,
                });
            }
        }
        _ => return Err(format!("--budget: `{unit}` has no width parameters to sweep")),
    }
    Ok(points)
}

/// The indices of the Pareto set (no other point as good in every figure and better in one), and of the cheapest
/// point whose max error is within `budget` (at equal cost, the more accurate).
pub fn pareto(points: &[Point], budget: f64) -> (Vec<usize>, Option<usize>) {
    let front: Vec<usize> = (0..points.len()).filter(|&k| !points.iter().any(|q| q.dominates(&points[k]))).collect();
    // at equal cost the more accurate (so the choice is always on the Pareto set)
    let cheapest = (0..points.len()).filter(|&k| points[k].max <= budget).min_by(|&a, &b| {
        let (p, q) = (&points[a], &points[b]);
        p.cost().cmp(&q.cost()).then(p.max.total_cmp(&q.max)).then(p.mean.total_cmp(&q.mean))
    });
    (front, cheapest)
}

/// `bumprtl widths <unit> --budget X`: the sweep's table, its Pareto set, and the cheapest setting within X.
pub fn budget(unit: &str, budget: f64, part: synth::fpga::Part, dir: &std::path::Path) -> Result<(), String> {
    let Some(&(_, what)) = SWEPT.iter().find(|s| s.0 == unit) else {
        let names: Vec<&str> = SWEPT.iter().map(|s| s.0).collect();
        return Err(format!(
            "--budget: `{unit}` has no width parameters to sweep; the units that do: {}",
            names.join(", ")
        ));
    };
    let yosys = synth::tools::toolchain().yosys();
    if !synth::tools::runs(&yosys) {
        return Err(format!(
            "--budget costs each setting with yosys, and {yosys} is missing (`bash .ci/run` installs it)"
        ));
    }
    let t = std::time::Instant::now();
    let steps = crate::progress::Chain::default();
    let points =
        sweep(unit, part.family, dir, &|name| steps.next(&format!("yosys: {name} for {}", part.title), "costed"));
    steps.end("costed", &points);
    let points = points?;
    let (front, cheapest) = pareto(&points, budget);
    println!(
        "width sweep of `{unit}`: error against the ideal in {what} (mean / max), cost from yosys for {} ({:.0} s)",
        part.title,
        t.elapsed().as_secs_f64()
    );
    println!("P: on the Pareto set (no other setting as good in error and every resource, and better in one); *: the unit's own");
    let [lut, ff, dsp, bram, _] = part.family.cells();
    println!("{:<34} {:>10} {:>10} {:>8} {:>8} {:>6} {:>6}  ", "setting", "mean", "max", lut, ff, dsp, bram);
    for (k, p) in points.iter().enumerate() {
        let marks = format!(
            "{}{}{}",
            if front.contains(&k) { "P" } else { " " },
            if p.own { "*" } else { " " },
            if cheapest == Some(k) { " <- cheapest within the budget" } else { "" }
        );
        println!(
            "{:<34} {:>10.4} {:>10.4} {:>8} {:>8} {:>6} {:>6}  {marks}{}",
            p.setting,
            p.mean,
            p.max,
            p.cells.lut4,
            p.cells.ff,
            p.cells.dsp,
            p.cells.bram,
            p.also.as_ref().map(|a| format!("  ({a})")).unwrap_or_default()
        );
    }
    match cheapest {
        Some(k) => println!(
            "budget {budget} {what} (max): the cheapest setting within it is {} ({} {dsp}, {} {bram}, {} {lut}, {} {ff}; max {:.4})",
            points[k].setting, points[k].cells.dsp, points[k].cells.bram, points[k].cells.lut4, points[k].cells.ff, points[k].max
        ),
        None => println!("budget {budget} {what} (max): no setting meets it; the most accurate has max {:.4}", points.iter().map(|p| p.max).fold(f64::MAX, f64::min)),
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(max: f64, lut4: u64, bram: u64) -> Point {
        Point {
            setting: String::new(),
            own: false,
            mean: max / 2.0,
            max,
            also: None,
            cells: synth::fpga::Cells { lut4, ff: 10, dsp: 0, bram, carry: 0, soft: 0, spram: 0 },
        }
    }

    #[test]
    fn the_pareto_set_drops_what_another_setting_beats_everywhere() {
        // 1 is as accurate as 0 and cheaper: 0 is dominated; 2 is less accurate but smaller; 3 loses to 2 everywhere
        let pts = [p(0.5, 100, 2), p(0.5, 90, 2), p(2.0, 40, 0), p(3.0, 50, 0)];
        let (front, cheapest) = pareto(&pts, 1.0);
        assert_eq!(front, [1, 2]);
        assert_eq!(cheapest, Some(1));
        // a looser budget takes the setting without block RAM; one below every error takes none
        assert_eq!(pareto(&pts, 2.0).1, Some(2));
        assert_eq!(pareto(&pts, 0.1).1, None);
        // two settings of the same cells: the more accurate is chosen, and it is the one on the Pareto set
        let same = [p(0.9, 16, 2), p(0.1, 16, 2)];
        assert_eq!(pareto(&same, 1.0), (vec![1], Some(1)));
    }
}
