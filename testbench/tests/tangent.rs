//! tangent: random vectors through rust-hdl and Verilator, hard cases (the steepest differences, the factors' ends).
use rtl::tangent::Tangent;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::tangent::MODEL;

unit_tests!(tangent, Tangent, MODEL);

#[test]
fn tangent_random_vs_model() {
    random_vs_model::<Tangent>(&MODEL, 50, 2_000);
}

#[test]
fn tangent_random_vs_model_verilator() {
    random_vs_model_verilator::<Tangent>(&MODEL, 100_000, 14);
}

#[test]
fn tangent_hard_cases() {
    rust_hdl::<Tangent>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    // equal results give zero tangents; G − R of one full 12-bit step at V = 0 is that step
    assert_eq!((MODEL.exact)(&[7 << 17, 7 << 17, 7 << 17, 7 << 17, 200, 100]), vec![0, 0]);
    assert_eq!((MODEL.exact)(&[0, 1 << 5, 0, 0, 0, 0]), vec![1, 0]);
    // one LSB below the step truncates away
    assert_eq!((MODEL.exact)(&[0, (1 << 5) - 1, 0, 0, 0, 0]), vec![0, 0]);
}
