//! cart_pipeline_hemi_oct: the Cartesian pipeline around the hemi-octahedral decode, against its model, three ways.
use rtl::cart_pipeline::CartPipelineHemiOct;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::cart_pipeline::{exact_trace_with, Decode, MODEL_HEMI_OCT};

unit_tests!(cart_pipeline_hemi_oct, CartPipelineHemiOct, MODEL_HEMI_OCT);

#[test]
fn cart_pipeline_hemi_oct_random_vs_model() {
    random_vs_model::<CartPipelineHemiOct>(&MODEL_HEMI_OCT, 10, 1_000);
}

#[test]
fn cart_pipeline_hemi_oct_random_vs_model_verilator() {
    random_vs_model_verilator::<CartPipelineHemiOct>(&MODEL_HEMI_OCT, 100_000, 22);
}

#[test]
fn cart_pipeline_hemi_oct_hard_cases() {
    let h = (MODEL_HEMI_OCT.hard_cases)();
    rust_hdl::<CartPipelineHemiOct>(&MODEL_HEMI_OCT, &h, Bubbles::Random { one_in: 2, seed: 5 })
        .assert_clean("hard cases");
    let tr = |k: usize| exact_trace_with(Decode::HemiOct, &h[k]);
    let n = h.len();
    // the square's corner (0, 0) is (−1, 0, 0) on the horizon: lit along itself it is full, lit from above it is dark
    assert_eq!(tr(n - 4).bump, [-255, 0, 0]);
    assert!(tr(n - 4).x >= 1020, "{:?}", tr(n - 4));
    assert_eq!(tr(n - 2).x, 0);
    // (255, 0) is (0, 0, +1); a light below the horizon gives nothing
    assert_eq!(tr(n - 3).bump, [0, 0, 255]);
    assert_eq!(tr(n - 1).x, 0);
}
