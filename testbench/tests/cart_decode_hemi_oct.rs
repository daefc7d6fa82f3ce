//! cart_decode_hemi_oct: all 65,536 texel pairs, three ways; the horizon and the pole.
use rtl::cart_decode_hemi_oct::CartDecodeHemiOct;
use testbench::{rust_hdl, unit_tests, Bubbles};
use vectors::cart_decode_hemi_oct::MODEL;

unit_tests!(cart_decode_hemi_oct, CartDecodeHemiOct, MODEL, exhaustive: [rust_hdl, verilator, icarus] with Bubbles::Random { one_in: 7, seed: 2 });

fn all() -> Vec<Vec<i64>> {
    (MODEL.exhaustive.unwrap())()
}

#[test]
fn cart_decode_hemi_oct_hard_cases() {
    let d = |u: i64, v: i64| (MODEL.exact)(&[u, v]);
    // the pole, and the texels beside it (the smallest tilts, L1 length 255 kept exactly)
    assert_eq!(d(127, 128), vec![0, 254, -1]);
    assert_eq!(d(128, 128), vec![1, 254, 0]);
    // the square's corners and edge midpoints are the horizon: BumpY = 0, |BumpX| or |BumpZ| = 255 (INT9's edge)
    assert_eq!(d(0, 0), vec![-255, 0, 0]);
    assert_eq!(d(255, 255), vec![255, 0, 0]);
    assert_eq!(d(255, 0), vec![0, 0, 255]);
    assert_eq!(d(0, 255), vec![0, 0, -255]);
    assert_eq!(d(127, 0), vec![-128, 0, 127]);
    // every texel: a legal hemisphere vector of L1 length 255, never INT9's -256
    for t in all() {
        let o = (MODEL.exact)(&t);
        assert!(o[0] > -256 && o[2] > -256 && o[1] >= 0 && o[0].abs() + o[1] + o[2].abs() == 255, "{t:?} → {o:?}");
    }
    rust_hdl::<CartDecodeHemiOct>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
}
