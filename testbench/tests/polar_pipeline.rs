//! polar_pipeline: shade → power → blend, 100,000 proptest vectors in rust-hdl, 100,000 under Verilator.
use rtl::polar_pipeline::PolarPipeline;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::polar_pipeline::MODEL;

unit_tests!(polar_pipeline, PolarPipeline, MODEL);

#[test]
fn polar_pipeline_random_vs_model() {
    random_vs_model::<PolarPipeline>(&MODEL, 50, 2_000);
}

#[test]
fn polar_pipeline_random_vs_model_verilator() {
    random_vs_model_verilator::<PolarPipeline>(&MODEL, 100_000, 17);
}

#[test]
fn polar_pipeline_hard_cases() {
    rust_hdl::<PolarPipeline>(&MODEL, &(MODEL.hard_cases)(), Bubbles::Random { one_in: 2, seed: 9 }).assert_clean("hard cases");
}
