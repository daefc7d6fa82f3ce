//! cart_pipeline_matte and cart_pipeline_hemi_oct_matte: the per-vertex-light pipelines without a gloss unit (a
//! material with C = 0), each against its model, three ways, and the hard cases without C.
use rtl::cart_pipeline::{CartPipelineHemiOctMatte, CartPipelineMatte};
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::cart_pipeline::{
    exact_trace, exact_trace_with, with_zero_conc, Decode, MODEL_HEMI_OCT_MATTE, MODEL_MATTE,
};

unit_tests!(cart_pipeline_matte, CartPipelineMatte, MODEL_MATTE);
unit_tests!(cart_pipeline_hemi_oct_matte, CartPipelineHemiOctMatte, MODEL_HEMI_OCT_MATTE);

#[test]
fn random_vs_model_with_bubbles() {
    random_vs_model::<CartPipelineMatte>(&MODEL_MATTE, 16, 500);
    random_vs_model::<CartPipelineHemiOctMatte>(&MODEL_HEMI_OCT_MATTE, 17, 500);
}

#[test]
fn random_vs_model_verilator_both() {
    random_vs_model_verilator::<CartPipelineMatte>(&MODEL_MATTE, 50_000, 23);
    random_vs_model_verilator::<CartPipelineHemiOctMatte>(&MODEL_HEMI_OCT_MATTE, 50_000, 24);
}

#[test]
fn hard_cases() {
    let h = (MODEL_MATTE.hard_cases)();
    rust_hdl::<CartPipelineMatte>(&MODEL_MATTE, &h, Bubbles::Random { one_in: 2, seed: 5 }).assert_clean("hard cases");
    let tr = |k: usize| exact_trace(&with_zero_conc(&h[k]));
    // pole lit from straight above: P = X = 1023; on and below the horizon: 0
    assert_eq!(tr(0).p, 1023);
    assert_eq!((tr(1).p, tr(2).p), (0, 0));
    // texel 255 guarded; opposite vertex lights through zero length give no light
    assert_eq!(tr(3).bump, [127, 1, 127]);
    let z =
        h.iter().map(|v| exact_trace(&with_zero_conc(v))).find(|t| t.light == [0, 0, 0]).expect("a zero-length light");
    assert_eq!((z.light_n, z.p), ([0, 0, 0], 0));
    let h = (MODEL_HEMI_OCT_MATTE.hard_cases)();
    rust_hdl::<CartPipelineHemiOctMatte>(&MODEL_HEMI_OCT_MATTE, &h, Bubbles::Random { one_in: 2, seed: 6 })
        .assert_clean("hard cases");
    // the hemi-octahedral square's corner (0, 0) is (−1, 0, 0) on the horizon
    assert!(h.iter().any(|v| exact_trace_with(Decode::HemiOct, &with_zero_conc(v)).bump == [-255, 0, 0]));
}
