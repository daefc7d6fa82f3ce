//! blend: at least 100,000 proptest-driven vectors through rust-hdl, 100,000 under Verilator, hard cases.
use rtl::blend::Blend;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::blend::MODEL;

unit_tests!(blend, Blend, MODEL);

#[test]
fn blend_random_vs_model() {
    random_vs_model::<Blend>(&MODEL, 50, 2_000);
}

#[test]
fn blend_random_vs_model_verilator() {
    random_vs_model_verilator::<Blend>(&MODEL, 100_000, 11);
}

#[test]
fn blend_hard_cases() {
    rust_hdl::<Blend>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    let e = |v: &[i64]| (MODEL.exact)(v);
    // α = 0 and 255 in both modes; src 255 · α 128 / 255 = 128.0 → 128
    assert_eq!(e(&[0, 0, 255, 128, 1, 9, 9, 9]), vec![0, 0, 0]);
    assert_eq!(e(&[255, 0, 255, 128, 1, 9, 9, 9]), vec![255, 128, 1]);
    assert_eq!(e(&[0, 1, 255, 128, 1, 9, 200, 255]), vec![9, 200, 255]);
    assert_eq!(e(&[128, 0, 255, 0, 0, 0, 0, 0]), vec![128, 0, 0]);
    // 127·255/255 exact; 1·1/255 = 0.004 → 0
    assert_eq!(e(&[255, 1, 127, 1, 0, 0, 0, 0]), vec![127, 1, 0]);
}
