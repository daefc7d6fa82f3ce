//! replicate: random windows through rust-hdl and Verilator, hard cases (every position distinct).
use rtl::replicate::Replicate;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::replicate::MODEL;

unit_tests!(replicate, Replicate, MODEL);

#[test]
fn replicate_random_vs_model() {
    random_vs_model::<Replicate>(&MODEL, 20, 1_000);
}

#[test]
fn replicate_random_vs_model_verilator() {
    random_vs_model_verilator::<Replicate>(&MODEL, 100_000, 12);
}

#[test]
fn replicate_hard_cases() {
    rust_hdl::<Replicate>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    // a b c / d e f / g h k = 1..9: red [1 2; 4 5], green [2 3; 5 6], blue [4 5; 7 8], alpha [5 6; 8 9]
    let out = (MODEL.exact)(&(1..=9).collect::<Vec<i64>>());
    assert_eq!(out, vec![1, 2, 4, 5, 2, 3, 5, 6, 4, 5, 7, 8, 5, 6, 8, 9]);
}
