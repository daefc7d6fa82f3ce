//! Minification: on the demo's torus, trilinear at the LOD bias its scene names beats bilinear on the minified
//! pixels against the supersampled ideal, and loses to it at no bias (the isotropic rule's over-blur the bias is
//! there for); the sweep's rows are the table's own measure at each bias.
use sim::minify::{self, FILTERS, SWEEP};
use sim::pipelines::Filter;
use std::path::Path;

fn minified(lines: &[minify::Line], f: Filter) -> f64 {
    lines.iter().find(|l| l.filter == f).expect("every filter measured").minified.mean()
}

#[test]
fn trilinear_beats_bilinear_where_the_map_is_minified_at_its_scenes_bias_and_not_without_one() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/torus_trilinear.toml");
    let spec = sim::scene_file::load(&path).unwrap();
    let scene = &spec.scene;
    assert_eq!(scene.lod_bias, -1.25, "the scene this test reads");
    let ideal = minify::ideal(scene, 4);
    let lines = minify::measure(scene, &ideal).unwrap();
    let (b, t) = (minified(&lines, Filter::Bilinear), minified(&lines, Filter::Trilinear));
    assert!(t < 0.97 * b, "trilinear {t:.3} against bilinear {b:.3} at bias {}", scene.lod_bias);
    // the same filter without a bias: more blur than the footprint, more error than bilinear's aliasing here
    let flat = sim::scene::Scene { lod_bias: 0.0, ..scene.clone() };
    let unbiased = minify::measure(&flat, &minify::ideal(&flat, 4)).unwrap();
    let t0 = minified(&unbiased, Filter::Trilinear);
    assert!(t0 > b && t0 > t, "trilinear {t0:.3} at bias 0, {t:.3} at −1.25, bilinear {b:.3}");
    // the bias moves only the MIP filters
    for f in [Filter::Nearest, Filter::Bilinear] {
        assert_eq!(minified(&lines, f), minified(&unbiased, f), "{}", f.name());
    }
}

#[test]
fn each_row_of_the_sweep_is_the_measure_at_that_bias() {
    let spec = sim::scene_file::demo().unwrap();
    let ideal = minify::ideal(&spec.scene, 2);
    let swept = minify::sweep(&spec.scene, &ideal).unwrap();
    assert_eq!(swept.iter().map(|w| w.bias).collect::<Vec<_>>(), SWEEP.to_vec());
    for w in [&swept[0], &swept[4]] {
        let at = sim::scene::Scene { lod_bias: w.bias, ..spec.scene.clone() };
        let lines = minify::measure(&at, &minify::ideal(&at, 2)).unwrap();
        for (k, (f, _)) in FILTERS.iter().enumerate() {
            let want = f.front().mip().then(|| minified(&lines, *f));
            assert_eq!(w.hardware[k], want, "{} at bias {}", f.name(), w.bias);
        }
    }
}
