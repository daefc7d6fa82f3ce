//! tex_addr: the texture unit's address unit three ways, the hard cases (the wrap seam and the clamp edge of every
//! level of maps from 1 × 1 to 256 × 256, the level past the last, the ends of the coordinates' range), ≥ 100,000
//! random positions under Verilator, and footprints worked by hand.
use rtl::tex_addr::TexAddr;
use testbench::{rust_hdl, unit_tests, Bubbles};
use vectors::tex_addr::MODEL;

unit_tests!(tex_addr, TexAddr, MODEL);

#[test]
fn tex_addr_random_vs_model() {
    testbench::random_vs_model::<TexAddr>(&MODEL, 16, 2_000);
    testbench::random_vs_model_verilator::<TexAddr>(&MODEL, 100_000, 13);
}

#[test]
fn tex_addr_hard_cases_back_to_back_and_worked_by_hand() {
    let inputs = (MODEL.hard_cases)();
    rust_hdl::<TexAddr>(&MODEL, &inputs, Bubbles::BackToBack).assert_clean("hard cases");
    // ports: u, v, level, log_side, uwrap, vwrap, linear → level_log2, x0, x1, y0, y1, ublend, vblend
    // u = 100.75 texels, v = −3.5 on a 128 × 128 map at level 2 (32 × 32): u/4 − ½ = 24.6875 → texels 24 and 25,
    // blend 0.6875·256 = 176; v/4 − ½ = −1.375, repeated: 30.625 → texels 30 and 31, blend 160
    assert_eq!((MODEL.exact)(&[100 * 256 + 192, -3 * 256 - 128, 2, 7, 1, 1, 1]), vec![5, 24, 25, 30, 31, 176, 160]);
    // the same v clamped: the first texel, all of its weight
    assert_eq!((MODEL.exact)(&[100 * 256 + 192, -3 * 256 - 128, 2, 7, 1, 0, 1]), vec![5, 24, 25, 0, 1, 176, 0]);
    // u = −0.00390625 (one LSB below 0) at level 8 of a 256 map (1 × 1): texel 0 whatever the mode
    assert_eq!((MODEL.exact)(&[-1, -1, 8, 8, 0, 0, 1]), vec![0, 0, 0, 0, 0, 0, 0]);
    // floor, not truncation toward 0: u = −1 LSB at level 1 of a 4-texel map, nearest, repeat: −1/512 texel of
    // level 1 is in its last texel (1)
    assert_eq!((MODEL.exact)(&[-1, 0, 1, 2, 1, 1, 0]), vec![1, 1, 1, 0, 0, 0, 0]);
}
