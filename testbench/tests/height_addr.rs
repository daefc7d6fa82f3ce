//! height_addr: random vectors through rust-hdl and Verilator, hard cases (the borders of every mode), and every
//! coordinate of three sizes in all four modes under Verilator.
use rtl::height_addr::HeightAddr;
use testbench::{external, random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::height_addr::MODEL;

unit_tests!(height_addr, HeightAddr, MODEL);

#[test]
fn height_addr_random_vs_model() {
    random_vs_model::<HeightAddr>(&MODEL, 50, 2_000);
}

#[test]
fn height_addr_random_vs_model_verilator() {
    random_vs_model_verilator::<HeightAddr>(&MODEL, 100_000, 13);
}

#[test]
fn height_addr_hard_cases() {
    rust_hdl::<HeightAddr>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
}

#[test]
fn height_addr_every_coordinate_of_a_1_a_128_and_a_256_texel_axis() {
    // 3 sizes × 4 modes × 2^16 coordinates = 786,432 vectors: the whole space of these sizes
    let mut inputs = vec![];
    for size_log2 in [0, 7, 8] {
        for (wrap, height) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
            inputs.extend((0..1i64 << 16).map(|c| vec![c, size_log2, wrap, height]));
        }
    }
    external::<HeightAddr>(synth::cosim::Simulator::Verilator, &MODEL, &inputs, Bubbles::BackToBack)
        .assert_clean("every coordinate");
}
