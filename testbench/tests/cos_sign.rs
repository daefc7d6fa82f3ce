//! cos_sign: the cosine unit with its sign, every d three ways, in the unit's size and another (the rtl tables of
//! every swept size against the model's: `sim/tests/units.rs`, beside the table of settings).
use rtl::cos_sign::{CosSign, CosSignUnit};
use testbench::{three_ways, unit_tests};
use vectors::cos_sign::MODEL;
use vectors::{Port, UnitModel};

unit_tests!(cos_sign, CosSignUnit, MODEL);

fn exact_sized<const TB: u32, const W: u32>(i: &[i64]) -> Vec<i64> {
    let (m, n) = vectors::cos_sign::exact_with(TB, W, i[0]);
    vec![m, n as i64]
}

static M16X12: UnitModel = UnitModel {
    name: "cos_sign",
    inputs: vectors::cos_sign::INPUTS,
    outputs: &[Port::u("mag", 12), Port::u("neg", 1)],
    exact: exact_sized::<4, 12>,
    random: MODEL.random,
    exhaustive: MODEL.exhaustive,
    hard_cases: MODEL.hard_cases,
    accuracy: None,
    stream: None,
};

#[test]
fn every_d_three_ways_in_two_sizes() {
    let all = (MODEL.exhaustive.unwrap())();
    three_ways::<CosSignUnit>(&MODEL, &all, "cos_sign_256x8");
    three_ways::<CosSign<4, 12>>(&M16X12, &all, "cos_sign_16x12");
}
