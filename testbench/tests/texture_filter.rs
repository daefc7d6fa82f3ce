//! texture_filter: one set of four bilinear units in both modes; random vectors through rust-hdl and Verilator,
//! hard cases (every window offset, flat and steepest blocks, the factors' ends), and the two modes against the
//! colour filter and the height pipeline.
use rtl::texture_filter::TextureFilter;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::texture_filter::MODEL;

unit_tests!(texture_filter, TextureFilter, MODEL);

#[test]
fn texture_filter_random_vs_model() {
    random_vs_model::<TextureFilter>(&MODEL, 20, 1_000);
}

#[test]
fn texture_filter_random_vs_model_verilator() {
    random_vs_model_verilator::<TextureFilter>(&MODEL, 100_000, 17);
}

#[test]
fn texture_filter_hard_cases() {
    rust_hdl::<TextureFilter>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    // a flat block in height mode: exactly straight up, at every window offset
    for (ox, oy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
        let out = (MODEL.exact)(&[vec![90; 16], vec![77, 200, 1, ox, oy, 16]].concat());
        assert_eq!(out[4..], [0, 1024, 0]);
    }
}

#[test]
fn synthesis_keeps_one_set_of_four_bilinear_units() {
    // the colour filter and the normal generator share the units: yosys's netlist holds unit$0..3 and no other
    // instance with the bilinear units' multipliers
    use synth::fpga::{blocks_of, synth_unit, Family};
    let dir = testbench::work_dir("synth", "texture_filter");
    let unit = synth::Unit::of::<TextureFilter>();
    let cells = synth_unit(&unit, &dir, Family::Ecp5).unwrap_or_else(|e| panic!("{e}"));
    let b = blocks_of(&unit, &dir, Family::Ecp5);
    let units: Vec<&(String, u64, u64)> = b.by_instance.iter().filter(|(n, ..)| n.starts_with("unit$")).collect();
    assert_eq!(
        units.iter().map(|u| u.0.as_str()).collect::<Vec<_>>(),
        ["unit$0", "unit$1", "unit$2", "unit$3"],
        "{b:?}"
    );
    assert!(units.iter().all(|u| u.1 == 3), "three multipliers a unit: {b:?}");
    // the rest are the tangent, normal and normaliser behind them
    let rest: u64 = b.by_instance.iter().filter(|(n, ..)| !n.starts_with("unit$")).map(|x| x.1).sum();
    assert_eq!(rest + 12, cells.dsp, "{b:?}");
    // no instance but those holds a multiplier (the colour's delay line holds a block RAM, no multiplier)
    assert!(b.by_instance.iter().all(|(n, dsp, _)| *dsp == 0 || n.starts_with("unit$") || n == "back"), "{b:?}");
}
