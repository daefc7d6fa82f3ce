//! palette_pipeline: the builder and the lookup together against the model's stream: golden vectors three ways
//! (both tables built, flipped, read), random streams after the hard cases under rust-hdl with bubbles (the order of
//! writes and reads must not depend on the idle clocks) and under Verilator. The 12-bit unit (s_N up to 4,096) is
//! `palette_pipeline_12.rs`.
use rtl::palette_pipeline::PalettePipeline;
use testbench::{external, rust_hdl, unit_tests, Bubbles};
use vectors::palette_pipeline::MODEL;

type PalettePipeline8 = PalettePipeline<8, 9>;

unit_tests!(palette_pipeline, PalettePipeline8, MODEL);

fn stream(count: usize, seed: u64) -> Vec<Vec<i64>> {
    vectors::unit::generate(&MODEL, false, count, seed).unwrap() // the hard cases, then `count` random vectors
}

#[test]
fn palette_pipeline_random_after_the_hard_cases_with_bubbles() {
    for (seed, one_in) in [(31, 2), (32, 5)] {
        rust_hdl::<PalettePipeline8>(&MODEL, &stream(3_000, seed), Bubbles::Random { one_in, seed })
            .assert_clean("rust-hdl, bubbles");
    }
}

#[test]
fn palette_pipeline_random_after_the_hard_cases_verilator() {
    external::<PalettePipeline8>(
        synth::cosim::Simulator::Verilator,
        &MODEL,
        &stream(50_000, 33),
        Bubbles::Random { one_in: 3, seed: 33 },
    )
    .assert_clean("verilator, random");
}
