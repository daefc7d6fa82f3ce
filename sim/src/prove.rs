//! `bumprtl prove`: the width report's claims proved by a solver on the exported Verilog. `widths::formal` writes
//! the assertions into the export; yosys reads it with `-formal` and writes SMT-LIB 2; `yosys-smtbmc` with z3 checks
//! every assertion from the registers' initial zero for `depth` clocks (bounded model check) and then by temporal
//! induction of the same depth. The pipelines are feed-forward: after `latency` clocks every register is a function
//! of the last `latency` inputs, so a depth past the latency makes the induction complete, and an induction that
//! still fails says the block holds state that is not (a memory, a counter) rather than that the claim is false.
//!
//! Each run names the assertions that failed; they are set aside (refuted by the bounded check, with its trace's
//! inputs; or not proven by induction) and the rest checked again, until a run passes.

use crate::units::Unit;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};
use widths::formal::{Kind, Prop, Request};
use widths::wraps::{Kind as WrapKind, Waived};

/// What the solver made of one claim.
#[derive(Clone, Debug, PartialEq)]
pub enum Status {
    Proven,
    /// the bounded check found a trace from the initial state that breaks it: the trace's inputs, clock by clock
    Refuted(String),
    /// not decided, and why (time, induction, no Verilog form for the step)
    NotTried(String),
}

impl Status {
    pub fn word(&self) -> &'static str {
        match self {
            Status::Proven => "proven",
            Status::Refuted(_) => "refuted",
            Status::NotTried(_) => "not tried",
        }
    }
}

/// One claim and its outcome.
pub struct Outcome {
    pub prop: Prop,
    /// the wrap list's entry for the step, if it has one (`a`: argued in range)
    pub listed: Option<&'static Waived>,
    pub status: Status,
    /// the solver run that decided it
    pub seconds: f64,
}

/// A unit's proof.
pub struct Proved {
    pub unit: &'static str,
    pub depth: usize,
    pub outcomes: Vec<Outcome>,
    /// the steps with no assertion, and why
    pub skipped: Vec<(String, String)>,
    /// the solver runs and their total time
    pub runs: usize,
    pub seconds: f64,
}

impl Proved {
    pub fn count(&self, word: &str) -> usize {
        self.outcomes.iter().filter(|o| o.status.word() == word).count()
    }
}

/// What to prove beyond the report's own claims.
#[derive(Default, Clone)]
pub struct Options {
    /// claim this signal's range one bit narrower than the interval proof's (to see the solver refute it)
    pub narrow: Option<String>,
    /// each solver run's time limit
    pub limit: Option<Duration>,
    /// only the exact claims (no range claims)
    pub exact_only: bool,
}

/// The range one bit narrower than `(lo, hi)` needs: a bound the data reaches, claimed too small.
pub fn narrower(lo: i128, hi: i128, signed: bool) -> (i128, i128) {
    let bits = |x: i128| 128 - x.unsigned_abs().leading_zeros();
    if signed {
        let b = bits(lo).max(bits(hi)); // magnitude bits; the signed width is b + 1
        let h = (1i128 << b.saturating_sub(1)) - 1;
        (lo.max(-h - 1), hi.min(h))
    } else {
        (lo, hi.min((1i128 << bits(hi).saturating_sub(1)) - 1))
    }
}

/// The tools the proof needs, if one is missing.
pub fn missing_tools() -> Vec<&'static str> {
    synth::tools::missing(&["yosys", "yosys-smtbmc", "z3"])
}

/// Prove `unit`'s claims in `dir` (the harness, yosys's script and its SMT-LIB 2, the traces).
pub fn prove(unit: &Unit, dir: &Path, o: &Options) -> Result<Proved, String> {
    let missing = missing_tools();
    if !missing.is_empty() {
        return Err(format!("prove: {} not on the PATH (the test command installs them)", missing.join(", ")));
    }
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let (m, rtl) = (unit.model, unit.rtl);
    let name = rtl.name();
    let a = rtl.analyse(m);
    let sites = a.sites();
    let listed =
        |signal: &str| -> Option<&'static Waived> { sites.iter().find(|s| s.name == signal).and_then(|s| s.listed) };
    let signed = |n: &str| a.formats.format(n).is_some_and(|f| f.signed);
    let skip = |_: &str, n: &str| -> Option<String> {
        match listed(n).map(|w| w.kind) {
            Some(k @ (WrapKind::Split | WrapKind::Modular)) => Some(format!("wraps on purpose ({})", k.name())),
            _ => None,
        }
    };
    // the range claims: every signal whose proven range is narrower than its format, at the proof's range
    let mut ranges = vec![];
    if !o.exact_only || o.narrow.is_some() {
        let mut names: Vec<&String> = a.proof.values.keys().collect();
        names.sort();
        for n in names {
            if n.ends_with("clock") || (o.exact_only && o.narrow.as_ref() != Some(n)) {
                continue;
            }
            let Some(f) = a.formats.format(n) else { continue };
            if f.bits > 100 {
                continue; // the interval proof keeps 100 bits of a wider word's range (a memory's packed row)
            }
            let v = a.proof.values[n];
            let (lo, hi) = v.range(f.signed);
            let full = if f.signed {
                (-(1i128 << (f.bits - 1)), (1i128 << (f.bits - 1)) - 1)
            } else {
                (0, (1i128 << f.bits) - 1)
            };
            let (lo, hi) = if o.narrow.as_ref() == Some(n) { narrower(lo, hi, f.signed) } else { (lo, hi) };
            if (lo, hi) != full {
                ranges.push((n.clone(), lo, hi));
            }
        }
    }
    if let Some(n) = &o.narrow {
        if !ranges.iter().any(|r| &r.0 == n) {
            return Err(format!("prove {name}: --narrow {n}: no signal of that name with a declared format (names as in `bumprtl widths {name}`)"));
        }
    }
    let inputs: Vec<(&str, i64, i64)> = m.inputs.iter().map(|p| (p.name, p.range().0, p.range().1)).collect();
    let verilog = rtl.verilog();
    let h = rtl.harness(&Request {
        top: name,
        verilog: &verilog,
        inputs: &inputs,
        signed: &signed,
        ranges: &ranges,
        skip: &skip,
        gate: &|_: &str, n: &str| listed(n).is_some_and(|w| w.kind == WrapKind::Bound),
    })?;
    let depth = rtl.latency() + 2;
    let limit = o.limit.unwrap_or(Duration::from_secs(600));
    let base: Vec<String> = h.text.lines().map(String::from).collect();
    let lines: Vec<usize> = h.props.iter().map(|p| p.line).collect();
    let start = Instant::now();
    let (status, runs) = ladder(dir, name, &base, &lines, depth, limit)?;
    let outcomes = h
        .props
        .into_iter()
        .zip(status)
        .map(|(p, s)| {
            let (status, seconds) = s;
            Outcome { listed: if p.kind == Kind::Exact { listed(&p.signal) } else { None }, prop: p, status, seconds }
        })
        .collect();
    Ok(Proved { unit: name, depth, outcomes, skipped: h.skipped, runs, seconds: start.elapsed().as_secs_f64() })
}

/// The claims at lines `props` of the harness `base` (top module `name`, written and run in `dir`), each decided:
/// a ladder of depths up to `depth`, each a bounded check from the initial state (a failure there is a real trace:
/// refuted) and then induction (a failure there is tried again deeper, and at `depth` is not proven).
fn ladder(
    dir: &Path,
    name: &str,
    base: &[String],
    props: &[usize],
    depth: usize,
    limit: Duration,
) -> Result<(Vec<(Status, f64)>, usize), String> {
    let mut status: Vec<Option<(Status, f64)>> = vec![None; props.len()];
    let by_line: HashMap<usize, usize> = props.iter().enumerate().map(|(i, &l)| (l, i)).collect();
    let mut runs = 0;
    // a ladder of depths: a claim about stage s needs the induction to reach back only to where its operands part,
    // so most are proven at a small depth, cheaply; the proven ones are then assumed (they hold in every reachable
    // state) and the rest tried deeper, up to the latency + 2, where the induction is complete for a feed-forward
    // block
    let mut rungs = vec![];
    let mut k = 2;
    while k < depth {
        rungs.push(k);
        k *= 2;
    }
    rungs.push(depth);
    'ladder: for &k in &rungs {
        let mut aside = vec![false; status.len()];
        for induction in [false, true] {
            loop {
                if status.iter().zip(&aside).all(|(s, a)| s.is_some() || *a) {
                    break;
                }
                let lines: Vec<String> = base
                    .iter()
                    .enumerate()
                    .map(|(n, l)| match by_line.get(&(n + 1)) {
                        Some(&i) => match (&status[i], aside[i]) {
                            (Some((Status::Proven, _)), _) => l.replacen("assert(", "assume(", 1),
                            (None, false) => l.clone(),
                            _ => format!("    // set aside: {}", l.trim()),
                        },
                        None => l.clone(),
                    })
                    .collect();
                runs += 1;
                let t0 = Instant::now();
                let r = run_once(dir, name, &lines, k, induction, limit)?;
                let secs = t0.elapsed().as_secs_f64();
                match r {
                    Run::Passed => {
                        if induction {
                            for (s, a) in status.iter_mut().zip(&aside) {
                                if s.is_none() && !a {
                                    *s = Some((Status::Proven, secs));
                                }
                            }
                        }
                        break;
                    }
                    Run::Failed(failed, trace) => {
                        let mut any = false;
                        for l in failed {
                            let Some(&i) = by_line.get(&l) else { continue };
                            if status[i].is_some() || aside[i] {
                                continue;
                            }
                            any = true;
                            if !induction {
                                status[i] = Some((Status::Refuted(trace.clone()), secs));
                            } else if k < depth {
                                aside[i] = true; // tried again deeper
                            } else {
                                status[i] = Some((
                                    Status::NotTried(format!(
                                        "induction at depth {depth} fails (state that is not feed-forward: a memory or a counter)"
                                    )),
                                    secs,
                                ));
                            }
                        }
                        if !any {
                            return Err(format!(
                                "prove {name}: the solver failed an assertion the harness does not list ({})",
                                dir.display()
                            ));
                        }
                    }
                    Run::Timeout => {
                        for s in status.iter_mut().filter(|s| s.is_none()) {
                            *s = Some((
                                Status::NotTried(format!("the solver ran past {} s at depth {k}", limit.as_secs())),
                                secs,
                            ));
                        }
                        break 'ladder;
                    }
                }
            }
        }
    }
    let status = status.into_iter().map(|s| s.unwrap_or((Status::NotTried("not reached".into()), 0.0))).collect();
    Ok((status, runs))
}

pub(crate) enum Run {
    Passed,
    /// the failed assertions' lines in the harness, and the trace's inputs
    Failed(Vec<usize>, String),
    Timeout,
}

pub(crate) fn run_once(
    dir: &Path,
    top: &str,
    lines: &[String],
    depth: usize,
    induction: bool,
    limit: Duration,
) -> Result<Run, String> {
    let v = dir.join(format!("{top}_formal.v"));
    let mut text = lines.join("\n");
    text.push('\n');
    std::fs::write(&v, text).map_err(|e| format!("{}: {e}", v.display()))?;
    let smt = format!("{top}_formal.smt2");
    let script = format!(
        "read_verilog -formal {top}_formal.v\nprep -top {top}\nflatten\nopt_clean\ndffunmap\nwrite_smt2 -wires {smt}\n"
    );
    let ys = dir.join(format!("{top}_formal.ys"));
    std::fs::write(&ys, script).map_err(|e| format!("{}: {e}", ys.display()))?;
    synth::tools::run(dir, "yosys", &["-q", "-s", &format!("{top}_formal.ys")])?;
    let t = depth.to_string();
    let vcd = format!("{top}_cex.vcd");
    let mut args = vec!["-s", "z3", "--presat", "-t", &t];
    if induction {
        args.push("-i");
    } else {
        args.extend(["--dump-vcd", &vcd]);
    }
    args.push(&smt);
    let (out, finished) = synth::tools::run_limited_any(dir, "yosys-smtbmc", &args, limit)?;
    if !finished {
        return Ok(Run::Timeout);
    }
    let log = String::from_utf8_lossy(&out.stdout).to_string();
    if log.contains("Status: PASSED") {
        return Ok(Run::Passed);
    }
    let file = format!("{top}_formal.v:");
    // `Assert failed in top: f.v:l0.c0-l1.c1|f.v:…`: the spans of the instances down to the assertion (flattened),
    // each `l0.c0-l1.c1`; an assertion inside a block is spanned from the end of the statement before it, so its
    // own line is a span's end line. Every end line is returned; the caller keeps the ones that are claims.
    let failed: Vec<usize> = log
        .lines()
        .filter(|l| l.contains("Assert failed in"))
        .flat_map(|l| {
            let spans = l.split_whitespace().find(|w| w.contains(&file)).unwrap_or("");
            spans
                .split('|')
                .filter_map(|s| {
                    let span = s.split_once(&file)?.1;
                    let end = span.rsplit_once('-').map_or(span, |x| x.1);
                    end.split('.').next()?.parse().ok()
                })
                .collect::<Vec<usize>>()
        })
        .collect();
    if failed.is_empty() {
        let tail: Vec<&str> = log.lines().rev().take(5).collect();
        return Err(format!("yosys-smtbmc in {}: no verdict ({})", dir.display(), tail.join(" / ")));
    }
    let trace = if induction { String::new() } else { inputs_of(&dir.join(&vcd), top).unwrap_or_default() };
    Ok(Run::Failed(failed, trace))
}

/// The top module's input ports clock by clock in a trace: `0: a=1 b=2; 1: …` (values unsigned).
fn inputs_of(vcd: &PathBuf, top: &str) -> Option<String> {
    let text = std::fs::read_to_string(vcd).ok()?;
    let mut ids: HashMap<String, String> = HashMap::new();
    let mut scope: Vec<String> = vec![];
    let mut steps: Vec<Vec<(String, u128)>> = vec![];
    let mut cur: HashMap<String, u128> = HashMap::new();
    let mut t: Option<u64> = None;
    let verilog = std::fs::read_to_string(vcd.with_file_name(format!("{top}_formal.v"))).ok()?;
    let header = verilog.lines().find(|l| l.starts_with(&format!("module {top}(")))?;
    let ports: Vec<&str> = header.split_once('(')?.1.trim_end_matches(");").split(',').map(str::trim).collect();
    let is_input =
        |n: &str| verilog.lines().any(|l| l.trim().starts_with("input wire") && l.trim().ends_with(&format!(" {n};")));
    let flush = |cur: &HashMap<String, u128>, steps: &mut Vec<Vec<(String, u128)>>| {
        let mut v: Vec<(String, u128)> =
            ports.iter().filter(|p| **p != "clock").filter_map(|p| cur.get(*p).map(|x| (p.to_string(), *x))).collect();
        v.sort_by_key(|(n, _)| ports.iter().position(|p| p == n));
        steps.push(v);
    };
    for l in text.lines() {
        let w: Vec<&str> = l.split_whitespace().collect();
        match w.first() {
            Some(&"$scope") => scope.push(w.get(2)?.to_string()),
            Some(&"$upscope") => {
                scope.pop();
            }
            Some(&"$var") if scope.len() == 1 => {
                let n = w.get(4)?.to_string();
                if ports.contains(&n.as_str()) && is_input(&n) {
                    ids.insert(w.get(3)?.to_string(), n);
                }
            }
            Some(s) if s.starts_with('#') => {
                if t.is_some() {
                    flush(&cur, &mut steps);
                }
                t = s[1..].parse().ok();
            }
            Some(s) if s.starts_with('b') => {
                if let Some(n) = ids.get(*w.get(1)?) {
                    cur.insert(n.clone(), u128::from_str_radix(&s[1..].replace(['x', 'z'], "0"), 2).ok()?);
                }
            }
            Some(s) if s.len() >= 2 && (s.starts_with('0') || s.starts_with('1')) => {
                if let Some(n) = ids.get(&s[1..]) {
                    cur.insert(n.clone(), s[..1].parse().ok()?);
                }
            }
            _ => {}
        }
    }
    if t.is_some() {
        flush(&cur, &mut steps);
    }
    // the clock toggles: one step a rising edge, the inputs as they are there
    let steps: Vec<String> = steps
        .iter()
        .enumerate()
        .map(|(k, v)| format!("{k}: {}", v.iter().map(|(n, x)| format!("{n}={x}")).collect::<Vec<_>>().join(" ")))
        .collect();
    Some(steps.join("; "))
}

/// A top module's ports as its export declares them: (name, bits, is an input), clock included.
pub(crate) fn ports(verilog: &str, top: &str) -> Result<Vec<(String, u32, bool)>, String> {
    let head = format!("module {top}(");
    let at = verilog.find(&head).ok_or_else(|| format!("the export has no module {top}"))?;
    let mut out = vec![];
    for l in verilog[at..].lines().skip(1) {
        let l = l.trim();
        if l.starts_with("// Stub") || l.starts_with("endmodule") {
            break;
        }
        let (input, rest) = if let Some(r) = l.strip_prefix("input wire") {
            (true, r)
        } else if let Some(r) = l.strip_prefix("output reg").or_else(|| l.strip_prefix("output wire")) {
            (false, r)
        } else {
            continue;
        };
        let rest = rest.trim().trim_end_matches(';');
        let (bits, name) = match rest.strip_prefix('[') {
            Some(r) => {
                let (range, name) = r.split_once(']').ok_or_else(|| format!("{top}: a port as `{l}`"))?;
                let hi: u32 =
                    range.split(':').next().unwrap_or("").trim().parse().map_err(|_| format!("{top}: `{l}`"))?;
                (hi + 1, name.trim())
            }
            None => (1, rest.trim()),
        };
        out.push((name.to_string(), bits, input));
    }
    Ok(out)
}

/// Two units claimed to compute the same outputs: `a`'s inputs in `fix` held at a value; `b`'s inputs named in
/// `bind` fed by `a`'s input of the name given there (or, where `a` has none, by a free input of that name), the
/// rest of `b`'s inputs by `a`'s of the same name or, without one, free (`b_<port>`); the unit with the shorter
/// latency has its outputs delayed to the other's. The claim: the valid flags
/// agree on every clock, and where they are high every output of the same name does.
pub struct Miter<'a> {
    pub a: &'a Unit,
    pub b: &'a Unit,
    pub fix: &'a [(&'a str, i64)],
    pub bind: &'a [(&'a str, &'a str)],
}

/// The solver's verdict on a miter.
pub struct Equivalence {
    pub name: String,
    pub status: Status,
    pub depth: usize,
    pub runs: usize,
    pub seconds: f64,
}

/// The miter of `m`, its claims decided as `prove` decides a unit's (bounded check, then induction up to the longer
/// latency + 2).
pub fn equivalence(m: &Miter, dir: &Path, limit: Duration) -> Result<Equivalence, String> {
    let missing = missing_tools();
    if !missing.is_empty() {
        return Err(format!("prove: {} not on the PATH (the test command installs them)", missing.join(", ")));
    }
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let (na, nb) = (m.a.rtl.name(), m.b.rtl.name());
    let (va, vb) = (m.a.rtl.verilog(), m.b.rtl.verilog());
    let (pa, pb) = (ports(&va, na)?, ports(&vb, nb)?);
    let (la, lb) = (m.a.rtl.latency(), m.b.rtl.latency());
    let top = format!("miter_{na}_{nb}");
    let range = |u: &Unit, p: &str| u.model.inputs.iter().find(|i| i.name == p).map(|i| i.range());
    // the miter's inputs: a's (but the fixed ones), then b's free ones
    let mut free: Vec<(String, u32, (i64, i64))> = vec![];
    for (n, bits, input) in &pa {
        if *input && n != "clock" && !m.fix.iter().any(|f| f.0 == n) {
            free.push((n.clone(), *bits, range(m.a, n).unwrap_or((0, (1i64 << bits.min(&62)) - 1))));
        }
    }
    // one unit against itself (fed differently) is one set of modules, instanced twice
    let mut text = if na == nb { format!("{va}\n") } else { format!("{va}\n{vb}\n") };
    let mut conn_b = vec![];
    for (n, bits, input) in &pb {
        if !*input || n == "clock" {
            continue;
        }
        let a_has = |s: &str| pa.iter().any(|p| p.0 == s && p.2);
        let src = match m.bind.iter().find(|b| b.0 == n) {
            Some((_, s)) if a_has(s) => s.to_string(),
            Some((_, s)) => s.to_string(), // a free input of its own, named there
            None if a_has(n) => n.clone(),
            None => format!("b_{n}"),
        };
        if !a_has(&src) && !free.iter().any(|f| f.0 == src) {
            let r = range(m.b, n).unwrap_or((0, (1i64 << bits.min(&62)) - 1));
            free.push((src.clone(), *bits, r));
        }
        if let Some((_, v)) = m.fix.iter().find(|f| f.0 == src) {
            conn_b.push(format!(".{n}({v})"));
        } else {
            conn_b.push(format!(".{n}({src})"));
        }
    }
    let names: Vec<&str> = free.iter().map(|f| f.0.as_str()).collect();
    text.push_str(&format!("module {top}(clock, {});\n    input wire clock;\n", names.join(", ")));
    for (n, bits, _) in &free {
        text.push_str(&format!("    input wire {};\n", decl(n, *bits)));
    }
    let outs: Vec<(String, u32)> =
        pa.iter().filter(|p| !p.2 && pb.iter().any(|q| q.0 == p.0 && !q.2)).map(|p| (p.0.clone(), p.1)).collect();
    let mut conn_a = vec![".clock(clock)".to_string()];
    for (n, _, input) in &pa {
        if *input && n != "clock" {
            match m.fix.iter().find(|f| f.0 == n) {
                Some((_, v)) => conn_a.push(format!(".{n}({v})")),
                None => conn_a.push(format!(".{n}({n})")),
            }
        }
    }
    conn_b.insert(0, ".clock(clock)".to_string());
    for (n, bits) in &outs {
        text.push_str(&format!(
            "    wire {};\n    wire {};\n",
            decl(&format!("a_{n}"), *bits),
            decl(&format!("b_{n}"), *bits)
        ));
        conn_a.push(format!(".{n}(a_{n})"));
        conn_b.push(format!(".{n}(b_{n})"));
    }
    text.push_str(&format!("    {na} ua({});\n    {nb} ub({});\n", conn_a.join(", "), conn_b.join(", ")));
    // the earlier unit's outputs through a line of registers (initial zero) to the later one's clock
    let (early, d) = if la < lb { ("a", lb - la) } else { ("b", la - lb) };
    for (n, bits) in &outs {
        let mut prev = format!("{early}_{n}");
        for k in 1..=d {
            let r = format!("{early}_{n}_d{k}");
            text.push_str(&format!("    reg {} = 0;\n    always @(posedge clock) {r} <= {prev};\n", decl(&r, *bits)));
            prev = r;
        }
    }
    let at =
        |side: &str, n: &str| if side == early && d > 0 { format!("{side}_{n}_d{d}") } else { format!("{side}_{n}") };
    let mut k = 0;
    let mut lines: Vec<String> = vec![];
    for (n, _) in &outs {
        k += 1;
        let claim = if n == "valid_out" {
            format!("{} == {}", at("a", n), at("b", n))
        } else {
            format!("!{} || {} == {}", at("b", "valid_out"), at("a", n), at("b", n))
        };
        lines.push(format!("    always @(*) assert({claim}); // bumprtl prop {k}"));
    }
    for (n, bits, (lo, hi)) in &free {
        lines.push(assume_range(n, *bits, *lo, *hi));
    }
    text.push_str(&lines.join("\n"));
    text.push_str("\nendmodule\n");
    decide(dir, top, &text, la.max(lb) + 2, limit)
}

/// A harness's verdict: its `// bumprtl prop` claims decided by `ladder` up to `depth`; refuted if any claim is, not
/// tried if any is, else proven.
fn decide(dir: &Path, top: String, text: &str, depth: usize, limit: Duration) -> Result<Equivalence, String> {
    let base: Vec<String> = text.lines().map(String::from).collect();
    let props: Vec<usize> =
        base.iter().enumerate().filter(|(_, l)| l.contains("// bumprtl prop ")).map(|(i, _)| i + 1).collect();
    let start = Instant::now();
    let (status, runs) = ladder(dir, &top, &base, &props, depth, limit)?;
    let verdict = status
        .iter()
        .map(|s| s.0.clone())
        .find(|s| matches!(s, Status::Refuted(_)))
        .or_else(|| status.iter().map(|s| s.0.clone()).find(|s| matches!(s, Status::NotTried(_))))
        .unwrap_or(Status::Proven);
    Ok(Equivalence { name: top, status: verdict, depth, runs, seconds: start.elapsed().as_secs_f64() })
}

/// A Verilog declaration's range and name: `n` alone for one bit, `[bits-1:0] n` otherwise.
fn decl(n: &str, bits: u32) -> String {
    if bits == 1 {
        n.to_string()
    } else {
        format!("[{}:0] {n}", bits - 1)
    }
}

/// The assumption that the free input `n` (`bits` wide, two's complement where `lo` < 0) lies in `lo ..= hi`,
/// compared two bits wider so neither end wraps.
fn assume_range(n: &str, bits: u32, lo: i64, hi: i64) -> String {
    let w = bits + 2;
    let v = if lo < 0 {
        let top = if bits == 1 { n.to_string() } else { format!("{n}[{}]", bits - 1) };
        format!("$signed({{{{2{{{top}}}}}, {n}}})")
    } else {
        format!("$signed({{2'd0, {n}}})")
    };
    let l = |x: i64| if x < 0 { format!("(-{w}'sd{})", -(x as i128)) } else { format!("{w}'sd{x}") };
    format!("    always @(*) assume({v} >= {} && {v} <= {});", l(lo), l(hi))
}

/// The equivalences the project claims (and tests on random vectors), each as a miter decided in `dir/<miter>/`:
/// the matte pipeline is the glossy one at C = 0, and the one-light-per-surface pipeline is the per-vertex one with
/// three equal lights (any weights).
pub fn run_claimed(dir: &Path, limit: Duration, say: &dyn Fn(&str)) -> Result<Vec<Equivalence>, String> {
    let u = |n: &str| crate::units::unit(n);
    let equal_lights: Vec<(&str, &str)> = vec![
        ("l0_x", "l_x"),
        ("l0_y", "l_y"),
        ("l0_z", "l_z"),
        ("l1_x", "l_x"),
        ("l1_y", "l_y"),
        ("l1_z", "l_z"),
        ("l2_x", "l_x"),
        ("l2_y", "l_y"),
        ("l2_z", "l_z"),
    ];
    let miters = [
        Miter { a: u("cart_pipeline")?, b: u("cart_pipeline_matte")?, fix: &[("conc", 0)], bind: &[] },
        Miter { a: u("cart_surface")?, b: u("cart_pipeline")?, fix: &[], bind: &equal_lights },
    ];
    let mut out = vec![];
    for m in &miters {
        say(&format!("miter {} = {} …", m.a.rtl.name(), m.b.rtl.name()));
        out.push(equivalence(m, &dir.join(format!("miter_{}_{}", m.a.rtl.name(), m.b.rtl.name())), limit)?);
    }
    // the sub-blocks where the two pipelines of each pair part: gloss at C = 0 passes N·L through (the matte
    // pipeline has no gloss); the light interpolator with three equal lights passes the light through (the surface
    // pipeline holds its one light, already of unit length, where the per-vertex one normalises the interpolated
    // light: that normaliser's part is not among these)
    say("gloss at C = 0 …");
    out.push(echo(u("gloss")?, &[("conc", 0)], &[], &[("p", "x", 0)], &dir.join("echo_gloss"), limit)?);
    say("light_iter with three equal lights …");
    let same: Vec<(&str, &str)> = vec![
        ("l1_x", "l0_x"),
        ("l1_y", "l0_y"),
        ("l1_z", "l0_z"),
        ("l2_x", "l0_x"),
        ("l2_y", "l0_y"),
        ("l2_z", "l0_z"),
    ];
    // the interpolated light is Sq7.2, the vertex lights whole numbers (S8): 4 · l
    let pairs = [("light_x", "l0_x", 2), ("light_y", "l0_y", 2), ("light_z", "l0_z", 2)];
    out.push(echo(u("light_iter")?, &[], &same, &pairs, &dir.join("echo_light_iter"), limit)?);
    Ok(out)
}

/// A unit claimed to pass inputs through unchanged when some of its inputs are held (gloss at C = 0; the light
/// interpolator with three equal lights): `fix` holds inputs at a value, `same` ties inputs to another input, and
/// each (output, input, k) of `pairs` is claimed equal, where the output is valid, to that input `latency` clocks
/// before, times 2^k (its bits shifted up k places). The sub-block form of a claimed equivalence whose whole miter the solver cannot finish.
pub fn echo(
    u: &Unit,
    fix: &[(&str, i64)],
    same: &[(&str, &str)],
    pairs: &[(&str, &str, u32)],
    dir: &Path,
    limit: Duration,
) -> Result<Equivalence, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let name = u.rtl.name();
    let v = u.rtl.verilog();
    let p = ports(&v, name)?;
    let l = u.rtl.latency();
    let top = format!("echo_{name}");
    let free: Vec<&(String, u32, bool)> = p
        .iter()
        .filter(|(n, _, input)| {
            *input && n != "clock" && !fix.iter().any(|f| f.0 == n) && !same.iter().any(|s| s.0 == n)
        })
        .collect();
    let mut text = format!(
        "{v}\nmodule {top}(clock, {});\n    input wire clock;\n",
        free.iter().map(|f| f.0.as_str()).collect::<Vec<_>>().join(", ")
    );
    let mut conn = vec![".clock(clock)".to_string()];
    for (n, bits, input) in &p {
        if n == "clock" {
            continue;
        }
        if !*input {
            text.push_str(&format!("    wire {};\n", decl(&format!("o_{n}"), *bits)));
            conn.push(format!(".{n}(o_{n})"));
        } else if let Some((_, x)) = fix.iter().find(|f| f.0 == n) {
            conn.push(format!(".{n}({x})"));
        } else if let Some((_, s)) = same.iter().find(|s| s.0 == n) {
            conn.push(format!(".{n}({s})"));
        } else {
            text.push_str(&format!("    input wire {};\n", decl(n, *bits)));
            conn.push(format!(".{n}({n})"));
        }
    }
    text.push_str(&format!("    {name} ua({});\n", conn.join(", ")));
    let mut lines = vec![];
    for (k, (out, inp, shift)) in pairs.iter().enumerate() {
        let bits = p.iter().find(|x| &x.0 == inp).map(|x| x.1).ok_or_else(|| format!("{name} has no input {inp}"))?;
        let mut prev = inp.to_string();
        for d in 1..=l {
            let r = format!("{inp}_d{d}");
            text.push_str(&format!("    reg {} = 0;\n    always @(posedge clock) {r} <= {prev};\n", decl(&r, bits)));
            prev = r;
        }
        let scaled = if *shift == 0 { prev } else { format!("{{{prev}, {shift}'d0}}") };
        lines.push(format!("    always @(*) assert(!o_valid_out || o_{out} == {scaled}); // bumprtl prop {}", k + 1));
    }
    for (n, bits, _) in &free {
        if let Some((lo, hi)) = u.model.inputs.iter().find(|i| i.name == n).map(|i| i.range()) {
            lines.push(assume_range(n, *bits, lo, hi));
        }
    }
    text.push_str(&lines.join("\n"));
    text.push_str("\nendmodule\n");
    decide(dir, top, &text, l + 2, limit)
}
