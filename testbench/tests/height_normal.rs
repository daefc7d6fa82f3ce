//! height_normal: random vectors through rust-hdl and Verilator, hard cases (flat, the largest scale and tangents,
//! the shift that grows by one when rounding carries).
use rtl::height_normal::HeightNormal;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::height_normal::MODEL;

unit_tests!(height_normal, HeightNormal, MODEL);

#[test]
fn height_normal_random_vs_model() {
    random_vs_model::<HeightNormal>(&MODEL, 50, 2_000);
}

#[test]
fn height_normal_random_vs_model_verilator() {
    random_vs_model_verilator::<HeightNormal>(&MODEL, 100_000, 15);
}

#[test]
fn height_normal_hard_cases() {
    rust_hdl::<HeightNormal>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    // flat: (0, 448, 0), which the normaliser returns as (0, 1024, 0); a positive tangent leans N towards −x
    assert_eq!((MODEL.exact)(&[0, 0, 16]), vec![0, 448, 0]);
    let n = (MODEL.exact)(&[1 << 12, 0, 16]);
    assert!(n[0] < 0 && n[1] > 0 && n[2] == 0, "{n:?}");
    // 7k·t at 511.5·2^s0 and above rounds to 512: the shift grows by one and the largest is 256
    assert_eq!((MODEL.exact)(&[601_000, 0, 255])[0], -256);
    assert_eq!((MODEL.exact)(&[-74_836, 0, 16])[0], 256);
    // every hard case keeps the largest magnitude at 256..511
    for v in (MODEL.hard_cases)() {
        let m = (MODEL.exact)(&v).iter().map(|c| c.abs()).max().unwrap();
        assert!((256..=511).contains(&m), "{v:?}: {m}");
    }
}
