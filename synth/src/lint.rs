//! `verilator --lint-only -Wall` on an exported unit. Every warning is either one of rust-hdl's own
//! code-generation habits, listed here with its reason, or the design's: a design warning fails the lint.

use std::path::{Path, PathBuf};

/// One of rust-hdl's code-generation habits: its name, why it is rust-hdl's and harmless, and the test that
/// recognises it from the warning's code, its message and the Verilog line it points at.
pub struct Habit {
    pub name: &'static str,
    pub why: &'static str,
    matches: fn(code: &str, msg: &str, src: &str) -> bool,
}

/// rust-hdl's habits. A warning is waived only when the Verilog line it points at shows the habit; anything else is
/// the design's, and fails the lint unless the unit's own row in the table of units (`sim::units::UNITS`) waives that signal.
pub const HABITS: &[Habit] = &[
    Habit {
        name: "WIDTH/literal",
        why: "rust-hdl writes every literal as a 32-bit constant (`32'h3ff - x`); each signal still wraps at its own \
            width on assignment, the rust-hdl semantics the co-simulation checks bit for bit",
        matches: |code, _, src| code == "WIDTH" && src.contains("32'h"),
    },
    Habit {
        name: "WIDTH/bit_cast",
        why: "rust-hdl exports bit_cast as `((x) & N'hmask)`, a zero-extension that Verilog's own widening would do \
            anyway",
        matches: |code, _, src| code == "WIDTH" && src.contains(") & ") && src.contains("'h"),
    },
    Habit {
        name: "UNUSEDSIGNAL/slice",
        why: "a named intermediate whose dropped bits are unused: rust-hdl can slice only named signals, so a shift \
            (`get_bits`) or a 16×16→32 product (its only multiply) leaves bits unread by design",
        matches: |code, msg, _| code == "UNUSEDSIGNAL" && msg.contains("Bits of signal are not used"),
    },
    Habit {
        name: "DECLFILENAME/dff",
        why: "rust-hdl writes every DFF as its own module (`unit$stage`) in the unit's one file",
        matches: |code, msg, _| code == "DECLFILENAME" && msg.contains("MODULE name:") && msg.contains('$'),
    },
];

/// What waives a warning: a habit of rust-hdl's, or the unit's own waiver of an unused signal.
fn classify(code: &str, msg: &str, src: &str, design: &[(&'static str, &'static str)]) -> Option<&'static str> {
    if code == "UNUSEDSIGNAL" {
        if let Some((sig, _)) = design.iter().find(|(sig, _)| msg.ends_with(&format!("'{sig}'"))) {
            return Some(sig);
        }
    }
    HABITS.iter().find(|h| (h.matches)(code, msg, src)).map(|h| h.name)
}

/// A warning a waiver covers: what waives it (a habit's name, or the unit's own waived signal), Verilator's code
/// for it, and the line of the file it points at.
#[derive(Debug, Clone)]
pub struct Waived {
    pub by: &'static str,
    pub code: String,
    pub line: usize,
    pub text: String,
}

#[derive(Debug, Default)]
pub struct LintReport {
    pub waived: Vec<Waived>,
    pub design: Vec<String>,
}

/// `verilator --lint-only -Wall` on `files` (in `dir`) with `top` as the top module: every warning line it prints.
pub fn warnings(dir: &Path, files: &[&Path], top: &str) -> Result<Vec<String>, String> {
    let mut cmd = std::process::Command::new("verilator");
    cmd.args(["--lint-only", "-Wall", "--top-module", top]).args(files).current_dir(dir);
    let out = cmd.output().map_err(|e| format!("cannot run verilator: {e}"))?;
    let text = String::from_utf8_lossy(&out.stderr);
    let found: Vec<String> = text
        .lines()
        .filter(|l| (l.starts_with("%Warning-") || l.starts_with("%Error")) && !l.starts_with("%Error: Exiting due to"))
        .map(str::to_string)
        .collect();
    if !out.status.success() && found.is_empty() {
        return Err(format!("verilator --lint-only failed on {top}: {}", text.trim()));
    }
    Ok(found)
}

/// Lint the unit `module` in `file`; `design` is the unit's own waivers (signal, reason).
pub fn lint(
    dir: &Path,
    file: &Path,
    module: &str,
    design: &[(&'static str, &'static str)],
) -> Result<LintReport, String> {
    let found = warnings(dir, &[file], module)?;
    let source = std::fs::read_to_string(dir.join(file)).map_err(|e| format!("cannot read {}: {e}", file.display()))?;
    let lines: Vec<&str> = source.lines().collect();
    let mut r = LintReport::default();
    for line in found {
        // %Warning-CODE: file:LINE:COL: message
        let code = line.trim_start_matches("%Warning-").split(':').next().unwrap_or("").to_string();
        let lineno: usize = line.split(':').nth(2).and_then(|x| x.trim().parse().ok()).unwrap_or(0);
        let src = lineno.checked_sub(1).and_then(|k| lines.get(k)).copied().unwrap_or("");
        match classify(&code, &line, src, design) {
            Some(by) if lineno > 0 => r.waived.push(Waived { by, code, line: lineno, text: line }),
            _ => r.design.push(line),
        }
    }
    Ok(r)
}

/// The Verilator configuration file `<unit>.vlt` that travels with the exported files: one `lint_off` by rule and
/// line for each warning `-Wall` gives that a habit of rust-hdl's or one of the unit's own waivers covers, each
/// under the reason it is waived, so that `verilator --lint-only -Wall <unit>.vlt <file>...` is silent. `files`
/// are each file's name and its lint; `design` the unit's own waivers (signal, reason). A warning no waiver
/// covers is the design's, and the file leaves it to be seen.
pub fn waiver_file(unit: &str, files: &[(&str, &LintReport)], design: &[(&'static str, &'static str)]) -> String {
    let mut s = String::from("`verilator_config\n");
    let names: Vec<&str> = files.iter().map(|f| f.0).collect();
    s += &format!(
        "// generated by bumprtl: Verilator's waivers for {}, one `lint_off` by rule and line for each warning\n",
        names.join(" and ")
    );
    s += &format!("// `verilator --lint-only -Wall` gives on them: read it first, `verilator --lint-only -Wall {unit}.vlt FILE.v`.\n");
    s += "// Each is one of rust-hdl's code-generation habits or a fact of the design, named here with its reason.\n";
    s +=
        "// (each rule is written for the file alone and under a folder, as Verilator matches the name it was given)\n";
    let reason = |by: &str| -> String {
        HABITS.iter().find(|h| h.name == by).map(|h| h.why.to_string()).unwrap_or_else(|| {
            let why = design.iter().find(|(sig, _)| *sig == by).map(|d| d.1).unwrap_or("the unit's own waiver");
            format!("`{by}` is left unused by design: {why}")
        })
    };
    let mut bys: Vec<&'static str> = files.iter().flat_map(|f| f.1.waived.iter().map(|w| w.by)).collect();
    bys.sort();
    bys.dedup();
    for by in bys {
        s += &format!("\n// {by}: {}\n", reason(by).split_whitespace().collect::<Vec<_>>().join(" "));
        for (name, report) in files {
            let mut keys: Vec<(&str, usize)> =
                report.waived.iter().filter(|w| w.by == by).map(|w| (w.code.as_str(), w.line)).collect();
            keys.sort();
            keys.dedup();
            for (code, range) in ranges(&keys) {
                for file in [name.to_string(), format!("*/{name}")] {
                    s += &format!("lint_off -rule {code} -file \"{file}\" -lines {range}\n");
                }
            }
        }
    }
    s
}

/// Lint each of a unit's exported files in `dir` (its name and its top module) and write `<unit>.vlt` beside them:
/// its path, and the warnings no waiver covers (the design's, which Verilator still shows with it).
pub fn write_waivers(
    dir: &Path,
    unit: &str,
    files: &[(&str, &str)],
    design: &[(&'static str, &'static str)],
) -> Result<(PathBuf, Vec<String>), String> {
    let mut reports = Vec::new();
    for (file, top) in files {
        reports.push(lint(dir, Path::new(file), top, design)?);
    }
    let named: Vec<(&str, &LintReport)> = files.iter().map(|f| f.0).zip(&reports).collect();
    let path = dir.join(format!("{unit}.vlt"));
    crate::export::write_atomic(&path, waiver_file(unit, &named, design).as_bytes())?;
    Ok((path, reports.into_iter().flat_map(|r| r.design).collect()))
}

/// Runs of consecutive lines of one rule, as Verilator's `-lines a-b`.
fn ranges<'a>(keys: &[(&'a str, usize)]) -> Vec<(&'a str, String)> {
    let mut out: Vec<(&str, usize, usize)> = Vec::new();
    for &(code, line) in keys {
        match out.last_mut() {
            Some((c, _, to)) if *c == code && *to + 1 == line => *to = line,
            _ => out.push((code, line, line)),
        }
    }
    out.into_iter().map(|(c, a, b)| (c, if a == b { a.to_string() } else { format!("{a}-{b}") })).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn consecutive_lines_of_a_rule_make_one_range() {
        let keys = [("WIDTH", 3), ("WIDTH", 4), ("WIDTH", 5), ("WIDTH", 9), ("WIDTHEXPAND", 10)];
        let r = ranges(&keys);
        assert_eq!(r, [("WIDTH", "3-5".to_string()), ("WIDTH", "9".into()), ("WIDTHEXPAND", "10".into())]);
    }
}
