//! gloss: the seed's quadratic glossiness, all 2^18 (C, X) pairs.
use rtl::gloss::Gloss;
use testbench::{rust_hdl, unit_tests, Bubbles};
use vectors::gloss::MODEL;

unit_tests!(gloss, Gloss, MODEL, exhaustive: [rust_hdl, verilator] with Bubbles::Random { one_in: 9, seed: 1 });

#[test]
fn gloss_hard_cases() {
    // C = 0 gives P = X exactly, through the rtl
    let inputs: Vec<Vec<i64>> = (0..1024).map(|x| vec![0, x]).collect();
    rust_hdl::<Gloss>(&MODEL, &inputs, Bubbles::BackToBack).assert_clean("C = 0");
    // X = 0 and 1023 at C = 0 and 255, against the recipe worked by hand:
    // C=255, X=0: k=263, k·1023>>3 = 33630 > 1023 → L=0, P=0. C=255, X=1023: L=1023, Q=1022, P=1023−1=1022.
    assert_eq!((MODEL.exact)(&[255, 0]), vec![0]);
    assert_eq!((MODEL.exact)(&[255, 1023]), vec![1022]);
    assert_eq!((MODEL.exact)(&[0, 1023]), vec![1023]);
    // C=128, X=512: k=136, 136·511 = 69496 >> 3 = 8687 > 1023 → L = 0, P = 0
    assert_eq!((MODEL.exact)(&[128, 512]), vec![0]);
    // C=1, X=1000: k=9, 9·23 = 207 >> 3 = 25, L = 998, Q = 998² >> 10 = 972, P = 998 + ((1·(−26)) >> 8) = 997
    assert_eq!((MODEL.exact)(&[1, 1000]), vec![997]);
}

#[test]
fn gloss_threaded_simulation_agrees() {
    // rust-hdl's own threaded Simulation, on the golden vectors with bubbles: the same outputs, the same cycles
    let (inputs, _) = testbench::golden(&MODEL);
    let s = testbench::slots(&MODEL, 1, &inputs, Bubbles::Random { one_in: 4, seed: 7 });
    let got = rtl::stream::run_threaded::<Gloss>(s.clone()).unwrap_or_else(|e| panic!("{e}"));
    testbench::check(&MODEL, <Gloss as rtl::StreamUnit>::LATENCY, &inputs, &s, &got)
        .assert_clean("threaded Simulation");
}
