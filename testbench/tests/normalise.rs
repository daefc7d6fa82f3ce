//! normalise: at least 100,000 proptest-driven vectors through rust-hdl, 100,000 under Verilator, hard cases.
use rtl::normalise::Normalise;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::normalise::MODEL;

unit_tests!(normalise, Normalise, MODEL);

#[test]
fn normalise_random_vs_model() {
    random_vs_model::<Normalise>(&MODEL, 50, 2_000);
}

#[test]
fn normalise_random_vs_model_verilator() {
    random_vs_model_verilator::<Normalise>(&MODEL, 100_000, 11);
}

#[test]
fn normalise_hard_cases() {
    rust_hdl::<Normalise>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    let e = |v: &[i64]| (MODEL.exact)(v);
    // zero length (opposite lights through their midpoint): a defined zero vector
    assert_eq!(e(&[0, 0, 0]), vec![0, 0, 0]);
    // the most negative S10 everywhere: −1/√3 each, 591.2 → −591
    assert_eq!(e(&[-512, -512, -512]), vec![-591, -591, -591]);
    // axis vectors of every length come out as ±1024 (the table is exact at bin midpoints only: within 1)
    for k in 0..10 {
        let o = e(&[1 << k, 0, 0]);
        assert!((o[0] - 1024).abs() <= 1 && o[1] == 0 && o[2] == 0, "2^{k}: {o:?}");
        let o = e(&[-(1 << k), 0, 0]);
        assert!((o[0] + 1024).abs() <= 1, "−2^{k}: {o:?}");
    }
    // the shortest L1-scaled bump (x = y = z) and the seed's minimal step near the pole
    let o = e(&[85, 85, 85]);
    assert!(o.iter().all(|&c| (c - 591).abs() <= 1), "{o:?}");
    let o = e(&[2, 254, 0]);
    assert!(o[0] == 8 && (o[1] - 1024).abs() <= 1, "{o:?}");
}

#[test]
fn normalise_rtl_table_is_the_models() {
    let t = rtl::normalise::table();
    assert_eq!(t.len(), 1 << vectors::normalise::TABLE_BITS);
    for (k, &v) in t.iter().enumerate() {
        assert_eq!(v, vectors::normalise::table_entry(k as u64, vectors::normalise::TABLE_BITS), "entry {k}");
    }
}

// Other seed-table sizes of the same block (the width sweep's), three ways on the hard cases and random vectors.
fn exact_table<const T: u32>(i: &[i64]) -> Vec<i64> {
    vectors::normalise::exact_with([i[0], i[1], i[2]], T, 0).to_vec()
}

const fn sized(exact: fn(&[i64]) -> Vec<i64>) -> vectors::UnitModel {
    vectors::UnitModel { exact, accuracy: None, ..MODEL }
}

static T8: vectors::UnitModel = sized(exact_table::<8>);
static T12: vectors::UnitModel = sized(exact_table::<12>);

fn vectors_of(m: &vectors::UnitModel) -> Vec<Vec<i64>> {
    vectors::unit::generate(m, false, 3_000, 17).unwrap()
}

#[test]
fn other_table_sizes_three_ways() {
    testbench::three_ways::<Normalise<8>>(&T8, &vectors_of(&T8), "normalise_t8");
    testbench::three_ways::<Normalise<12>>(&T12, &vectors_of(&T12), "normalise_t12");
    // and they are other sizes: the model's outputs differ from the unit's somewhere
    let v = vectors_of(&MODEL);
    assert!(v.iter().any(|i| (T8.exact)(i) != (MODEL.exact)(i)) && v.iter().any(|i| (T12.exact)(i) != (MODEL.exact)(i)));
}
