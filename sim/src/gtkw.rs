//! GTKWave save files: beside every VCD the program writes, a `.gtkw` that opens it readable. The signals come from
//! the VCD's own header (so every name is one GTKWave finds), grouped: the valid flags first (the top block's, then
//! every unit's inside it), then the top block's ports, then each block's registers stage by stage (the rtl names
//! a stage's registers `sN_*` or `sNb_*`), its other registers, and its wires. A register shows its output `q`; a
//! signal the rtl declares signed (`widths::Formats`) is shown as signed decimal, other buses as decimal, bits
//! as binary. Only the top groups are open.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;
use widths::Formats;

/// GTKWave's trace flags (its `TR_*`), written in hex after `@`.
const RJUSTIFY: u32 = 0x20;
const DEC: u32 = 0x4;
const BIN: u32 = 0x8;
const BLANK: u32 = 0x200;
const SIGNED: u32 = 0x400;
const CLOSED: u32 = 0x40_0000;
const GRP_BEGIN: u32 = 0x80_0000;
const GRP_END: u32 = 0x100_0000;

/// One variable of a VCD header: its hierarchical name (scopes joined by '.') and width.
#[derive(Clone, Debug, PartialEq)]
pub struct Var {
    pub path: Vec<String>,
    pub bits: usize,
}

impl Var {
    pub fn name(&self) -> String {
        self.path.join(".")
    }
}

/// The variables of a VCD's header, in order (the text up to `$enddefinitions`, or all of it).
pub fn header_vars(vcd: &str) -> Vec<Var> {
    let mut scope: Vec<String> = vec![];
    let mut vars = vec![];
    let mut toks = vcd.split_whitespace();
    while let Some(t) = toks.next() {
        match t {
            "$scope" => {
                let _kind = toks.next();
                if let Some(n) = toks.next() {
                    scope.push(n.to_string());
                }
            }
            "$upscope" => {
                scope.pop();
            }
            "$var" => {
                let (_kind, bits, _id, name) = (toks.next(), toks.next(), toks.next(), toks.next());
                if let (Some(b), Some(n)) = (bits.and_then(|b| b.parse().ok()), name) {
                    let mut path = scope.clone();
                    path.push(n.to_string());
                    vars.push(Var { path, bits: b });
                }
            }
            "$enddefinitions" => break,
            _ => {}
        }
    }
    vars
}

/// The name GTKWave gives a VCD variable: a bus without a range in its reference gets `[bits−1:0]`.
pub fn facility(v: &Var) -> String {
    if v.bits > 1 {
        format!("{}[{}:0]", v.name(), v.bits - 1)
    } else {
        v.name()
    }
}

/// The stage of a register field name: `s7_p$0` → 7, `s6b_c$1` → 6.
pub fn stage_of(field: &str) -> Option<u32> {
    let rest = field.strip_prefix('s')?;
    let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
    let after = &rest[digits.len()..];
    (!digits.is_empty() && (after.starts_with('_') || after.starts_with("b_"))).then(|| digits.parse().ok()).flatten()
}

#[derive(Default)]
struct Block {
    stages: BTreeMap<u32, Vec<Var>>,
    registers: Vec<Var>,
    wires: Vec<Var>,
}

/// The save file's text for `vcd_name` (as written in `[dumpfile]`), from its variables; `signed` says which
/// hierarchical names the rtl declares signed.
pub fn save_file(vcd_name: &str, vars: &[Var], signed: &dyn Fn(&str) -> bool) -> String {
    // a register is a scope holding d, q and clock and nothing else; its q is what is shown
    let mut scopes: BTreeMap<Vec<String>, Vec<&str>> = BTreeMap::new();
    for v in vars {
        scopes.entry(v.path[..v.path.len() - 1].to_vec()).or_default().push(v.path.last().map_or("", |s| s.as_str()));
    }
    let is_register = |p: &[String]| {
        scopes.get(p).is_some_and(|names| names.len() == 3 && ["d", "q", "clock"].iter().all(|n| names.contains(n)))
            && !scopes.keys().any(|k| k.len() > p.len() && k.starts_with(p))
    };
    let top = vars.first().map(|v| v.path[0].clone()).unwrap_or_default();
    let mut valid = vec![];
    let mut ports = vec![];
    let mut blocks: Vec<(Vec<String>, Block)> = vec![];
    let block_of = |blocks: &mut Vec<(Vec<String>, Block)>, p: &[String]| -> usize {
        match blocks.iter().position(|(b, _)| b == p) {
            Some(k) => k,
            None => {
                blocks.push((p.to_vec(), Block::default()));
                blocks.len() - 1
            }
        }
    };
    for v in vars {
        let leaf = v.path.last().map_or("", |s| s.as_str());
        let parent = &v.path[..v.path.len() - 1];
        if leaf == "clock" {
            continue;
        }
        if (leaf == "valid_in" || leaf == "valid_out") && !is_register(parent) {
            valid.push(v.clone());
            continue;
        }
        if is_register(parent) {
            if leaf != "q" {
                continue;
            }
            // the register's field is the last scope; its block the scopes above it, past any delay line
            let field = parent.last().map_or("", |s| s.as_str());
            let mut owner = parent[..parent.len() - 1].to_vec();
            while owner.len() > 1 && owner.last().is_some_and(|s| s.starts_with("line$")) {
                owner.pop();
            }
            let k = block_of(&mut blocks, &owner);
            match stage_of(field) {
                Some(s) => blocks[k].1.stages.entry(s).or_default().push(v.clone()),
                None => blocks[k].1.registers.push(v.clone()),
            }
            continue;
        }
        if parent.len() == 1 && parent[0] == top {
            ports.push(v.clone());
        } else {
            let k = block_of(&mut blocks, parent);
            blocks[k].1.wires.push(v.clone());
        }
    }
    let mut s = String::new();
    let _ = writeln!(s, "[*] GTKWave save file written by bumprtl beside its VCD");
    let _ = writeln!(s, "[dumpfile] \"{vcd_name}\"");
    let _ = writeln!(s, "[timestart] 0");
    let _ = writeln!(s, "[treeopen] {top}.");
    let _ = writeln!(s, "[signals_width] 320");
    let _ = writeln!(s, "[sst_expanded] 1");
    let trace = |s: &mut String, v: &Var| {
        let flags = if v.bits == 1 {
            RJUSTIFY | BIN
        } else if signed(&v.name()) {
            RJUSTIFY | DEC | SIGNED
        } else {
            RJUSTIFY | DEC
        };
        let _ = writeln!(s, "@{flags:x}\n{}", facility(v));
    };
    let group = |s: &mut String, title: &str, vs: &[Var], open: bool| {
        if vs.is_empty() {
            return;
        }
        let closed = if open { 0 } else { CLOSED };
        let _ = writeln!(s, "@{:x}\n-{title}", GRP_BEGIN | BLANK | closed);
        for v in vs {
            trace(s, v);
        }
        let _ = writeln!(s, "@{:x}\n-{title}", GRP_END | BLANK | closed);
    };
    group(&mut s, "valid flags", &valid, true);
    group(&mut s, &format!("{top} ports"), &ports, true);
    for (path, b) in &blocks {
        let name = path.join(".");
        for (st, vs) in &b.stages {
            group(&mut s, &format!("{name} stage {st}"), vs, false);
        }
        group(&mut s, &format!("{name} other registers"), &b.registers, false);
        group(&mut s, &format!("{name} wires and ports"), &b.wires, false);
    }
    s
}

/// Write `vcd`'s save file beside it (`x.vcd` → `x.gtkw`), whole or not at all; `formats` are the traced block's.
pub fn write_beside(vcd: &Path, formats: &Formats) -> Result<std::path::PathBuf, String> {
    let text = std::fs::read(vcd).map_err(|e| format!("cannot read {}: {e}", vcd.display()))?;
    // the header is at the top; read no further than it
    let end = text.windows(15).position(|w| w == b"$enddefinitions").map_or(text.len(), |p| p + 15);
    let head = String::from_utf8_lossy(&text[..end]);
    let vars = header_vars(&head);
    let name = vcd.file_name().map_or("".into(), |n| n.to_string_lossy().into_owned());
    let body = save_file(&name, &vars, &|n| formats.format(n).is_some_and(|f| f.signed));
    let out = vcd.with_extension("gtkw");
    synth::export::write_atomic(&out, body.as_bytes())?;
    Ok(out)
}
