//! This is the bumprtl tool crate: the only one that runs external EDA tools. It exports each rtl block's Verilog,
//! lints it with Verilator, co-simulates it under Verilator and Icarus on the same vectors as the model, and
//! synthesises it for iCE40 UP5K with yosys and nextpnr-ice40.

pub mod cosim;
pub mod export;
pub mod ice40;
pub mod lint;
pub mod tools;

pub use export::{export, Exported};
