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

// Other seed-table sizes and Newton steps of the same block (the width sweep's), three ways on the hard cases and
// random vectors.
fn exact_table<const T: u32, const N: u32>(i: &[i64]) -> Vec<i64> {
    vectors::normalise::exact_with([i[0], i[1], i[2]], T, N).to_vec()
}

const fn sized(exact: fn(&[i64]) -> Vec<i64>) -> vectors::UnitModel {
    vectors::UnitModel { exact, accuracy: None, ..MODEL }
}

static T8: vectors::UnitModel = sized(exact_table::<8, 0>);
static T12: vectors::UnitModel = sized(exact_table::<12, 0>);
static T6N1: vectors::UnitModel = sized(exact_table::<6, 1>);
static T8N2: vectors::UnitModel = sized(exact_table::<8, 2>);

fn vectors_of(m: &vectors::UnitModel) -> Vec<Vec<i64>> {
    vectors::unit::generate(m, false, 3_000, 17).unwrap()
}

#[test]
fn other_table_sizes_three_ways() {
    testbench::three_ways::<Normalise<8>>(&T8, &vectors_of(&T8), "normalise_t8");
    testbench::three_ways::<Normalise<12>>(&T12, &vectors_of(&T12), "normalise_t12");
    // and they are other sizes: the model's outputs differ from the unit's somewhere
    let v = vectors_of(&MODEL);
    assert!(
        v.iter().any(|i| (T8.exact)(i) != (MODEL.exact)(i)) && v.iter().any(|i| (T12.exact)(i) != (MODEL.exact)(i))
    );
}

#[test]
fn newton_steps_three_ways() {
    testbench::three_ways::<Normalise<6, 1>>(&T6N1, &vectors_of(&T6N1), "normalise_t6n1");
    testbench::three_ways::<Normalise<8, 2>>(&T8N2, &vectors_of(&T8N2), "normalise_t8n2");
    // a step changes the result: 2^6 entries refined are not 2^6 entries bare, nor the unit's
    let v = vectors_of(&MODEL);
    let bare = |i: &Vec<i64>| vectors::normalise::exact_with([i[0], i[1], i[2]], 6, 0).to_vec();
    assert!(v.iter().any(|i| (T6N1.exact)(i) != bare(i)) && v.iter().any(|i| (T6N1.exact)(i) != (MODEL.exact)(i)));
}

#[test]
fn newton_three_is_the_models() {
    assert_eq!(rtl::normalise::NEWTON_THREE as i64, vectors::normalise::NEWTON_THREE);
}
