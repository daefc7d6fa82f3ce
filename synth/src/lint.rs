//! `verilator --lint-only -Wall` on an exported unit. Every warning is either one of rust-hdl's own
//! code-generation habits, listed here with its reason, or the design's: a design warning fails the lint.

use std::path::Path;

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

#[derive(Debug, Default)]
pub struct LintReport {
    pub waived: Vec<(String, String)>,
    pub design: Vec<String>,
}

/// Lint the unit `module` in `file`; `design` is the unit's own waivers (signal, reason).
pub fn lint(
    dir: &Path,
    file: &Path,
    module: &str,
    design: &[(&'static str, &'static str)],
) -> Result<LintReport, String> {
    let f = file.to_str().ok_or("non-UTF-8 path")?;
    let out = std::process::Command::new("verilator")
        .args(["--lint-only", "-Wall", "--top-module", module, f])
        .current_dir(dir)
        .output()
        .map_err(|e| format!("cannot run verilator: {e}"))?;
    let text = String::from_utf8_lossy(&out.stderr).to_string();
    let source = std::fs::read_to_string(dir.join(file)).map_err(|e| format!("cannot read {}: {e}", file.display()))?;
    let lines: Vec<&str> = source.lines().collect();
    let mut r = LintReport::default();
    for line in text.lines().filter(|l| l.starts_with("%Warning-") || l.starts_with("%Error")) {
        if line.starts_with("%Error: Exiting due to") {
            continue;
        }
        let code = line.trim_start_matches("%Warning-").split(':').next().unwrap_or("").to_string();
        // %Warning-CODE: file:LINE:COL: message
        let lineno: usize = line.split(':').nth(2).and_then(|x| x.trim().parse().ok()).unwrap_or(0);
        let src = lineno.checked_sub(1).and_then(|k| lines.get(k)).copied().unwrap_or("");
        match classify(&code, line, src, design) {
            Some(habit) => r.waived.push((habit.to_string(), line.to_string())),
            None => r.design.push(line.to_string()),
        }
    }
    Ok(r)
}
