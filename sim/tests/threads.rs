//! The model on several threads: every pipeline's frame split across threads (the prologue loaded once, each run
//! from a copy of the state it left) is its one-thread stream's, pixel for pixel, and the split does carry that state.
use sim::pipeline::{build, Pipeline};
use sim::pipelines::{named, Settings, PIPELINES};
use sim::scene::Scene;

/// A scene the pipeline renders (C = 0 for one without the gloss unit), prepared.
fn prepared(p: &dyn Pipeline, size: usize) -> sim::prepared::Prepared {
    let conc = if p.units().contains(&"gloss") { Scene::default().conc } else { 0 };
    let mut scene = Scene { size, conc, ..Scene::default() };
    if p.row().serves.colour {
        scene.colour_map = Some(std::sync::Arc::new(sim::heightmap::ColourMap::tiles(scene.tex)));
    }
    p.prepare(&scene)
}

#[test]
fn the_model_on_several_threads_is_the_one_thread_stream_on_every_pipeline() {
    for row in PIPELINES {
        let p = build(row, &Scene::default(), &Settings::default());
        let prep = prepared(p.as_ref(), 24);
        let m = p.model();
        // the stream from reset, vector by vector, every output made (the prologue's too), then cut
        let want: sim::render::Outs = m.run(&prep.inputs).split_off(prep.prologue).into_iter().collect();
        assert_eq!(want.len(), 24 * 24, "{}", m.name);
        for threads in [1, 2, 3, 7, want.len() + 5] {
            let got = sim::render::model_on(m, &prep, threads).outs;
            assert!(got == want, "{} on {threads} threads", m.name);
        }
    }
}

/// The runs read the state the prologue left: without it a palette's pixels read empty tables and a textured
/// pipeline's an empty memory, so the split frame of the pixels alone differs.
#[test]
fn a_frame_without_its_prologue_differs_so_the_runs_carry_its_state() {
    for name in ["palette_pipeline", "palette_pipeline_12", "cart_tex_bilinear", "cart_tex_trilinear_matte"] {
        let p = build(named(name).unwrap(), &Scene::default(), &Settings::default());
        let prep = prepared(p.as_ref(), 16);
        assert!(prep.prologue > 0, "{name} has a prologue");
        let w = p.model().outputs.len();
        let with = p.model().frame(&prep.inputs, prep.prologue, 2);
        let without = p.model().frame(&prep.inputs[prep.prologue..], 0, 2);
        assert_eq!((with.len(), without.len()), (256 * w, 256 * w));
        let differ = with.chunks_exact(w).zip(without.chunks_exact(w)).filter(|(a, b)| a != b).count();
        assert!(differ > 256 / 10, "{name}: {differ} of 256 pixels differ");
    }
}

/// A prologue loaded (its outputs not made) moves a unit's state as stepping through it does: on every unit of the
/// table, a stream of its hard cases and random vectors (writes among reads) cut at several places, the rest on one
/// thread, is the whole stream's tail.
#[test]
fn loading_a_prologue_leaves_the_state_stepping_leaves_on_every_unit() {
    use rand::SeedableRng;
    for u in sim::units::UNITS {
        let m = u.model;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(41);
        let mut v = (m.hard_cases)();
        v.extend((0..400).map(|_| (m.random)(&mut rng)));
        let all = m.run(&v);
        for cut in [0, 1, v.len() / 3, v.len() - 1, v.len()] {
            assert!(m.frame(&v, cut, 1) == all[cut..].concat(), "{} cut at {cut}", m.name);
        }
    }
}
