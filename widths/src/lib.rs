//! The bumprtl width analysis: every signal of an rtl block with the fixed-point format its declaration gives it,
//! the range of values it takes in the rust-hdl simulation of the unit's vectors (here), the range it can take over
//! every input sequence (`bounds`), and the steps that may leave their format on purpose (`wraps`). It reads rtl
//! blocks, not scenes: `bumprtl widths` prints it, and `sim`'s GTKWave save files take the signedness from it.
//!
//! The simulator keeps widths but not formats (`Sq1_10` and `Uq0_12` are both `Bits<12>` to it), so the formats
//! come from what the compiler records of each block's declaration (`rtl::prim::declared`: every field's name and
//! type as written, and that type's own declaration): a signal's hierarchical name (`uut.norm.s3_l.q`, as in the
//! VCD) is followed through them, generic parameters substituted in the types' text, down to its type alias
//! (`rtl::prim::q::ALIASES`). The values come from a rust-hdl probe that visits every signal once a clock,
//! with the clock low and the slot settled (every register's d is then what the edge latches).

pub mod bounds;
pub mod formal;
pub mod stages;
pub mod wraps;

use rtl::prim::declared::{Declaration, Declared};
use rtl::stream::Runner;
use rtl::StreamUnit;
use rust_hdl::core::atom::Atom;
use rust_hdl::core::block::Block;
use rust_hdl::core::probe::Probe;
use std::collections::HashMap;
use vectors::UnitModel;

/// A type as a declaration writes it (`stringify!` of a field's type).
#[derive(Clone, Debug, PartialEq)]
pub enum Ty {
    /// `Name` or `Name<args>` (the last path segment)
    Path(String, Vec<Ty>),
    /// `[T; len]`
    Array(Box<Ty>, String),
    /// a const argument: a number, `false`, `{ expr }`
    Expr(String),
}

impl Ty {
    fn parse(s: &str) -> Option<Ty> {
        let mut p = Parser { s: s.as_bytes(), i: 0 };
        let t = p.ty()?;
        p.ws();
        (p.i == p.s.len()).then_some(t)
    }

    /// The type with generic names replaced by the instance's arguments.
    fn subst(&self, env: &HashMap<String, Ty>) -> Ty {
        match self {
            Ty::Path(n, args) if args.is_empty() => env.get(n).cloned().unwrap_or_else(|| self.clone()),
            Ty::Path(n, args) => Ty::Path(n.clone(), args.iter().map(|a| a.subst(env)).collect()),
            Ty::Array(t, len) => Ty::Array(Box::new(t.subst(env)), len.clone()),
            Ty::Expr(_) => self.clone(),
        }
    }

    pub fn text(&self) -> String {
        match self {
            Ty::Path(n, a) if a.is_empty() => n.clone(),
            Ty::Path(n, a) => format!("{n}<{}>", a.iter().map(Ty::text).collect::<Vec<_>>().join(", ")),
            Ty::Array(t, len) => format!("[{}; {len}]", t.text()),
            Ty::Expr(e) => e.clone(),
        }
    }
}

struct Parser<'a> {
    s: &'a [u8],
    i: usize,
}

impl Parser<'_> {
    fn ws(&mut self) {
        while self.i < self.s.len() && self.s[self.i].is_ascii_whitespace() {
            self.i += 1;
        }
    }
    fn peek(&mut self) -> Option<u8> {
        self.ws();
        self.s.get(self.i).copied()
    }
    fn eat(&mut self, c: u8) -> Option<()> {
        (self.peek()? == c).then(|| self.i += 1)
    }
    /// Text up to the `close` that balances, nested `open`s counted.
    fn balanced(&mut self, open: u8, close: u8) -> Option<String> {
        let start = self.i;
        let mut depth = 0;
        while self.i < self.s.len() {
            let c = self.s[self.i];
            if c == open {
                depth += 1;
            } else if c == close {
                if depth == 0 {
                    return Some(String::from_utf8_lossy(&self.s[start..self.i]).trim().to_string());
                }
                depth -= 1;
            }
            self.i += 1;
        }
        None
    }
    fn ty(&mut self) -> Option<Ty> {
        match self.peek()? {
            b'[' => {
                self.i += 1;
                let t = self.ty()?;
                self.eat(b';')?;
                let len = self.balanced(b'[', b']')?;
                self.eat(b']')?;
                Some(Ty::Array(Box::new(t), len))
            }
            b'{' => {
                self.i += 1;
                let e = self.balanced(b'{', b'}')?;
                self.eat(b'}')?;
                Some(Ty::Expr(e))
            }
            c if c.is_ascii_digit() || c == b'-' => {
                let start = self.i;
                self.i += 1;
                while self.i < self.s.len() && (self.s[self.i].is_ascii_alphanumeric() || self.s[self.i] == b'_') {
                    self.i += 1;
                }
                Some(Ty::Expr(String::from_utf8_lossy(&self.s[start..self.i]).to_string()))
            }
            c if c.is_ascii_alphabetic() || c == b'_' => {
                let mut name;
                loop {
                    let start = self.i;
                    while self.i < self.s.len() && (self.s[self.i].is_ascii_alphanumeric() || self.s[self.i] == b'_') {
                        self.i += 1;
                    }
                    name = String::from_utf8_lossy(&self.s[start..self.i]).to_string();
                    if self.s[self.i..].starts_with(b"::") {
                        self.i += 2;
                    } else {
                        break;
                    }
                }
                let mut args = vec![];
                if self.peek() == Some(b'<') {
                    self.i += 1;
                    loop {
                        args.push(self.ty()?);
                        match self.peek()? {
                            b',' => self.i += 1,
                            b'>' => {
                                self.i += 1;
                                break;
                            }
                            _ => return None,
                        }
                    }
                }
                match name.as_str() {
                    "true" | "false" => Some(Ty::Expr(name)),
                    _ => Some(Ty::Path(name, args)),
                }
            }
            _ => None,
        }
    }
}

/// A signal's declared fixed-point format.
#[derive(Clone, Debug, PartialEq)]
pub struct Format {
    /// as the source names it after aliases and generics: `Sq1_10`, `U8`, `Bits<23>`, `Bit`
    pub name: String,
    pub signed: bool,
    pub bits: usize,
    /// fraction bits (0 for integers and raw bits)
    pub frac: u32,
}

impl Format {
    /// Qm.n, the sign not counted in m (the convention of `rtl::prim::q`), with `s`/`u`: "sQ1.10", "uQ0.10", "u8".
    pub fn q(&self) -> String {
        let int = self.bits as i64 - self.frac as i64 - self.signed as i64;
        match (self.signed, self.frac) {
            (s, 0) => format!("{}{}", if s { "s" } else { "u" }, self.bits),
            (true, f) => format!("sQ{int}.{f}"),
            (false, f) => format!("uQ{int}.{f}"),
        }
    }

    /// The format an alias of `rtl::prim::q` names (`Sq1_10`, `Uq0_10`, `U8`, `S11`), or `Bit`/`bool`: its width is the
    /// compiler's (`rtl::prim::q::ALIASES`), its sign and fraction the name's, by the Q convention.
    fn of(name: &str) -> Option<Format> {
        let f = |signed: bool, bits: usize, frac: u32| Some(Format { name: name.to_string(), signed, bits, frac });
        if name == "Bit" || name == "bool" {
            return f(false, 1, 0);
        }
        let &(_, bits) = rtl::prim::q::ALIASES.iter().find(|a| a.0 == name)?;
        match Format::by_name(name) {
            Some((signed, _, frac)) => f(signed, bits, frac),
            None => f(false, bits, 0),
        }
    }

    /// (signed, bits, fraction bits) as a name in the Q convention says: `SqM_N` 1 + M + N, `UqM_N` M + N, `Sn` and
    /// `Un` n; None for a name that does not follow it.
    fn by_name(name: &str) -> Option<(bool, usize, u32)> {
        let num = |s: &str| s.parse::<usize>().ok();
        if let Some((m, n)) = name.strip_prefix("Sq").and_then(|r| r.split_once('_')) {
            return Some((true, 1 + num(m)? + num(n)?, num(n)? as u32));
        }
        if let Some((m, n)) = name.strip_prefix("Uq").and_then(|r| r.split_once('_')) {
            return Some((false, num(m)? + num(n)?, num(n)? as u32));
        }
        if let Some(b) = name.strip_prefix('U').and_then(num) {
            return Some((false, b, 0));
        }
        if let Some(b) = name.strip_prefix('S').and_then(num) {
            return Some((true, b, 0));
        }
        None
    }
}

/// The format of the leaf type a signal's path ends at, or None (a clock, an unresolved name). `bits` is the
/// compiler's width of the signal, which a width written with a named constant (`Bits<ANGLE_BITS>`) takes.
fn leaf_format(t: &Ty, bits: usize) -> Option<Format> {
    let raw = |kind: &str, signed: bool, w: &Ty| match w {
        Ty::Expr(n) => Some(Format { name: format!("{kind}<{n}>"), signed, bits: n.parse().ok()?, frac: 0 }),
        // a named constant (a generic parameter left unbound is no path: see `Formats::types_along`)
        Ty::Path(c, ca) if ca.is_empty() => Some(Format { name: format!("{kind}<{c}>"), signed, bits, frac: 0 }),
        _ => None,
    };
    match t {
        Ty::Path(n, a) if n == "Bits" && a.len() == 1 => raw("Bits", false, &a[0]),
        // a two's complement integer of a parameter's width
        Ty::Path(n, a) if n == "SBits" && a.len() == 1 => raw("SBits", true, &a[0]),
        Ty::Path(n, a) if a.is_empty() => Format::of(n),
        _ => None,
    }
}

/// The formats of a unit's signals: the declaration the compiler records of its rtl block and of every block it
/// holds (`rtl::prim::declared`), read along each signal's path, with the types' text as the declarations write it.
pub struct Formats {
    top: Ty,
    root: Declaration,
}

impl Formats {
    pub fn of<U: Declared>() -> Formats {
        let top = Ty::parse(std::any::type_name::<U>()).unwrap_or(Ty::Path(String::new(), vec![]));
        Formats { top, root: U::declaration() }
    }

    /// The types along a signal's path: the top block's, then each field's (its type as written, the enclosing
    /// block's generic arguments substituted, array elements for `name$k`), the last the signal's own
    /// (`Signal<In, Sq1_10>`); each beside the compiler's declaration of it.
    fn types_along(&self, path: &str) -> Option<Vec<(Ty, &Declaration)>> {
        let mut types = vec![(self.top.clone(), &self.root)];
        for seg in path.split('.').skip(1) {
            let (Ty::Path(_, args), Declaration::Block(b)) = types.last()? else { return None };
            // each generic bound to the argument the enclosing type gives it, else to its default; one left unbound
            // reads as an expression no format takes
            let env: HashMap<String, Ty> = b
                .generics
                .iter()
                .enumerate()
                .map(|(k, g)| {
                    let t = args.get(k).cloned().or_else(|| g.default.and_then(Ty::parse));
                    (g.name.to_string(), t.unwrap_or_else(|| Ty::Expr(format!("{{ {} }}", g.name))))
                })
                .collect();
            let mut parts = seg.split('$');
            let name = parts.next()?;
            let field = b.fields.iter().find(|f| f.name == name)?;
            let (mut t, mut d) = (Ty::parse(field.ty)?.subst(&env), &field.decl);
            for _ in parts {
                let (Ty::Array(inner, _), Declaration::Array(e)) = (t, d) else { return None };
                (t, d) = (*inner, &**e);
            }
            types.push((t, d));
        }
        Some(types)
    }

    /// The type of the block at `path` ("uut.unit$0"), by the name its struct has in the source.
    pub fn block_at(&self, path: &str) -> Option<String> {
        match self.types_along(path)?.pop()?.1 {
            Declaration::Block(b) => Some(b.name.to_string()),
            _ => None,
        }
    }

    /// The block that declares the signal `path` and its name there, array indices dropped: for
    /// "uut.unit$0.s2_d0.d", ("Bilinear", "s2_d0.d"). The library's registers and memories are not owners; the
    /// block holding one is.
    pub fn owner(&self, path: &str) -> Option<(String, String)> {
        let types = self.types_along(path)?;
        let segs: Vec<&str> = path.split('.').skip(1).collect();
        // the last block on the path (not the signal itself) that is not a library register or memory
        let (k, name) = types[..types.len() - 1].iter().enumerate().rev().find_map(|(k, t)| match t.1 {
            Declaration::Block(b) if !b.library => Some((k, b.name.to_string())),
            _ => None,
        })?;
        let local: Vec<&str> = segs[k..].iter().map(|s| s.split('$').next().unwrap_or(s)).collect();
        Some((name, local.join(".")))
    }

    /// The declared format of the signal `path` ("uut.norm.s3_l.q"), or None where the declarations do not say.
    pub fn format(&self, path: &str) -> Option<Format> {
        let (t, d) = self.types_along(path)?.pop()?;
        let Declaration::Wire { bits } = *d else { return None };
        match t {
            Ty::Path(n, a) if n == "Signal" && a.len() == 2 => leaf_format(&a[1], bits),
            Ty::Path(n, a) if n == "Constant" && a.len() == 1 => leaf_format(&a[0], bits),
            _ => None,
        }
    }
}

/// Bits a range needs: for a signed one, the two's complement width holding min and max; for an unsigned one, the
/// width holding max (at least 1).
pub fn bits_needed(signed: bool, min: i64, max: i64) -> usize {
    let mag = |v: i64| 64 - v.leading_zeros() as usize; // bits of a non-negative value
    if signed {
        1 + mag(max.max(0)).max(mag((-min - 1).max(0)))
    } else {
        mag(max.max(0)).max(1)
    }
}

/// The range a signal took: its raw bit patterns, and read as two's complement.
#[derive(Clone, Debug)]
pub struct Seen {
    pub name: String,
    pub bits: usize,
    pub umin: u64,
    pub umax: u64,
    pub smin: i64,
    pub smax: i64,
    /// the clocks the range is over: those where the signal's stage held a pixel, or every clock where `every`
    pub clocks: u64,
    /// read on every clock: a valid flag, or a signal with no single stage (`stages`)
    pub every: bool,
    /// its stage, where it has one
    pub stage: Option<u32>,
}

/// Every signal's range over a run (the signals in the probe's order, which is the block's field order), each read
/// on the clocks where it holds data: a signal at stage d (`stages`) where `valid_in` was high d clocks before, so
/// neither the registers' zeros before the first pixel nor what a bubble leaves behind count.
#[derive(Default)]
pub struct Ranges {
    pub signals: Vec<Seen>,
    /// clocks probed
    pub clocks: u64,
    /// what left the unit, in order (bit patterns)
    pub outputs: Vec<Vec<u64>>,
    path: Vec<String>,
    next: usize,
    /// each signal's stage, by name, and then by its place in the probe's order (none: read every clock)
    stages: HashMap<String, stages::Stage>,
    gates: Vec<Option<usize>>,
    /// `valid_in` on each clock so far
    valid: Vec<bool>,
}

/// The path is only read on the first clock, when the signals are named: later clocks keep no names.
impl Probe for Ranges {
    fn visit_start_scope(&mut self, name: &str, _node: &dyn Block) {
        if self.clocks == 0 {
            self.path.push(name.to_string());
        }
    }
    fn visit_end_scope(&mut self, _name: &str, _node: &dyn Block) {
        self.path.pop();
    }
    fn visit_start_namespace(&mut self, name: &str, _node: &dyn Block) {
        if self.clocks == 0 {
            self.path.push(name.to_string());
        }
    }
    fn visit_end_namespace(&mut self, _name: &str, _node: &dyn Block) {
        self.path.pop();
    }
    fn visit_atom(&mut self, name: &str, a: &dyn Atom) {
        // the value as its VCD gives it (a `Z` bit reads 0), without building the VCD's vector of bits
        let Some(v) = a.short_word() else { return };
        let bits = a.bits();
        let s = if bits < 64 && bits > 0 && v >> (bits - 1) & 1 == 1 { v as i64 - (1i64 << bits) } else { v as i64 };
        if self.clocks == 0 {
            // the first clock: the signals in visiting order, named as the VCD names them, each with its stage
            // (the valid flags themselves are read on every clock: they say which clocks hold data)
            let full = format!("{}.{name}", self.path.join("."));
            let flag = full.split('.').skip(1).any(|seg| seg.starts_with("valid"));
            let stage = match self.stages.get(&full) {
                Some(stages::Stage::At(d)) => Some(*d),
                _ => None,
            };
            let gate = stage.filter(|_| !flag).map(|d| d as usize);
            self.gates.push(gate);
            let every = gate.is_none();
            let empty = Seen {
                name: full,
                bits,
                umin: u64::MAX,
                umax: 0,
                smin: i64::MAX,
                smax: i64::MIN,
                clocks: 0,
                every,
                stage,
            };
            self.signals.push(empty);
        }
        let k = self.next;
        self.next += 1;
        let now = self.clocks as usize;
        if let Some(d) = self.gates[k] {
            if d > now || !self.valid[now - d] {
                return;
            }
        }
        let r = &mut self.signals[k];
        (r.umin, r.umax, r.smin, r.smax) = (r.umin.min(v), r.umax.max(v), r.smin.min(s), r.smax.max(s));
        r.clocks += 1;
    }
}

/// The unit's vectors through its rust-hdl block, every signal probed every clock (the flush included: the last
/// vectors are still in the pipeline then, bubbles with zero inputs behind them) and counted where its stage holds
/// a vector.
pub fn seen<U: StreamUnit>(m: &UnitModel, inputs: &[Vec<i64>]) -> Ranges {
    seen_ticking::<U>(m, inputs, &|_| {})
}

/// `seen`, calling `tick` with the vectors done every 4,096.
pub fn seen_ticking<U: StreamUnit>(m: &UnitModel, inputs: &[Vec<i64>], tick: &dyn Fn(usize)) -> Ranges {
    let mut r = Runner::<U>::new();
    let mut ranges = Ranges::default();
    let ports: Vec<&str> = U::INPUTS.iter().map(|p| p.0).collect();
    ranges.stages = stages::stages(&U::build(), &ports);
    let zeros = vec![0u64; U::INPUTS.len()];
    let slots = rtl::stream::paced::<U>(inputs.iter().map(|v| vectors::unit::to_patterns(v, m.inputs)))
        .chain((0..U::LATENCY + 1).map(|_| None));
    for (k, s) in slots.enumerate() {
        if k % 4096 == 0 {
            tick((k / U::INTERVAL).min(inputs.len()));
        }
        ranges.next = 0;
        ranges.valid.push(s.is_some());
        let out = match &s {
            Some(v) => r.step_probed(true, v, Some(&mut ranges)),
            None => r.step_probed(false, &zeros, Some(&mut ranges)),
        };
        ranges.outputs.extend(out);
        ranges.clocks += 1;
    }
    // a signal whose stage never held data (none here: every vector is flushed through) reads as zero
    for r in ranges.signals.iter_mut().filter(|r| r.clocks == 0) {
        (r.umin, r.umax, r.smin, r.smax) = (0, 0, 0, 0);
    }
    ranges
}

/// How many vectors' outputs differ from the model's (a stream unit's model runs over the whole stream), and how
/// many outputs are missing: the evidence behind the steps `wraps` argues for, since the model does not wrap.
pub fn mismatches(m: &UnitModel, inputs: &[Vec<i64>], outputs: &[Vec<u64>]) -> usize {
    let want = m.run(inputs);
    let differ = want.iter().zip(outputs).filter(|(w, o)| vectors::unit::from_patterns(o, m.outputs) != **w).count();
    differ + want.len().abs_diff(outputs.len())
}

/// What the width analysis reads of a block without simulating it: every signal's declared format, and the proof of
/// the range each takes over every input sequence (the model's ports at their full ranges).
pub struct Analysis {
    pub formats: Formats,
    pub proof: bounds::Proof,
}

impl Analysis {
    /// Every step of the block that may leave its target's declared range.
    pub fn sites(&self) -> Vec<Site> {
        sites(&self.formats, &self.proof)
    }
}

/// The block `U` analysed over the ranges of `m`'s input ports.
pub fn analyse<U: StreamUnit>(m: &UnitModel) -> Analysis {
    let formats = Formats::of::<U>();
    let ports: Vec<(&str, i64, i64)> = m.inputs.iter().map(|p| (p.name, p.range().0, p.range().1)).collect();
    // asked for every read of a signal: each path's answer kept (walking a path parses the types along it)
    let known = std::cell::RefCell::new(HashMap::<String, bool>::new());
    let signed = |n: &str| {
        if let Some(&s) = known.borrow().get(n) {
            return s;
        }
        let s = formats.format(n).is_some_and(|x| x.signed);
        known.borrow_mut().insert(n.to_string(), s);
        s
    };
    let proof = bounds::prove(&U::build(), &ports, &signed);
    Analysis { formats, proof }
}

/// The simulation against the analysis: every probed signal but the clocks must have a declared format as wide as
/// the simulator's signal, take only values that format holds, and stay inside the range the proof gives (the proof
/// is sound, or this names the signal). One line per failure.
pub fn audit(ranges: &Ranges, a: &Analysis) -> Vec<String> {
    let mut bad = vec![];
    for s in &ranges.signals {
        if s.name.ends_with("clock") || s.clocks == 0 {
            continue;
        }
        let Some(fmt) = a.formats.format(&s.name) else {
            bad.push(format!("{}: no declared format", s.name));
            continue;
        };
        if fmt.bits != s.bits {
            bad.push(format!("{}: declared {} ({} bits), simulated {} bits", s.name, fmt.name, fmt.bits, s.bits));
            continue;
        }
        let (lo, hi) = if fmt.signed { (s.smin as i128, s.smax as i128) } else { (s.umin as i128, s.umax as i128) };
        match a.proof.values.get(&s.name) {
            Some(p) => {
                let pieces = if fmt.signed { p.signed() } else { p.unsigned() };
                for x in [lo, hi] {
                    if !pieces.iter().any(|&(a, b)| a <= x && x <= b) {
                        bad.push(format!("{}: seen {x} outside the proven {pieces:?}", s.name));
                    }
                }
            }
            None => bad.push(format!("{}: no proven range", s.name)),
        }
        let fits = if fmt.signed {
            s.smin >= -(1i64 << (s.bits - 1)) && s.smax < 1i64 << (s.bits - 1)
        } else {
            s.bits >= 64 || s.umax < 1u64 << s.bits
        };
        if !fits {
            bad.push(format!("{}: seen outside {}", s.name, fmt.q()));
        }
    }
    bad
}

/// A step the proof finds may leave its target's declared range: the signal it writes (VCD name), the block that
/// owns the step and the signal's name there, what the step computes, and its entry in `wraps` if it is listed.
pub struct Site {
    pub name: String,
    pub owner: String,
    pub local: String,
    pub exact: (i128, i128),
    pub listed: Option<&'static wraps::Waived>,
}

/// Every such step of a block, from its proof.
pub fn sites(f: &Formats, proof: &bounds::Proof) -> Vec<Site> {
    let mut out: Vec<Site> = proof
        .wraps
        .iter()
        .map(|((module, name), &exact)| {
            // the step belongs to the block whose statement it is: a parent writing a child's port owns that write
            let owner = f.block_at(module).unwrap_or_else(|| String::from("?"));
            let rest = name.strip_prefix(&format!("{module}.")).unwrap_or(name);
            let local: Vec<&str> = rest.split('.').map(|s| s.split('$').next().unwrap_or(s)).collect();
            let local = local.join(".");
            let listed = wraps::find(&owner, &local);
            Site { name: name.clone(), owner, local, exact, listed }
        })
        .collect();
    out.sort_by(|a, b| a.name.cmp(&b.name));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn types_parse_with_their_arguments() {
        assert_eq!(
            Ty::parse("[Delay<Sq1_10, { table_builder::LATENCY }>; 3]"),
            Some(Ty::Array(
                Box::new(Ty::Path(
                    "Delay".into(),
                    vec![Ty::Path("Sq1_10".into(), vec![]), Ty::Expr("table_builder::LATENCY".into())]
                )),
                "3".into()
            ))
        );
        assert_eq!(
            Ty::parse("rtl::palette::palette_pipeline::PalettePipeline<8, 9>").map(|t| t.text()),
            Some("PalettePipeline<8, 9>".into())
        );
        assert_eq!(Ty::parse("Signal<Local, Bits<16>>").map(|t| t.text()), Some("Signal<Local, Bits<16>>".into()));
        // as `stringify!` writes a type captured by a macro
        assert_eq!(Ty::parse("Signal < In, Bits < 8 > >").map(|t| t.text()), Some("Signal<In, Bits<8>>".into()));
    }

    #[test]
    fn bits_needed_counts_the_sign_once() {
        assert_eq!(bits_needed(true, -1024, 1023), 11);
        assert_eq!(bits_needed(true, -1024, 1024), 12);
        assert_eq!(bits_needed(true, -1025, 0), 12);
        assert_eq!(bits_needed(true, 0, 0), 1);
        assert_eq!(bits_needed(false, 0, 255), 8);
        assert_eq!(bits_needed(false, 0, 256), 9);
        assert_eq!(bits_needed(false, 0, 0), 1);
    }

    #[test]
    fn formats_follow_the_q_convention() {
        let q = |n: &str| Format::of(n).map(|f| (f.q(), f.bits));
        assert_eq!(q("Sq1_10"), Some(("sQ1.10".into(), 12)));
        assert_eq!(q("Uq0_10"), Some(("uQ0.10".into(), 10)));
        assert_eq!(q("U8"), Some(("u8".into(), 8)));
        assert_eq!(q("S11"), Some(("s11".into(), 11)));
        assert_eq!(q("Bit"), Some(("u1".into(), 1)));
        // a name `rtl::prim::q` does not declare is no format, whatever it looks like
        assert_eq!(q("Sq3_3"), None);
    }

    #[test]
    fn every_alias_of_q_is_as_wide_as_its_name_says() {
        assert!(rtl::prim::q::ALIASES.len() >= 14, "{:?}", rtl::prim::q::ALIASES);
        for &(name, bits) in rtl::prim::q::ALIASES {
            let (_, by_name, _) = Format::by_name(name).unwrap_or_else(|| panic!("{name}: not in the Q convention"));
            assert_eq!(by_name, bits, "{name}: the compiler makes it {bits} bits");
        }
    }

    #[test]
    fn the_stream_blocks_and_the_library_blocks_are_declared() {
        let Declaration::Block(dot3) = rtl::dot3::Dot3::declaration() else { panic!("Dot3 is a block") };
        let names: Vec<&str> = dot3.fields.iter().map(|f| f.name).collect();
        assert!(names.starts_with(&["clock", "valid_in", "n_x"]), "{names:?}");
        assert!(names.contains(&"s3_t") && names.contains(&"w_partial"));
        let s3_t = dot3.fields.iter().find(|f| f.name == "s3_t").unwrap();
        assert_eq!(Ty::parse(s3_t.ty).map(|t| t.text()), Some("[DFF<Sq4_20>; 3]".into()));
        let Declaration::Array(e) = &s3_t.decl else { panic!("s3_t is an array") };
        let Declaration::Block(dff) = &**e else { panic!("a DFF is a block") };
        assert!(dff.library && dff.name == "DFF");
        assert!(matches!(
            dff.fields.iter().find(|f| f.name == "q").map(|f| &f.decl),
            Some(Declaration::Wire { bits: 25 })
        ));
        let Declaration::Block(p) = rtl::palette_lookup::PaletteLookup::<8, 9>::declaration() else { panic!() };
        assert_eq!(p.generics.iter().map(|g| g.name).collect::<Vec<_>>(), ["A", "R"]);
        let Declaration::Block(d) = rtl::prim::delay::Delay::<bool, 3>::declaration() else { panic!() };
        assert_eq!(d.generics.iter().map(|g| (g.name, g.default)).collect::<Vec<_>>(), [("T", None), ("N", None)]);
        let Declaration::Block(b) = rtl::bilinear::Bilinear::<8, 0>::declaration() else { panic!() };
        assert_eq!(
            b.generics.iter().map(|g| (g.name, g.default)).collect::<Vec<_>>(),
            [("F", Some("8")), ("D", Some("0"))]
        );
    }

    #[test]
    fn a_signal_path_resolves_through_blocks_arrays_and_generics() {
        let f = Formats::of::<rtl::palette_pipeline::PalettePipeline<12, 13>>();
        let q = |p: &str| f.format(p).map(|x| (x.name, x.bits, x.signed));
        assert_eq!(q("uut.idx"), Some(("Bits<12>".into(), 12, false)));
        assert_eq!(q("uut.lookup.tables.read_address"), Some(("Bits<13>".into(), 13, false)));
        assert_eq!(q("uut.builder.diffuse.s3_t$2.q"), Some(("Sq4_20".into(), 25, true)));
        assert_eq!(q("uut.builder.l_dly$1.line$3.d"), Some(("Sq1_10".into(), 12, true)));
        assert_eq!(q("uut.builder.conc"), Some(("U8".into(), 8, false)));
        assert_eq!(q("uut.clock"), None);
        assert_eq!(q("uut.no_such_field"), None);
        assert_eq!(f.owner("uut.builder.diffuse.s3_t$2.q"), Some(("Dot3".into(), "s3_t.q".into())));
        assert_eq!(f.owner("uut.builder.l_dly$1.line$3.d"), Some(("Delay".into(), "line.d".into())));
        assert_eq!(f.owner("uut.lookup.tables.read_data"), Some(("PaletteLookup".into(), "tables.read_data".into())));
        assert_eq!(f.owner("uut.idx"), Some(("PalettePipeline".into(), "idx".into())));
        assert_eq!(f.block_at("uut.builder.diffuse").as_deref(), Some("Dot3"));
        assert_eq!(f.block_at("uut").as_deref(), Some("PalettePipeline"));
    }

    #[test]
    fn a_width_written_with_a_named_constant_is_the_compiler_s() {
        let f = Formats::of::<rtl::sincos::SinCosUnit>();
        let angle = f.format("uut.angle").expect("a format");
        assert_eq!(
            (angle.name.as_str(), angle.bits, angle.signed),
            ("Bits<ANGLE_BITS>", rtl::sincos::ANGLE_BITS, false)
        );
        // a generic left unbound is no format: `Delay<T, N>` seen alone, without its arguments' text
        let d =
            Formats { top: Ty::Path("Delay".into(), vec![]), root: rtl::prim::delay::Delay::<bool, 3>::declaration() };
        assert_eq!(d.format("uut.q"), None);
        assert_eq!(d.format("uut.line$0.q"), None);
    }
}
