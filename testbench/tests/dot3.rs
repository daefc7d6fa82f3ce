//! dot3: at least 100,000 proptest-driven vectors through rust-hdl, 100,000 under Verilator, hard cases.
use rtl::dot3::Dot3;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::dot3::MODEL;

unit_tests!(dot3, Dot3, MODEL);

#[test]
fn dot3_random_vs_model() {
    random_vs_model::<Dot3>(&MODEL, 50, 2_000);
}

#[test]
fn dot3_random_vs_model_verilator() {
    random_vs_model_verilator::<Dot3>(&MODEL, 100_000, 11);
}

#[test]
fn dot3_hard_cases() {
    rust_hdl::<Dot3>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    let e = |v: &[i64]| (MODEL.exact)(v);
    // N = L = 1.0: 1024 reads as the seed's 1.0, 1023
    assert_eq!(e(&[0, 1024, 0, 0, 1024, 0]), vec![1023]);
    // light on the normal's horizon and below it: 0
    assert_eq!(e(&[1024, 0, 0, 0, 1024, 0]), vec![0]);
    assert_eq!(e(&[0, 1024, 0, 0, -1024, 0]), vec![0]);
    // the most negative S12 everywhere: 3·2048² = 12,582,912 >> 10 = 12,288 → saturated to 1023
    assert_eq!(e(&[-2048, -2048, -2048, -2048, -2048, -2048]), vec![1023]);
    // floor, not round: 1·1023 = 1023 < 1024 → 0; 1·1024 → 1
    assert_eq!(e(&[1, 0, 0, 1023, 0, 0]), vec![0]);
    assert_eq!(e(&[1, 0, 0, 1024, 0, 0]), vec![1]);
}
