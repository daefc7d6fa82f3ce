//! cart_decode: all 65,536 texel pairs, three ways; the guard's hard cases.
use rtl::cart_decode::CartDecode;
use testbench::{rust_hdl, unit_tests, Bubbles};
use vectors::cart_decode::MODEL;

unit_tests!(cart_decode, CartDecode, MODEL, exhaustive: [rust_hdl, verilator, icarus] with Bubbles::Random { one_in: 7, seed: 2 });

fn all() -> Vec<Vec<i64>> {
    (MODEL.exhaustive.unwrap())()
}

#[test]
fn cart_decode_hard_cases() {
    let d = |x: i64, z: i64| (MODEL.exact)(&[x, z]);
    // texel 255 would be BumpX = +256, past INT9: saturated to +254 (1.0), BumpY = 1
    assert_eq!(d(255, 127), vec![254, 1, 0]);
    // the pole and the seed's formula inside the diamond
    assert_eq!(d(127, 127), vec![0, 255, 0]);
    assert_eq!(d(128, 127), vec![2, 253, 0]);
    assert_eq!(d(190, 127), vec![126, 129, 0]);
    // |x| + |z| = 254 exactly: legal, BumpY = 1
    assert_eq!(d(190, 191), vec![126, 1, 128]);
    // one step past the diamond (ax = az = 64, 2·128 = 256 > 255): projected, not wrapped
    assert_eq!(d(191, 191), vec![127, 1, 127]);
    // the square's corners: projected onto the diamond's edge in their own quadrant
    assert_eq!(d(0, 0), vec![-127, 1, -127]);
    assert_eq!(d(255, 0), vec![127, 1, -127]);
    // every texel: a legal hemisphere vector, the most negative INT9 value never produced
    for t in all() {
        let o = (MODEL.exact)(&t);
        assert!(o[0] > -256 && o[2] > -256 && o[1] >= 1 && o[0].abs() + o[1] + o[2].abs() <= 255, "{t:?} → {o:?}");
    }
    rust_hdl::<CartDecode>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
}
