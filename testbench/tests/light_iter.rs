//! light_iter: at least 100,000 proptest-driven vectors through rust-hdl, 100,000 under Verilator, hard cases.
use rtl::light_iter::LightIter;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::light_iter::MODEL;

unit_tests!(light_iter, LightIter, MODEL);

#[test]
fn light_iter_random_vs_model() {
    random_vs_model::<LightIter>(&MODEL, 50, 2_000);
}

#[test]
fn light_iter_random_vs_model_verilator() {
    random_vs_model_verilator::<LightIter>(&MODEL, 100_000, 11);
}

#[test]
fn light_iter_hard_cases() {
    rust_hdl::<LightIter>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    let e = |v: &[i64]| (MODEL.exact)(v);
    // opposite vertex lights through their midpoint: exactly zero length at w1 = 128
    assert_eq!(e(&[127, 0, 0, -127, 0, 0, 127, 0, 0, 128, 0]), vec![0, 0, 0]);
    // the most negative S8 vertex comes back exactly at its own vertex
    assert_eq!(e(&[-128, -128, -128, 127, 127, 127, -128, 127, -128, 0, 0]), vec![-512, -512, -512]);
    assert_eq!(e(&[-128, -128, -128, 127, 127, 127, -128, 127, -128, 256, 0]), vec![508, 508, 508]);
    // weights outside the triangle saturate instead of wrapping
    assert_eq!(e(&[-128, -128, -128, 127, 127, 127, -128, 127, -128, 511, 511]), vec![511, 511, 511]);
    // 120° apart: the midpoint keeps half the length (the seed's 1/2): (110, 63)/(−110, 63) → (0, 63·4)
    assert_eq!(e(&[110, 63, 0, -110, 63, 0, 110, 63, 0, 128, 0]), vec![0, 252, 0]);
}
