//! rust-hdl's two ways of running a block, on the same stream of gloss vectors: a plain loop calling `simulate`
//! (what the tests and the demo use) against rust-hdl's threaded `Simulation` (clock and testbench threads
//! exchanging the circuit over channels). Throughput is reported in cycles per second.
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rand::SeedableRng;
use rtl::gloss::Gloss;
use rtl::stream::{run_threaded, Runner};
use rtl::StreamUnit;

fn bench(c: &mut Criterion) {
    let model = &vectors::gloss::MODEL;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
    let slots: Vec<Option<Vec<u64>>> =
        (0..2000).map(|_| Some((model.random)(&mut rng).iter().map(|&v| v as u64).collect())).collect();
    let cycles = (slots.len() + Gloss::LATENCY + 1) as u64;
    let mut g = c.benchmark_group("rust-hdl gloss, 2000 vectors");
    g.sample_size(10);
    g.throughput(Throughput::Elements(cycles));
    g.bench_function("loop-driven simulate", |b| {
        b.iter(|| Runner::<Gloss>::new().run(slots.iter().cloned()).outputs.len())
    });
    g.bench_function("threaded Simulation", |b| {
        b.iter(|| run_threaded::<Gloss>(slots.clone()).expect("simulation").outputs.len())
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
