//! A unit as this crate's exporters, harnesses, benches and synthesis flows read it, without its block's type.

use crate::export::Exported;
use rtl::StreamUnit;

/// What `rtl::StreamUnit` says of a unit (its name, latency, ports, map port and interval) and its Verilog, as
/// values. This crate's functions that write a harness, a bench or a core, or run yosys and nextpnr, take it rather
/// than being generic over the block: a generic one would be compiled again for each unit in every crate that
/// names them.
#[derive(Clone, Copy)]
pub struct Unit {
    pub name: &'static str,
    pub latency: usize,
    pub inputs: &'static [(&'static str, usize)],
    pub outputs: &'static [(&'static str, usize)],
    pub map: &'static [&'static str],
    pub interval: usize,
    export: fn() -> Exported,
}

impl Unit {
    pub fn of<U: StreamUnit>() -> Unit {
        Unit {
            name: U::NAME,
            latency: U::LATENCY,
            inputs: U::INPUTS,
            outputs: U::OUTPUTS,
            map: U::MAP,
            interval: U::INTERVAL,
            export: crate::export::export::<U>,
        }
    }

    /// Its Verilog, made now: rust-hdl's, the top module named after the unit (`export::export`).
    pub fn export(&self) -> Exported {
        (self.export)()
    }
}
