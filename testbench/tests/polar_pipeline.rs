//! polar_pipeline: shade → power → blend, 100,000 proptest vectors in rust-hdl, 100,000 under Verilator.
use rtl::polar_pipeline::PolarPipelineSeed as PolarPipeline;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::polar_pipeline::MODEL;

unit_tests!(polar_pipeline, PolarPipeline, MODEL);

/// The Dreamcast-scale build: the same checks on its own golden file and streams.
mod dreamcast {
    use rtl::polar_pipeline::PolarPipelineDc;
    use testbench::{random_vs_model, random_vs_model_verilator, unit_tests};
    use vectors::polar_pipeline::MODEL_DC;

    unit_tests!(polar_pipeline_dc, PolarPipelineDc, MODEL_DC);

    #[test]
    fn polar_pipeline_dc_random_vs_model() {
        random_vs_model::<PolarPipelineDc>(&MODEL_DC, 10, 2_000);
    }

    #[test]
    fn polar_pipeline_dc_random_vs_model_verilator() {
        random_vs_model_verilator::<PolarPipelineDc>(&MODEL_DC, 100_000, 19);
    }

    #[test]
    fn the_scales_differ_where_the_tables_do() {
        // S = 255 is 89.65° in the seed's scale and 90° in the Dreamcast one: cos S is 2/255 against 0
        let v = [255, 0, 0, 0, 0, 255, 4, 1, 200, 150, 100, 10, 20, 30];
        assert_eq!((MODEL_DC.exact)(&v)[0], 0);
        assert_eq!((super::MODEL.exact)(&v)[0], 2);
    }
}

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
    rust_hdl::<PolarPipeline>(&MODEL, &(MODEL.hard_cases)(), Bubbles::Random { one_in: 2, seed: 9 })
        .assert_clean("hard cases");
}
