//! `bumprtl prove <unit>` and `prove --all`: the solver's verdict on the width report's claims (`sim::prove`), as a
//! table on the terminal and, with `--md`, in Markdown.

use sim::prove::{Options, Proved, Status};
use std::path::Path;
use widths::wraps::Kind as WrapKind;

pub(crate) fn claim(o: &sim::prove::Outcome) -> String {
    let when = o.prop.stage.map_or(String::new(), |d| format!(" where stage {d} holds a pixel"));
    format!("{} {} .. {}{when}", o.prop.kind.name(), o.prop.lo, o.prop.hi)
}

/// One unit's table: every claim not proven first, then the proven ones counted by kind.
fn table(p: &Proved) -> String {
    let mut t = format!(
        "{}: {} claims at depth {} ({} solver runs, {:.1} s): {} proven, {} refuted, {} not tried; {} steps without a claim\n",
        p.unit,
        p.outcomes.len(),
        p.depth,
        p.runs,
        p.seconds,
        p.count("proven"),
        p.count("refuted"),
        p.count("not tried"),
        p.skipped.len()
    );
    t.push_str("| signal | claim | wrap list | solver | s | why / trace |\n|---|---|---|---|---|---|\n");
    let mut rows: Vec<&sim::prove::Outcome> = p.outcomes.iter().collect();
    rows.sort_by_key(|o| (o.status == Status::Proven, o.listed.is_none(), o.prop.signal.clone()));
    for o in rows {
        let listed = o.listed.map_or(String::new(), |w| format!("{} ({})", w.kind.flag(), w.kind.name()));
        let why = match &o.status {
            Status::Refuted(trace) => trace.clone(),
            Status::NotTried(why) => why.clone(),
            Status::Proven => String::new(),
        };
        t.push_str(&format!(
            "| {} | {} | {listed} | {} | {:.1} | {why} |\n",
            o.prop.signal,
            claim(o),
            o.status.word(),
            o.seconds
        ));
    }
    let argued: Vec<_> = p.outcomes.iter().filter(|o| o.listed.map(|w| w.kind) == Some(WrapKind::Bound)).collect();
    t.push_str(&format!(
        "\nthe wrap list's argued (`a`) entries here: {}, {} proven by the solver, {} refuted, {} not tried\n",
        argued.len(),
        argued.iter().filter(|o| o.status == Status::Proven).count(),
        argued.iter().filter(|o| matches!(o.status, Status::Refuted(_))).count(),
        argued.iter().filter(|o| matches!(o.status, Status::NotTried(_))).count()
    ));
    if !p.skipped.is_empty() {
        t.push_str("\nsteps without a claim:\n");
        for (s, why) in &p.skipped {
            t.push_str(&format!("- {s}: {why}\n"));
        }
    }
    t
}

/// `prove --axis`: each unit's wrapper's rules, a table a unit.
pub fn axis(names: &[String], all: bool, dir: &Path, o: &Options, md: Option<&Path>) -> Result<(), String> {
    if let Some(f) = md {
        crate::output::writable_file(f)?;
    }
    crate::output::writable_folder(dir)?;
    let units = pick(names, all)?;
    let limit = o.limit.unwrap_or(std::time::Duration::from_secs(600));
    let mut text = String::from("| unit | rule | solver | s | trace |\n|---|---|---|---|---|\n");
    let mut failed = vec![];
    for u in units {
        let name = u.rtl.name();
        eprintln!("prove the AXI4-Stream rules of {name} …");
        let p = match sim::axis_rules::prove(u, &dir.join(format!("{name}_axis")), 0, None, limit) {
            Ok(p) => p,
            Err(e) => {
                eprintln!("bumprtl: {e}");
                text.push_str(&format!("| {name} | | error: {} | | |\n", e.replace('|', "/")));
                failed.push(name);
                continue;
            }
        };
        for r in &p.rules {
            let (word, trace) = match &r.status {
                Status::Proven if r.unbounded() => ("proven (every trace)".to_string(), String::new()),
                Status::Proven => (format!("proven to {} clocks from reset", p.depth), String::new()),
                Status::Refuted(t) => ("refuted".into(), t.clone()),
                Status::NotTried(w) => ("not tried".into(), w.clone()),
            };
            text.push_str(&format!("| {name} | {} | {word} | {:.1} | {trace} |\n", r.name, r.seconds));
        }
        // the depth only where a bounded rule ran to it
        let ran = p.rules.iter().any(|r| !r.unbounded() && !matches!(r.status, Status::NotTried(_)));
        let depth = if ran { format!("{} clocks", p.depth) } else { "no bounded rule run".into() };
        text.push_str(&format!("| {name} | (all, {depth}) | | {:.1} | |\n", p.seconds));
    }
    println!("{text}");
    if let Some(f) = md {
        synth::export::write_atomic(f, text.as_bytes())?;
    }
    if !failed.is_empty() {
        return Err(format!("prove --axis: no verdict for {} (each error above)", failed.join(", ")));
    }
    Ok(())
}

fn pick(names: &[String], all: bool) -> Result<Vec<&'static sim::units::Unit>, String> {
    if all {
        Ok(sim::units::UNITS.iter().collect())
    } else {
        names.iter().map(|n| sim::units::unit(n)).collect()
    }
}

pub fn run(
    names: &[String],
    all: bool,
    equivalences: bool,
    dir: &Path,
    o: &Options,
    md: Option<&Path>,
) -> Result<(), String> {
    if let Some(f) = md {
        crate::output::writable_file(f)?;
    }
    crate::output::writable_folder(dir)?;
    let units = pick(names, all)?;
    let several = units.len() > 1;
    let mut text = String::new();
    let mut proved: Vec<Proved> = vec![];
    let mut failed: Vec<&str> = vec![];
    let mut summary =
        String::from("| unit | claims | proven | refuted | not tried | runs | s |\n|---|---|---|---|---|---|---|\n");
    for u in units {
        let name = u.rtl.name();
        let p = crate::progress::step(
            &format!("prove {name}"),
            |p: &Result<Proved, String>| {
                p.as_ref().ok().map(|p| format!("{} claims, {} solver runs", p.outcomes.len(), p.runs))
            },
            || sim::prove::prove(u, &dir.join(name), o),
        );
        let p = match p {
            Ok(p) => p,
            Err(e) if several => {
                // the other units still run; the command fails at the end
                eprintln!("bumprtl: {e}");
                summary.push_str(&format!("| {name} | error: {} | | | | | |\n", e.replace('|', "/")));
                failed.push(name);
                continue;
            }
            Err(e) => return Err(e),
        };
        let t = table(&p);
        println!("{t}");
        summary.push_str(&format!(
            "| {name} | {} | {} | {} | {} | {} | {:.1} |\n",
            p.outcomes.len(),
            p.count("proven"),
            p.count("refuted"),
            p.count("not tried"),
            p.runs,
            p.seconds
        ));
        text.push_str(&t);
        text.push('\n');
        proved.push(p);
    }
    if several {
        let entries = argued_entries(&proved);
        println!("{summary}\n{entries}");
        text.insert_str(0, &format!("{summary}\n{entries}\n"));
    }
    if equivalences {
        let limit = o.limit.unwrap_or(std::time::Duration::from_secs(600));
        let steps = crate::progress::Chain::default();
        let found = sim::prove::run_claimed(dir, limit, &|s| steps.next(s, "decided"));
        steps.end("decided", &found);
        let found = found?;
        let mut t = String::from("| miter | solver | depth | runs | s | why / trace |\n|---|---|---|---|---|---|\n");
        for e in &found {
            let why = match &e.status {
                Status::Refuted(x) | Status::NotTried(x) => x.clone(),
                Status::Proven => String::new(),
            };
            t.push_str(&format!(
                "| {} | {} | {} | {} | {:.1} | {why} |\n",
                e.name,
                e.status.word(),
                e.depth,
                e.runs,
                e.seconds
            ));
        }
        println!("{t}");
        text.push_str(&t);
    }
    if let Some(f) = md {
        synth::export::write_atomic(f, text.as_bytes())?;
    }
    if !failed.is_empty() {
        return Err(format!("prove: no verdict for {} (each error above)", failed.join(", ")));
    }
    Ok(())
}

/// Every argued (`a`) entry of the wrap list and what the solver made of it in the units run: refuted where any
/// unit refutes the step, proven where one proves it, else not tried or not reached (no unit run holds the block).
fn argued_entries(proved: &[Proved]) -> String {
    let mut t = String::from("| block | signal | solver | where |\n|---|---|---|---|\n");
    let (mut n, mut counts) = (0, std::collections::BTreeMap::<&str, usize>::new());
    for w in widths::wraps::WAIVED.iter().filter(|w| w.kind == WrapKind::Bound) {
        let at: Vec<(&str, &sim::prove::Outcome)> = proved
            .iter()
            .flat_map(|p| p.outcomes.iter().map(move |o| (p.unit, o)))
            .filter(|(_, o)| o.listed.is_some_and(|l| (l.block, l.signal) == (w.block, w.signal)))
            .collect();
        let pick = |word: &str| at.iter().find(|(_, o)| o.status.word() == word);
        let (word, place) = match pick("refuted").or_else(|| pick("proven")).or_else(|| pick("not tried")) {
            Some((u, o)) => (o.status.word(), u.to_string()),
            None => ("not reached", String::new()),
        };
        n += 1;
        *counts.entry(word).or_default() += 1;
        t.push_str(&format!("| {} | {} | {word} | {place} |\n", w.block, w.signal));
    }
    let c: Vec<String> = counts.iter().map(|(k, v)| format!("{v} {k}")).collect();
    format!("the wrap list's {n} argued entries: {}\n\n{t}", c.join(", "))
}
