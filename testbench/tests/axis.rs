//! The AXI4-Stream wrapper around units of several latencies, in rust-hdl: the golden vectors under random gaps and
//! stalls, the rate it keeps, its minimum depth, a reset in the middle of a stream, and 25,000 random vectors a
//! family (`BUMPRTL_RUST_HDL_VECTORS=100000` for the full streams). The exported wrapper of every unit, linted and
//! under Verilator and Icarus, is tested where the table of units is: `sim/tests/axis.rs`.

use rtl::axis::{AxisBlock, AxisDut, AxisRunner};
use rtl::StreamUnit;
use testbench::axis::{run, Reset, Traffic, FAMILIES};
use testbench::golden;
use vectors::UnitModel;

type GlossAxis = rtl::axis_of!(rtl::gloss::Gloss);
type CartAxis = rtl::axis_of!(rtl::cart_pipeline::CartPipeline);

fn gloss() -> AxisRunner<GlossAxis> {
    AxisRunner::new(GlossAxis::build())
}

#[test]
fn gloss_golden_vectors_under_gaps_and_stalls() {
    let (inputs, _) = golden(&vectors::gloss::MODEL);
    for seed in 1..=3 {
        run(&mut gloss(), &vectors::gloss::MODEL, &inputs, Traffic::random(seed), None)
            .assert_clean(&format!("gloss_axis, seed {seed}"));
    }
}

#[test]
fn one_beat_a_clock_at_the_minimum_depth_and_not_one_place_less() {
    let (inputs, _) = golden(&vectors::gloss::MODEL);
    let n = inputs.len() as u64;
    let l = rtl::gloss::Gloss::LATENCY as u64;
    let r = run(&mut gloss(), &vectors::gloss::MODEL, &inputs, Traffic::FULL, None);
    r.assert_clean("gloss_axis, full rate");
    assert_eq!(r.refused, 0, "the wrapper refused a beat with its sink always ready");
    // the first beat in at edge 0, the last out LATENCY + 1 edges after it went in at edge n − 1
    assert_eq!(r.clocks, n + l + 1, "{n} beats");
    let shallow = rtl::axis::depth(rtl::gloss::Gloss::LATENCY) - 1;
    let mut one_less = AxisRunner::new(GlossAxis::with_depth(shallow));
    let r = run(&mut one_less, &vectors::gloss::MODEL, &inputs, Traffic::FULL, None);
    r.assert_clean("gloss_axis, one place less");
    assert!(r.refused > 0 && r.clocks > n + l + 1, "a FIFO of {shallow} places kept the rate: {} clocks", r.clocks);
}

#[test]
fn a_reset_in_the_middle_drops_what_was_in_flight_and_the_stream_runs_again() {
    let (inputs, _) = golden(&vectors::gloss::MODEL);
    for (seed, after, clocks) in [(5, 37, 1), (6, 200, 3), (7, 5, 2)] {
        let cut = Reset { after, clocks };
        run(&mut gloss(), &vectors::gloss::MODEL, &inputs, Traffic::random(seed), Some(cut))
            .assert_clean(&format!("gloss_axis, reset after {after} clocks"));
        run(&mut gloss(), &vectors::gloss::MODEL, &inputs, Traffic::FULL, Some(cut))
            .assert_clean(&format!("gloss_axis, full rate, reset after {after} clocks"));
    }
}

#[test]
fn cart_pipeline_golden_vectors_under_gaps_stalls_and_a_reset() {
    let (inputs, _) = golden(&vectors::cart_pipeline::MODEL);
    let mut dut = AxisRunner::new(CartAxis::build());
    assert_eq!(dut.name(), "cart_pipeline_axis");
    run(&mut dut, &vectors::cart_pipeline::MODEL, &inputs, Traffic::random(11), Some(Reset { after: 90, clocks: 2 }))
        .assert_clean("cart_pipeline_axis");
}

type TexAxis = rtl::axis_map_of!(rtl::cart_tex::CartTexTrilinearMatte);
type FetchAxis = rtl::axis_map_of!(rtl::tex_fetch::TexFetch);

#[test]
fn map_units_take_their_writes_on_a_second_stream_and_give_no_beat_for_them() {
    let m = &vectors::cart_tex::trilinear_matte::MODEL;
    let (inputs, _) = golden(m);
    let mut dut = AxisRunner::new(TexAxis::build());
    let r = run(&mut dut, m, &inputs, Traffic::random(31), Some(Reset { after: 400, clocks: 2 }));
    r.assert_clean("cart_tex_trilinear_matte_axis");
    let writes = inputs.iter().filter(|v| v[m.inputs.iter().position(|p| p.name == "we").unwrap()] == 1).count();
    assert!(
        writes > 0 && r.expected == r.vectors - writes,
        "{} vectors, {writes} writes, {} beats",
        r.vectors,
        r.expected
    );
    let f = &vectors::tex_fetch::MODEL;
    let (inputs, _) = golden(f);
    let mut dut = AxisRunner::new(FetchAxis::build());
    run(&mut dut, f, &inputs, Traffic::random(32), None).assert_clean("tex_fetch_axis");
    let r = run(&mut AxisRunner::new(FetchAxis::build()), f, &inputs, Traffic::FULL, None);
    r.assert_clean("tex_fetch_axis, full rate");
    assert_eq!(r.refused, 0, "the wrapper refused a beat with its sink always ready");
}

type TwoPassAxis = rtl::axis_map_of!(rtl::cart_tex::CartTexTrilinearTwoPassMatte);

/// A unit taking two clocks a vector (`StreamUnit::INTERVAL`) gets one every other clock, a map write as much as a
/// pixel: offered back to back with the sink always ready, each beat after the first waits exactly one clock; and
/// under gaps, stalls and a reset every beat is the model's (the exported wrapper under Verilator:
/// `sim/tests/axis.rs`).
#[test]
fn a_two_clock_unit_takes_a_beat_every_other_clock_on_either_stream() {
    let m = &vectors::cart_tex::trilinear_two_pass_matte::MODEL;
    let (inputs, _) = golden(m);
    let r = run(&mut AxisRunner::new(TwoPassAxis::build()), m, &inputs, Traffic::FULL, None);
    r.assert_clean("cart_tex_trilinear_two_pass_matte_axis, full rate");
    assert_eq!(r.refused, inputs.len() as u64 - 1, "one clock refused after each beat taken");
    run(
        &mut AxisRunner::new(TwoPassAxis::build()),
        m,
        &inputs,
        Traffic::random(33),
        Some(Reset { after: 500, clocks: 2 }),
    )
    .assert_clean("cart_tex_trilinear_two_pass_matte_axis");
}

#[test]
fn a_map_write_offered_beside_a_pixel_goes_first_and_holds_no_fifo_place() {
    use rust_hdl::prelude::*;
    let mut w = FetchAxis::build();
    w.connect_all();
    let clock = |w: &mut FetchAxis, s: bool, map: bool, m_ready: bool| {
        w.aresetn.next = true;
        w.s_axis_tvalid.next = s;
        w.s_axis_map_tvalid.next = map;
        w.m_axis_tready.next = m_ready;
        w.aclk.next = Clock { clk: false };
        assert!(simulate(w, 10_000));
        let seen = (w.s_axis_tready.val(), w.s_axis_map_tready.val(), w.m_axis_tvalid.val());
        w.aclk.next = Clock { clk: true };
        assert!(simulate(w, 10_000));
        seen
    };
    // past the flush of a reset, then both offered: the write is taken, the pixel waits
    for _ in 0..rtl::tex_fetch::LATENCY + 2 {
        clock(&mut w, false, false, true);
    }
    assert_eq!(clock(&mut w, true, true, true), (false, true, false));
    // the sink stalls: the write held no place, so `places` pixels go in after it, then both streams stop
    let places = rtl::axis::depth(rtl::tex_fetch::LATENCY);
    for k in 0..places {
        assert!(clock(&mut w, true, false, false).0, "pixel {k}");
    }
    let (s, map, _) = clock(&mut w, true, true, false);
    assert!(!s && !map, "full: s_axis_tready {s}, s_axis_map_tready {map}");
    // and the writes give no beat: exactly `places` beats come out
    let mut beats = 0;
    for _ in 0..places + rtl::tex_fetch::LATENCY + 4 {
        beats += usize::from(clock(&mut w, false, false, true).2);
    }
    assert_eq!(beats, places);
}

type PolarAxis = rtl::axis_of!(rtl::polar_pipeline::PolarPipeline<false>);
type HeightAxis = rtl::axis_of!(rtl::height_pipeline::HeightPipeline);
type PaletteAxis = rtl::axis_of!(rtl::palette_pipeline::PalettePipeline<8, 9>);

/// The model's random vectors, the first of the Verilator test's streams, through each wrapper in rust-hdl, under
/// random gaps, stalls and long stalls: every beat the model's, in order, no rule broken. rust-hdl runs these
/// pipelines behind their wrappers at about 3,500 clocks a second, so the suite sends 25,000 a pipeline (28 s), and
/// `BUMPRTL_RUST_HDL_VECTORS=100000` sends the Verilator test's full 100,000.
#[test]
fn random_streams_through_each_familys_wrapper_under_back_pressure_in_rust_hdl() {
    use rand::SeedableRng;
    let n = std::env::var("BUMPRTL_RUST_HDL_VECTORS").ok().and_then(|v| v.parse().ok()).unwrap_or(25_000);
    let runners: [(&UnitModel, &mut dyn AxisDut); 4] = [
        (&vectors::cart_pipeline::MODEL, &mut AxisRunner::new(CartAxis::build())),
        (&vectors::polar_pipeline::MODEL, &mut AxisRunner::new(PolarAxis::build())),
        (&vectors::height_pipeline::MODEL, &mut AxisRunner::new(HeightAxis::build())),
        (&vectors::palette_pipeline::MODEL, &mut AxisRunner::new(PaletteAxis::build())),
    ];
    for ((m, dut), (family, seed)) in runners.into_iter().zip(FAMILIES) {
        let name = m.name;
        assert_eq!(name, family);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let inputs: Vec<Vec<i64>> = (0..n).map(|_| (m.random)(&mut rng)).collect();
        let r = run(dut, m, &inputs, Traffic::random(seed), None);
        r.assert_clean(&format!("{name}_axis, {n} random vectors"));
        assert_eq!(r.expected, inputs.len(), "{name}: every vector is a pixel");
    }
}
