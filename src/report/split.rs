//! The shade's error split three ways: encoding, method, datapath.

use super::figures::stats;
use super::points::{settings, Point};
use sim::pipeline::Height;
use sim::pipelines::Family;
use sim::prepared::Prepared;
use sim::scene::Scene;
use vectors::cart_pipeline::Decode;
use vectors::stats::ErrorStats;

/// The split of a pipeline's shade error (8-bit units): encoding (the codes read as the directions they mean,
/// filtered as the ideal filters, shaded by the ideal's own curve `curve(n, l)`, against the ideal), method (the
/// pipeline's method in reals on those codes, `float(input)`, against the codes' meaning) and datapath (the model
/// against that float run).
fn split(
    scene: &Scene,
    meaning: &[[f64; 3]],
    prep: &Prepared,
    exact_shade: &[f64],
    curve: &dyn Fn([f64; 3], [f64; 3]) -> f64,
    float: &dyn Fn(&[i64]) -> f64,
) -> [(f64, f64); 3] {
    let frame = sim::raster::frame(scene, meaning);
    let (mut e, mut m, mut d) = (ErrorStats::default(), ErrorStats::default(), ErrorStats::default());
    for (k, px) in frame.pixels.iter().enumerate() {
        let s_enc = curve(px.normal, px.light);
        let s_float = float(&prep.pixels()[k]);
        e.add((s_enc - prep.ideal[k].shade).abs(), || format!("pixel {k}"));
        m.add((s_float - s_enc).abs(), || format!("pixel {k}"));
        d.add((exact_shade[k] - s_float).abs(), || format!("pixel {k}"));
    }
    [stats(&e), stats(&m), stats(&d)]
}

/// What each texel's Cartesian code means, as a unit vector.
fn cartesian_meaning(scene: &Scene, decode: Decode) -> Vec<[f64; 3]> {
    use vectors::cart_encode::{self, Encoder};
    let enc = if decode == Decode::Seed { Encoder::Seed } else { Encoder::HemiOct };
    scene
        .normals()
        .iter()
        .map(|&n| {
            let t = cart_encode::encode(enc, n);
            match decode {
                Decode::Seed => vectors::cart_decode::ideal(t.0, t.1),
                Decode::HemiOct => vectors::cart_decode_hemi_oct::ideal(t.0, t.1),
            }
        })
        .collect()
}

/// The three parts for the pipelines that have a float run of their method: the Cartesian ones (N·L through the
/// gloss curve) and the polar one (equation 3 on its own codes, then p's power, both in reals).
pub(super) fn three_parts(p: &Point, scene: &Scene, prep: &Prepared, exact_shade: &[f64]) -> Option<[(f64, f64); 3]> {
    let gloss = |n: [f64; 3], l: [f64; 3]| sim::pipeline::gloss_shade(scene.conc, n, l);
    let p10 = |p: f64| p / 1023.0 * 255.0;
    let own = settings(p);
    match p.row.family {
        Family::Cartesian(d) => {
            let g = p.row.serves.gloss;
            // a matte pipeline's vectors are the full one's without C (which is 0)
            let float = |i: &[i64]| {
                let full = if g { i.to_vec() } else { vectors::cart_pipeline::with_zero_conc(i) };
                p10(vectors::cart_pipeline::float_p(d, &full))
            };
            Some(split(scene, &cartesian_meaning(scene, d), prep, exact_shade, &gloss, &float))
        }
        Family::CartSurface(v) => {
            Some(split(scene, &cartesian_meaning(scene, v.decode), prep, exact_shade, &gloss, &|i| {
                p10(vectors::cart_surface::float_p(v, i))
            }))
        }
        Family::Polar(sc) => {
            use vectors::polar_encode;
            use vectors::polar_pipeline::input;
            let meaning: Vec<[f64; 3]> = scene
                .normals()
                .iter()
                .map(|&n| {
                    let (s, r) = polar_encode::encode_normal(sc, n);
                    polar_encode::decode_normal(sc, s, r)
                })
                .collect();
            let (h, p) = (own.h, own.pw as f64 / 4.0);
            let curve = |n: [f64; 3], l: [f64; 3]| {
                255.0 * ((1.0 - h) + h * (n[0] * l[0] + n[1] * l[1] + n[2] * l[2])).clamp(0.0, 1.0).powf(p)
            };
            let float = |i: &[i64]| {
                let own = vectors::polar_shade::ideal(
                    sc,
                    i[input::s],
                    i[input::r],
                    i[input::q],
                    i[input::k1],
                    i[input::k2],
                    i[input::k3],
                )
                .clamp(0.0, 255.0);
                vectors::power::ideal_real(own, i[input::pw])
            };
            Some(split(scene, &meaning, prep, exact_shade, &curve, &float))
        }
        Family::Height => Some(height_parts(scene, own.height_bits, prep, exact_shade)),
        // the texture unit's pipelines: no float run of the front yet (its texel comes out of the memory's stream)
        Family::CartTex { .. } => None,
        Family::Palette => {
            let s_n = own.palette.unwrap_or(1 << p.row.serves.index_bits);
            // a texel's index means its entry: the S10 code the table builder takes, as a unit vector
            let normals = scene.normals();
            let q = vectors::palette::quantize::quantize(&normals, s_n);
            let entry: Vec<[f64; 3]> = q
                .palette
                .iter()
                .map(|n| vectors::stats::unit(n.map(|c| ((c * 511.0).round()).clamp(-512.0, 511.0))))
                .collect();
            let meaning: Vec<[f64; 3]> = q.index.iter().map(|&k| entry[k as usize]).collect();
            let l = vectors::table_builder::sq1_10(scene.light_dir(0.5, 0.5)).map(|c| c as f64 / 1024.0);
            let float = |i: &[i64]| {
                sim::pipeline::gloss_shade(scene.conc, entry[i[vectors::palette_pipeline::input::idx] as usize], l)
            };
            Some(split(scene, &meaning, prep, exact_shade, &gloss, &float))
        }
    }
}

/// The height pipeline's three parts. Its texel codes are heights, whose normal needs a method, so the parts are
/// taken through the method: encoding (the B-spline in reals on the codes against the B-spline in reals on the
/// true heights), method (the B-spline in reals on the true heights against the ideal, the true surface's normal)
/// and datapath (the model against the B-spline in reals on the codes).
fn height_parts(scene: &Scene, bits: u32, prep: &Prepared, exact_shade: &[f64]) -> [(f64, f64); 3] {
    let (t, n) = (scene.tex, scene.size);
    let h = Height::heights(scene);
    let lo = h.iter().copied().fold(f64::MAX, f64::min);
    let (codes, k) = Height::codes_in(scene, bits);
    // the true heights in the codes' units (UQ6.2 steps: 4·m per texel of height, m = 16/k)
    let m = 16.0 / k as f64;
    let real: Vec<f64> = h.iter().map(|x| (x - lo) * 4.0 * m).collect();
    let pipe = Height::with_bits(scene, bits);
    let size_log2 = t.trailing_zeros() as i64;
    let kf = k as f64 / 16.0;
    let normal = |w: [f64; 9], ub: i64, vb: i64| {
        let (_, hu, hv) = vectors::height_pipeline::bspline(&w, ub as f64 / 256.0, vb as f64 / 256.0);
        vectors::height_normal::ideal(hu / 2.0, hv / 2.0, kf)
    };
    let (mut e, mut me, mut d) = (ErrorStats::default(), ErrorStats::default(), ErrorStats::default());
    for py in 0..n {
        for px in 0..n {
            let k_ = py * n + px;
            let (i, ub, j, vb) = Height::sample(px, py, n, t);
            let (xs, ys) =
                (vectors::height_fetch::axis(i, size_log2, false), vectors::height_fetch::axis(j, size_log2, false));
            let at = |q: usize| ys[q / 3] as usize * t + xs[q % 3] as usize;
            let (wt, wc): ([f64; 9], [f64; 9]) =
                (std::array::from_fn(|q| real[at(q)]), std::array::from_fn(|q| codes[at(q)] as f64));
            // the same window the pipeline was given
            assert_eq!(wc.map(|c| c as i64).to_vec(), prep.pixels()[k_][..9].to_vec(), "pixel ({px}, {py})");
            let (s_true, s_codes) = (pipe.shade_of(normal(wt, ub, vb)), pipe.shade_of(normal(wc, ub, vb)));
            e.add((s_codes - s_true).abs(), || format!("pixel ({px}, {py})"));
            me.add((s_true - prep.ideal[k_].shade).abs(), || format!("pixel ({px}, {py})"));
            d.add((exact_shade[k_] - s_codes).abs(), || format!("pixel ({px}, {py})"));
        }
    }
    [stats(&e), stats(&me), stats(&d)]
}
