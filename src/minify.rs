//! `bumprtl minify [SCENE.toml] --out DIR`: the texture unit's filters (nearest, the nearest texel of the nearest
//! MIP level, bilinear, trilinear) on one scene, the demo's torus by default, against a supersampled f64 ideal
//! (`sim::minify`): the colour error over every pixel and over the minified ones, as a table (DIR/minify.md, and
//! printed), and as pictures: the ideal, and each filter's frame beside its error heat map on one scale
//! (DIR/minify_<filter>.png). The scene is read (or refused) before anything is written.

use sim::minify::{self, Line, MINIFIED};
use sim::render::{heat, write_png, BACKGROUND};
use std::fmt::Write as _;
use std::path::Path;

/// The heat maps' scale: an error of this many 8-bit LSB or more is white.
pub const HEAT_MAX: f64 = 64.0;

fn table(name: &str, n: usize, ideal: &minify::Ideal, lines: &[Line]) -> String {
    let minified = ideal.lambda.iter().filter(|&&l| l > MINIFIED).count();
    let mut s = String::new();
    let _ = writeln!(s, "# Minification: {name}\n");
    let _ = writeln!(
        s,
        "Colour error in 8-bit LSB (mean / max of the worst channel) of each filter's pipeline (the bit-exact model, \
         which the rtl equals) against the ideal supersampled {n} × {n} a pixel through level 0 of the map in f64; \
         {} pixels, {minified} of them minified (λ > {MINIFIED}). Beside it, the same filter computed in f64 on \
         the float MIP chain the unit's memory is loaded from (each level's texel the normalised mean of the four \
         under it): the method's own error, without the texels' encoding or the datapath's widths.\n",
        ideal.rgb.len()
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
    s
}

pub fn run(path: Option<&Path>, out: &Path, samples: usize) -> Result<(), String> {
    if !(1..=16).contains(&samples) {
        return Err(format!("--samples {samples}: 1 to 16 a side"));
    }
    let spec = match path {
        Some(p) => sim::scene_file::load(p)?,
        None => sim::scene_file::demo()?,
    };
    let scene = &spec.scene;
    let ideal = minify::ideal(scene, samples);
    let lines = minify::measure(scene, &ideal).map_err(|e| match path {
        Some(p) => format!("{}: {e}", p.display()),
        None => e,
    })?;
    crate::output::writable_folder(out)?;
    let size = scene.size;
    let mut ideal_at = vec![None; size * size];
    for (k, &at) in ideal.at.iter().enumerate() {
        ideal_at[at] = Some(ideal.rgb[k].map(|c| c.round().clamp(0.0, 255.0) as u8));
    }
    write_png(&out.join("minify_ideal.png"), size, |k| ideal_at[k].unwrap_or(BACKGROUND))?;
    for l in &lines {
        // the frame on the left, its error on the right
        let mut img = image::RgbImage::new(2 * size as u32, size as u32);
        for k in 0..size * size {
            let (x, y) = ((k % size) as u32, (k / size) as u32);
            img.put_pixel(x, y, image::Rgb(l.frame[k].unwrap_or(BACKGROUND)));
            img.put_pixel(x + size as u32, y, image::Rgb(l.error[k].map_or(BACKGROUND, |e| heat(e, HEAT_MAX))));
        }
        sim::render::save_png(&out.join(format!("minify_{}.png", l.filter.name())), &img)?;
    }
    let text = table(&spec.name, samples, &ideal, &lines);
    let md = out.join("minify.md");
    let tmp = md.with_extension("md.partial");
    std::fs::write(&tmp, &text)
        .and_then(|_| std::fs::rename(&tmp, &md))
        .map_err(|e| format!("cannot write {}: {e}", md.display()))?;
    print!("{text}");
    println!(
        "\nwrote {}: the ideal (minify_ideal.png), each filter's frame and its error, black 0 to white {HEAT_MAX} LSB \
         (minify_<filter>.png)",
        out.display()
    );
    Ok(())
}
