//! tex_fetch: the map memory with its MIP chain, written texel by texel then read a footprint a clock, against the
//! model's stream: golden vectors three ways; random streams through rust-hdl and Verilator after the hard cases
//! have filled the chain they read; and a whole 128 × 128 chain (every level down to 1 × 1) written, then every
//! footprint of every level read, with its repeat seams, under Verilator; the same unit built for maps up to
//! 256 × 256, likewise.
use rtl::tex_fetch::TexFetch;
use testbench::{external, random_vs_model, rust_hdl, unit_tests, Bubbles};
use vectors::tex_fetch::{self as tf, load, pattern, read, MAX_LOG_SIDE, MODEL};
use vectors::UnitModel;

unit_tests!(tex_fetch, TexFetch, MODEL);

#[test]
fn tex_fetch_random_vs_model() {
    random_vs_model::<TexFetch>(&MODEL, 20, 2_000);
}

#[test]
fn tex_fetch_random_after_the_hard_cases_verilator() {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(19);
    let mut inputs = (MODEL.hard_cases)();
    inputs.extend((0..50_000).map(|_| (MODEL.random)(&mut rng)));
    external::<TexFetch>(synth::cosim::Simulator::Verilator, &MODEL, &inputs, Bubbles::Random { one_in: 3, seed: 19 })
        .assert_clean("verilator, random");
}

#[test]
fn tex_fetch_hard_cases() {
    rust_hdl::<TexFetch>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
}

#[test]
fn tex_fetch_a_whole_chain_written_then_every_footprint_of_every_level() {
    // 21,845 texels written, then every footprint (with its right and lower neighbour, modulo the side) of every
    // level: 21,845 reads, each against the texel pattern the writes put there
    let inputs = whole_chain(MAX_LOG_SIDE, vectors::tex_fetch::run);
    external::<TexFetch>(synth::cosim::Simulator::Verilator, &MODEL, &inputs, Bubbles::BackToBack)
        .assert_clean("verilator, a whole chain");
}

/// A whole chain of a map of side 2^top written (`pattern`), then every footprint (with its right and lower
/// neighbour, modulo the side) of every level read; the model (`run`) checked to read back the pattern there (the
/// layout holds every texel apart). The stream, for the rtl.
fn whole_chain(top: i64, run: fn(&[Vec<i64>]) -> Vec<Vec<i64>>) -> Vec<Vec<i64>> {
    let mut inputs = load(top, pattern);
    let mut want = vec![];
    for m in 0..=top {
        let side = 1i64 << m;
        for y in 0..side {
            for x in 0..side {
                let (xs, ys) = ([x, (x + 1) % side], [y, (y + 1) % side]);
                inputs.push(read(m, xs, ys));
                want.push(
                    [(xs[0], ys[0]), (xs[1], ys[0]), (xs[0], ys[1]), (xs[1], ys[1])].map(|(a, b)| pattern(m, a, b)),
                );
            }
        }
    }
    let got = run(&inputs);
    let reads = &got[got.len() - want.len()..];
    for (k, (g, w)) in reads.iter().zip(&want).enumerate() {
        assert_eq!(g.as_slice(), w.as_slice(), "side 2^{top}, read {k}");
    }
    inputs
}

fn exact_256(v: &[i64]) -> Vec<i64> {
    vectors::unit::run_machine::<tf::Chain<8>>(&[v.to_vec()]).remove(0)
}
fn random_256(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    (MODEL.random)(rng)
}
fn hard_256() -> Vec<Vec<i64>> {
    tf::hard_cases_with(8)
}

/// The unit built for maps up to 256 × 256 (`TexFetch<ALL, 15, 8>`, its model `Chain<8>`).
static M256: UnitModel = UnitModel::new("tex_fetch", (tf::INPUTS, tf::OUTPUTS), exact_256, random_256, hard_256)
    .with_stream::<tf::Chain<8>>();

/// Map sides up to 2^8 as a parameter: the hard cases at 256 (the top level's corners and edges, a side log2 past
/// it read as 8) and random streams three ways; then a whole 256 × 256 chain written and every footprint of every
/// level read under Verilator (87,381 texels each way).
#[test]
fn tex_fetch_at_256_three_ways_and_a_whole_256_chain_under_verilator() {
    use rand::SeedableRng;
    assert_eq!((tf::Levels::All.addr_bits_up_to(8), tf::Levels::All.base(9)), (15, 21_846));
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(29);
    let mut stream = hard_256();
    stream.extend((0..3_000).map(|_| random_256(&mut rng)));
    testbench::three_ways::<TexFetch<0, 15, 8>>(&M256, &stream, "tex_fetch_256");

    let inputs = whole_chain(8, vectors::unit::run_machine::<tf::Chain<8>>);
    let built = synth::cosim::build_as(
        &synth::Unit::of::<TexFetch<0, 15, 8>>(),
        synth::cosim::Simulator::Verilator,
        &testbench::work_dir("verilator", "tex_fetch_256_chain"),
        synth::cosim::Compile::Quick,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let s = testbench::slots(&M256, 1, &inputs, Bubbles::BackToBack);
    let out = built.run(&s).unwrap_or_else(|e| panic!("{e}"));
    testbench::check(&M256, rtl::tex_fetch::LATENCY, &inputs, &s, &out).assert_clean("verilator, a whole 256 chain");
}
