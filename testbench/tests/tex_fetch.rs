//! tex_fetch: the map memory with its MIP chain, written texel by texel then read a footprint a clock, against the
//! model's stream: golden vectors three ways; random streams through rust-hdl and Verilator after the hard cases
//! have filled the chain they read; and a whole 128 × 128 chain (every level down to 1 × 1) written, then every
//! footprint of every level read, with its repeat seams, under Verilator.
use rtl::tex_fetch::TexFetch;
use testbench::{external, random_vs_model, rust_hdl, unit_tests, Bubbles};
use vectors::tex_fetch::{load, pattern, read, MAX_LOG_SIDE, MODEL};

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
    let mut inputs = load(MAX_LOG_SIDE, pattern);
    let mut want = vec![];
    for m in 0..=MAX_LOG_SIDE {
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
    // the model itself reads back the pattern: the layout holds every texel apart
    let got = vectors::tex_fetch::run(&inputs);
    let reads = &got[got.len() - want.len()..];
    for (k, (g, w)) in reads.iter().zip(&want).enumerate() {
        assert_eq!(g.as_slice(), w.as_slice(), "read {k}");
    }
    external::<TexFetch>(synth::cosim::Simulator::Verilator, &MODEL, &inputs, Bubbles::BackToBack)
        .assert_clean("verilator, a whole chain");
}
