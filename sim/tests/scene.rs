//! The demo scene at a small size: every pipeline bit-identical across model, rust-hdl and Verilator, and the
//! seed's polar shortcomings shown, not hidden (these are the demo's claims; a change that hid one fails here).
use vectors::polar_encode::Scale;
use vectors::scene::Scene;

const SIZE: usize = 48;

fn scene() -> Scene {
    Scene { size: SIZE, ..Scene::default() }
}

fn agree<U: rtl::StreamUnit>(m: &vectors::UnitModel, inputs: &[Vec<i64>]) {
    let model = sim::render::model(m, SIZE, inputs);
    let hdl = sim::render::rust_hdl::<U>(m, SIZE, inputs, &|_| {});
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("bumprtl-scene-{}-{}", m.name, std::process::id()));
    let vl = sim::render::verilator::<U>(m, SIZE, inputs, &dir, 2).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(model.p, hdl.p, "{}: rust-hdl", m.name);
    assert_eq!(model.rgb, hdl.rgb, "{}: rust-hdl", m.name);
    // the frame on one model and split across two threads
    for (how, img) in [("one thread", &vl.single), ("two threads", &vl.image)] {
        assert_eq!(model.p, img.p, "{}: Verilator, {how}", m.name);
        assert_eq!(model.rgb, img.rgb, "{}: Verilator, {how}", m.name);
    }
}

#[test]
fn every_pipeline_renders_bit_identically_in_the_three_paths() {
    let s = scene();
    agree::<rtl::cart_pipeline::CartPipeline>(&vectors::cart_pipeline::MODEL, &s.prepare().inputs);
    let hemi = Scene { encoder: vectors::cart_encode::Encoder::HemiOct, ..s.clone() };
    agree::<rtl::cart_pipeline::CartPipelineHemiOct>(&vectors::cart_pipeline::MODEL_HEMI_OCT, &hemi.prepare().inputs);
    agree::<rtl::polar_pipeline::PolarPipelineSeed>(&vectors::polar_pipeline::MODEL, &s.prepare_polar(Scale::Seed, 16, 1.0).inputs);
    agree::<rtl::polar_pipeline::PolarPipelineDc>(&vectors::polar_pipeline::MODEL_DC, &s.prepare_polar(Scale::Dc255, 16, 1.0).inputs);
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[test]
fn filtering_s_and_r_as_numbers_goes_wrong_across_the_wrap() {
    let p = scene().prepare_polar(Scale::Seed, 4, 1.0);
    let (mut wrap, mut rest) = ((0.0, 0), (0.0, 0));
    for k in 0..SIZE * SIZE {
        let shade = vectors::polar_pipeline::exact_trace(Scale::Seed, &p.inputs[k]).shade as f64;
        let e = (shade - 255.0 * dot(p.normal[k], p.surface_dir).clamp(0.0, 1.0)).abs();
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
    let c = low.prepare();
    let p = low.prepare_polar(Scale::Seed, 4, 1.0);
    assert!(p.light.moved && p.light.t == 0.0 && p.light.k2 == 0);
    let (mut ce, mut pe) = (0.0, 0.0);
    for k in 0..SIZE * SIZE {
        let ideal = 255.0 * dot(p.normal[k], p.light_dir[k]).max(0.0);
        let x = vectors::cart_pipeline::exact_trace(&c.inputs[k]).x as f64 / 1023.0 * 255.0;
        ce += (x - ideal).abs();
        pe += (vectors::polar_pipeline::exact_trace(Scale::Seed, &p.inputs[k]).shade as f64 - ideal).abs();
    }
    assert!(pe > 5.0 * ce, "polar {pe:.0} against Cartesian {ce:.0} summed LSB");
}
