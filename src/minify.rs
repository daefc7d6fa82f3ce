//! `bumprtl minify [SCENE.toml] --out DIR`: the texture unit's filters (nearest, the nearest texel of the nearest
//! MIP level, bilinear, trilinear; for a polar scene the polar pipelines' bilinear and trilinear, lit as they are;
//! for a palette scene the palette pipelines' nearest and nearest-MIP)
//! on one scene, the demo's torus by default, against a supersampled f64 ideal (`sim::minify`): the colour error
//! over every pixel and over the minified ones, as a table (DIR/minify.md, and printed), and as pictures: the
//! ideal, and each filter's frame beside its error heat map on one scale (DIR/minify_<filter>.png); then the MIP
//! filters over a sweep of LOD biases. The scene is read (or refused) before anything is written.

use sim::minify::{self, Line, MINIFIED};
use sim::render::{write_png, BACKGROUND};
use std::fmt::Write as _;
use std::path::Path;

/// The heat maps' scale: an error of this many 8-bit LSB or more is white.
pub const HEAT_MAX: f64 = 64.0;

fn table(name: &str, n: usize, bias: f64, ideal: &minify::Ideal, lines: &[Line], swept: &[minify::Swept]) -> String {
    let minified = ideal.lambda.iter().filter(|&&l| l > MINIFIED).count();
    let mut s = String::new();
    let _ = writeln!(s, "# Minification: {name}\n");
    let _ = writeln!(
        s,
        "Colour error in 8-bit LSB (mean / max of the worst channel) of each filter's pipeline (the bit-exact model, \
         which the rtl equals) against the ideal supersampled {n} × {n} a pixel through level 0 of the map in f64; \
         {} pixels, {minified} of them minified (λ > {MINIFIED}). Beside it, the same filter computed in f64 on \
         the float MIP chain the unit's memory is loaded from (each level's texel the normalised mean of the four \
         under it): the method's own error, without the texels' encoding or the datapath's widths. The MIP filters \
         read λ + {bias} (the LOD bias).{}\n",
        ideal.rgb.len(),
        match ideal.shading {
            minify::Shading::Polar { pw, h } => format!(
                " Polar texels (US 6,819,319's first embodiment): the filters are the polar pipelines' on the texture \
                 unit, which filter S and R as numbers; the ideal is lit as they are, max(0, (1 − h) + h·N·L)^p with \
                 h = {h} and p = {}.",
                pw as f64 / 4.0
            ),
            minify::Shading::Palette { conc, s_n } => format!(
                " Tarini et al.'s palette: the filters are the palette pipelines' on the texture unit, the nearest \
                 texel of level 0 and of the nearest level of the index map's §5.2 chain (each texel the index \
                 nearest the mean of the four normals below it), s_N = {s_n}, one light a frame (the quad \
                 centre's); the ideal is lit as the Cartesian pipelines' at C = {conc}, under each pixel's own light, \
                 so the error counts the palette, the one light and the sampling."
            ),
            minify::Shading::Gloss(_) => String::new(),
        }
    );
    let _ = writeln!(
        s,
        "| filter | pipeline | all pixels | minified (λ > {MINIFIED}) | the filter in f64: all | in f64: minified |"
    );
    let _ = writeln!(s, "| --- | --- | --- | --- | --- | --- |");
    for l in lines {
        let _ = writeln!(
            s,
            "| {} | {} | {:.3} / {:.1} | {:.3} / {:.1} | {:.3} / {:.1} | {:.3} / {:.1} |",
            l.filter.name(),
            l.pipeline,
            l.all.mean(),
            l.all.max,
            l.minified.mean(),
            l.minified.max,
            l.method_all.mean(),
            l.method_all.max,
            l.method_minified.mean(),
            l.method_minified.max
        );
    }
    // the same errors by band of λ: the share of the pixels in each, and each filter's mean there
    let band_name = |k: usize| match k {
        0 => format!("λ ≤ {}", minify::BANDS[0]),
        k if k + 1 == minify::BANDS.len() => format!("λ > {}", minify::BANDS[k - 1]),
        k => format!("{} < λ ≤ {}", minify::BANDS[k - 1], minify::BANDS[k]),
    };
    let _ = writeln!(s, "\nMean colour error by band of λ (the pixels in each band in brackets):\n");
    let counts: Vec<u64> = lines.first().map(|l| l.bands.iter().map(|b| b.count).collect()).unwrap_or_default();
    let heads: Vec<String> = (0..minify::BANDS.len()).map(|k| format!("{} ({})", band_name(k), counts[k])).collect();
    let _ = writeln!(s, "| filter | {} |", heads.join(" | "));
    let _ = writeln!(s, "| --- |{}", " --- |".repeat(heads.len()));
    for l in lines {
        let cells: Vec<String> = l.bands.iter().map(|b| format!("{:.3}", b.mean())).collect();
        let _ = writeln!(s, "| {} | {} |", l.filter.name(), cells.join(" | "));
    }
    let by = |f: sim::pipelines::Filter| lines.iter().find(|l| l.filter == f).map(|l| l.minified.mean());
    if let (Some(b), Some(t)) = (by(sim::pipelines::Filter::Bilinear), by(sim::pipelines::Filter::Trilinear)) {
        let _ = writeln!(
            s,
            "\nOn the minified pixels trilinear's mean error is {t:.3} LSB against bilinear's {b:.3}: {:.1} % of it.",
            100.0 * t / b.max(1e-12)
        );
    }
    // the sweep: each MIP filter's minified mean at each bias, the pipeline's and the method's in f64
    let mip: Vec<usize> =
        (0..minify::FILTERS.len()).filter(|&k| swept.iter().any(|w| w.hardware[k].is_some())).collect();
    let _ = writeln!(
        s,
        "\nThe MIP filters' mean error on the minified pixels by LOD bias (the pipeline / the filter in f64). The \
         isotropic rule's λ, read through trilinear's kernel (a level's texel, a box 2^λ texels wide, under \
         bilinear's tent as wide), blurs more than the pixel's own footprint; a negative bias trades that blur for \
         aliasing.\n"
    );
    let heads: Vec<&str> = mip.iter().map(|&k| minify::FILTERS[k].0.name()).collect();
    let _ = writeln!(s, "| bias | {} |", heads.join(" | "));
    let _ = writeln!(s, "| --- |{}", " --- |".repeat(heads.len()));
    for w in swept {
        let cells: Vec<String> = mip
            .iter()
            .map(|&k| format!("{:.3} / {:.3}", w.hardware[k].unwrap_or(f64::NAN), w.method[k].unwrap_or(f64::NAN)))
            .collect();
        let _ = writeln!(s, "| {} | {} |", w.bias, cells.join(" | "));
    }
    let tri = minify::FILTERS.iter().position(|f| f.0 == sim::pipelines::Filter::Trilinear);
    let best = tri.and_then(|k| {
        swept.iter().filter_map(|w| w.hardware[k].map(|e| (w.bias, e))).min_by(|a, b| a.1.total_cmp(&b.1))
    });
    if let (Some((bias, t)), Some(b)) = (best, by(sim::pipelines::Filter::Bilinear)) {
        let _ = writeln!(
            s,
            "\nTrilinear's best bias of the sweep is {bias}: {t:.3} LSB on the minified pixels against bilinear's \
             {b:.3}, {:.1} % of it ({:.1} % less).",
            100.0 * t / b.max(1e-12),
            100.0 * (1.0 - t / b.max(1e-12))
        );
    }
    s
}

pub fn run(path: Option<&Path>, out: &Path, samples: usize, bias: Option<f64>) -> Result<(), String> {
    if !(1..=16).contains(&samples) {
        return Err(format!("--samples {samples}: 1 to 16 a side"));
    }
    let spec = match path {
        Some(p) => sim::scene_file::load(p)?,
        None => sim::scene_file::demo()?,
    };
    let mut scene = spec.scene.clone();
    if let Some(b) = bias {
        scene.lod_bias = sim::scene_file::LodBias::try_from(b).map_err(|e| format!("--lod-bias {b}: {e}"))?.0;
    }
    let scene = &scene;
    let ideal = crate::progress::step(
        &format!("the supersampled ideal, {samples} × {samples} a pixel"),
        |i: &minify::Ideal| Some(format!("{} px", i.at.len())),
        || minify::ideal_shaded(scene, samples, minify::Shading::of(&spec)),
    );
    let named = |e: String| match path {
        Some(p) => format!("{}: {e}", p.display()),
        None => e,
    };
    let lines = crate::progress::step(
        "each filter of the texture unit",
        |l: &Result<Vec<_>, String>| l.as_ref().ok().map(|l| format!("{} filters", l.len())),
        || minify::measure(scene, &ideal),
    )
    .map_err(named)?;
    let swept = crate::progress::step(
        "the MIP filters over LOD biases",
        |l: &Result<Vec<_>, String>| l.as_ref().ok().map(|l| format!("{} rows", l.len())),
        || minify::sweep(scene, &ideal),
    )
    .map_err(named)?;
    crate::output::writable_folder(out)?;
    let size = scene.size;
    let mut ideal_at = vec![None; size * size];
    for (k, &at) in ideal.at.iter().enumerate() {
        ideal_at[at] = Some(ideal.rgb[k].map(|c| c.round().clamp(0.0, 255.0) as u8));
    }
    write_png(&out.join("minify_ideal.png"), size, |k| ideal_at[k].unwrap_or(BACKGROUND))?;
    for l in &lines {
        // the frame on the left, its error on the right with its colour bar under it
        let heat = sim::render::heat_image(size, |k| l.error[k], HEAT_MAX, "LSB")?;
        let mut img = image::RgbImage::from_pixel(2 * size as u32, heat.height(), image::Rgb(BACKGROUND));
        for k in 0..size * size {
            let (x, y) = ((k % size) as u32, (k / size) as u32);
            img.put_pixel(x, y, image::Rgb(l.frame[k].unwrap_or(BACKGROUND)));
        }
        image::imageops::replace(&mut img, &heat, size as i64, 0);
        sim::render::save_png(&out.join(format!("minify_{}.png", l.filter.name())), &img)?;
    }
    let text = table(&spec.name, samples, scene.lod_bias, &ideal, &lines, &swept);
    let md = out.join("minify.md");
    let tmp = md.with_extension("md.partial");
    std::fs::write(&tmp, &text)
        .and_then(|_| std::fs::rename(&tmp, &md))
        .map_err(|e| format!("cannot write {}: {e}", md.display()))?;
    print!("{text}");
    println!(
        "\nwrote {}: the ideal (minify_ideal.png), each filter's frame and its error, black 0 to white {HEAT_MAX} LSB \
         on the bar under it (minify_<filter>.png)",
        out.display()
    );
    Ok(())
}
