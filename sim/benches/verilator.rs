//! The Verilator path against Verilator's own speed, on the same build of `cart_pipeline` and the same number of
//! clocks: a whole 128 × 128 frame of the demo scene through the piped binary records (one process, and split
//! across two), beside the harness's bare loop (inputs made in C++, no I/O). Needs Verilator (`bash .ci/run`
//! installs it). Throughput is in clocks per second.
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rtl::cart_pipeline::CartPipeline;
use rtl::StreamUnit;
use synth::cosim::{self, Simulator};

fn bench(c: &mut Criterion) {
    let m = &vectors::cart_pipeline::MODEL;
    let prep = vectors::scene::Scene { size: 128, ..Default::default() }.prepare();
    let slots: Vec<Option<Vec<u64>>> =
        prep.inputs.iter().map(|v| Some(vectors::unit::to_patterns(v, m.inputs))).collect();
    let dir = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/cosim/bench/cart_pipeline");
    let built = cosim::build::<CartPipeline>(Simulator::Verilator, &dir).expect("a Verilator build");
    let cycles = (slots.len() + CartPipeline::LATENCY + 1) as u64;
    let mut g = c.benchmark_group("Verilator cart_pipeline, 128x128 frame");
    g.sample_size(20);
    g.throughput(Throughput::Elements(cycles));
    g.bench_function("bare loop", |b| b.iter(|| built.bare(cycles).expect("bare loop")));
    g.bench_function("frame, 1 process", |b| b.iter(|| built.run_records(&slots).expect("records").0.outputs.len()));
    g.bench_function("frame, 2 processes", |b| b.iter(|| built.run_split(&slots, 2).expect("records").0.outputs.len()));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
