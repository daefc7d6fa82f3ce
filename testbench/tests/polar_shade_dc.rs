//! polar_shade_dc: the shade unit in the Dreamcast toolchains' angle scale (its own tables), every (S, R − Q) pair
//! under the k sweep in rust-hdl and Verilator; the standard tests on its own golden vectors.
type PolarShadeDc = rtl::polar_shade::PolarShade<true>;
use testbench::unit_tests;
use vectors::polar_shade::MODEL_DC;

unit_tests!(polar_shade_dc, PolarShadeDc, MODEL_DC, exhaustive: [rust_hdl, verilator] with Bubbles::Random { one_in: 11, seed: 8 });

fn all() -> Vec<Vec<i64>> {
    (MODEL_DC.exhaustive.unwrap())()
}

#[test]
fn the_two_scales_are_different_units() {
    // the same codes mean other angles: the models must disagree somewhere, or one of them is not its own
    let differ = all().iter().filter(|v| (vectors::polar_shade::MODEL.exact)(v) != (MODEL_DC.exact)(v)).count();
    assert!(differ > 1000, "only {differ} of the sweep's vectors differ between the scales");
}
