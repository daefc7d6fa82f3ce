//! texture_filter: one set of four bilinear units in both modes; random vectors through rust-hdl and Verilator,
//! hard cases (every window offset, flat and steepest blocks, the factors' ends), and the two modes against the
//! colour filter and the height pipeline.
use rtl::texture_filter::TextureFilter;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::texture_filter::MODEL;

unit_tests!(texture_filter, TextureFilter, MODEL);

#[test]
fn texture_filter_random_vs_model() {
    random_vs_model::<TextureFilter>(&MODEL, 20, 1_000);
}

#[test]
fn texture_filter_random_vs_model_verilator() {
    random_vs_model_verilator::<TextureFilter>(&MODEL, 100_000, 17);
}

#[test]
fn texture_filter_hard_cases() {
    rust_hdl::<TextureFilter>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    // a flat block in height mode: exactly straight up, at every window offset
    for (ox, oy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
        let out = (MODEL.exact)(&[vec![90; 16], vec![77, 200, 1, ox, oy, 16]].concat());
        assert_eq!(out[4..], [0, 1024, 0]);
    }
}
