//! This is the bumprtl tool crate: the only one that runs external EDA tools. It exports each rtl block's Verilog
//! (with a self-checking Verilog testbench of the unit's vectors, when asked), lints it with Verilator,
//! co-simulates it under Verilator and Icarus on the same vectors as the model, and synthesises and places it for
//! the iCE40 UP5K and the ECP5 25F / 45F / 85F with yosys and nextpnr.

pub mod axis_bench;
pub mod cache;
pub mod cosim;
pub mod export;
pub mod fpga;
pub mod lint;
pub mod package;
pub mod regpack;
pub mod selfcheck;
pub mod softsplit;
pub mod tools;
pub mod unit;

pub use export::{export, export_axis, Exported};
pub use unit::Unit;
