//! blend_adjust: every (U, V) pair, three ways.
use rtl::blend_adjust::BlendAdjust;
use testbench::unit_tests;
use vectors::blend_adjust::MODEL;

unit_tests!(blend_adjust, BlendAdjust, MODEL, exhaustive: [rust_hdl, verilator, icarus] with Bubbles::Random { one_in: 5, seed: 6 });

#[test]
fn blend_adjust_ends() {
    // factor 0: U0 = ½, U1 = 0; the largest: U0 = 511/512, U1 = 255/512
    assert_eq!((MODEL.exact)(&[0, 0]), vec![256, 0, 256, 0]);
    assert_eq!((MODEL.exact)(&[255, 255]), vec![511, 255, 511, 255]);
}
