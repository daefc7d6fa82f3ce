//! palette_pipeline_shared: the UP5K's palette pipeline (the shared builder, one normal every two clocks) against
//! the model's stream: golden vectors three ways (both tables built, builds in a row refused, flips, reads), random
//! streams after the hard cases (half the vectors build, so refusals are everywhere) under rust-hdl with bubbles
//! (what is taken must not depend on idle clocks) and under Verilator.
use rtl::palette_pipeline_shared::PalettePipelineShared;
use testbench::{external, rust_hdl, unit_tests, Bubbles};
use vectors::palette_pipeline_shared::MODEL;

unit_tests!(palette_pipeline_shared, PalettePipelineShared, MODEL);

fn stream(count: usize, seed: u64) -> Vec<Vec<i64>> {
    vectors::unit::generate(&MODEL, false, count, seed).unwrap() // the hard cases, then `count` random vectors
}

#[test]
fn palette_pipeline_shared_random_after_the_hard_cases_with_bubbles() {
    for (seed, one_in) in [(41, 2), (42, 5)] {
        rust_hdl::<PalettePipelineShared>(&MODEL, &stream(3_000, seed), Bubbles::Random { one_in, seed })
            .assert_clean("rust-hdl, bubbles");
    }
}

#[test]
fn palette_pipeline_shared_random_after_the_hard_cases_verilator() {
    external::<PalettePipelineShared>(
        synth::cosim::Simulator::Verilator,
        &MODEL,
        &stream(50_000, 43),
        Bubbles::Random { one_in: 3, seed: 43 },
    )
    .assert_clean("verilator, random");
}
