//! The bit-exact model beside software written as a graphics programmer writes it: a scene's pixels through
//! `cart_pipeline` (the seed's texels, lights per vertex, gloss) three ways, each timed (its fastest of a few runs,
//! the frame's input vectors in and its output vectors out) and its error against the scene's ideal measured as the
//! demo measures the model's: the f64 method in reals a pixel at a time, the same in f32 eight pixels a step
//! (`vectors::cart_f32`; from the input vectors, and from its input already in f32 lanes, as a renderer keeps it),
//! and the bit-exact model on one thread and split across the cores.

use crate::pipeline::{errors, Cartesian, Errors, Pipeline};
use crate::render::{self, Image, Outs};
use crate::scene::Scene;
use vectors::cart_f32;
use vectors::cart_pipeline::Decode;

/// One way through the pixels: what it is, its frame (outputs and time) and its errors against the ideal.
pub struct Way {
    pub what: String,
    pub image: Image,
    pub errors: Errors,
}

/// The scene's pixels through the f64 method, the f32 SIMD peer and the model (on 1 and `threads` threads).
pub fn compare(scene: &Scene, threads: usize) -> Vec<Way> {
    let pipe = Cartesian::glossy(Decode::Seed);
    let prep = pipe.prepare(scene);
    let px = prep.pixels();
    let float = |f: fn(&[Vec<i64>]) -> Vec<i64>| {
        render::fastest(|| render::timed(prep.size, || Outs::new(cart_f32::OUTPUTS, f(px))))
    };
    let model = pipe.model();
    let ways: Vec<(String, Image)> = vec![
        ("f64 method in reals, 1 thread".into(), float(cart_f32::frame_f64)),
        ("f32 SIMD peer (8 lanes), 1 thread".into(), float(cart_f32::frame)),
        ("  the same, its input already in lanes".into(), {
            let lanes = cart_f32::lanes(px);
            let n = px.len();
            render::fastest(|| {
                render::timed(prep.size, || Outs::new(cart_f32::OUTPUTS, cart_f32::frame_of_lanes(&lanes, n)))
            })
        }),
        (render::on_threads("bit-exact model", 1), render::fastest(|| render::model_on(model, &prep, 1))),
        (render::on_threads("bit-exact model", threads), render::fastest(|| render::model_on(model, &prep, threads))),
    ];
    ways.into_iter()
        .map(|(what, image)| {
            let errors = errors(&pipe, scene, &prep, &image);
            Way { what, image, errors }
        })
        .collect()
}
