//! Datapath widths, proven: a sound bound on every signal of an rtl block over every input sequence, by interval
//! analysis of the block's own hdl (the rust-hdl AST its `#[hdl_gen]` writes, the one the Verilog is printed from).
//!
//! A value is a set of bit patterns written as an interval [lo, hi] of integers of a width `bits`: the patterns are
//! `v mod 2^bits` for v in it. Two's complement arithmetic is arithmetic mod 2^bits, so + − ! and negation are
//! exact on such intervals whether the bits are read signed or unsigned, and so is `get_bits` (a floor division);
//! the operations that read patterns unsigned (×, logical >>, comparisons, zero extension) split the interval where
//! it crosses 2^bits. An interval as long as 2^bits is every pattern. Each block's statements are evaluated with
//! every signal at the hull of the values it can take, `if` branches refining the tested signal (its top bit, or a
//! comparison with a constant); a register's q takes its d's values and its initial zero; RAM reads take what is
//! written and the initial contents; ROM outputs the hull of their tables. All blocks are swept until nothing
//! grows: the least fixed point, which holds every value any input sequence within the ports' ranges can produce.

use rust_hdl::core::ast::{
    Verilog, VerilogBlock, VerilogBlockOrConditional, VerilogExpression as E, VerilogLoop, VerilogOp, VerilogOpUnary,
    VerilogStatement as S,
};
use rust_hdl::core::atom::{Atom, AtomKind};
use rust_hdl::core::block::Block;
use rust_hdl::core::probe::Probe;
use std::collections::HashMap;

/// A set of `bits`-wide patterns: `v mod 2^bits` for lo ≤ v ≤ hi.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct V {
    pub lo: i128,
    pub hi: i128,
    pub bits: u32,
    /// a literal of the source (its width is the other operand's)
    lit: bool,
}

fn m(bits: u32) -> i128 {
    1i128 << bits.min(100)
}

impl V {
    pub fn new(lo: i128, hi: i128, bits: u32) -> V {
        V { lo, hi, bits, lit: false }.norm()
    }
    pub fn full(bits: u32) -> V {
        V { lo: 0, hi: m(bits) - 1, bits, lit: false }
    }
    fn exact(v: i128, bits: u32) -> V {
        V::new(v, v, bits)
    }
    pub fn is_full(&self) -> bool {
        self.hi - self.lo + 1 >= m(self.bits)
    }
    fn norm(self) -> V {
        if self.hi - self.lo + 1 >= m(self.bits) {
            V { lit: false, ..V::full(self.bits) }
        } else {
            self
        }
    }
    fn with_bits(self, bits: u32) -> V {
        V { bits, lit: false, ..self }.norm()
    }
    /// The patterns read unsigned, as one or two intervals in [0, 2^bits).
    pub fn unsigned(&self) -> Vec<(i128, i128)> {
        if self.is_full() {
            return vec![(0, m(self.bits) - 1)];
        }
        let a = self.lo.rem_euclid(m(self.bits));
        let len = self.hi - self.lo;
        if a + len < m(self.bits) {
            vec![(a, a + len)]
        } else {
            vec![(a, m(self.bits) - 1), (0, a + len - m(self.bits))]
        }
    }
    /// The patterns read as two's complement, as one or two intervals in [−2^(bits−1), 2^(bits−1)).
    pub fn signed(&self) -> Vec<(i128, i128)> {
        let h = m(self.bits) / 2;
        let mut p: Vec<(i128, i128)> = self
            .unsigned()
            .into_iter()
            .flat_map(|(a, b)| {
                if b < h {
                    vec![(a, b)]
                } else if a >= h {
                    vec![(a - m(self.bits), b - m(self.bits))]
                } else {
                    vec![(h - m(self.bits), b - m(self.bits)), (a, h - 1)]
                }
            })
            .collect();
        // pieces that touch are one run: [−6, −1] and [0, 4] are [−6, 4]
        p.sort();
        let mut out: Vec<(i128, i128)> = vec![];
        for (a, b) in p {
            match out.last_mut() {
                Some(l) if a <= l.1 + 1 => l.1 = l.1.max(b),
                _ => out.push((a, b)),
            }
        }
        out
    }
    /// The range in one reading: (min, max) over the patterns, unsigned or two's complement.
    pub fn range(&self, signed: bool) -> (i128, i128) {
        let p = if signed { self.signed() } else { self.unsigned() };
        (p.iter().map(|x| x.0).min().unwrap_or(0), p.iter().map(|x| x.1).max().unwrap_or(0))
    }
    /// The smallest interval of patterns holding both (the same width).
    pub fn join(self, o: V) -> V {
        let bits = self.bits.max(o.bits);
        let (a, b) = (self.with_bits(bits), o.with_bits(bits));
        if a.is_full() || b.is_full() {
            return V::full(bits);
        }
        let period = m(bits);
        let base = a.lo.rem_euclid(period);
        let a = V { lo: base, hi: base + (a.hi - a.lo), ..a };
        let bstart = b.lo.rem_euclid(period);
        let blen = b.hi - b.lo;
        // b placed a period lower, level, or higher: the shortest hull
        let best = [-period, 0, period]
            .iter()
            .map(|&k| (a.lo.min(bstart + k), a.hi.max(bstart + k + blen)))
            .min_by_key(|(lo, hi)| hi - lo)
            .unwrap();
        V::new(best.0, best.1, bits)
    }
    fn from_pieces(p: &[(i128, i128)], bits: u32) -> V {
        let lo = p.iter().map(|x| x.0).min().unwrap_or(0);
        let hi = p.iter().map(|x| x.1).max().unwrap_or(0);
        V::new(lo, hi, bits)
    }
    /// Restricted to the patterns whose `signed`/unsigned reading lies in [lo, hi]; None when none does.
    fn within(self, signed: bool, lo: i128, hi: i128) -> Option<V> {
        let p: Vec<(i128, i128)> = (if signed { self.signed() } else { self.unsigned() })
            .into_iter()
            .filter(|&(a, b)| a.max(lo) <= b.min(hi))
            .map(|(a, b)| (a.max(lo), b.min(hi)))
            .collect();
        if p.is_empty() {
            return None;
        }
        // two pieces in the signed reading may be one run in the unsigned one: join them as patterns
        let mut it = p.into_iter().map(|(a, b)| V::new(a, b, self.bits));
        let first = it.next()?;
        Some(it.fold(first, V::join))
    }
}

fn bitlen(x: i128) -> u32 {
    128 - x.max(0).leading_zeros()
}

/// Where one operand is one constant c and every value of the other lies below c's lowest set bit: (the other's
/// pieces, c). Then x | c = x ^ c = x + c.
fn disjoint<'a>(a: &'a [(i128, i128)], b: &'a [(i128, i128)]) -> Option<(&'a [(i128, i128)], i128)> {
    let one = |p: &[(i128, i128)]| (p.len() == 1 && p[0].0 == p[0].1 && p[0].0 > 0).then(|| p[0].0);
    for (x, c) in [(a, one(b)), (b, one(a))] {
        if let Some(c) = c {
            let low = c & -c;
            if x.iter().all(|p| p.1 < low) {
                return Some((x, c));
            }
        }
    }
    None
}

/// Binary operations on intervals, as rust-hdl computes them (the width of the operands; a literal takes the other's).
fn binary(a: V, op: &VerilogOp, b: V) -> V {
    let bits = match (a.lit, b.lit) {
        (true, false) => b.bits,
        (false, true) => a.bits,
        _ => a.bits.max(b.bits),
    };
    let bool_of = |t: Option<bool>| match t {
        Some(x) => V::exact(x as i128, 1),
        None => V::new(0, 1, 1),
    };
    let (ua, ub) = (a.with_bits(bits).unsigned(), b.with_bits(bits).unsigned());
    let (amin, amax) = (ua.iter().map(|x| x.0).min().unwrap(), ua.iter().map(|x| x.1).max().unwrap());
    let (bmin, bmax) = (ub.iter().map(|x| x.0).min().unwrap(), ub.iter().map(|x| x.1).max().unwrap());
    let cmp = |f: &dyn Fn(i128, i128) -> bool| -> Option<bool> {
        // decided when every pair of pieces' ends agrees (the relations are monotone in each operand)
        let mut seen = None;
        for &(a0, a1) in &ua {
            for &(b0, b1) in &ub {
                for (x, y) in [(a0, b0), (a0, b1), (a1, b0), (a1, b1)] {
                    let r = f(x, y);
                    if seen.is_some_and(|s| s != r) {
                        return None;
                    }
                    seen = Some(r);
                }
            }
        }
        seen
    };
    match op {
        VerilogOp::Add => V::new(a.lo + b.lo, a.hi + b.hi, bits),
        VerilogOp::Sub => V::new(a.lo - b.hi, a.hi - b.lo, bits),
        VerilogOp::Mul => {
            // Bits<16> × Bits<16> → Bits<32>, the patterns unsigned
            let mut p = vec![];
            for &(a0, a1) in &ua {
                for &(b0, b1) in &ub {
                    p.push((a0 * b0, a1 * b1));
                }
            }
            V::from_pieces(&p, 2 * bits)
        }
        // a constant whose set bits all lie above the other operand's: | and ^ add it, & with its complement's
        // low mask keeps the operand (sign extension by `x | 0x100`, a field put beside another)
        VerilogOp::BitOr | VerilogOp::BitXor if disjoint(&ua, &ub).is_some() => {
            let (x, c) = disjoint(&ua, &ub).unwrap();
            V::from_pieces(&x.iter().map(|(a, b)| (a + c, b + c)).collect::<Vec<_>>(), bits)
        }
        VerilogOp::BitAnd => V::new(0, amax.min(bmax), bits),
        VerilogOp::BitOr => V::new(amin.max(bmin), ((1i128 << bitlen(amax.max(bmax))) - 1).min(amax + bmax), bits),
        VerilogOp::BitXor => V::new(0, ((1i128 << bitlen(amax.max(bmax))) - 1).min(amax + bmax), bits),
        VerilogOp::LogicalAnd | VerilogOp::LogicalOr => {
            let (ta, tb) = (
                (amin > 0).then_some(true).or((amax == 0).then_some(false)),
                (bmin > 0).then_some(true).or((bmax == 0).then_some(false)),
            );
            bool_of(match op {
                VerilogOp::LogicalAnd => match (ta, tb) {
                    (Some(false), _) | (_, Some(false)) => Some(false),
                    (Some(true), Some(true)) => Some(true),
                    _ => None,
                },
                _ => match (ta, tb) {
                    (Some(true), _) | (_, Some(true)) => Some(true),
                    (Some(false), Some(false)) => Some(false),
                    _ => None,
                },
            })
        }
        VerilogOp::Shl => match (b.lo == b.hi, b.lo) {
            (true, k) if (0..64).contains(&k) => V::new(a.lo << k, a.hi << k, bits),
            // a shift by an amount in [k0, k1]: the patterns read unsigned, while the largest stays inside the width
            _ if ub.len() == 1 && bmax < 64 && amax << bmax < m(bits) => V::new(amin << bmin, amax << bmax, bits),
            _ => V::full(bits),
        },
        VerilogOp::Shr => match (b.lo == b.hi, b.lo) {
            (true, k) if (0..128).contains(&k) => {
                V::from_pieces(&ua.iter().map(|(x, y)| (x >> k, y >> k)).collect::<Vec<_>>(), bits)
            }
            _ if ub.len() == 1 && bmax < 128 => V::new(amin >> bmax, amax >> bmin, bits),
            _ => V::new(0, amax, bits),
        },
        VerilogOp::Eq => bool_of(if amin == amax && bmin == bmax && ua.len() == 1 && ub.len() == 1 {
            Some(amin == bmin)
        } else if amax < bmin || bmax < amin {
            Some(false)
        } else {
            None
        }),
        VerilogOp::Ne => bool_of(if amin == amax && bmin == bmax && ua.len() == 1 && ub.len() == 1 {
            Some(amin != bmin)
        } else if amax < bmin || bmax < amin {
            Some(true)
        } else {
            None
        }),
        VerilogOp::Lt => bool_of(cmp(&|x, y| x < y)),
        VerilogOp::Le => bool_of(cmp(&|x, y| x <= y)),
        VerilogOp::Gt => bool_of(cmp(&|x, y| x > y)),
        VerilogOp::Ge => bool_of(cmp(&|x, y| x >= y)),
    }
}

/// A walk over a module's statements, each `for` loop unrolled by its literal bounds with the index's value in
/// `loops` while its body is walked (what `full_name` and `index_value` read): the interval evaluation, the solver's
/// harness and the stages each implement `step` and share the rest.
pub(crate) trait Walker {
    /// one statement
    fn step(&mut self, s: &S);
    /// the loop indices' values, outermost first
    fn loops(&mut self) -> &mut Vec<(String, i128)>;
    fn block(&mut self, b: &VerilogBlock) {
        for s in b {
            self.step(s);
        }
    }
    /// The loop's body once for each index from its first bound up to its last, each bound a literal: a bound that
    /// is not one would leave the body unwalked and its steps unproven, so it stops the walk (no rtl block has one;
    /// the width tests walk every block).
    fn unroll(&mut self, l: &VerilogLoop) {
        let bound = |e: &dyn std::fmt::Display, which: &str| {
            let text = e.to_string();
            literal(&text).map(|x| x.0).unwrap_or_else(|| {
                panic!("a loop's {which} bound `{text}` is not a literal: the width walkers unroll literal bounds only")
            })
        };
        let (from, to) = (bound(&l.from, "first"), bound(&l.to, "last"));
        for k in from..to {
            self.loops().push((l.index.clone(), k));
            self.block(&l.block);
            self.loops().pop();
        }
    }
}

/// A literal as rust-hdl prints it: `12'h7ff`, `5'b10011`.
pub(crate) fn literal(text: &str) -> Option<(i128, u32)> {
    let (bits, rest) = text.split_once('\'')?;
    let bits: u32 = bits.parse().ok()?;
    let v = match rest.as_bytes().first()? {
        b'h' => i128::from_str_radix(&rest[1..], 16).ok()?,
        b'b' => i128::from_str_radix(&rest[1..], 2).ok()?,
        b'd' => rest[1..].parse().ok()?,
        _ => return None,
    };
    Some((v, bits))
}

/// A literal's value, if the expression is one.
pub(crate) fn literal_value(e: &E) -> Option<i128> {
    match e {
        E::Literal(l) => literal(&l.to_string()).map(|x| x.0),
        E::Paren(x) => literal_value(x),
        _ => None,
    }
}

/// What a module is, to the analysis.
pub(crate) enum Code {
    Comb(VerilogBlock),
    Dff,
    Rom(Vec<i128>, bool),
    Ram(Vec<i128>),
    Other,
}

pub(crate) struct Module {
    pub(crate) path: String,
    pub(crate) code: Code,
}

/// Walks the block tree: every module's code, every signal's width, the constants' values.
#[derive(Default)]
pub(crate) struct Collect {
    path: Vec<String>,
    pub(crate) modules: Vec<Module>,
    pub(crate) widths: HashMap<String, u32>,
    pub(crate) consts: HashMap<String, V>,
}

impl Probe for Collect {
    fn visit_start_scope(&mut self, name: &str, node: &dyn Block) {
        self.path.push(name.to_string());
        let code = match node.hdl() {
            Verilog::Combinatorial(b) => Code::Comb(b),
            Verilog::Custom(t) if t.contains("q <= d") => Code::Dff,
            Verilog::Custom(t) if t.contains("case (address)") => {
                let vals: Vec<i128> = t
                    .lines()
                    .filter_map(|l| l.split_once("data = "))
                    .filter(|(k, _)| !k.contains("default"))
                    .filter_map(|(_, v)| literal(v.trim_end_matches(';').trim()).map(|x| x.0))
                    .collect();
                let cases = vals.len();
                let addr_bits = t
                    .lines()
                    .filter_map(|l| l.trim().split_once(':'))
                    .filter_map(|(k, _)| literal(k.trim()).map(|x| x.1))
                    .next()
                    .unwrap_or(0);
                Code::Rom(vals, cases as i128 == m(addr_bits))
            }
            Verilog::Custom(t) if t.contains("read_data <= mem") => Code::Ram(
                t.lines()
                    .filter_map(|l| l.split_once("] = "))
                    .filter_map(|(_, v)| literal(v.trim_end_matches(';').trim()).map(|x| x.0))
                    .collect(),
            ),
            _ => Code::Other,
        };
        self.modules.push(Module { path: self.path.join("."), code });
    }
    fn visit_end_scope(&mut self, _name: &str, _node: &dyn Block) {
        self.path.pop();
    }
    fn visit_start_namespace(&mut self, name: &str, _node: &dyn Block) {
        self.path.push(name.to_string());
    }
    fn visit_end_namespace(&mut self, _name: &str, _node: &dyn Block) {
        self.path.pop();
    }
    fn visit_atom(&mut self, name: &str, a: &dyn Atom) {
        let full = format!("{}.{name}", self.path.join("."));
        self.widths.insert(full.clone(), a.bits() as u32);
        if a.kind() == AtomKind::Constant {
            if let Some((v, _)) = literal(&a.verilog().to_string()) {
                self.consts.insert(full, V::exact(v, a.bits() as u32));
            }
        }
    }
}

/// An array index as the hdl writes it (`4*i+1`, `i - 1`): sums of products of numbers and loop variables.
pub(crate) fn index_value(text: &str, loops: &[(String, i128)]) -> Option<i128> {
    let spaced = text.replace('-', " - ").replace('+', " + ").replace('*', " * ");
    let (mut total, mut term, mut sign) = (0i128, 1i128, 1i128);
    let mut expect_value = true;
    for tok in spaced.split_whitespace() {
        match (tok, expect_value) {
            ("+" | "-", false) => {
                total += sign * term;
                (term, sign, expect_value) = (1, if tok == "-" { -1 } else { 1 }, true);
            }
            ("*", false) => expect_value = true,
            (t, true) => {
                let v = t.parse::<i128>().ok().or_else(|| loops.iter().rev().find(|(n, _)| n == t).map(|x| x.1))?;
                term *= v;
                expect_value = false;
            }
            _ => return None,
        }
    }
    (!expect_value).then_some(total + sign * term)
}

/// A module's local signal name as the hdl writes it (`s1_nm[i]$d$next`, loop indices bound) → the probe's name
/// under `path` (`uut.dot.s1_nm$0.d`).
pub(crate) fn full_name(path: &str, local: &str, loops: &[(String, i128)]) -> String {
    let local = local.strip_suffix("$next").unwrap_or(local);
    // array indices: `[0]`, `[i]`, `[i-1]`: sums and differences of loop variables and numbers
    let mut s = String::with_capacity(local.len());
    let mut rest = local;
    while let Some(open) = rest.find('[') {
        s.push_str(&rest[..open]);
        let Some(close) = rest[open..].find(']') else { break };
        let index = &rest[open + 1..open + close];
        if let Some(total) = index_value(index, loops) {
            s.push_str(&format!("${total}"));
        } else {
            s.push_str(&rest[open..open + close + 1]);
        }
        rest = &rest[open + close + 1..];
    }
    s.push_str(rest);
    let mut out = String::from(path);
    for (i, seg) in s.split('$').enumerate() {
        let numeric = !seg.is_empty() && seg.bytes().all(|c| c.is_ascii_digit());
        out.push(if i > 0 && numeric { '$' } else { '.' });
        out.push_str(seg);
    }
    out
}

/// The analysis' state: every signal's values so far.
struct State<'a> {
    vals: HashMap<String, V>,
    widths: &'a HashMap<String, u32>,
    /// how each signal's patterns are read (its declared format): two's complement or unsigned
    signed: &'a dyn Fn(&str) -> bool,
    /// the assignments whose exact result, read in its operands' formats, may leave the target's range, by
    /// (the assigning block's path, the signal): the exact hull of what they compute
    wraps: HashMap<(String, String), (i128, i128)>,
    changed: bool,
    /// a count of the changes to `vals`, and the count at each signal's last change: a module whose reads have not
    /// changed since it was last evaluated would write what it wrote then, so it is not evaluated again
    tick: u64,
    changed_at: HashMap<String, u64>,
}

impl State<'_> {
    /// A value as the signal `name` holds it: at its width (a literal takes it; a narrower value is zero-extended).
    fn fit(&self, name: &str, v: V) -> V {
        let bits = self.widths.get(name).copied().unwrap_or(v.bits);
        if v.lit || v.bits >= bits {
            v.with_bits(bits)
        } else {
            V::from_pieces(&v.unsigned(), bits)
        }
    }

    fn grow(&mut self, name: &str, v: V) {
        let v = self.fit(name, v);
        let next = match self.vals.get(name) {
            Some(old) => old.join(v),
            None => v,
        };
        if self.vals.get(name) != Some(&next) {
            self.vals.insert(name.to_string(), next);
            self.mark(name);
        }
    }

    fn mark(&mut self, name: &str) {
        self.changed = true;
        self.tick += 1;
        self.changed_at.insert(name.to_string(), self.tick);
    }
}

/// A value written on a path, and the exact hull of what its step computes (its operands read in their declared
/// formats), where known.
type Write = (V, Option<(i128, i128)>, Option<std::rc::Rc<(E, Vec<(String, i128)>)>>);

/// One evaluation of a module's statements; `refine` holds a branch's narrower view of tested signals, `writes`
/// the values assigned on this path (the last assignment wins).
struct Eval<'s, 'a> {
    st: &'s State<'a>,
    path: &'s str,
    loops: Vec<(String, i128)>,
    refine: HashMap<String, V>,
    /// what this path has written so far (the last write wins); a block's own local and output signals read
    /// their write on the path, as rust-hdl's `val()` of a `Local` or `Out` signal returns its `next`
    cur: HashMap<String, Write>,
    /// the signals whose values so far this evaluation has read
    reads: std::cell::RefCell<Vec<String>>,
}

impl Walker for Eval<'_, '_> {
    fn step(&mut self, s: &S) {
        match s {
            S::Assignment(target, value) => {
                let E::Signal(t) = target else { return };
                let n = full_name(self.path, t, &self.loops);
                if let Some(v) = self.expr(value) {
                    // the exact value rides with the write: a later assignment on the same path replaces both. A
                    // bitwise step (a sign extension `x | 0x100`, fields put side by side) is no arithmetic to
                    // overflow: its patterns are the value, read in the target's format
                    let bitwise =
                        matches!(value, E::Binary(_, VerilogOp::BitOr | VerilogOp::BitAnd | VerilogOp::BitXor, _));
                    let exact = if bitwise { None } else { self.exact(value) };
                    let w = (v, exact, Some(std::rc::Rc::new((value.clone(), self.loops.clone()))));
                    self.cur.insert(n, w);
                }
            }
            S::SliceAssignment { base, .. } => {
                if let E::Signal(t) = base {
                    let n = full_name(self.path, t, &self.loops);
                    let bits = self.st.widths.get(&n).copied().unwrap_or(1);
                    self.cur.insert(n, (V::full(bits), None, None));
                }
            }
            S::If(c) => {
                let t = self.expr(&c.test);
                let (go_then, go_else) = match t.map(|v| v.unsigned()) {
                    Some(u) if u == [(1, 1)] => (true, false),
                    Some(u) if u == [(0, 0)] => (false, true),
                    Some(_) => (true, true),
                    None => (false, false), // the test is not yet defined: nothing flows this sweep
                };
                let split = self.split(&c.test);
                let (rt, re) = match &split {
                    Some((n, t, e)) => (t.map(|v| (n.clone(), v)), e.map(|v| (n.clone(), v))),
                    None => (None, None),
                };
                // a side the refinement shows empty is not taken
                let go_then = go_then && !matches!(&split, Some((_, None, _)));
                let go_else = go_else && !matches!(&split, Some((_, _, None)));
                let base = self.cur.clone();
                let mut outs = vec![];
                if go_then {
                    outs.push(self.branch(rt, &|e| e.block(&c.then), &base));
                }
                if go_else {
                    let other = |e: &mut Self| match &c.otherwise {
                        VerilogBlockOrConditional::Block(b) => e.block(b),
                        VerilogBlockOrConditional::Conditional(s) => e.step(s),
                        VerilogBlockOrConditional::None => {}
                    };
                    outs.push(self.branch(re, &other, &base));
                }
                self.merge(&base, outs);
            }
            S::Match(mt) => {
                let base = self.cur.clone();
                let outs: Vec<HashMap<String, Write>> =
                    mt.cases.iter().map(|c| self.branch(None, &|e| e.block(&c.block), &base)).collect();
                self.merge(&base, outs);
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

impl Eval<'_, '_> {
    fn read(&self, local: &str) -> Option<V> {
        if let Some((_, k)) = self.loops.iter().find(|(v, _)| v == local) {
            return Some(V { lit: true, ..V::exact(*k, 32) });
        }
        let n = full_name(self.path, local, &self.loops);
        if let Some(v) = self.refine.get(&n) {
            return Some(*v);
        }
        // a field of this block itself (not a child's port): its write on this path, if any
        let own = n.strip_prefix(self.path).is_some_and(|r| !r[1..].contains('.'));
        if own {
            if let Some(w) = self.cur.get(&n) {
                return Some(self.st.fit(&n, w.0));
            }
        }
        let v = self.st.vals.get(&n).copied();
        self.reads.borrow_mut().push(n);
        v
    }

    /// The exact value of an expression over integers, each signal read in its declared format, nothing
    /// wrapped: what the arithmetic means, to hold against the width it is stored in.
    fn exact(&self, e: &E) -> Option<(i128, i128)> {
        let view = |v: V, signed: bool| -> (i128, i128) { v.range(signed) };
        Some(match e {
            E::Signal(s) => {
                let v = self.read(s)?;
                if v.lit {
                    (v.lo, v.hi)
                } else {
                    view(v, (self.st.signed)(&full_name(self.path, s, &self.loops)))
                }
            }
            E::Literal(_) => {
                let v = self.expr(e)?;
                (v.lo, v.hi)
            }
            E::Paren(x) | E::Signed(x) | E::Unsigned(x) => self.exact(x)?,
            E::Cast(x, w) => {
                let v = self.expr(x)?;
                if *w as u32 >= v.bits {
                    // zero extension: the patterns read unsigned
                    view(v, false)
                } else {
                    self.exact(x)? // a narrowing cast keeps the value; the target's range judges it
                }
            }
            E::Slice(x, _, off) => {
                let (a, b) = self.exact(x)?;
                let k = self.expr(off)?;
                if k.lo != k.hi {
                    return None;
                }
                (a.div_euclid(1 << k.lo), b.div_euclid(1 << k.lo))
            }
            // `!x + 1`, two's complement negation written out: −x, whatever x's format (its patterns are −x's)
            E::Binary(a, VerilogOp::Add, b)
                if matches!(&**a, E::Unary(VerilogOpUnary::Not, _)) && literal_value(b) == Some(1) =>
            {
                let E::Unary(_, x) = &**a else { unreachable!() };
                let (lo, hi) = self.exact(x)?;
                (-hi, -lo)
            }
            E::Binary(a, op, b) => {
                let (x, y) = (self.exact(a)?, self.exact(b)?);
                match op {
                    VerilogOp::Add => (x.0 + y.0, x.1 + y.1),
                    VerilogOp::Sub => (x.0 - y.1, x.1 - y.0),
                    VerilogOp::Mul => {
                        let p = [x.0 * y.0, x.0 * y.1, x.1 * y.0, x.1 * y.1];
                        (*p.iter().min().unwrap(), *p.iter().max().unwrap())
                    }
                    VerilogOp::Shl if y.0 == y.1 && (0..64).contains(&y.0) => (x.0 << y.0, x.1 << y.0),
                    VerilogOp::Shr if y.0 == y.1 && (0..128).contains(&y.0) => (x.0 >> y.0, x.1 >> y.0),
                    // the bitwise operations and the tests: their pattern result is their value
                    _ => {
                        let v = self.expr(e)?;
                        view(v, false)
                    }
                }
            }
            E::Unary(VerilogOpUnary::Not, x) => {
                let v = self.expr(x)?;
                let signed = match &**x {
                    E::Signal(s) => (self.st.signed)(&full_name(self.path, s, &self.loops)),
                    _ => false,
                };
                let (a, b) = self.exact(x)?;
                if signed {
                    (-b - 1, -a - 1)
                } else {
                    (m(v.bits) - 1 - b, m(v.bits) - 1 - a)
                }
            }
            E::Unary(VerilogOpUnary::Neg, x) => {
                let (a, b) = self.exact(x)?;
                (-b, -a)
            }
            _ => {
                let v = self.expr(e)?;
                view(v, false)
            }
        })
    }

    fn expr(&self, e: &E) -> Option<V> {
        Some(match e {
            E::Signal(s) => self.read(s)?,
            E::Literal(l) => {
                let (v, bits) = literal(&l.to_string())?;
                V { lit: true, ..V::exact(v, bits) }
            }
            E::Paren(x) | E::Signed(x) | E::Unsigned(x) => self.expr(x)?,
            E::Cast(x, w) => {
                let v = self.expr(x)?;
                let w = *w as u32;
                if w >= v.bits {
                    V::from_pieces(&v.unsigned(), w)
                } else {
                    v.with_bits(w)
                }
            }
            E::Slice(x, w, off) => {
                let (v, k) = (self.expr(x)?, self.expr(off)?);
                if k.lo != k.hi {
                    return Some(V::full(*w as u32));
                }
                let (w, k) = (*w as u32, k.lo as u32);
                if w + k <= v.bits {
                    // the patterns' bits k.. are floor(v / 2^k) mod 2^w, whichever reading
                    V::new(v.lo.div_euclid(1 << k), v.hi.div_euclid(1 << k), w)
                } else {
                    V::from_pieces(&v.unsigned().iter().map(|(a, b)| (a >> k, b >> k)).collect::<Vec<_>>(), w)
                }
            }
            E::Index(x, i) => {
                let (v, i) = (self.expr(x)?, self.expr(i)?);
                if i.lo != i.hi || v.is_full() {
                    return Some(V::new(0, 1, 1));
                }
                let (a, b) = (v.lo.div_euclid(1 << i.lo), v.hi.div_euclid(1 << i.lo));
                if a == b {
                    V::exact(a.rem_euclid(2), 1)
                } else {
                    V::new(0, 1, 1)
                }
            }
            E::Binary(a, op, b) => binary(self.expr(a)?, op, self.expr(b)?),
            E::Unary(op, x) => {
                let v = self.expr(x)?;
                match op {
                    VerilogOpUnary::Not => V::new(-v.hi - 1, -v.lo - 1, v.bits),
                    VerilogOpUnary::Neg => V::new(-v.hi, -v.lo, v.bits),
                    VerilogOpUnary::Any => {
                        let u = v.unsigned();
                        if u == [(0, 0)] {
                            V::exact(0, 1)
                        } else if u.iter().all(|p| p.0 > 0) {
                            V::exact(1, 1)
                        } else {
                            V::new(0, 1, 1)
                        }
                    }
                    VerilogOpUnary::All => {
                        let u = v.unsigned();
                        let top = m(v.bits) - 1;
                        if u == [(top, top)] {
                            V::exact(1, 1)
                        } else if u.iter().all(|p| p.1 < top) {
                            V::exact(0, 1)
                        } else {
                            V::new(0, 1, 1)
                        }
                    }
                    VerilogOpUnary::Xor => V::new(0, 1, 1),
                }
            }
            E::IndexReplace(x, ..) => V::full(self.expr(x)?.bits),
        })
    }

    /// The tested signal narrowed on each side of `test`, where it is a top-bit test or a comparison with a
    /// constant: (name, then, otherwise).
    fn split(&self, test: &E) -> Option<(String, Option<V>, Option<V>)> {
        let unparen = |e: &E| -> E {
            let mut e = e.clone();
            while let E::Paren(x) = e {
                e = *x;
            }
            e
        };
        match unparen(test) {
            // (x & sign_bit).any(): the top bit alone
            E::Unary(VerilogOpUnary::Any, inner) => {
                let E::Binary(x, VerilogOp::BitAnd, c) = unparen(&inner) else { return None };
                let (E::Signal(s), c) = (unparen(&x), self.expr(&c)?) else { return None };
                let v = self.read(&s)?;
                (c.lo == c.hi && c.lo == m(v.bits) / 2).then_some(())?;
                let h = m(v.bits) / 2;
                Some((full_name(self.path, &s, &self.loops), v.within(true, -h, -1), v.within(true, 0, h - 1)))
            }
            E::Index(x, i) => {
                let E::Signal(s) = unparen(&x) else { return None };
                let (v, i) = (self.read(&s)?, self.expr(&i)?);
                (i.lo == i.hi && i.lo == v.bits as i128 - 1).then_some(())?;
                let h = m(v.bits) / 2;
                Some((full_name(self.path, &s, &self.loops), v.within(true, -h, -1), v.within(true, 0, h - 1)))
            }
            // a compare of a signal with a constant or another signal (unsigned, as rust-hdl compares): on each side
            // the signal lies on that side of the other's extreme
            E::Binary(a, op, b) => {
                let (E::Signal(s), c) = (unparen(&a), self.expr(&b)?) else { return None };
                let v = self.read(&s)?;
                let (lo, hi) = c.with_bits(v.bits).range(false);
                let top = m(v.bits) - 1;
                let (t, f) = match op {
                    VerilogOp::Gt => ((lo + 1, top), (0, hi)),
                    VerilogOp::Ge => ((lo, top), (0, hi - 1)),
                    VerilogOp::Lt => ((0, hi - 1), (lo, top)),
                    VerilogOp::Le => ((0, hi), (lo + 1, top)),
                    _ => return None,
                };
                Some((full_name(self.path, &s, &self.loops), v.within(false, t.0, t.1), v.within(false, f.0, f.1)))
            }
            _ => None,
        }
    }

    fn branch(
        &mut self,
        refine: Option<(String, V)>,
        then: &dyn Fn(&mut Self),
        base: &HashMap<String, Write>,
    ) -> HashMap<String, Write> {
        let saved = self.refine.clone();
        let mut w = base.clone();
        if let Some((n, v)) = refine {
            self.refine.insert(n, v);
            // what the path wrote before the test, recomputed knowing the test's side (`x = v; if v < 0 { x = −v }`
            // writes a non-negative x on both sides)
            let loops = std::mem::take(&mut self.loops);
            for (_, x) in w.iter_mut() {
                if let Some(e) = x.2.clone() {
                    self.loops = e.1.clone();
                    if let Some(v) = self.expr(&e.0) {
                        let bitwise =
                            matches!(&e.0, E::Binary(_, VerilogOp::BitOr | VerilogOp::BitAnd | VerilogOp::BitXor, _));
                        *x = (v, if bitwise { None } else { self.exact(&e.0) }, x.2.clone());
                    }
                }
            }
            self.loops = loops;
        }
        let outer = std::mem::replace(&mut self.cur, w);
        then(self);
        self.refine = saved;
        std::mem::replace(&mut self.cur, outer)
    }

    /// The writes after the branches: a signal written on every branch takes their join; one written on some
    /// only also keeps what it held before (the path's earlier write, or its value so far).
    fn merge(&mut self, base: &HashMap<String, Write>, outs: Vec<HashMap<String, Write>>) {
        if outs.is_empty() {
            return;
        }
        let mut names: Vec<&String> = outs.iter().flat_map(|o| o.keys()).collect();
        names.sort();
        names.dedup();
        let mut merged = base.clone();
        for n in names {
            let (mut v, mut ex): (Option<V>, Option<(i128, i128)>) = (None, None);
            for o in &outs {
                // not written on this branch: what the path wrote before, or the signal's value (which fits)
                let x = o.get(n).cloned().or_else(|| base.get(n).cloned()).or_else(|| {
                    self.reads.borrow_mut().push(n.clone());
                    self.st.vals.get(n).map(|v| (*v, None, None))
                });
                if let Some((xv, xe, _)) = x {
                    v = Some(v.map_or(xv, |a| a.join(xv)));
                    ex = match (ex, xe) {
                        (Some(a), Some(b)) => Some((a.0.min(b.0), a.1.max(b.1))),
                        (a, b) => a.or(b),
                    };
                }
            }
            if let Some(v) = v {
                merged.insert(n.clone(), (v, ex, None));
            }
        }
        self.cur = merged;
    }
}

/// What the analysis proves of a block.
pub struct Proof {
    /// every signal's possible patterns, by the probe's names (`uut.…`)
    pub values: HashMap<String, V>,
    /// the assignments that may wrap, by (the path of the block whose statement it is, the signal): the exact
    /// hull of the values the step computes, its operands read in their declared formats, which the target's
    /// declared range does not hold
    pub wraps: HashMap<(String, String), (i128, i128)>,
    /// sweeps to the fixed point
    pub sweeps: usize,
}

/// The proof for `block`, its inputs ranging over `inputs` (port name, min, max), each signal read signed where
/// `signed` says its declared format is.
pub fn prove(block: &dyn Block, inputs: &[(&str, i64, i64)], signed: &dyn Fn(&str) -> bool) -> Proof {
    let mut c = Collect::default();
    block.accept("uut", &mut c);
    let mut st = State {
        vals: HashMap::new(),
        widths: &c.widths,
        signed,
        wraps: HashMap::new(),
        changed: false,
        tick: 0,
        changed_at: HashMap::new(),
    };
    // per combinational module: the tick it was last evaluated at and the signals it read then
    let mut evaluated: Vec<Option<(u64, Vec<String>)>> = vec![None; c.modules.len()];
    for (name, lo, hi) in inputs {
        let n = format!("uut.{name}");
        let bits = c.widths.get(&n).copied().unwrap_or(64);
        st.vals.insert(n, V::new(*lo as i128, *hi as i128, bits));
    }
    st.vals.insert("uut.valid_in".into(), V::new(0, 1, 1));
    for (n, v) in &c.consts {
        st.vals.insert(n.clone(), *v);
    }
    const SWEEPS: usize = 400;
    let mut sweeps = 0;
    loop {
        sweeps += 1;
        st.changed = false;
        let before = (sweeps >= SWEEPS).then(|| st.vals.clone());
        for (md, last) in c.modules.iter().zip(evaluated.iter_mut()) {
            let p = md.path.as_str();
            match &md.code {
                Code::Comb(b) => {
                    if let Some((at, reads)) = last {
                        if reads.iter().all(|n| st.changed_at.get(n).is_none_or(|t| t <= at)) {
                            continue;
                        }
                    }
                    let (writes, mut reads) = {
                        let mut e = Eval {
                            st: &st,
                            path: p,
                            loops: vec![],
                            refine: HashMap::new(),
                            cur: HashMap::new(),
                            reads: Default::default(),
                        };
                        e.block(b);
                        (e.cur, e.reads.into_inner())
                    };
                    reads.sort_unstable();
                    reads.dedup();
                    *last = Some((st.tick, reads));
                    for (n, (v, exact, _)) in writes {
                        if n.ends_with("clock") {
                            continue;
                        }
                        // the final write's exact value against the target's range in its declared format
                        if let (Some((a, b)), Some(&bits)) = (exact, c.widths.get(&n)) {
                            let (lo, hi) =
                                if (st.signed)(&n) { (-m(bits) / 2, m(bits) / 2 - 1) } else { (0, m(bits) - 1) };
                            if a < lo || b > hi {
                                let w = st.wraps.entry((p.to_string(), n.clone())).or_insert((a, b));
                                *w = (w.0.min(a), w.1.max(b));
                            }
                        }
                        st.grow(&n, v);
                    }
                }
                Code::Dff => {
                    let (d, q) = (format!("{p}.d"), format!("{p}.q"));
                    let bits = c.widths.get(&q).copied().unwrap_or(1);
                    st.grow(&q, V::exact(0, bits));
                    if let Some(v) = st.vals.get(&d).copied() {
                        st.grow(&q, v);
                    }
                }
                Code::Rom(vals, full) => {
                    let n = format!("{p}.data");
                    let bits = c.widths.get(&n).copied().unwrap_or(1);
                    let mut v = vals.iter().fold(None, |acc: Option<V>, &x| {
                        Some(acc.map_or(V::exact(x, bits), |a| a.join(V::exact(x, bits))))
                    });
                    if !full {
                        v = Some(v.map_or(V::exact(0, bits), |a| a.join(V::exact(0, bits))));
                    }
                    if let Some(v) = v {
                        st.grow(&n, v);
                    }
                }
                Code::Ram(init) => {
                    let n = format!("{p}.read_data");
                    let bits = c.widths.get(&n).copied().unwrap_or(1);
                    st.grow(&n, V::exact(0, bits)); // the simulator's unwritten words read zero
                    for &x in init {
                        st.grow(&n, V::exact(x, bits));
                    }
                    if let Some(v) = st.vals.get(&format!("{p}.write_data")).copied() {
                        st.grow(&n, v);
                    }
                }
                Code::Other => {}
            }
        }
        if !st.changed {
            break;
        }
        if let Some(before) = before {
            // past a feed-forward pipeline's depth many times over, something still grows (a counter, an
            // accumulator, a loop through a register): whatever grew this sweep takes every pattern (widening)
            let grew: Vec<String> =
                st.vals.iter().filter(|(n, v)| before.get(*n) != Some(*v)).map(|(n, _)| n.clone()).collect();
            for n in grew {
                let bits = st.vals[&n].bits;
                st.vals.insert(n.clone(), V::full(bits));
                st.mark(&n);
            }
            if sweeps >= 4 * SWEEPS {
                break;
            }
        }
    }
    Proof { values: st.vals, wraps: st.wraps, sweeps }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A loop's bounds as rust-hdl writes them (`for i in 0..4` in a block) are literals the walkers read, wide or
    /// narrow, so `Walker::unroll` walks the body once an index; what it cannot read stops it rather than skipping
    /// the body.
    #[test]
    fn a_loops_bounds_as_rust_hdl_writes_them_are_read() {
        for (x, want) in [(0u32, 0), (3, 3), (4, 4), (1000, 1000)] {
            let l = rust_hdl::core::ast::VerilogLiteral::from(x);
            assert_eq!(literal(&l.to_string()).map(|v| v.0), Some(want), "{l}");
        }
        assert_eq!(literal(&rust_hdl::core::ast::VerilogLiteral::from(true).to_string()), Some((1, 1)));
        assert_eq!(literal("N"), None);
    }

    #[test]
    fn intervals_of_patterns_read_both_ways() {
        let v = V::new(-5, 5, 8);
        assert_eq!(v.range(true), (-5, 5));
        assert_eq!(v.range(false), (0, 255));
        assert_eq!(v.unsigned(), [(251, 255), (0, 5)]);
        assert_eq!(V::new(250, 260, 8).signed(), [(-6, 4)]);
        assert!(V::new(0, 256, 8).is_full());
        assert_eq!(V::new(-3, -1, 8).join(V::new(0, 2, 8)).range(true), (-3, 2));
        assert_eq!(V::new(253, 255, 8).join(V::new(0, 2, 8)).range(true), (-3, 2));
    }

    #[test]
    fn operations_bound_what_the_simulator_computes() {
        let (a, b) = (V::new(-2048, 2047, 12), V::new(3, 3, 12));
        assert_eq!(binary(a, &VerilogOp::Add, b).range(true), (-2048, 2047)); // it can wrap: every pattern
        assert_eq!(binary(V::new(-2000, 2000, 12), &VerilogOp::Add, b).range(true), (-1997, 2003));
        let mag = V::new(0, 2048, 16);
        assert_eq!(binary(mag, &VerilogOp::Mul, mag).range(false), (0, 2048 * 2048));
        assert_eq!(
            binary(V::new(-4, 4, 8), &VerilogOp::Shr, V { lit: true, ..V::exact(1, 32) }).range(false),
            (0, 127)
        );
        // a shift by a variable amount: 1 << (0..7) is 1..128; 1000 >> (1..3) is 125..500
        assert_eq!(binary(V::new(1, 1, 32), &VerilogOp::Shl, V::new(0, 7, 5)).range(false), (1, 128));
        assert_eq!(binary(V::new(1000, 1000, 16), &VerilogOp::Shr, V::new(1, 3, 4)).range(false), (125, 500));
        assert!(binary(V::new(1, 3, 8), &VerilogOp::Shl, V::new(0, 7, 3)).is_full());
        // sign extension of a negative S8 into 9 bits: −128..−1 exactly
        assert_eq!(
            binary(V::new(128, 255, 9), &VerilogOp::BitOr, V { lit: true, ..V::exact(0x100, 32) }).range(true),
            (-128, -1)
        );
        assert_eq!(
            binary(V::new(0, 256, 9), &VerilogOp::BitOr, V { lit: true, ..V::exact(0x100, 32) }).range(false),
            (256, 511)
        );
        assert_eq!(
            binary(V::new(0, 1023, 15), &VerilogOp::Gt, V { lit: true, ..V::exact(1023, 32) }).unsigned(),
            [(0, 0)]
        );
        assert_eq!(
            binary(V::new(0, 1024, 15), &VerilogOp::Gt, V { lit: true, ..V::exact(1023, 32) }).unsigned(),
            [(0, 1)]
        );
    }

    #[test]
    fn hdl_names_become_the_probe_s() {
        let l = [("i".to_string(), 2)];
        assert_eq!(full_name("uut.d", "line[i-1]$q", &l), "uut.d.line$1.q");
        assert_eq!(full_name("uut", "s1_nm[i]$d$next", &l), "uut.s1_nm$2.d");
        assert_eq!(full_name("uut", "unit$0$out", &[]), "uut.unit$0.out");
        assert_eq!(full_name("uut", "line[0]$q", &[]), "uut.line$0.q");
        assert_eq!(full_name("uut", "s1_t[4 * i + 3]$q", &l), "uut.s1_t$11.q");
        assert_eq!(full_name("uut", "s1_t[4*i+1]$q", &l), "uut.s1_t$9.q");
    }

    #[test]
    fn the_literals_read_as_rust_hdl_prints_them() {
        assert_eq!(literal("12'h7ff"), Some((2047, 12)));
        assert_eq!(literal("5'b10011"), Some((19, 5)));
        assert_eq!(literal("32'h0"), Some((0, 32)));
    }
}
