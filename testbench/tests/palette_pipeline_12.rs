//! palette_pipeline_12: the builder and the lookup together at 12 index bits (s_N up to 4,096, the demo's larger
//! palette), against the model's stream as `palette_pipeline.rs` does at 8: golden vectors three ways, random
//! streams in the built entries under rust-hdl with bubbles and under Verilator.
use rtl::palette_pipeline::PalettePipeline;
use testbench::{external, rust_hdl, unit_tests, Bubbles};
use vectors::palette_pipeline::MODEL_12;

type PalettePipeline12 = PalettePipeline<12, 13>;

unit_tests!(palette_pipeline_12, PalettePipeline12, MODEL_12);

fn stream(count: usize, seed: u64) -> Vec<Vec<i64>> {
    vectors::unit::generate(&MODEL_12, false, count, seed).unwrap() // the hard cases, then `count` random vectors
}

#[test]
fn palette_pipeline_12_random_after_the_hard_cases_with_bubbles() {
    for (seed, one_in) in [(31, 2), (32, 5)] {
        rust_hdl::<PalettePipeline12>(&MODEL_12, &stream(3_000, seed), Bubbles::Random { one_in, seed })
            .assert_clean("rust-hdl, bubbles");
    }
}

#[test]
fn palette_pipeline_12_random_after_the_hard_cases_verilator() {
    external::<PalettePipeline12>(
        synth::cosim::Simulator::Verilator,
        &MODEL_12,
        &stream(50_000, 33),
        Bubbles::Random { one_in: 3, seed: 33 },
    )
    .assert_clean("verilator, random");
}
