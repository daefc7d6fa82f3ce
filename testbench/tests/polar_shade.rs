//! polar_shade: every (S, R − Q) pair under a sweep of k's (2^19 vectors) in rust-hdl and Verilator; hard cases
//! (R − Q wrap, S at its ends, both S11 extremes, k's at 0 and max, a light on the horizon) with bubbles.
type PolarShade = rtl::polar_shade::PolarShade<false>;
use testbench::{random_vs_model, rust_hdl, unit_tests, Bubbles};
use vectors::polar_encode::Scale;
use vectors::polar_shade::{exact_trace, MODEL};

unit_tests!(polar_shade, PolarShade, MODEL, exhaustive: [rust_hdl, verilator] with Bubbles::Random { one_in: 11, seed: 6 });

#[test]
fn polar_shade_random_vs_model() {
    // Q varies here too (the exhaustive set holds Q = 0)
    random_vs_model::<PolarShade>(&MODEL, 50, 2_000);
}

#[test]
fn polar_shade_hard_cases() {
    rust_hdl::<PolarShade>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    // the wrap: R = 1, Q = 255 is the same angle as R = 3, Q = 1
    let a = exact_trace(Scale::Seed, 100, 1, 255, 0, 128, 255);
    assert_eq!(a.d, 2);
    // both S11 extremes reach the clamp: −255 → 0 and 616 → 255
    let lo = (MODEL.exact)(&[0, 128, 0, 0, 0, 255]);
    assert_eq!(lo, vec![-255, 0]);
    let hi = (MODEL.exact)(&[128, 0, 0, 255, 255, 255]);
    assert!(hi[0] > 600 && hi[1] == 255, "{hi:?}");
    // a light on the horizon (k2 = 0) and a texel facing away from it: cos(R − Q) < 0 subtracts, clamped at 0
    let away = (MODEL.exact)(&[40, 192, 64, 0, 0, 255]);
    assert!(away[0] < 0 && away[1] == 0, "{away:?}");
}
