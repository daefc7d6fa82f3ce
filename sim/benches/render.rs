//! The bit-exact model against the f64 ideal on the demo scene, in one run.
use criterion::{criterion_group, criterion_main, Criterion};
use vectors::scene::Scene;

fn bench(c: &mut Criterion) {
    let scene = Scene { size: 64, ..Scene::default() };
    let p = scene.prepare();
    let mut g = c.benchmark_group("demo scene 64x64");
    g.sample_size(10);
    g.bench_function("ideal (f64, scene set-up included)", |b| b.iter(|| scene.prepare().ideal_p.len()));
    g.bench_function("bit-exact model", |b| b.iter(|| sim::render::model(&vectors::cart_pipeline::MODEL, p.size, &p.inputs).p.len()));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
