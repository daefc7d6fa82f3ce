//! An rtl block behind a trait object: everything that needs the block's type (rust-hdl, Verilator, the VCD, the
//! Verilog, yosys and nextpnr, the width analysis), so that the tables of units and pipelines (`crate::units`,
//! `crate::pipelines`) can name each block as a value, and the code that reads them needs no type parameter.
//!
//! Two levels, so that a block is compiled for no more than its row needs: `RtlBlock` is what a swept setting of a
//! unit's width parameters is read through (its Verilog, its cells, its widths); `RtlPaths` adds what a unit of the
//! table is run through (its waveform, its self-checking export, placement, rendering). `Rtl::<U>::PATHS` is both.

use crate::prepared::Prepared;
use crate::render::{self, Image, VerilatorRun};
use rtl::axis::AxisBlock;
use rtl::StreamUnit;
use std::marker::PhantomData;
use std::path::{Path, PathBuf};
use synth::fpga::{Blocks, Cells, Family, Fit, Part, Seeds, SynthReport};
use vectors::UnitModel;

/// A block as its Verilog, its cells and its widths.
pub trait RtlBlock: Sync {
    fn name(&self) -> &'static str;
    fn latency(&self) -> usize;
    /// Clocks a vector (`StreamUnit::INTERVAL`).
    fn interval(&self) -> usize;
    /// The exported module's text.
    fn verilog(&self) -> String;
    /// The module written to `dir/<name>.v`: that path.
    fn export(&self, dir: &Path) -> Result<PathBuf, String>;
    /// Its yosys cells in `family` (cached).
    fn synth_unit(&self, dir: &Path, family: Family) -> Result<Cells, String>;
    /// Every signal's declared format and its range proven over `m`'s input ports (no simulation).
    fn analyse(&self, m: &UnitModel) -> widths::Analysis;
    /// `inputs` through rust-hdl, every signal probed every clock; `tick` gets the vectors done.
    fn seen(&self, m: &UnitModel, inputs: &[Vec<i64>], tick: &dyn Fn(usize)) -> widths::Ranges;
    /// The exported Verilog with the width report's claims as assertions for a solver (`widths::formal`).
    fn harness(&self, r: &widths::formal::Request) -> Result<widths::formal::Harness, String>;
}

/// A unit's block as every path runs it.
pub trait RtlPaths: RtlBlock {
    /// The signals the block's Verilog leaves unused on purpose (`rtl::StreamUnit::waivers`).
    fn waivers(&self) -> Vec<rtl::stream::Waiver>;
    fn rust_hdl(&self, m: &UnitModel, p: &Prepared, tick: &dyn Fn(usize)) -> Image;
    fn verilator(&self, m: &UnitModel, p: &Prepared, dir: &Path, threads: usize) -> Result<VerilatorRun, String>;
    /// The outputs of `inputs` through rust-hdl, back to back, as values.
    fn outputs(&self, m: &UnitModel, inputs: &[Vec<i64>]) -> Vec<Vec<i64>>;
    fn write_vcd(&self, m: &UnitModel, inputs: &[Vec<i64>], path: &Path) -> Result<(), String>;
    /// The VCD of `inputs` into any writer (standard output, say); Err when a write failed.
    fn trace(&self, m: &UnitModel, inputs: &[Vec<i64>], w: Box<dyn std::io::Write>) -> std::io::Result<()>;
    /// The prepared vectors through rust-hdl with every signal traced to `path`: the outputs past the prologue.
    fn traced(&self, m: &UnitModel, p: &Prepared, path: &Path) -> Result<Vec<Vec<i64>>, String>;
    /// A self-checking testbench of these bit patterns beside the module in `dir`: the files written.
    fn selfcheck(&self, dir: &Path, ins: &[Vec<u64>], outs: &[Vec<u64>], source: &str) -> Result<Vec<PathBuf>, String>;
    /// Cells and, for each part that holds them, placement and timing.
    fn measure(
        &self,
        dir: &Path,
        parts: &[Part],
        seeds: Seeds,
        say: &dyn Fn(String),
    ) -> Result<Vec<(Part, Fit)>, String>;
    /// The part it is placed on when the user names none, its cells there, and why each smaller part was passed over.
    fn choose(&self, dir: &Path) -> Result<(Part, Cells, String), String>;
    /// Placed on `part` at each of `seeds`, each placement cached: the median placement's report.
    fn synth_and_place(
        &self,
        dir: &Path,
        part: Part,
        freq: f64,
        choice: &str,
        seeds: Seeds,
    ) -> Result<SynthReport, String>;
    /// Its cells with some inputs tied to constants (a mode's view of the block).
    fn synth_tied(
        &self,
        dir: &Path,
        family: Family,
        tag: &str,
        ties: &[(&str, u64)],
        keep: &[&str],
    ) -> Result<(Cells, Blocks), String>;
}

/// A unit behind its AXI4-Stream wrapper (`rtl::axis`): the module `<unit>_axis` and its self-checking bench.
pub trait AxisPaths: Sync {
    /// The exported module's name, `<unit>_axis`.
    fn module(&self) -> String;
    /// The exported module's text.
    fn verilog(&self) -> String;
    /// `dir/<unit>_axis.v` and `dir/<unit>_axis_tb.v` (which reads the unit's `<unit>_in.hex` and `<unit>_out.hex`,
    /// written beside it by `RtlPaths::selfcheck`), for `n` vectors from `source`: the paths written.
    fn selfcheck(&self, dir: &Path, n: usize, source: &str) -> Result<Vec<PathBuf>, String>;
    /// `dir/<unit>_io.v`, `<unit>.core`, `test_<unit>.py` and the `Makefile` (`synth::package`): `waivers`, whether
    /// `<unit>.vlt` is beside them; `scratch`, a folder for yosys's files of the fit check. The paths written, and
    /// why the core has no `synth` target when it has none.
    fn package(&self, dir: &Path, waivers: bool, scratch: &Path) -> Result<(Vec<PathBuf>, Option<String>), String>;
    /// Whether an input row (the unit's input values) gives an output beat: a map write gives none.
    fn emits(&self, row: &[u64]) -> bool;
    /// The output FIFO: its places (`rtl::axis::depth`), the RAM's words (2^A) and the word's bits (TDATA's).
    fn fifo(&self) -> (usize, usize, usize);
    /// What the wrapper adds to the unit (its control and output FIFO) in `family`'s cells, from yosys (cached);
    /// `dir` holds yosys's files.
    fn ctl_cells(&self, dir: &Path, family: Family) -> Result<Cells, String>;
}

/// The AXI4-Stream paths of a wrapper type (`rtl::axis_of!` and `rtl::axis_map_of!` work out its widths: see
/// `units`).
pub struct AxisRtl<W>(PhantomData<fn() -> W>);

impl<W: AxisBlock> AxisRtl<W> {
    pub const PATHS: AxisRtl<W> = AxisRtl(PhantomData);
}

impl<W: AxisBlock> AxisPaths for AxisRtl<W> {
    fn module(&self) -> String {
        W::name()
    }
    fn verilog(&self) -> String {
        synth::export_axis::<W>().text
    }
    fn selfcheck(&self, dir: &Path, n: usize, source: &str) -> Result<Vec<PathBuf>, String> {
        let v = synth::export_axis::<W>().write(dir)?;
        let tb = dir.join(format!("{}_tb.v", self.module()));
        synth::export::write_atomic(
            &tb,
            synth::axis_bench::bench(&synth::Unit::of::<W::Unit>(), n, source).as_bytes(),
        )?;
        Ok(vec![v, tb])
    }
    fn package(&self, dir: &Path, waivers: bool, scratch: &Path) -> Result<(Vec<PathBuf>, Option<String>), String> {
        let unit = synth::Unit::of::<W::Unit>();
        let target = synth::package::synth_target(&unit, scratch);
        let none = target.as_ref().err().cloned();
        Ok((synth::package::write(&unit, dir, waivers, target)?, none))
    }
    fn emits(&self, row: &[u64]) -> bool {
        W::emits(row)
    }
    fn fifo(&self) -> (usize, usize, usize) {
        W::fifo()
    }
    fn ctl_cells(&self, dir: &Path, family: Family) -> Result<Cells, String> {
        synth::fpga::synth_axis_ctl::<W>(dir, family)
    }
}

/// The paths of the rtl block `U`.
pub struct Rtl<U>(PhantomData<fn() -> U>);

impl<U: StreamUnit + Send + 'static> Rtl<U> {
    pub const PATHS: Rtl<U> = Rtl(PhantomData);
}

impl<U: StreamUnit + Send + 'static> RtlBlock for Rtl<U> {
    fn name(&self) -> &'static str {
        U::NAME
    }
    fn latency(&self) -> usize {
        U::LATENCY
    }
    fn interval(&self) -> usize {
        U::INTERVAL
    }
    fn verilog(&self) -> String {
        synth::export::<U>().text
    }
    fn export(&self, dir: &Path) -> Result<PathBuf, String> {
        synth::export::<U>().write(dir)
    }
    fn synth_unit(&self, dir: &Path, family: Family) -> Result<Cells, String> {
        synth::fpga::synth_unit(&synth::Unit::of::<U>(), dir, family)
    }
    fn analyse(&self, m: &UnitModel) -> widths::Analysis {
        widths::analyse::<U>(m)
    }
    fn seen(&self, m: &UnitModel, inputs: &[Vec<i64>], tick: &dyn Fn(usize)) -> widths::Ranges {
        widths::seen_ticking::<U>(m, inputs, tick)
    }
    fn harness(&self, r: &widths::formal::Request) -> Result<widths::formal::Harness, String> {
        widths::formal::harness(&U::build(), r)
    }
}

impl<U: StreamUnit + Send + 'static> RtlPaths for Rtl<U> {
    fn waivers(&self) -> Vec<rtl::stream::Waiver> {
        U::waivers()
    }
    fn rust_hdl(&self, m: &UnitModel, p: &Prepared, tick: &dyn Fn(usize)) -> Image {
        render::rust_hdl::<U>(m, p, tick)
    }
    fn verilator(&self, m: &UnitModel, p: &Prepared, dir: &Path, threads: usize) -> Result<VerilatorRun, String> {
        render::verilator::<U>(m, p, dir, threads)
    }
    fn outputs(&self, m: &UnitModel, inputs: &[Vec<i64>]) -> Vec<Vec<i64>> {
        let mut r = rtl::stream::Runner::<U>::new();
        let got = r.run(rtl::stream::paced::<U>(inputs.iter().map(|v| vectors::unit::to_patterns(v, m.inputs))));
        got.outputs.iter().map(|o| vectors::unit::from_patterns(o, m.outputs)).collect()
    }
    fn write_vcd(&self, m: &UnitModel, inputs: &[Vec<i64>], path: &Path) -> Result<(), String> {
        crate::wave::write_vcd::<U>(m, inputs, path).map(|_| ())
    }
    fn trace(&self, m: &UnitModel, inputs: &[Vec<i64>], w: Box<dyn std::io::Write>) -> std::io::Result<()> {
        crate::wave::trace::<U>(m, inputs, w).map(|_| ())
    }
    fn traced(&self, m: &UnitModel, p: &Prepared, path: &Path) -> Result<Vec<Vec<i64>>, String> {
        let got = crate::wave::write_vcd::<U>(m, &p.inputs, path)?;
        Ok(got[p.prologue.min(got.len())..].iter().map(|o| vectors::unit::from_patterns(o, m.outputs)).collect())
    }
    fn selfcheck(&self, dir: &Path, ins: &[Vec<u64>], outs: &[Vec<u64>], source: &str) -> Result<Vec<PathBuf>, String> {
        let mut written = vec![self.export(dir)?];
        written.extend(synth::selfcheck::write(&synth::Unit::of::<U>(), dir, ins, outs, source)?);
        Ok(written)
    }
    fn measure(
        &self,
        dir: &Path,
        parts: &[Part],
        seeds: Seeds,
        say: &dyn Fn(String),
    ) -> Result<Vec<(Part, Fit)>, String> {
        synth::fpga::measure(&synth::Unit::of::<U>(), dir, parts, seeds, say)
    }
    fn choose(&self, dir: &Path) -> Result<(Part, Cells, String), String> {
        synth::fpga::choose(&synth::Unit::of::<U>(), dir)
    }
    fn synth_and_place(
        &self,
        dir: &Path,
        part: Part,
        freq: f64,
        choice: &str,
        seeds: Seeds,
    ) -> Result<SynthReport, String> {
        synth::fpga::synth_and_place(&synth::Unit::of::<U>(), dir, part, freq, choice, seeds)
    }
    fn synth_tied(
        &self,
        dir: &Path,
        family: Family,
        tag: &str,
        ties: &[(&str, u64)],
        keep: &[&str],
    ) -> Result<(Cells, Blocks), String> {
        synth::fpga::synth_tied(&synth::Unit::of::<U>(), dir, family, tag, ties, keep)
    }
}
