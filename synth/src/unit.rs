//! A unit as this crate's exporters, harnesses, benches and synthesis flows read it, without its block's type.

use crate::export::Exported;
use rtl::stream::Waiver;
use rtl::StreamUnit;

/// What `rtl::StreamUnit` says of a unit (its name, latency, ports, map port, interval and waivers) and its Verilog,
/// as values. The functions here that write a harness, a bench or a core, or run yosys and nextpnr, take it rather
/// than being generic over the block: a generic one is compiled again for each of the 109 units in every crate that
/// names them (they were half of the code of `sim`'s library, the longest compile of the test command).
#[derive(Clone, Copy)]
pub struct Unit {
    pub name: &'static str,
    pub latency: usize,
    pub inputs: &'static [(&'static str, usize)],
    pub outputs: &'static [(&'static str, usize)],
    pub map: &'static [&'static str],
    pub interval: usize,
    waivers: fn() -> Vec<Waiver>,
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
            waivers: U::waivers,
            export: crate::export::export::<U>,
        }
    }

    /// The signals its Verilog leaves unused on purpose (`StreamUnit::waivers`).
    pub fn waivers(&self) -> Vec<Waiver> {
        (self.waivers)()
    }

    /// Its Verilog, made now: rust-hdl's, the top module named after the unit (`export::export`).
    pub fn export(&self) -> Exported {
        (self.export)()
    }
}
