//! sincos: the elevation sine/cosine table, every 10-bit angle three ways, and the rtl table against the model's.
use rtl::sincos::SinCos;
use synth::cosim::Simulator;
use testbench::{external, rust_hdl, unit_tests, Bubbles};
use vectors::polar_encode::Scale;
use vectors::sincos::MODEL;

unit_tests!(sincos, SinCos, MODEL);

fn all() -> Vec<Vec<i64>> {
    (MODEL.exhaustive.unwrap())()
}

#[test]
fn sincos_exhaustive_rust_hdl() {
    rust_hdl::<SinCos>(&MODEL, &all(), Bubbles::Random { one_in: 3, seed: 2 }).assert_clean("rust-hdl, every angle");
}

#[test]
fn sincos_exhaustive_verilator() {
    external::<SinCos>(Simulator::Verilator, &MODEL, &all(), Bubbles::BackToBack).assert_clean("verilator, every angle");
}

#[test]
fn sincos_exhaustive_icarus() {
    external::<SinCos>(Simulator::Icarus, &MODEL, &all(), Bubbles::BackToBack).assert_clean("icarus, every angle");
}

#[test]
fn rtl_tables_are_the_models() {
    let e = vectors::sincos::elevation_table(Scale::Seed, 8, 8);
    let c = vectors::sincos::cos_sign_table(Scale::Seed, 8);
    let (re, rc) = (rtl::tables::elevation(false), rtl::tables::cos_sign(false));
    for k in 0..256 {
        assert_eq!(re[k], vectors::sincos::pack_elevation(e[k], 8), "elevation entry {k}");
        assert_eq!(rc[k], vectors::sincos::pack_cos_sign(c[k], 8), "cosine entry {k}");
    }
    // and the Dreamcast scale's
    let e = vectors::sincos::elevation_table(Scale::Dc255, 8, 8);
    let c = vectors::sincos::cos_sign_table(Scale::Dc255, 8);
    let (re, rc) = (rtl::tables::elevation(true), rtl::tables::cos_sign(true));
    for k in 0..256 {
        assert_eq!(re[k], vectors::sincos::pack_elevation(e[k], 8), "Dreamcast elevation entry {k}");
        assert_eq!(rc[k], vectors::sincos::pack_cos_sign(c[k], 8), "Dreamcast cosine entry {k}");
    }
    let (l, x) = (rtl::tables::log2(), rtl::tables::exp2());
    for k in 0..256 {
        assert_eq!(l[k] as i64, vectors::power::log_table()[k], "log entry {k}");
        assert_eq!(x[k] as i64, vectors::power::exp_table()[k], "exp entry {k}");
    }
}
