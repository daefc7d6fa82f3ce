//! The analytic surfaces: their frames right-handed and unit along the parameters, the rasteriser's cover of a
//! sphere and of a torus.
use sim::surface::*;
use std::f64::consts::{PI, TAU};

fn shapes() -> [Shape; 2] {
    [Shape::Sphere, Shape::Torus { minor: 0.3 }]
}

#[test]
fn frames_are_right_handed_unit_and_follow_the_parameters() {
    for s in shapes() {
        for (u, v) in [(0.1, 0.2), (0.5, 0.5), (0.8, 0.9), (0.33, 0.61)] {
            let f = s.frame(u, v);
            for a in [f.t, f.n, f.b] {
                assert!((dot(a, a) - 1.0).abs() < 1e-9, "{s:?} {u} {v}");
            }
            assert!(dot(f.t, f.n).abs() < 1e-9 && dot(f.n, f.b).abs() < 1e-9);
            // T and B along the surface's own derivatives, N outwards
            let e = 1e-6;
            let p = s.point(u, v);
            let du = s.point(u + e, v);
            let dv = s.point(u, v + e);
            let (pu, pv) =
                (unit([du[0] - p[0], du[1] - p[1], du[2] - p[2]]), unit([dv[0] - p[0], dv[1] - p[1], dv[2] - p[2]]));
            assert!(
                dot(pu, f.t) > 0.999 && dot(pv, f.b) > 0.999,
                "{s:?} at ({u}, {v}): {:?} {:?}",
                dot(pu, f.t),
                dot(pv, f.b)
            );
            assert!(dot(f.n, pu).abs() < 1e-5 && dot(f.n, pv).abs() < 1e-5);
            // outwards: away from the centre (sphere), away from the tube's centre line (torus)
            let centre = match s {
                Shape::Sphere => [0.0; 3],
                Shape::Torus { minor } => {
                    let th = TAU * u;
                    [(1.0 - minor) * th.cos(), 0.0, (1.0 - minor) * th.sin()]
                }
            };
            assert!(dot(f.n, [p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]]) > 0.0);
        }
    }
}

#[test]
fn a_sphere_covers_its_disc_and_shows_its_near_side() {
    let size = 128;
    let m = tessellate(Shape::Sphere, 48, 24);
    let view = View { tilt_deg: 20.0, spin_deg: 30.0 };
    let c = rasterise(&m, view, size);
    // the unit disc's area in pixels: π (size / 2.2)²; the tessellation's polygon is a little smaller
    let disc = PI * (size as f64 / (2.0 * SCREEN_HALF)).powi(2);
    assert!((c.len() as f64 / disc - 1.0).abs() < 0.03, "{} of {disc:.0}", c.len());
    // every covered pixel's point faces the camera
    let to_cam = view.towards_camera();
    for cv in &c {
        let t = m.tris[cv.tri];
        let p: [f64; 3] = std::array::from_fn(|k| (0..3).map(|i| cv.bary[i] * m.p[t[i]][k]).sum());
        assert!(dot(unit(p), to_cam) > -0.05, "pixel {} sees the far side", cv.at);
        assert!((cv.bary.iter().sum::<f64>() - 1.0).abs() < 1e-9);
    }
    // frame order, no pixel twice
    assert!(c.windows(2).all(|w| w[0].at < w[1].at));
}

#[test]
fn a_torus_seen_from_above_has_its_hole() {
    let size = 96;
    let m = tessellate(Shape::Torus { minor: 0.3 }, 64, 32);
    let c = rasterise(&m, View { tilt_deg: 90.0, spin_deg: 0.0 }, size);
    let covered = |x: usize, y: usize| c.iter().any(|cv| cv.at == y * size + x);
    assert!(!covered(size / 2, size / 2), "the hole");
    assert!(covered(size / 2, size / 2 + (0.7 / SCREEN_HALF * size as f64 / 2.0) as usize), "the ring");
    assert!(!covered(2, 2), "a corner");
}
