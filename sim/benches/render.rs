//! The bit-exact models against the f64 ideals on the demo scene, every pipeline, in one run, the model on one
//! thread and on two.
use criterion::{criterion_group, criterion_main, Criterion};
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
}

criterion_group!(benches, bench);
criterion_main!(benches);
