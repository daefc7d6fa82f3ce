//! power: all 2^16 (x, p) pairs three ways.
use rtl::power::Power;
use synth::cosim::Simulator;
use testbench::{external, rust_hdl, unit_tests, Bubbles};
use vectors::power::MODEL;

unit_tests!(power, Power, MODEL);

fn all() -> Vec<Vec<i64>> {
    (MODEL.exhaustive.unwrap())()
}

#[test]
fn power_exhaustive_rust_hdl() {
    rust_hdl::<Power>(&MODEL, &all(), Bubbles::Random { one_in: 7, seed: 5 }).assert_clean("rust-hdl, all 2^16 pairs");
}

#[test]
fn power_exhaustive_verilator() {
    external::<Power>(Simulator::Verilator, &MODEL, &all(), Bubbles::BackToBack).assert_clean("verilator, all 2^16 pairs");
}

#[test]
fn power_exhaustive_icarus() {
    external::<Power>(Simulator::Icarus, &MODEL, &all(), Bubbles::BackToBack).assert_clean("icarus, all 2^16 pairs");
}
