//! A pipeline's rtl block behind a trait object: the paths that need its type (rust-hdl, Verilator, the VCD, the
//! Verilog, synthesis), so that the table of pipelines (`crate::pipelines`) can name each block as a value.

use crate::prepared::Prepared;
use crate::render::{self, Image, VerilatorRun};
use rtl::StreamUnit;
use std::marker::PhantomData;
use std::path::Path;
use synth::fpga::{Fit, Part};
use vectors::UnitModel;

/// What a pipeline's rtl block does in the paths that need its type; `Rtl::<U>::PATHS` is one.
pub trait RtlPaths: Sync {
    fn name(&self) -> &'static str;
    fn latency(&self) -> usize;
    fn rust_hdl(&self, m: &UnitModel, p: &Prepared, tick: &dyn Fn(usize)) -> Image;
    fn verilator(&self, m: &UnitModel, p: &Prepared, dir: &Path, threads: usize) -> Result<VerilatorRun, String>;
    fn write_vcd(&self, m: &UnitModel, inputs: &[Vec<i64>], path: &Path) -> Result<(), String>;
    /// The prepared vectors through rust-hdl with every signal traced to `path`: the outputs past the prologue.
    fn traced(&self, m: &UnitModel, p: &Prepared, path: &Path) -> Result<Vec<Vec<i64>>, String>;
    fn export(&self, dir: &Path) -> Result<(), String>;
    /// The exported module's text.
    fn verilog(&self) -> String;
    fn measure(&self, dir: &Path, parts: &[Part], say: &dyn Fn(String)) -> Result<Vec<(Part, Fit)>, String>;
}

/// The paths of the rtl block `U`.
pub struct Rtl<U>(PhantomData<fn() -> U>);

impl<U: StreamUnit + Send + 'static> Rtl<U> {
    pub const PATHS: Rtl<U> = Rtl(PhantomData);
}

impl<U: StreamUnit + Send + 'static> RtlPaths for Rtl<U> {
    fn name(&self) -> &'static str {
        U::NAME
    }
    fn latency(&self) -> usize {
        U::LATENCY
    }
    fn rust_hdl(&self, m: &UnitModel, p: &Prepared, tick: &dyn Fn(usize)) -> Image {
        render::rust_hdl::<U>(m, p, tick)
    }
    fn verilator(&self, m: &UnitModel, p: &Prepared, dir: &Path, threads: usize) -> Result<VerilatorRun, String> {
        render::verilator::<U>(m, p, dir, threads)
    }
    fn write_vcd(&self, m: &UnitModel, inputs: &[Vec<i64>], path: &Path) -> Result<(), String> {
        crate::wave::write_vcd::<U>(m, inputs, path).map(|_| ())
    }
    fn traced(&self, m: &UnitModel, p: &Prepared, path: &Path) -> Result<Vec<Vec<i64>>, String> {
        let got = crate::wave::write_vcd::<U>(m, &p.inputs, path)?;
        Ok(got[p.prologue.min(got.len())..].iter().map(|o| vectors::unit::from_patterns(o, m.outputs)).collect())
    }
    fn export(&self, dir: &Path) -> Result<(), String> {
        synth::export::<U>().write(dir).map(|_| ())
    }
    fn verilog(&self) -> String {
        synth::export::<U>().text
    }
    fn measure(&self, dir: &Path, parts: &[Part], say: &dyn Fn(String)) -> Result<Vec<(Part, Fit)>, String> {
        synth::fpga::measure::<U>(dir, parts, say)
    }
}
