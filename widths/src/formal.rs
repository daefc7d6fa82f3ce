//! The width report's claims as assertions on the exported Verilog, for a solver (`yosys-smtbmc`) to prove by
//! k-induction. Two kinds:
//!
//! - **exact**: a step's exact value (its operands read in their declared formats, nothing wrapped: what
//!   `bounds` calls the exact hull) lies inside the declared range of the signal it writes. This is what a wrap
//!   entry argues (`a`) and what the interval proof shows for every other step; the solver decides it over every
//!   reachable state, correlated operands and all.
//! - **range**: a signal's value, read in its declared format, lies inside a stated range (the interval proof's,
//!   or one a caller narrows to see it refuted).
//!
//! Each module of the export gains, under `ifdef FORMAL`, a second `always @(*)` block that follows the first one's
//! branches and computes each step's exact value in a signed word wide enough never to wrap (`bp<N>_x`), and which
//! write of each signal was the last on the path taken (`bw_<signal>`, the step's number, or 0 for a write that
//! claims nothing). The second block reads every signal at its settled value, so a step that reads a signal its
//! block writes again later (in program order) is not tried. The top module assumes each input port inside its
//! range.

use crate::bounds::{full_name, index_value, literal, literal_value, Code, Collect, Walker};
use crate::stages::{stages, Stage};
use rust_hdl::core::ast::{
    VerilogBlockOrConditional, VerilogExpression as E, VerilogOp, VerilogOpUnary, VerilogStatement as S,
};
use rust_hdl::core::block::Block;
use std::collections::{HashMap, HashSet};

/// What an assertion claims.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// the step that writes `signal` computes an exact value inside [lo, hi] (its declared range)
    Exact,
    /// `signal`, read in its declared format, stays inside [lo, hi]
    Range,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::Exact => "exact",
            Kind::Range => "range",
        }
    }
}

/// One assertion of the harness.
#[derive(Clone, Debug)]
pub struct Prop {
    /// the signal, by the probe's name (`uut.dot.s4_sum.d`)
    pub signal: String,
    /// the block whose statement or field it is (the probe's path of the module the assertion sits in)
    pub block: String,
    pub kind: Kind,
    pub lo: i128,
    pub hi: i128,
    /// its line in the harness's text (1-based), as the solver names a failed assertion
    pub line: usize,
    /// claimed only on the clocks where this stage holds a pixel (`stages`): the unit's `valid_in` that many clocks
    /// before; none: on every clock, idle ones too
    pub stage: Option<u32>,
}

/// The exported Verilog with the assertions in it.
pub struct Harness {
    pub text: String,
    pub props: Vec<Prop>,
    /// steps with no assertion: (signal, why)
    pub skipped: Vec<(String, String)>,
}

/// What to assert.
pub struct Request<'a> {
    /// the exported top module's name
    pub top: &'a str,
    /// the exported Verilog, every module
    pub verilog: &'a str,
    /// the input ports and their ranges (the unit's)
    pub inputs: &'a [(&'a str, i64, i64)],
    /// whether a signal's declared format is signed
    pub signed: &'a dyn Fn(&str) -> bool,
    /// the range claims: signal, lo, hi (in its format's reading)
    pub ranges: &'a [(String, i128, i128)],
    /// the exact steps not to assert, and why: (block path, signal) → a reason (a step that wraps on purpose)
    pub skip: &'a dyn Fn(&str, &str) -> Option<String>,
    /// the exact steps to claim only where their stage holds a pixel (block path, signal): an argued step whose
    /// argument is about data, which a register's reset zero or a bubble need not keep
    pub gate: &'a dyn Fn(&str, &str) -> bool,
}

/// The widest word a step's exact value is computed in; a step that needs more is not tried.
const WIDEST: u32 = 96;

fn lit(v: i128, w: u32) -> String {
    if v < 0 {
        format!("(-{w}'sd{})", -v)
    } else {
        format!("{w}'sd{v}")
    }
}

fn mask_hex(bits: u32) -> String {
    if bits == 0 {
        return "0".into();
    }
    let top = bits % 4;
    let mut s = String::new();
    if top > 0 {
        s.push(char::from_digit((1 << top) - 1, 16).unwrap());
    }
    s.push_str(&"f".repeat((bits / 4) as usize));
    s
}

fn bitlen(x: i128) -> u32 {
    128 - x.unsigned_abs().leading_zeros()
}

/// A signal's pattern as a `w`-bit signed word: sign- or zero-extended.
fn extend(id: &str, bits: u32, signed: bool, w: u32) -> String {
    let pad = w - bits;
    if signed {
        let top = if bits == 1 { id.to_string() } else { format!("{id}[{}]", bits - 1) };
        format!("$signed({{{{{pad}{{{top}}}}}, {id}}})")
    } else {
        format!("$signed({{{pad}'d0, {id}}})")
    }
}

/// rust-hdl's identifier as its Verilog prints it (`VerilogCodeGenerator::ident_fixup`): a loop variable's value,
/// `.` and `::` as `$`, `$next` dropped, an array index evaluated into `$N`.
fn fix(name: &str, loops: &[(String, i128)]) -> String {
    if let Some((_, k)) = loops.iter().rev().find(|(v, _)| v == name) {
        return k.to_string();
    }
    let x = name.strip_prefix('.').unwrap_or(name);
    let mut x = x.replace('.', "$").replace("::", "$");
    while let Some(s) = x.strip_suffix("$next") {
        x = s.to_string();
    }
    if let Some(open) = x.find('[') {
        if let Some(close) = x[open..].find(']') {
            if let Some(v) = index_value(&x[open + 1..open + close], loops) {
                x = format!("{}${v}{}", &x[..open], &x[open + close + 1..]);
            }
        }
    }
    x
}

/// The expression as rust-hdl prints it (`VerilogCodeGenerator`).
fn orig(e: &E, loops: &[(String, i128)]) -> String {
    let o = |x: &E| orig(x, loops);
    match e {
        E::Signal(s) => fix(s, loops),
        E::Literal(l) => l.to_string(),
        E::Paren(x) => format!("({})", o(x)),
        E::Cast(x, b) => format!("(({}) & {b}'h{})", o(x), mask_hex(*b as u32)),
        E::Signed(x) => format!("$signed({})", o(x)),
        E::Unsigned(x) => format!("$unsigned({})", o(x)),
        E::Index(a, b) => format!("{}[{}]", o(a), o(b)),
        E::Slice(x, w, off) => format!("{}[({})+:({w})]", o(x), o(off)),
        E::IndexReplace(s, i, v) => format!("({} & ~(1 << ({})) | (({}) << ({})))", o(s), o(i), o(v), o(i)),
        E::Binary(a, op, b) => {
            let op = match op {
                VerilogOp::Add => "+",
                VerilogOp::Sub => "-",
                VerilogOp::Mul => "*",
                VerilogOp::LogicalAnd => "&&",
                VerilogOp::LogicalOr => "||",
                VerilogOp::BitXor => "^",
                VerilogOp::BitAnd => "&",
                VerilogOp::BitOr => "|",
                VerilogOp::Shl => "<<",
                VerilogOp::Shr => ">>",
                VerilogOp::Eq => "==",
                VerilogOp::Lt => "<",
                VerilogOp::Le => "<=",
                VerilogOp::Ne => "!=",
                VerilogOp::Ge => ">=",
                VerilogOp::Gt => ">",
            };
            format!("{} {op} {}", o(a), o(b))
        }
        E::Unary(op, x) => {
            let op = match op {
                VerilogOpUnary::Not => "~",
                VerilogOpUnary::Neg => "-",
                VerilogOpUnary::All => "&",
                VerilogOpUnary::Any => "|",
                VerilogOpUnary::Xor => "^",
            };
            format!("{op}{}", o(x))
        }
    }
}

/// Every signal an expression reads, as printed.
fn reads(e: &E, loops: &[(String, i128)], out: &mut Vec<String>) {
    match e {
        E::Signal(s) => {
            if !loops.iter().any(|(v, _)| v == s) {
                out.push(fix(s, loops));
            }
        }
        E::Literal(_) => {}
        E::Paren(x) | E::Cast(x, _) | E::Signed(x) | E::Unsigned(x) | E::Unary(_, x) => reads(x, loops, out),
        E::Index(a, b) | E::Binary(a, _, b) | E::Slice(a, _, b) => {
            reads(a, loops, out);
            reads(b, loops, out);
        }
        E::IndexReplace(a, b, c) => {
            reads(a, loops, out);
            reads(b, loops, out);
            reads(c, loops, out);
        }
    }
}

/// The statements of one combinational block, walked twice in the same order: first for the last write of each
/// signal, then to print the second block.
struct Walk<'a> {
    path: &'a str,
    widths: &'a HashMap<String, u32>,
    signed: &'a dyn Fn(&str) -> bool,
    skip: &'a dyn Fn(&str, &str) -> Option<String>,
    loops: Vec<(String, i128)>,
    /// the writes so far, in program order
    pos: usize,
    /// pass 1's answer: each signal's last write
    last: HashMap<String, usize>,
    printing: bool,
    out: Vec<String>,
    depth: usize,
    /// enclosing branches whose test reads a signal written later
    unsafe_depth: usize,
    targets: Vec<String>,
    decls: Vec<String>,
    props: Vec<Prop>,
    /// the exact steps' numbers, beside their target as printed
    steps: Vec<(usize, String, u32)>,
    tainted: HashSet<String>,
    skipped: Vec<(String, String)>,
    first: usize,
}

impl Walker for Walk<'_> {
    fn step(&mut self, s: &S) {
        match s {
            S::Assignment(E::Signal(t), value) => self.assign(t, value),
            S::Assignment(..) => {}
            S::SliceAssignment { base: E::Signal(t), .. } => {
                let id = fix(t, &self.loops);
                self.write(&id);
                self.line(format!("bw_{id} = 0;"));
            }
            S::SliceAssignment { .. } => {}
            S::If(c) => {
                let late = self.late(&c.test);
                self.unsafe_depth += late as usize;
                self.line(format!("if ({}) begin", orig(&c.test, &self.loops)));
                self.depth += 1;
                self.block(&c.then);
                self.depth -= 1;
                match &c.otherwise {
                    VerilogBlockOrConditional::Block(b) => {
                        self.line("end else begin".into());
                        self.depth += 1;
                        self.block(b);
                        self.depth -= 1;
                        self.line("end".into());
                    }
                    VerilogBlockOrConditional::Conditional(s) => {
                        self.line("end else begin".into());
                        self.depth += 1;
                        self.step(s);
                        self.depth -= 1;
                        self.line("end".into());
                    }
                    VerilogBlockOrConditional::None => self.line("end".into()),
                }
                self.unsafe_depth -= late as usize;
            }
            S::Match(mt) => {
                let late = self.late(&mt.test);
                self.unsafe_depth += late as usize;
                self.line(format!("case ({})", orig(&mt.test, &self.loops)));
                for c in &mt.cases {
                    self.line(format!("{}: begin", fix(&c.condition, &self.loops)));
                    self.depth += 1;
                    self.block(&c.block);
                    self.depth -= 1;
                    self.line("end".into());
                }
                self.line("endcase".into());
                self.unsafe_depth -= late as usize;
            }
            S::Loop(l) => self.unroll(l),
            S::Macro(b) => self.block(b),
            S::Comment(_) | S::Link(_) => {}
        }
    }
    fn loops(&mut self) -> &mut Vec<(String, i128)> {
        &mut self.loops
    }
}

impl Walk<'_> {
    fn line(&mut self, s: String) {
        if self.printing {
            self.out.push(format!("{}{s}", "    ".repeat(self.depth + 2)));
        }
    }

    fn probe(&self, local: &str) -> String {
        full_name(self.path, local, &self.loops)
    }

    fn loop_value(&self, e: &E) -> Option<i128> {
        match e {
            E::Signal(s) => self.loops.iter().rev().find(|(v, _)| v == s).map(|x| x.1),
            E::Paren(x) => self.loop_value(x),
            _ => literal_value(e),
        }
    }

    /// The width rust-hdl's simulator gives the expression, and whether it is a bare literal (which takes the other
    /// operand's width), as `bounds` reads it.
    fn bits(&self, e: &E) -> Option<(u32, bool)> {
        Some(match e {
            E::Signal(s) if self.loops.iter().any(|(v, _)| v == s) => (32, true),
            E::Signal(s) => (*self.widths.get(&self.probe(s))?, false),
            E::Literal(l) => (literal(&l.to_string())?.1, true),
            E::Paren(x) | E::Signed(x) | E::Unsigned(x) => self.bits(x)?,
            E::Cast(_, w) | E::Slice(_, w, _) => (*w as u32, false),
            E::Index(..) => (1, false),
            E::IndexReplace(x, ..) => (self.bits(x)?.0, false),
            E::Binary(a, op, b) => {
                let ((x, xl), (y, yl)) = (self.bits(a)?, self.bits(b)?);
                let w = match (xl, yl) {
                    (true, false) => y,
                    (false, true) => x,
                    _ => x.max(y),
                };
                use VerilogOp::*;
                match op {
                    Mul => (2 * w, false),
                    Eq | Ne | Lt | Le | Gt | Ge | LogicalAnd | LogicalOr => (1, false),
                    _ => (w, false),
                }
            }
            E::Unary(VerilogOpUnary::Not | VerilogOpUnary::Neg, x) => (self.bits(x)?.0, false),
            E::Unary(..) => (1, false),
        })
    }

    /// Bits that hold the exact value as a signed word (an upper bound).
    fn need(&self, e: &E) -> Option<u32> {
        Some(match e {
            E::Signal(_) if self.loop_value(e).is_some() => bitlen(self.loop_value(e)?) + 1,
            E::Signal(_) => self.bits(e)?.0 + 1,
            E::Literal(_) => bitlen(literal_value(e)?) + 1,
            E::Paren(x) | E::Signed(x) | E::Unsigned(x) => self.need(x)?,
            E::Cast(x, w) => {
                let b = self.bits(x)?.0;
                if *w as u32 >= b {
                    b + 1
                } else {
                    self.need(x)?
                }
            }
            E::Slice(x, ..) => self.need(x)?,
            E::Binary(a, VerilogOp::Add, b)
                if matches!(&**a, E::Unary(VerilogOpUnary::Not, _)) && literal_value(b) == Some(1) =>
            {
                let E::Unary(_, x) = &**a else { unreachable!() };
                self.need(x)? + 1
            }
            E::Binary(a, op, b) => match op {
                VerilogOp::Add | VerilogOp::Sub => self.need(a)?.max(self.need(b)?) + 1,
                VerilogOp::Mul => self.need(a)? + self.need(b)?,
                VerilogOp::Shl if self.loop_value(b).is_some_and(|k| (0..64).contains(&k)) => {
                    self.need(a)? + self.loop_value(b)? as u32
                }
                VerilogOp::Shr if self.loop_value(b).is_some_and(|k| (0..128).contains(&k)) => self.need(a)?,
                _ => self.bits(e)?.0 + 1,
            },
            E::Unary(VerilogOpUnary::Not, x) => self.need(x)?.max(self.bits(x)?.0 + 1) + 1,
            E::Unary(VerilogOpUnary::Neg, x) => self.need(x)? + 1,
            _ => self.bits(e)?.0 + 1,
        })
    }

    /// The exact value as a `w`-bit signed Verilog expression (`bounds`'s exact hull, one value at a time).
    fn exact(&self, e: &E, w: u32) -> Option<String> {
        let pattern = |x: &E| -> Option<String> {
            let b = self.bits(x)?.0;
            (b < w).then(|| format!("$signed(({}) & {w}'h{})", orig(x, &self.loops), mask_hex(b)))
        };
        Some(match e {
            E::Signal(_) if self.loop_value(e).is_some() => lit(self.loop_value(e)?, w),
            E::Signal(s) => {
                let n = self.probe(s);
                let b = *self.widths.get(&n)?;
                if b >= w {
                    return None;
                }
                extend(&fix(s, &self.loops), b, (self.signed)(&n), w)
            }
            E::Literal(_) => lit(literal_value(e)?, w),
            E::Paren(x) | E::Signed(x) | E::Unsigned(x) => self.exact(x, w)?,
            E::Cast(x, c) => {
                if *c as u32 >= self.bits(x)?.0 {
                    pattern(x)? // zero extension: the patterns read unsigned
                } else {
                    self.exact(x, w)? // a narrowing cast keeps the value; the target's range judges it
                }
            }
            E::Slice(x, _, off) => format!("({} >>> {})", self.exact(x, w)?, self.loop_value(off)?),
            E::Binary(a, VerilogOp::Add, b)
                if matches!(&**a, E::Unary(VerilogOpUnary::Not, _)) && literal_value(b) == Some(1) =>
            {
                let E::Unary(_, x) = &**a else { unreachable!() };
                format!("({} - {})", lit(0, w), self.exact(x, w)?)
            }
            E::Binary(a, op, b) => match op {
                VerilogOp::Add => format!("({} + {})", self.exact(a, w)?, self.exact(b, w)?),
                VerilogOp::Sub => format!("({} - {})", self.exact(a, w)?, self.exact(b, w)?),
                VerilogOp::Mul => format!("({} * {})", self.exact(a, w)?, self.exact(b, w)?),
                VerilogOp::Shl if self.loop_value(b).is_some_and(|k| (0..64).contains(&k)) => {
                    format!("({} <<< {})", self.exact(a, w)?, self.loop_value(b)?)
                }
                VerilogOp::Shr if self.loop_value(b).is_some_and(|k| (0..128).contains(&k)) => {
                    format!("({} >>> {})", self.exact(a, w)?, self.loop_value(b)?)
                }
                _ => pattern(e)?,
            },
            E::Unary(VerilogOpUnary::Not, x) => {
                let signed = matches!(&**x, E::Signal(s) if (self.signed)(&self.probe(s)));
                if signed {
                    format!("({} - {} - {})", lit(0, w), self.exact(x, w)?, lit(1, w))
                } else {
                    let b = self.bits(x)?.0;
                    format!("({} - {})", lit((1i128 << b) - 1, w), self.exact(x, w)?)
                }
            }
            E::Unary(VerilogOpUnary::Neg, x) => format!("({} - {})", lit(0, w), self.exact(x, w)?),
            _ => pattern(e)?,
        })
    }

    /// A branch's test reads a signal the block writes after it: the second block may take another branch.
    fn late(&self, e: &E) -> bool {
        let mut r = vec![];
        reads(e, &self.loops, &mut r);
        r.iter().any(|s| self.last.get(s).is_some_and(|&p| p > self.pos))
    }

    fn write(&mut self, id: &str) {
        self.pos += 1;
        if !self.printing {
            self.last.insert(id.to_string(), self.pos);
        } else if !self.targets.iter().any(|t| t == id) {
            self.targets.push(id.to_string());
        }
    }

    fn assign(&mut self, target: &str, value: &E) {
        let id = fix(target, &self.loops);
        if id.ends_with("clock") {
            return;
        }
        self.write(&id);
        if !self.printing {
            return;
        }
        let n = self.probe(target);
        let claim = self.claim(&n, value);
        match claim {
            Ok(Some((text, w, lo, hi))) => {
                let k = self.first + self.props.len();
                self.decls.push(format!("reg signed [{}:0] bp{k}_x;", w - 1));
                self.line(format!("bp{k}_x = {text};"));
                self.line(format!("bw_{id} = {k};"));
                self.steps.push((k, id.clone(), w));
                self.props.push(Prop {
                    signal: n,
                    block: self.path.into(),
                    kind: Kind::Exact,
                    lo,
                    hi,
                    line: 0,
                    stage: None,
                });
                if self.unsafe_depth > 0 {
                    self.tainted.insert(id);
                }
            }
            Ok(None) => self.line(format!("bw_{id} = 0;")),
            Err(why) => {
                self.line(format!("bw_{id} = 0;"));
                self.skipped.push((n, why));
            }
        }
    }

    /// The step's exact value and its target's declared range, or None where the step claims nothing (a bitwise
    /// step, a copy that fits), or why it is not tried.
    #[allow(clippy::type_complexity)]
    fn claim(&self, n: &str, value: &E) -> Result<Option<(String, u32, i128, i128)>, String> {
        if matches!(value, E::Binary(_, VerilogOp::BitOr | VerilogOp::BitAnd | VerilogOp::BitXor, _)) {
            return Ok(None); // a bitwise step: its patterns are its value, read in the target's format
        }
        let Some(&bits) = self.widths.get(n) else { return Err("no width".into()) };
        let signed = (self.signed)(n);
        let (lo, hi) =
            if signed { (-(1i128 << (bits - 1)), (1i128 << (bits - 1)) - 1) } else { (0, (1i128 << bits) - 1) };
        // a copy of a signal that its target holds whatever it is, or a literal: a bit pattern (`32'h200` is
        // −512 to an S10 target), which claims nothing where the target is as wide
        let copy_fits = match value {
            E::Literal(_) => literal_value(value).is_some_and(|v| (0..1i128 << bits).contains(&v)),
            E::Signal(s) if self.loop_value(value).is_none() => {
                let src = self.probe(s);
                match self.widths.get(&src) {
                    Some(&b) => {
                        let ss = (self.signed)(&src);
                        (ss == signed && b <= bits) || (!ss && signed && b < bits)
                    }
                    None => false,
                }
            }
            _ => false,
        };
        if copy_fits {
            return Ok(None);
        }
        if let Some(why) = (self.skip)(self.path, n) {
            return Err(why);
        }
        let mut r = vec![];
        reads(value, &self.loops, &mut r);
        if let Some(s) = r.iter().find(|s| self.last.get(*s).is_some_and(|&p| p > self.pos)) {
            return Err(format!("reads {s}, which its block writes again later"));
        }
        let Some(need) = self.need(value) else { return Err("an operand's width is unknown".into()) };
        let w = need.max(bits + 1) + 1;
        if w > WIDEST {
            return Err(format!("its exact value needs {w} bits"));
        }
        match self.exact(value, w) {
            Some(t) => Ok(Some((t, w, lo, hi))),
            None => Err("a shift or slice by a variable amount".into()),
        }
    }
}

/// The module name the export gives the block at `path` (`uut.dot.s1_nm$0` → `<top>$dot$s1_nm$0`).
fn module_name(top: &str, path: &str) -> String {
    match path.strip_prefix("uut") {
        Some("") => top.to_string(),
        Some(rest) => format!("{top}{}", rest.replace('.', "$")),
        None => path.to_string(),
    }
}

/// The harness: `r.verilog` with each module's assertions in it.
pub fn harness(block: &dyn Block, r: &Request) -> Result<Harness, String> {
    let mut c = Collect::default();
    block.accept("uut", &mut c);
    let ports: Vec<&str> = r.inputs.iter().map(|i| i.0).collect();
    let stage = stages(block, &ports);
    // the modules with a claim gated by its stage, and the deepest stage gated
    let mut gated: HashSet<String> = HashSet::new();
    let mut deepest = 0;
    let mut per_module: HashMap<String, Vec<String>> = HashMap::new();
    let mut props: Vec<Prop> = vec![];
    let mut skipped = vec![];
    for md in &c.modules {
        let Code::Comb(b) = &md.code else { continue };
        let mut w = Walk {
            path: &md.path,
            widths: &c.widths,
            signed: r.signed,
            skip: r.skip,
            loops: vec![],
            pos: 0,
            last: HashMap::new(),
            printing: false,
            out: vec![],
            depth: 0,
            unsafe_depth: 0,
            targets: vec![],
            decls: vec![],
            props: vec![],
            steps: vec![],
            tainted: HashSet::new(),
            skipped: vec![],
            first: props.len() + 1,
        };
        w.block(b);
        w.pos = 0;
        w.printing = true;
        w.block(b);
        if w.props.is_empty() {
            skipped.extend(w.skipped);
            continue;
        }
        let mut text = vec![];
        text.extend(w.decls.iter().map(|d| format!("    {d}")));
        text.extend(w.targets.iter().map(|t| format!("    integer bw_{t};")));
        text.push("    always @(*) begin".into());
        for (k, _, width) in &w.steps {
            text.push(format!("        bp{k}_x = {};", lit(0, *width)));
        }
        text.extend(w.targets.iter().map(|t| format!("        bw_{t} = 0;")));
        text.append(&mut w.out);
        text.push("    end".into());
        text.push("    always @(*) begin".into());
        let first = w.first;
        for (i, mut p) in w.props.into_iter().enumerate() {
            let (k, id, width) = &w.steps[i];
            if w.tainted.contains(id) {
                skipped.push((p.signal, "a branch above it tests a signal its block writes later".into()));
                continue;
            }
            if (r.gate)(&md.path, &p.signal) {
                if let Some(Stage::At(d)) = stage.get(&p.signal) {
                    p.stage = Some(*d);
                    deepest = deepest.max(*d);
                    gated.insert(md.path.clone());
                }
            }
            let when = p.stage.map_or(String::new(), |d| format!("!fv_valid[{d}] || "));
            text.push(format!(
                "        assert({when}bw_{id} != {k} || (bp{k}_x >= {} && bp{k}_x <= {})); // bumprtl prop {}",
                lit(p.lo, *width),
                lit(p.hi, *width),
                props.len() + 1
            ));
            debug_assert!(*k >= first);
            props.push(p);
        }
        text.push("    end".into());
        skipped.extend(w.skipped);
        per_module.entry(md.path.clone()).or_default().extend(text);
    }
    // the range claims, each in the module that holds the signal
    for (n, lo, hi) in r.ranges {
        let Some((path, local)) = n.rsplit_once('.') else { continue };
        let Some(&bits) = c.widths.get(n) else {
            skipped.push((n.clone(), "no width".into()));
            continue;
        };
        let w = (bits + 2).max(bitlen(*lo).max(bitlen(*hi)) + 2);
        let v = extend(local, bits, (r.signed)(n), w);
        per_module.entry(path.to_string()).or_default().push(format!(
            "    always @(*) assert({v} >= {} && {v} <= {}); // bumprtl prop {}",
            lit(*lo, w),
            lit(*hi, w),
            props.len() + 1
        ));
        props.push(Prop {
            signal: n.clone(),
            block: path.into(),
            kind: Kind::Range,
            lo: *lo,
            hi: *hi,
            line: 0,
            stage: None,
        });
    }
    // the inputs inside their ranges
    let mut assumes = vec![];
    for (name, lo, hi) in r.inputs {
        let Some(&bits) = c.widths.get(&format!("uut.{name}")) else { continue };
        let w = (bits + 2).max(64);
        let v = extend(name, bits, *lo < 0, w);
        assumes.push(format!(
            "    always @(*) assume({v} >= {} && {v} <= {});",
            lit(*lo as i128, w),
            lit(*hi as i128, w)
        ));
    }
    per_module.entry("uut".into()).or_default().extend(assumes);
    let mut text = r.verilog.to_string();
    if !gated.is_empty() {
        // which clocks hold a pixel at each stage: bit d of `fv_valid` is `valid_in` d clocks before, made in the top
        // module and passed down as a port to every module with a gated claim and those between it and the top
        let d = deepest.max(1);
        per_module.entry("uut".into()).or_default().extend([
            format!("    reg [{d}:1] fv_hist = 0;"),
            format!("    wire [{d}:0] fv_valid = {{fv_hist, valid_in}};"),
            format!("    always @(posedge clock) fv_hist <= fv_valid[{}:0];", d - 1),
        ]);
        let mut down: Vec<String> = vec![];
        for g in &gated {
            let mut at = g.as_str();
            while at != "uut" {
                down.push(at.to_string());
                at = at.rsplit_once('.').map_or("uut", |x| x.0);
            }
        }
        down.sort();
        down.dedup();
        for path in &down {
            let name = module_name(r.top, path);
            let head = format!("module {name}(");
            let at = text.find(&head).ok_or(format!("the export has no module {name} for {path}"))?;
            let eol = at + text[at..].find('\n').ok_or(format!("module {name}: no header line"))?;
            text.insert_str(
                eol + 1,
                &format!("    input wire [{d}:0] fv_valid; // the formal harness's stage flags\n"),
            );
            text.insert_str(at + head.len(), "fv_valid,");
            let inst = format!("\n    {name} ");
            let at = text.find(&inst).ok_or(format!("no instance of {name}"))?;
            let open = at + text[at..].find("(\n").ok_or(format!("{name}: no port list"))?;
            text.insert_str(open + 1, "\n        .fv_valid(fv_valid),");
        }
    }
    // into the text, before each module's `endmodule`
    let mut paths: Vec<&String> = per_module.keys().collect();
    paths.sort();
    for path in paths {
        let name = module_name(r.top, path);
        let head = format!("module {name}(");
        let Some(at) = text.find(&head) else {
            return Err(format!("the export has no module {name} for {path}"));
        };
        let Some(end) = text[at..].find("\nendmodule") else {
            return Err(format!("module {name} has no endmodule"));
        };
        let insert = format!("\n`ifdef FORMAL\n{}\n`endif", per_module[path].join("\n"));
        text.insert_str(at + end, &insert);
    }
    for (i, l) in text.lines().enumerate() {
        if let Some((_, k)) = l.rsplit_once("// bumprtl prop ") {
            if let Ok(k) = k.trim().parse::<usize>() {
                props[k - 1].line = i + 1;
            }
        }
    }
    Ok(Harness { text, props, skipped })
}
