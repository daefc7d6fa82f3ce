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

/// A polar scene: the polar pipelines on the texture unit against an ideal lit as they are, max(0, N·L)^p at the
/// scene's p = 4 (against the Cartesian ideal, N·L to the first power, their frames would be tens of LSB away);
/// where λ plus the bias is below level 0, trilinear reads level 0 alone and its frame is bilinear's.
#[test]
fn a_polar_scene_measures_the_polar_pipelines_against_an_ideal_lit_as_they_are() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/torus_polar_trilinear.toml");
    let spec = sim::scene_file::load(&path).unwrap();
    let shading = minify::Shading::of(&spec);
    assert_eq!(shading, minify::Shading::Polar { pw: 16, h: 1.0 });
    let scene = &spec.scene;
    let ideal = minify::ideal_shaded(scene, 2, shading);
    let lines = minify::measure(scene, &ideal).unwrap();
    assert_eq!(lines.iter().map(|l| l.pipeline).collect::<Vec<_>>(), ["polar_tex_bilinear", "polar_tex_trilinear"]);
    let cartesian = minify::ideal_shaded(scene, 2, minify::Shading::Gloss(0));
    let apart =
        ideal.rgb.iter().zip(&cartesian.rgb).map(|(a, b)| (a[0] - b[0]).abs()).sum::<f64>() / ideal.rgb.len() as f64;
    for l in &lines {
        assert!(
            l.all.mean() < 4.0 && 5.0 * l.all.mean() < apart,
            "{}: {:.3}, the ideals {apart:.3} apart",
            l.pipeline,
            l.all.mean()
        );
    }
    let level0: Vec<usize> = (0..ideal.at.len()).filter(|&k| ideal.lambda[k] + scene.lod_bias < -0.1).collect();
    assert!(level0.len() > 1000, "{} pixels read level 0 alone", level0.len());
    for k in level0 {
        let at = ideal.at[k];
        assert_eq!(lines[0].frame[at], lines[1].frame[at], "pixel {at}: λ {:.3}", ideal.lambda[k]);
    }
}

/// A palette scene minified (scenes/palette_nearest_mip.toml: 128 texels into 64 pixels, λ = 1 everywhere)
/// measures the palette pipelines on the unit, nearest and nearest-MIP, against the Cartesian ideal at its C; the
/// MIP level, §5.2's index nearest the mean of four normals, gives less error than skipping every other texel of
/// level 0, and the frames differ where the four texels under a level-1 texel hold different indices.
#[test]
fn a_palette_scene_minified_reads_its_index_maps_mip_level_and_errs_less_than_level_0() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/palette_nearest_mip.toml");
    let spec = sim::scene_file::load(&path).unwrap();
    let shading = minify::Shading::of(&spec);
    assert_eq!(shading, minify::Shading::Palette { conc: 96, s_n: 256 });
    let ideal = minify::ideal_shaded(&spec.scene, 4, shading);
    assert!(ideal.lambda.iter().all(|&l| (l - 1.0).abs() < 1e-9), "the quad at half scale: λ = 1");
    let lines = minify::measure(&spec.scene, &ideal).unwrap();
    assert_eq!(
        lines.iter().map(|l| l.pipeline).collect::<Vec<_>>(),
        ["palette_tex_nearest", "palette_tex_nearest_mip"]
    );
    let (nearest, mip) = (minified(&lines, Filter::Nearest), minified(&lines, Filter::NearestMip));
    assert!(mip < nearest, "nearest_mip {mip:.3} against nearest {nearest:.3}");
    let differ = lines[0].frame.iter().zip(&lines[1].frame).filter(|(a, b)| a != b).count();
    assert!(differ > 20, "{differ} pixels differ");
}
