//! US 6,819,319's polar shortcomings, measured on a scene: the polar path against an ideal lit by the surface's one
//! light and against its own codes; the pixels filtered across R's 255 → 0 wrap (with the Cartesian path on the same
//! pixels); a light below the horizon, through both paths' N·L.

use crate::pipeline::{Cartesian, Pipeline, Polar, PolarSetup};
use crate::prepared::Prepared;
use crate::render::Image;
use crate::scene::Scene;
use vectors::cart_pipeline::Decode;
use vectors::stats::ErrorStats;

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The seed's polar shortcomings, measured: the polar path against an ideal lit by the surface's one light and
/// against its own codes; the pixels filtered across R's wrap; a light below the horizon.
pub struct Shortcomings {
    pub surface: ErrorStats,
    pub own: ErrorStats,
    pub surface_ideal: Vec<f64>,
    pub wrap: ErrorStats,
    pub rest: ErrorStats,
    pub wrap_cartesian: ErrorStats,
    pub low_cartesian: ErrorStats,
    pub low_polar: ErrorStats,
    pub low_below_deg: f64,
    pub low_moved: bool,
    pub low_ideal: Vec<f64>,
    pub low_cx: Vec<f64>,
    pub low_px: Vec<f64>,
}

impl Shortcomings {
    /// `polar_model` is the polar pipeline's model frame on `scene` (set up as `setup`); `cart` the Cartesian
    /// pipeline with its set-up and model frame on the same scene.
    pub fn measure(
        scene: &Scene,
        polar: &Polar,
        setup: &PolarSetup,
        polar_model: &Image,
        cart: (&dyn Pipeline, &Prepared, &Image),
    ) -> Shortcomings {
        let n = scene.size * scene.size;
        let where_ = crate::render::pixel_at(scene.size);
        let pw_real = polar.pw as f64 / 4.0;
        let ideal = &setup.prepared.ideal;
        let surface_ideal: Vec<f64> = (0..n)
            .map(|k| {
                255.0
                    * ((1.0 - polar.h) + polar.h * dot(ideal[k].normal, setup.surface_dir))
                        .clamp(0.0, 1.0)
                        .powf(pw_real)
            })
            .collect();
        let mut s = Shortcomings {
            surface: ErrorStats::default(),
            own: ErrorStats::default(),
            surface_ideal,
            wrap: ErrorStats::default(),
            rest: ErrorStats::default(),
            wrap_cartesian: ErrorStats::default(),
            low_cartesian: ErrorStats::default(),
            low_polar: ErrorStats::default(),
            low_below_deg: 0.0,
            low_moved: false,
            low_ideal: vec![0.0; n],
            low_cx: vec![0.0; n],
            low_px: vec![0.0; n],
        };
        for k in 0..n {
            let a = polar.shade(&polar_model.outs[k]);
            let e = (a - s.surface_ideal[k]).abs();
            s.surface.add(e, || where_(k));
            let v = &setup.prepared.inputs[k];
            use vectors::polar_pipeline::input;
            let (sr, q, ks) = ((v[input::s], v[input::r]), v[input::q], (v[input::k1], v[input::k2], v[input::k3]));
            let own = vectors::polar_shade::ideal(polar.scale, sr.0, sr.1, q, ks.0, ks.1, ks.2).clamp(0.0, 255.0);
            s.own.add((a - vectors::power::ideal_real(own, v[input::pw])).abs(), || where_(k));
            if setup.straddles[k] {
                s.wrap.add(e, || where_(k));
                s.wrap_cartesian.add((cart.0.shade(&cart.2.outs[k]) - cart.1.ideal[k].shade).abs(), || where_(k));
            } else {
                s.rest.add(e, || where_(k));
            }
        }
        // a light below the horizon. Both pipelines' N·L before their shading curves (Cartesian: dot3's X; polar: the
        // clamped shade with h = 1), 8-bit, against 255·max(0, N·L) with the pixel's true light
        let low = Scene { light_pos: [-0.6, -0.12, 0.5], ..scene.clone() };
        let low_c = Cartesian::glossy(Decode::Seed).prepare(&low);
        let low_p = Polar { h: 1.0, ..*polar }.set_up(&low);
        s.low_below_deg = -low_p.prepared.ideal[n / 2].light[1].asin().to_degrees();
        s.low_moved = low_p.light.moved;
        for k in 0..n {
            let p = &low_p.prepared.ideal[k];
            s.low_ideal[k] = 255.0 * dot(p.normal, p.light).max(0.0);
            s.low_cx[k] = vectors::cart_pipeline::exact_trace(&low_c.inputs[k]).x as f64 / 1023.0 * 255.0;
            s.low_px[k] = vectors::polar_pipeline::exact_trace(polar.scale, &low_p.prepared.inputs[k]).shade as f64;
            s.low_cartesian.add((s.low_cx[k] - s.low_ideal[k]).abs(), || where_(k));
            s.low_polar.add((s.low_px[k] - s.low_ideal[k]).abs(), || where_(k));
        }
        s
    }
}
