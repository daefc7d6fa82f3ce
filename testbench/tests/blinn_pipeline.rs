//! blinn_pipeline: Blinn's function on three of the shared bilinear units, random vectors through rust-hdl and
//! Verilator, hard cases (flat windows, the steepest steps both ways, the largest scale, the factors' ends).
use rtl::blinn_pipeline::BlinnPipeline;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::blinn_pipeline::MODEL;

unit_tests!(blinn_pipeline, BlinnPipeline, MODEL);

#[test]
fn blinn_pipeline_random_vs_model() {
    random_vs_model::<BlinnPipeline>(&MODEL, 20, 1_000);
}

#[test]
fn blinn_pipeline_random_vs_model_verilator() {
    random_vs_model_verilator::<BlinnPipeline>(&MODEL, 100_000, 18);
}

#[test]
fn blinn_pipeline_hard_cases() {
    rust_hdl::<BlinnPipeline>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
}
