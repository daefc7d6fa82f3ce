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
    })?;
    let depth = rtl.latency() + 2;
    let limit = o.limit.unwrap_or(Duration::from_secs(600));
    let mut status: Vec<Option<(Status, f64)>> = vec![None; h.props.len()];
    let mut lines: Vec<String> = h.text.lines().map(String::from).collect();
    let by_line: HashMap<usize, usize> = h.props.iter().enumerate().map(|(i, p)| (p.line, i)).collect();
    let (mut runs, start) = (0, Instant::now());
    // bounded from the initial state, then induction; each failure set aside and the rest run again
    for induction in [false, true] {
        loop {
            let open = status.iter().filter(|s| s.is_none()).count();
            if open == 0 {
                break;
            }
            runs += 1;
            let t0 = Instant::now();
            let r = run_once(dir, name, &lines, depth, induction, limit)?;
            let secs = t0.elapsed().as_secs_f64();
            match r {
                Run::Passed => {
                    if induction {
                        for s in status.iter_mut().filter(|s| s.is_none()) {
                            *s = Some((Status::Proven, secs));
                        }
                    }
                    break;
                }
                Run::Failed(failed, trace) => {
                    let mut any = false;
                    for l in failed {
                        let Some(&i) = by_line.get(&l) else { continue };
                        if status[i].is_some() {
                            continue;
                        }
                        any = true;
                        status[i] = Some((
                            if induction {
                                Status::NotTried(format!(
                                    "induction at depth {depth} fails (state that is not feed-forward: a memory or a counter)"
                                ))
                            } else {
                                Status::Refuted(trace.clone())
                            },
                            secs,
                        ));
                        lines[l - 1] = format!("    // set aside: {}", lines[l - 1].trim());
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
                        *s = Some((Status::NotTried(format!("the solver ran past {} s", limit.as_secs())), secs));
                    }
                    break;
                }
            }
        }
    }
    let outcomes = h
        .props
        .into_iter()
        .zip(status)
        .map(|(p, s)| {
            let (status, seconds) = s.unwrap_or((Status::NotTried("not reached".into()), 0.0));
            Outcome { listed: if p.kind == Kind::Exact { listed(&p.signal) } else { None }, prop: p, status, seconds }
        })
        .collect();
    Ok(Proved { unit: name, depth, outcomes, skipped: h.skipped, runs, seconds: start.elapsed().as_secs_f64() })
}

enum Run {
    Passed,
    /// the failed assertions' lines in the harness, and the trace's inputs
    Failed(Vec<usize>, String),
    Timeout,
}

fn run_once(
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
    let failed: Vec<usize> = log
        .lines()
        .filter(|l| l.contains("Assert failed in"))
        .filter_map(|l| l.split_once(&file))
        .filter_map(|(_, r)| {
            // `l0.c0-l1.c1`: an assertion inside a block is spanned from the end of the statement before it
            let span = r.split_whitespace().next()?;
            let end = span.rsplit_once('-').map_or(span, |x| x.1);
            end.split('.').next()?.parse().ok()
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
