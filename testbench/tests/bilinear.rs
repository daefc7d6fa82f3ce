//! bilinear: at least 100,000 proptest-driven vectors through rust-hdl, 100,000 under Verilator, hard cases.
use rtl::bilinear::Bilinear;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::bilinear::MODEL;

unit_tests!(bilinear, Bilinear, MODEL);

#[test]
fn bilinear_random_vs_model() {
    random_vs_model::<Bilinear>(&MODEL, 50, 2_000);
}

#[test]
fn bilinear_random_vs_model_verilator() {
    random_vs_model_verilator::<Bilinear>(&MODEL, 100_000, 11);
}

#[test]
fn bilinear_hard_cases() {
    rust_hdl::<Bilinear>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    let e = |v: &[i64]| (MODEL.exact)(v);
    // u = v = 0 returns t00 exactly; the largest factors (255/256) stay within the four texels
    assert_eq!(e(&[vec![7, 8, 9, 10], vec![255; 12], vec![0, 0]].concat()), vec![7, 8, 9, 10]);
    assert_eq!(e(&[vec![255; 16], vec![255, 255]].concat()), vec![255; 4]);
    // half-way between 0 and 1 rounds up
    assert_eq!(e(&[vec![0; 4], vec![1; 4], vec![0; 4], vec![1; 4], vec![128, 0]].concat()), vec![1; 4]);
    // 0 → 255 at u = 255/256: 254.0 exactly
    assert_eq!(e(&[vec![0; 4], vec![255; 4], vec![0; 4], vec![255; 4], vec![255, 0]].concat()), vec![254; 4]);
}
