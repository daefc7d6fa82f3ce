//! Stages: for each signal of a block, how many clock edges after its pixel entered the unit the value it holds
//! was made from that pixel, so that a report can read a signal only on the clocks where it holds data (the valid
//! flag of its own stage: the unit's `valid_in` that many clocks earlier) and a proof can claim an argued step
//! only there.
//!
//! Read from the same hdl as the interval proof (`bounds::Collect`): a step's target is at the stage of every
//! signal its value and the tests above it read; a register's q is one stage after its d; a RAM's read word one
//! after its read address (a `RamDelay`'s, N − 1 after the word written, its length read from its `ahead`
//! constant); a ROM's word at its address's stage. The input ports are stage 0. A signal whose sources disagree
//! (a loop through a register, a k-clock variant's held operand, a stage that mixes two) is `Mixed`, and a signal
//! no input reaches (a constant, a free-running counter) has no stage: both are read on every clock.

use crate::bounds::{full_name, Code, Collect, Walker};
use rust_hdl::core::ast::{VerilogBlockOrConditional, VerilogExpression as E, VerilogStatement as S};
use rust_hdl::core::block::Block;
use std::collections::HashMap;

/// A signal's stage.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// made from the pixel that entered this many clock edges before
    At(u32),
    /// made from more than one stage
    Mixed,
}

impl Stage {
    fn join(a: Option<Stage>, b: Stage) -> Stage {
        match (a, b) {
            (None, x) => x,
            (Some(Stage::At(x)), Stage::At(y)) if x == y => Stage::At(x),
            _ => Stage::Mixed,
        }
    }
    fn later(self, by: u32) -> Stage {
        match self {
            Stage::At(x) => Stage::At(x + by),
            Stage::Mixed => Stage::Mixed,
        }
    }
}

/// `target` is made from `sources`, `delay` clock edges later.
struct Edge {
    target: String,
    sources: Vec<String>,
    delay: u32,
}

/// Every signal an expression reads, by the probe's names.
fn reads(e: &E, path: &str, loops: &[(String, i128)], out: &mut Vec<String>) {
    match e {
        E::Signal(s) => {
            if !loops.iter().any(|(v, _)| v == s) {
                out.push(full_name(path, s, loops));
            }
        }
        E::Literal(_) => {}
        E::Paren(x) | E::Cast(x, _) | E::Signed(x) | E::Unsigned(x) | E::Unary(_, x) => reads(x, path, loops, out),
        E::Index(a, b) | E::Binary(a, _, b) | E::Slice(a, _, b) => {
            reads(a, path, loops, out);
            reads(b, path, loops, out);
        }
        E::IndexReplace(a, b, c) => {
            reads(a, path, loops, out);
            reads(b, path, loops, out);
            reads(c, path, loops, out);
        }
    }
}

/// One block's statements, path by path as the proof walks them: a later write on a path replaces an earlier one
/// (`dff_setup!` writes each d its q first, then the stage writes it), and after a branch a signal takes the
/// sources of every side that wrote it and of what it held before where a side did not.
struct Walk<'a> {
    path: &'a str,
    loops: Vec<(String, i128)>,
    /// what the enclosing tests read
    tests: Vec<String>,
    /// each signal's sources on this path
    cur: HashMap<String, Vec<String>>,
}

impl Walker for Walk<'_> {
    fn step(&mut self, s: &S) {
        match s {
            S::Assignment(t, v) => self.write(t, &[v]),
            S::SliceAssignment { base, offset, replacement, .. } => self.write(base, &[offset, replacement, base]),
            S::If(c) => {
                let other = |w: &mut Self| match &c.otherwise {
                    VerilogBlockOrConditional::Block(b) => w.block(b),
                    VerilogBlockOrConditional::Conditional(s) => w.step(s),
                    VerilogBlockOrConditional::None => {}
                };
                self.sides(&c.test, vec![&|w: &mut Self| w.block(&c.then), &other]);
            }
            S::Match(m) => {
                let cases: Vec<_> = m.cases.iter().map(|c| move |w: &mut Self| w.block(&c.block)).collect();
                self.sides(&m.test, cases.iter().map(|f| f as &dyn Fn(&mut Self)).collect());
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
    fn write(&mut self, target: &E, values: &[&E]) {
        let E::Signal(t) = target else { return };
        let mut sources = self.tests.clone();
        for v in values {
            reads(v, self.path, &self.loops, &mut sources);
        }
        sources.sort_unstable();
        sources.dedup();
        let target = full_name(self.path, t, &self.loops);
        self.cur.insert(target, sources);
    }
    fn sides(&mut self, test: &E, sides: Vec<&dyn Fn(&mut Self)>) {
        let mark = self.tests.len();
        reads(test, self.path, &self.loops, &mut self.tests);
        let base = self.cur.clone();
        let mut outs: Vec<HashMap<String, Vec<String>>> = vec![];
        for side in sides {
            self.cur = base.clone();
            side(self);
            outs.push(std::mem::take(&mut self.cur));
        }
        let mut merged = base.clone();
        for out in &outs {
            for n in out.keys() {
                // every side's sources for it: what that side wrote, or what the path held before it
                let mut all: Vec<String> =
                    outs.iter().filter_map(|o| o.get(n).or(base.get(n))).flatten().cloned().collect();
                all.sort_unstable();
                all.dedup();
                merged.insert(n.clone(), all);
            }
        }
        self.cur = merged;
        self.tests.truncate(mark);
    }
}

/// Every signal's stage in `block` (probe names, `uut.…`) whose input ports are `inputs`; a signal absent has none.
pub fn stages(block: &dyn Block, inputs: &[&str]) -> HashMap<String, Stage> {
    let mut c = Collect::default();
    block.accept("uut", &mut c);
    let mut edges = vec![];
    for md in &c.modules {
        let p = md.path.as_str();
        match &md.code {
            Code::Comb(b) => {
                let mut w = Walk { path: p, loops: vec![], tests: vec![], cur: HashMap::new() };
                w.block(b);
                edges.extend(w.cur.into_iter().map(|(target, sources)| Edge { target, sources, delay: 0 }));
            }
            Code::Dff => edges.push(Edge { target: format!("{p}.q"), sources: vec![format!("{p}.d")], delay: 1 }),
            Code::Rom(..) => {
                edges.push(Edge { target: format!("{p}.data"), sources: vec![format!("{p}.address")], delay: 0 })
            }
            Code::Ram(_) => {
                let parent = p.rsplit_once('.').map_or("", |x| x.0);
                let ahead = format!("{parent}.ahead");
                let (source, delay) = match (c.consts.get(&ahead), p.ends_with(".ring")) {
                    // a RamDelay: the word read N − 1 edges after it was written
                    (Some(a), true) => {
                        let size = 1i128 << a.bits;
                        (format!("{p}.write_data"), (3 + (size - a.lo).rem_euclid(size) - 1) as u32)
                    }
                    _ if c.widths.contains_key(&format!("{p}.read_address")) => (format!("{p}.read_address"), 1),
                    _ => (format!("{p}.address"), 1),
                };
                edges.push(Edge { target: format!("{p}.read_data"), sources: vec![source], delay });
            }
            Code::Other => {}
        }
    }
    let mut st: HashMap<String, Stage> = HashMap::new();
    for i in inputs.iter().chain(&["valid_in"]) {
        st.insert(format!("uut.{i}"), Stage::At(0));
    }
    // to the least fixed point: a stage only moves up the lattice (none, At, Mixed), so this ends
    loop {
        let mut changed = false;
        for e in &edges {
            let mut v = st.get(&e.target).copied();
            for s in &e.sources {
                if let Some(x) = st.get(s) {
                    v = Some(Stage::join(v, x.later(e.delay)));
                }
            }
            if let Some(v) = v {
                if st.get(&e.target) != Some(&v) {
                    st.insert(e.target.clone(), v);
                    changed = true;
                }
            }
        }
        if !changed {
            return st;
        }
    }
}
