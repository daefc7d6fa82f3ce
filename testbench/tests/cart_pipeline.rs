//! cart_pipeline: the composed units, against the composed model, three ways.
use rtl::cart_pipeline::CartPipeline;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::cart_pipeline::{exact_trace, MODEL};

unit_tests!(cart_pipeline, CartPipeline, MODEL);

#[test]
fn cart_pipeline_random_vs_model() {
    random_vs_model::<CartPipeline>(&MODEL, 10, 1_000);
}

#[test]
fn cart_pipeline_random_vs_model_verilator() {
    random_vs_model_verilator::<CartPipeline>(&MODEL, 100_000, 21);
}

#[test]
fn cart_pipeline_hard_cases() {
    let h = (MODEL.hard_cases)();
    rust_hdl::<CartPipeline>(&MODEL, &h, Bubbles::Random { one_in: 2, seed: 5 }).assert_clean("hard cases");
    // pole lit from straight above, C = 0: the decoded (0, 255, 0) and the light (0, 127·4, 0) normalise to
    // (0, 1024, 0) each, the dot reads 1023 and P = X = 1023
    assert_eq!(exact_trace(&h[0]).p, 1023);
    // the light on the horizon of an untilted bump: 0; below the horizon: 0
    assert_eq!(exact_trace(&h[1]).p, 0);
    assert_eq!(exact_trace(&h[2]).p, 0);
    // texel 255 is guarded to a legal vector on the diamond's edge
    assert_eq!(exact_trace(&h[3]).bump, [127, 1, 127]);
    // opposite vertex lights through zero length: the normaliser's zero, so no light
    let t = exact_trace(&h[5]);
    assert_eq!((t.light, t.light_n, t.p), ([0, 0, 0], [0, 0, 0], 0));
}
