//! `bumprtl prove <unit>` and `prove --all`: the solver's verdict on the width report's claims (`sim::prove`), as a
//! table on the terminal and, with `--md`, in Markdown.

use sim::prove::{Options, Proved, Status};
use std::path::Path;
use widths::wraps::Kind as WrapKind;

fn claim(o: &sim::prove::Outcome) -> String {
    format!("{} {} .. {}", o.prop.kind.name(), o.prop.lo, o.prop.hi)
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
        let listed = o.listed.map_or(String::new(), |k| format!("{} ({})", k.flag(), k.name()));
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
    let argued: Vec<_> = p.outcomes.iter().filter(|o| o.listed == Some(WrapKind::Bound)).collect();
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

pub fn run(unit: Option<String>, all: bool, dir: &Path, o: &Options, md: Option<&Path>) -> Result<(), String> {
    if let Some(f) = md {
        crate::output::writable_file(f)?;
    }
    crate::output::writable_folder(dir)?;
    let units: Vec<&'static sim::units::Unit> = if all {
        sim::units::UNITS.iter().collect()
    } else {
        vec![sim::units::unit(unit.as_deref().unwrap_or_default())?]
    };
    let mut text = String::new();
    let mut summary =
        String::from("| unit | claims | proven | refuted | not tried | runs | s |\n|---|---|---|---|---|---|---|\n");
    for u in units {
        let name = u.rtl.name();
        eprintln!("prove {name} …");
        let p = sim::prove::prove(u, &dir.join(name), o)?;
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
    }
    if all {
        println!("{summary}");
        text.insert_str(0, &format!("{summary}\n"));
    }
    if let Some(f) = md {
        synth::export::write_atomic(f, text.as_bytes())?;
    }
    Ok(())
}
