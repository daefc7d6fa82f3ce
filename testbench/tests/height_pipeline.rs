//! height_pipeline: the height path from the 3×3 window to the unit normal, random vectors through rust-hdl and
//! Verilator, hard cases (flat maps, the steepest steps, the largest scale, the factors' ends).
use rtl::height_pipeline::HeightPipeline;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::height_pipeline::MODEL;

unit_tests!(height_pipeline, HeightPipeline, MODEL);

#[test]
fn height_pipeline_random_vs_model() {
    random_vs_model::<HeightPipeline>(&MODEL, 20, 1_000);
}

#[test]
fn height_pipeline_random_vs_model_verilator() {
    random_vs_model_verilator::<HeightPipeline>(&MODEL, 100_000, 16);
}

#[test]
fn height_pipeline_hard_cases() {
    rust_hdl::<HeightPipeline>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    // a flat map comes out exactly straight up, at any level, factor and scale
    for h in [0, 255] {
        assert_eq!((MODEL.exact)(&[vec![h; 9], vec![255, 0, 255]].concat()), vec![0, 1024, 0]);
    }
}
