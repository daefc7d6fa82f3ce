//! The demo scene at a small size: every pipeline bit-identical across model, rust-hdl and Verilator, and the
//! seed's polar shortcomings shown, not hidden (these are the demo's claims; a change that hid one fails here).
use sim::pipeline::{Cartesian, Height, Palette, Pipeline, Polar};
use sim::scene::Scene;
use vectors::cart_pipeline::Decode;
use vectors::polar_encode::Scale;

const SIZE: usize = 48;

fn scene() -> Scene {
    Scene { size: SIZE, ..Scene::default() }
}

fn agree(p: &dyn Pipeline) {
    let (m, rtl) = (p.model(), p.rtl());
    let prep = p.prepare(&scene());
    let model = sim::render::model(m, &prep);
    let hdl = rtl.rust_hdl(m, &prep, &|_| {});
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "bumprtl-scene-{}-{}",
        m.name,
        std::process::id()
    ));
    let vl = rtl.verilator(m, &prep, &dir, 2).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(model.outs.len(), SIZE * SIZE);
    assert_eq!(model.outs, hdl.outs, "{}: rust-hdl", m.name);
    // the frame on one model and split across two threads
    for (how, img) in [("one thread", &vl.single), ("two threads", &vl.image)] {
        assert_eq!(model.outs, img.outs, "{}: Verilator, {how}", m.name);
    }
}

#[test]
fn every_pipeline_renders_bit_identically_in_the_three_paths() {
    agree(&Cartesian::glossy(Decode::Seed));
    agree(&Cartesian::glossy(Decode::HemiOct));
    agree(&Polar::new(Scale::Seed, 16, 1.0));
    agree(&Polar::new(Scale::Dc255, 16, 1.0));
    agree(&Height::new(&scene()));
    agree(&Palette::new(256, &scene()));
    agree(&Palette::new(4096, &scene()));
}

#[test]
fn the_height_path_lights_the_bumps_on_the_side_facing_the_light() {
    // the demo's light stands over the quad's upper left (u, v small): on the big bump at (0.25, 0.3), the texel
    // towards the light is brighter than the one away from it, in the bit-exact model
    let s = scene();
    let h = Height::new(&s);
    let p = h.prepare(&s);
    let model = sim::render::model(h.model(), &p);
    let at = |u: f64, v: f64| h.shade(&model.outs[(v * SIZE as f64) as usize * SIZE + (u * SIZE as f64) as usize]);
    assert!(at(0.18, 0.24) > at(0.32, 0.36) + 20.0, "towards {} away {}", at(0.18, 0.24), at(0.32, 0.36));
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[test]
fn filtering_s_and_r_as_numbers_goes_wrong_across_the_wrap() {
    let p = Polar::new(Scale::Seed, 4, 1.0).set_up(&scene());
    let (mut wrap, mut rest) = ((0.0, 0), (0.0, 0));
    for k in 0..SIZE * SIZE {
        let shade = vectors::polar_pipeline::exact_trace(Scale::Seed, &p.prepared.inputs[k]).shade as f64;
        let e = (shade - 255.0 * dot(p.prepared.ideal[k].normal, p.surface_dir).clamp(0.0, 1.0)).abs();
        let acc = if p.straddles[k] { &mut wrap } else { &mut rest };
        acc.0 += e;
        acc.1 += 1;
    }
    assert!(wrap.1 > 0, "the scene has pixels across R's wrap");
    let (w, r) = (wrap.0 / wrap.1 as f64, rest.0 / rest.1 as f64);
    assert!(w > 5.0 * r, "wrap pixels {w:.2} LSB against {r:.2} elsewhere");
}

#[test]
fn a_light_below_the_horizon_is_moved_onto_it_and_the_polar_path_pays_for_it() {
    let low = Scene { light_pos: [-0.6, -0.12, 0.5], ..scene() };
    let c = Cartesian::glossy(Decode::Seed).prepare(&low);
    let p = Polar::new(Scale::Seed, 4, 1.0).set_up(&low);
    assert!(p.light.moved && p.light.t == 0.0 && p.light.k2 == 0);
    let (mut ce, mut pe) = (0.0, 0.0);
    for k in 0..SIZE * SIZE {
        let i = &p.prepared.ideal[k];
        let ideal = 255.0 * dot(i.normal, i.light).max(0.0);
        let x = vectors::cart_pipeline::exact_trace(&c.inputs[k]).x as f64 / 1023.0 * 255.0;
        ce += (x - ideal).abs();
        pe += (vectors::polar_pipeline::exact_trace(Scale::Seed, &p.prepared.inputs[k]).shade as f64 - ideal).abs();
    }
    assert!(pe > 5.0 * ce, "polar {pe:.0} against Cartesian {ce:.0} summed LSB");
}

#[test]
fn the_palette_path_gets_closer_to_its_ideal_with_more_normals() {
    // under its own one light, the palette's shade error is what the quantization and the point sampling cost: it
    // falls as s_N grows, and the palette's normals get closer to the texels'
    let s = scene();
    let mut last = (f64::MAX, f64::MAX);
    for s_n in [16, 256, 4096] {
        let p = Palette::new(s_n, &s);
        let prep = p.prepare(&s);
        let model = sim::render::model(p.model(), &prep);
        let e: f64 = model
            .outs
            .iter()
            .zip(&prep.ideal)
            .map(|(o, i)| (p.shade(o) - p.surface_ideal(&s, i).unwrap()).abs())
            .sum::<f64>()
            / (SIZE * SIZE) as f64;
        let angle = p.built().unwrap().error.mean();
        assert!(e < last.0 && angle < last.1, "s_N {s_n}: shade {e:.3} LSB, {angle:.3}° after {last:?}");
        last = (e, angle);
    }
    assert!(last.0 < 1.0, "s_N 4096: {:.3} LSB", last.0);
}

#[test]
fn a_palette_of_one_normal_shades_the_frame_with_one_colour_in_the_model_and_in_rust_hdl() {
    let s = Scene { size: 16, ..scene() };
    let p = Palette::new(1, &s);
    let prep = p.prepare(&s);
    assert_eq!((prep.prologue, p.built().unwrap().codes.len()), (1, 1));
    let model = sim::render::model(p.model(), &prep);
    assert!(model.outs.iter().all(|o| *o == model.outs[0]), "one entry, one colour");
    assert_ne!(model.outs[0], vec![0; 4], "the entry was built before the first pixel read it");
    assert_eq!(p.rtl().rust_hdl(p.model(), &prep, &|_| {}).outs, model.outs);
}
