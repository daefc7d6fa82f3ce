//! `verilator --lint-only -Wall` on an exported unit. Every warning is either one of rust-hdl's own
//! code-generation habits, listed here with its reason, or the design's: a design warning fails the lint.

use std::path::Path;

/// rust-hdl's code-generation habits, each with why it is rust-hdl's and harmless. A warning is waived only when
/// the Verilog line it points at shows the habit; anything else is the design's and fails the lint.
pub const WAIVERS: &[(&str, &str)] = &[
    ("WIDTH/literal", "rust-hdl writes every literal as a 32-bit constant (`32'h3ff - x`); each signal still wraps \
        at its own width on assignment, the rust-hdl semantics the co-simulation checks bit for bit"),
    ("WIDTH/bit_cast", "rust-hdl exports bit_cast as `((x) & N'hmask)`, a zero-extension that Verilog's own \
        widening would do anyway"),
    ("UNUSEDSIGNAL/slice", "a named intermediate whose dropped bits are unused: rust-hdl can slice only named \
        signals, so a shift (`get_bits`) or a 16×16→32 product (its only multiply) leaves bits unread by design"),
    ("DECLFILENAME/dff", "rust-hdl writes every DFF as its own module (`unit$stage`) in the unit's one file"),
];

/// The design's own unused signals, each named exactly, with its reason.
pub const DESIGN_WAIVERS: &[(&str, &str)] = &[
    ("'filter$out_b'", "the Cartesian path filters TexelX and TexelZ on red and green; blue and alpha are the same \
        bilinear unit's other channels, tied to 0 and removed by synthesis"),
    ("'filter$out_a'", "as above"),
    ("'light$valid_out'", "the light path runs in lockstep with the bump path; the bump path's valid is used"),
    ("'light_norm$valid_out'", "as above"),
    ("'shader$sum'", "polar_shade's S11 before the clamp is an output for tests and waveforms; the polar pipeline \
        uses the clamped shade"),
];

fn classify(code: &str, msg: &str, src: &str) -> Option<&'static str> {
    if code == "UNUSEDSIGNAL" {
        if let Some((name, _)) = DESIGN_WAIVERS.iter().find(|(n, _)| msg.ends_with(n)) {
            return Some(name);
        }
    }
    match code {
        "WIDTH" if src.contains("32'h") => Some(WAIVERS[0].0),
        "WIDTH" if src.contains(") & ") && src.contains("'h") => Some(WAIVERS[1].0),
        "UNUSEDSIGNAL" if msg.contains("Bits of signal are not used") => Some(WAIVERS[2].0),
        "DECLFILENAME" if msg.contains("MODULE name:") && msg.contains('$') => Some(WAIVERS[3].0),
        _ => None,
    }
}

#[derive(Debug, Default)]
pub struct LintReport {
    pub waived: Vec<(String, String)>,
    pub design: Vec<String>,
}

pub fn lint(dir: &Path, file: &Path, module: &str) -> Result<LintReport, String> {
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
        match classify(&code, line, src) {
            Some(habit) => r.waived.push((habit.to_string(), line.to_string())),
            None => r.design.push(line.to_string()),
        }
    }
    Ok(r)
}
