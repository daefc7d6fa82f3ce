//! The Verilator path against Verilator's own speed, on the same build and the same number of clocks: a whole
//! 256 × 256 frame of the demo scene through each pipeline's exported Verilog, run in this process on one model
//! and split across two (one per core), beside the library's bare loop (inputs made in C++, no memory traffic).
//! Needs Verilator (`bash .ci/run` installs it). Throughput is in clocks per second.
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rtl::StreamUnit;
use synth::cosim::{self, Simulator};
use vectors::UnitModel;

fn frame<U: StreamUnit>(c: &mut Criterion, m: &UnitModel, inputs: &[Vec<i64>]) {
    let slots: Vec<Option<Vec<u64>>> = inputs.iter().map(|v| Some(vectors::unit::to_patterns(v, m.inputs))).collect();
    let dir = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/cosim/bench").join(m.name);
    let built = cosim::build(&synth::Unit::of::<U>(), Simulator::Verilator, &dir).expect("a Verilator build");
    let cycles = (slots.len() + U::LATENCY + 1) as u64;
    let mut g = c.benchmark_group(format!("Verilator {}, 256x256 frame", m.name));
    g.sample_size(20);
    g.throughput(Throughput::Elements(cycles));
    g.bench_function("bare loop", |b| b.iter(|| built.bare(cycles).expect("bare loop")));
    g.bench_function("frame, 1 thread", |b| b.iter(|| built.run_frame(&slots).expect("frame").len()));
    g.bench_function("frame, 2 threads", |b| b.iter(|| built.run_split(&slots, 2, 0).expect("frame").len()));
    g.finish();
}

fn bench(c: &mut Criterion) {
    use sim::pipeline::{Cartesian, Pipeline, Polar};
    let scene = sim::scene::Scene::default();
    let cart = Cartesian::glossy(vectors::cart_pipeline::Decode::Seed).prepare(&scene);
    frame::<rtl::cart_pipeline::CartPipeline>(c, &vectors::cart_pipeline::MODEL, &cart.inputs);
    let polar = Polar::new(vectors::polar_encode::Scale::Seed, 16, 1.0).prepare(&scene);
    frame::<rtl::polar_pipeline::PolarPipelineSeed>(c, &vectors::polar_pipeline::MODEL, &polar.inputs);
}

criterion_group!(benches, bench);
criterion_main!(benches);
