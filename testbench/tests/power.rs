//! power: all 2^16 (x, p) pairs three ways.
use rtl::power::Power;
use testbench::unit_tests;
use vectors::power::MODEL;

unit_tests!(power, Power, MODEL, exhaustive: [rust_hdl, verilator, icarus] with Bubbles::Random { one_in: 7, seed: 5 });

