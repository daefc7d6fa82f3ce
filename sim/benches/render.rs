//! The bit-exact models against the f64 ideals on the demo scene, every pipeline, in one run, the model on one
//! thread and on two; then `cart_pipeline`'s pixels of the demo's quad through the model, the f64 method in reals
//! and the f32 SIMD peer (`vectors::cart_f32`), all from the same input vectors.
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use sim::pipeline::{Cartesian, Height, Palette, Pipeline, Polar};
use sim::scene::Scene;
use vectors::cart_pipeline::Decode;
use vectors::polar_encode::Scale;

fn bench(c: &mut Criterion) {
    let scene = Scene { size: 64, ..Scene::default() };
    let mut g = c.benchmark_group("demo scene 64x64");
    g.sample_size(10);
    let (height, palette) = (Height::new(&scene), Palette::new(256, &scene));
    let pipes: [&dyn Pipeline; 5] = [
        &Cartesian::glossy(Decode::Seed),
        &Cartesian::glossy(Decode::HemiOct),
        &Polar::new(Scale::Seed, 16, 1.0),
        &height,
        &palette,
    ];
    for p in pipes {
        let prep = p.prepare(&scene);
        g.bench_function(format!("{} ideal (f64, scene set-up included)", p.model().name), |b| {
            b.iter(|| p.prepare(&scene).ideal.len())
        });
        for threads in [1, 2] {
            g.bench_function(format!("{} bit-exact model, {threads} thread(s)", p.model().name), |b| {
                b.iter(|| sim::render::model_on(p.model(), &prep, threads).outs.len())
            });
        }
    }
    g.finish();

    let scene = Scene { size: 256, ..sim::scene_file::quad().expect("the embedded quad").scene };
    let cart = Cartesian::glossy(Decode::Seed);
    let prep = cart.prepare(&scene);
    let px = prep.pixels();
    let mut g = c.benchmark_group("cart_pipeline, the demo's quad 256x256");
    g.sample_size(20);
    g.throughput(Throughput::Elements(px.len() as u64));
    g.bench_function("bit-exact model (exact), 1 thread", |b| b.iter(|| sim::render::model(cart.model(), &prep)));
    g.bench_function("bit-exact model (exact), 2 threads", |b| {
        b.iter(|| sim::render::model_on(cart.model(), &prep, 2))
    });
    g.bench_function("f64 method in reals, 1 thread", |b| b.iter(|| vectors::cart_f32::frame_f64(px)));
    g.bench_function("f32 SIMD peer, 1 thread", |b| b.iter(|| vectors::cart_f32::frame(px)));
    let lanes = vectors::cart_f32::lanes(px);
    g.bench_function("f32 SIMD peer, its input already in lanes", |b| {
        b.iter(|| vectors::cart_f32::frame_of_lanes(&lanes, px.len()))
    });
    g.bench_function("f32 SIMD peer, the kernel alone (lanes in, P unrounded out)", |b| {
        b.iter(|| lanes.iter().map(|l| vectors::cart_f32::shade8(l)[0]).fold(wide::f32x8::splat(0.0), |a, p| a + p))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
