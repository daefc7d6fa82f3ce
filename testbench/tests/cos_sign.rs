//! cos_sign: the cosine unit with its sign, every d three ways, in the unit's size and another; the rtl tables
//! against the model's for every size of the LUT-size table.
use rtl::cos_sign::{CosSign, CosSignUnit};
use rtl::StreamUnit;
use synth::cosim::Simulator;
use testbench::{rust_hdl, unit_tests, Bubbles};
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
};

fn three_ways<U: StreamUnit>(m: &UnitModel, tag: &str) {
    let inputs = (m.exhaustive.unwrap())();
    rust_hdl::<U>(m, &inputs, Bubbles::Random { one_in: 3, seed: 8 }).assert_clean(&format!("rust-hdl, {tag}"));
    for (sim, name) in [(Simulator::Verilator, "verilator"), (Simulator::Icarus, "icarus")] {
        let built = synth::cosim::build::<U>(sim, &testbench::work_dir(name, &format!("cos_sign_{tag}"))).unwrap();
        let s = testbench::slots(m, &inputs, Bubbles::BackToBack);
        testbench::check(m, U::LATENCY, &inputs, &s, &built.run(&s).unwrap()).assert_clean(&format!("{name}, {tag}"));
    }
}

#[test]
fn every_d_three_ways_in_two_sizes() {
    three_ways::<CosSignUnit>(&MODEL, "256x8");
    three_ways::<CosSign<4, 12>>(&M16X12, "16x12");
}

#[test]
fn rtl_entries_are_the_models_for_every_size_of_the_lut_table() {
    for &(tb, w) in vectors::cos_sign::LUT_SIZES {
        let r = rtl::cos_sign::entries(tb as usize, w as usize);
        for (i, e) in r.iter().enumerate() {
            let d = (i as i64) << (8 - tb);
            let (m, n) = vectors::cos_sign::exact_with(tb, w, d);
            assert_eq!((e.0 as i64, e.1), (m, n), "{}x{w}, entry {i}", 1 << tb);
        }
    }
}
