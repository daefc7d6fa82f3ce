//! power: all 2^16 (x, p) pairs three ways.
use rtl::power::Power;
use testbench::unit_tests;
use vectors::power::MODEL;

unit_tests!(power, Power, MODEL, exhaustive: [rust_hdl, verilator, icarus] with Bubbles::Random { one_in: 7, seed: 5 });

// Other table sizes of the same block (the width sweep's), three ways on every (x, p).
fn exact_sized<const LF: u32, const EB: u32>(i: &[i64]) -> Vec<i64> {
    vec![vectors::power::exact_with(i[0], i[1], LF, EB)]
}

const fn sized(exact: fn(&[i64]) -> Vec<i64>) -> vectors::UnitModel {
    vectors::UnitModel { exact, accuracy: None, ..MODEL }
}

static L12E6: vectors::UnitModel = sized(exact_sized::<12, 6>);
static L10E9: vectors::UnitModel = sized(exact_sized::<10, 9>);
static L8E7: vectors::UnitModel = sized(exact_sized::<8, 7>);

#[test]
fn other_table_sizes_three_ways() {
    let every = vectors::unit::generate(&MODEL, true, 0, 0).unwrap();
    testbench::three_ways::<Power<12, 6>>(&L12E6, &every, "power_l12e6");
    testbench::three_ways::<Power<10, 9>>(&L10E9, &every, "power_l10e9");
    testbench::three_ways::<Power<8, 7>>(&L8E7, &every, "power_l8e7");
    // and they are other sizes: each differs from the unit somewhere
    for m in [&L12E6, &L10E9, &L8E7] {
        assert!(every.iter().any(|i| (m.exact)(i) != (MODEL.exact)(i)));
    }
}
