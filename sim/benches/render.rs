//! The bit-exact models against the f64 ideals on the demo scene, both pipelines, in one run.
use criterion::{criterion_group, criterion_main, Criterion};
use vectors::scene::Scene;

fn bench(c: &mut Criterion) {
    let scene = Scene { size: 64, ..Scene::default() };
    let p = scene.prepare();
    let mut g = c.benchmark_group("demo scene 64x64");
    g.sample_size(10);
    g.bench_function("Cartesian ideal (f64, scene set-up included)", |b| b.iter(|| scene.prepare().ideal_p.len()));
    g.bench_function("Cartesian bit-exact model", |b| b.iter(|| sim::render::model(&vectors::cart_pipeline::MODEL, p.size, &p.inputs).p.len()));
    let scale = vectors::polar_encode::Scale::Seed;
    let q = scene.prepare_polar(scale, 16, 1.0);
    g.bench_function("polar ideal (f64, scene set-up included)", |b| b.iter(|| scene.prepare_polar(scale, 16, 1.0).ideal_alpha.len()));
    g.bench_function("polar bit-exact model", |b| b.iter(|| sim::render::model(&vectors::polar_pipeline::MODEL, q.size, &q.inputs).p.len()));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
