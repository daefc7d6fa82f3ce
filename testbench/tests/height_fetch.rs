//! height_fetch: the 2×2-interleaved map memory, written then read, against the model's stream: golden vectors
//! three ways, random streams through rust-hdl and Verilator (after the hard cases have filled the region they
//! read), and every window of a 16 × 8 map and of the largest map's borders in every border mode under Verilator.
use rtl::height_fetch::HeightFetch;
use testbench::{external, random_vs_model, rust_hdl, unit_tests, Bubbles};
use vectors::height_fetch::{Map, MODEL};

unit_tests!(height_fetch, HeightFetch, MODEL);

#[test]
fn height_fetch_random_vs_model() {
    random_vs_model::<HeightFetch>(&MODEL, 30, 2_000);
}

#[test]
fn height_fetch_random_after_the_hard_cases_verilator() {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(17);
    let mut inputs = (MODEL.hard_cases)();
    inputs.extend((0..50_000).map(|_| (MODEL.random)(&mut rng)));
    external::<HeightFetch>(
        synth::cosim::Simulator::Verilator,
        &MODEL,
        &inputs,
        Bubbles::Random { one_in: 3, seed: 17 },
    )
    .assert_clean("verilator, random");
}

#[test]
fn height_fetch_hard_cases() {
    rust_hdl::<HeightFetch>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
}

#[test]
fn height_fetch_every_window_of_a_16_by_8_map_and_of_a_1_by_8_map() {
    // a 16 × 8 map of distinct heights: every centre inside and one beyond, in all four border modes; then a
    // 1 × 8 map (one texel wide: every column is x = 0) written over it
    let heights: Vec<i64> = (0..128).map(|k| (k * 2 + 1) % 256).collect();
    let mut inputs = Map::from_heights(&heights, 16, 8).writes(16, 8);
    for (uw, vw) in [(false, false), (true, true), (true, false), (false, true)] {
        for j in 0..9 {
            for i in 0..17 {
                inputs.push(Map::read(i, j, 4, 3, uw, vw));
            }
        }
    }
    inputs.extend(Map::from_heights(&[200, 201, 202, 203, 204, 205, 206, 207], 1, 8).writes(1, 8));
    for (uw, vw) in [(false, false), (true, true)] {
        for j in 0..8 {
            inputs.push(Map::read(0, j, 0, 3, uw, vw));
        }
    }
    rust_hdl::<HeightFetch>(&MODEL, &inputs, Bubbles::Random { one_in: 3, seed: 5 }).assert_clean("rust-hdl");
    external::<HeightFetch>(synth::cosim::Simulator::Verilator, &MODEL, &inputs, Bubbles::BackToBack)
        .assert_clean("verilator");
}
