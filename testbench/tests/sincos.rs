//! sincos: the elevation sine/cosine table, every 10-bit angle three ways, and the rtl table against the model's.
use rtl::sincos::{SinCos, SinCosUnit};
use testbench::unit_tests;
use vectors::polar_encode::Scale;
use vectors::sincos::MODEL;

unit_tests!(sincos, SinCosUnit, MODEL, exhaustive: [rust_hdl, verilator, icarus] with Bubbles::Random { one_in: 3, seed: 2 });

fn all() -> Vec<Vec<i64>> {
    (MODEL.exhaustive.unwrap())()
}

#[test]
fn rtl_tables_are_the_models() {
    for (sc, dc) in [(Scale::Seed, false), (Scale::Dc255, true)] {
        let e = vectors::sincos::elevation_table(sc, 8, 8);
        let c = vectors::sincos::cos_sign_table(sc, 8);
        let (re, rc) = (rtl::tables::elevation(dc, 8, 8), rtl::tables::cos_sign(dc, 8, 8));
        for k in 0..256 {
            assert_eq!((re[k].0 as i64, re[k].1 as i64), e[k], "{sc:?} elevation entry {k}");
            assert_eq!((rc[k].0 as i64, rc[k].1), c[k], "{sc:?} cosine entry {k}");
        }
    }
    let (l, x) = (rtl::tables::log2(), rtl::tables::exp2());
    for k in 0..256 {
        assert_eq!(l[k] as i64, vectors::power::log_table()[k], "log entry {k}");
        assert_eq!(x[k] as i64, vectors::power::exp_table()[k], "exp entry {k}");
    }
}

#[test]
fn the_polar_shade_unit_holds_the_tested_table_blocks() {
    // a type check: polar_shade's sine/cosine and cosine blocks are the units `sincos` and `cos_sign` (with the
    // Dreamcast contents in polar_shade_dc); this fails to compile if either becomes a block of its own again
    fn same<T>(_: &T, _: &T) {}
    let (seed, dc) =
        (rtl::polar_shade::PolarShade::<false>::default(), rtl::polar_shade::PolarShade::<true>::default());
    same(&seed.sin_cos, &SinCosUnit::default());
    same(&seed.cos_sign, &rtl::cos_sign::CosSignUnit::default());
    same(&dc.sin_cos, &SinCos::<8, 8, true>::default());
}

// Two other sizes of the same block, every angle, three ways: 64 entries of 8 bits and 1,024 of 12.
use vectors::{Port, UnitModel};

fn exact_sized<const TB: u32, const W: u32>(i: &[i64]) -> Vec<i64> {
    let (s, c) = vectors::sincos::exact_with(Scale::Seed, TB, W, i[0]);
    vec![s, c]
}

static M64X8: UnitModel = UnitModel {
    name: "sincos",
    inputs: vectors::sincos::INPUTS,
    outputs: &[Port::u("sin", 8), Port::u("cos", 8)],
    exact: exact_sized::<6, 8>,
    random: MODEL.random,
    exhaustive: MODEL.exhaustive,
    hard_cases: MODEL.hard_cases,
    accuracy: None,
    stream: None,
};

static M1024X12: UnitModel = UnitModel {
    name: "sincos",
    inputs: vectors::sincos::INPUTS,
    outputs: &[Port::u("sin", 12), Port::u("cos", 12)],
    exact: exact_sized::<10, 12>,
    random: MODEL.random,
    exhaustive: MODEL.exhaustive,
    hard_cases: MODEL.hard_cases,
    accuracy: None,
    stream: None,
};

#[test]
fn other_table_sizes_three_ways() {
    testbench::three_ways::<SinCos<6, 8>>(&M64X8, &all(), "sincos_64x8");
    testbench::three_ways::<SinCos<10, 12>>(&M1024X12, &all(), "sincos_1024x12");
}
