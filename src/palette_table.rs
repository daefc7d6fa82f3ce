//! `bumprtl palette-table`: the paper's Table 1 (Tarini et al. 2000, §8) on this machine. For s_N = 256, 2048 and
//! 16,384 normals quantized from one 512 × 512 normal map (the demo's procedural heights, §4.1's plane fit), the
//! per-frame table under Lambert, Lambert + specular, chrome and environment: the paper's Pentium-300 milliseconds,
//! this machine's (the bit-exact model of `table_builder` where the hardware builds the table, the f64 table where it
//! does not), the rtl builders' clocks and microseconds at their fmax (`table_builder` on the ECP5, one normal a
//! clock; the UP5K's shared builder, one every two clocks, where its RAM holds the tables), and two columns the paper lacks: the quantization's
//! angular error and the image error of the table against shading the unquantized normals the same way. Then the
//! quantizer's own time at every s_N from 16 to 16,384, and the paper's Figure 3 sweep (16 … 2048 normals) as
//! pictures of the map shaded through each palette, beside the unquantized one.

use std::time::Instant;
use vectors::palette::{plane_fit, quantize, table_builder, tables};
use vectors::stats::unit;

/// The paper's per-frame overhead, ms, for (256, 2048, 16,348 normals): Lambert, L + specular, chrome, environment.
const PAPER_MS: [[f64; 3]; 4] = [[0.0, 0.3, 3.9], [0.1, 1.2, 12.5], [0.0, 0.7, 8.6], [0.1, 1.7, 18.3]];
const SIZES: [usize; 3] = [256, 2048, 16_384];
const MAP: usize = 512;

/// The map's normals in the project frame (x along u, y up, z along v).
fn normal_map() -> Vec<[f64; 3]> {
    let relief = MAP as f64 / 16.0;
    let h: Vec<f64> = (0..MAP * MAP)
        .map(|k| {
            sim::scene::height(((k % MAP) as f64 + 0.5) / MAP as f64, ((k / MAP) as f64 + 0.5) / MAP as f64) * relief
        })
        .collect();
    plane_fit::normals(&h, MAP, MAP, 8)
}

/// A unit normal as the builder's S10 input: × 448, rounded (a flat normal is (0, 448, 0), exact after normalising).
fn s10(n: [f64; 3]) -> [i64; 3] {
    n.map(|c| (c * 448.0).round() as i64)
}

/// Seconds per call of `f`, the fastest of five runs of enough calls to last 20 ms.
fn per_call(mut f: impl FnMut()) -> f64 {
    let t = Instant::now();
    f();
    let once = t.elapsed().as_secs_f64().max(1e-7);
    let reps = ((0.02 / once) as usize).clamp(1, 100_000);
    (0..5)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..reps {
                f();
            }
            t.elapsed().as_secs_f64() / reps as f64
        })
        .fold(f64::MAX, f64::min)
}

/// Every palette size the quantizer sweep times, 16 to 16,384; Figure 3's pictures are the first eight.
const SWEEP: [usize; 11] = [16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192, 16_384];
const FIGURE_3: usize = 8;

/// The material of the pictures (RGBA), equation (1)'s o.
const MATERIAL: [f64; 4] = [0.85, 0.7, 0.5, 1.0];

/// The builders' placed fmax, MHz, when measured: `table_builder` on the ECP5-25F, `palette_pipeline_shared` (its
/// shared builder inside) on the UP5K; and for each how many placements it is the median of ("5", "4 of 5"), or
/// why it has none (a design that does not place).
#[derive(Clone, Debug, Default)]
pub struct Fmax {
    pub builder_mhz: Option<f64>,
    pub shared_mhz: Option<f64>,
    pub builder_placed: String,
    pub shared_placed: String,
}

/// How many placements a report's fmax is the median of, or why it has none.
fn placed(r: &synth::fpga::SynthReport) -> String {
    match &r.place_error {
        Some(e) => format!("{}: {e}", r.unplaced_text()),
        None => r.placed_of(),
    }
}

/// The largest palette `palette_pipeline_shared` holds: its 8-bit index (two tables of 256 words in 4 of the UP5K's
/// 30 block RAMs; 2 × 2,048 words would need 32).
const SHARED_MAX: usize = 256;

/// `bumprtl palette-table`: the rtl columns' fmax from placing the table builders (unless skipped, or the tools
/// are missing), then the table and Figure 3's pictures into `out`.
pub fn command(no_synth: bool, dir: &std::path::Path, out: &std::path::Path) -> Result<(), String> {
    crate::output::writable_folder(out)?; // before the minutes of work, synthesis included
    let tools = synth::tools::toolchain().missing().is_empty() && synth::tools::nextpnr_ecp5().is_some();
    let fmax = if no_synth || !tools {
        if !no_synth {
            println!("the rtl columns need yosys, nextpnr-ice40 and nextpnr-ecp5 (`bash .ci/run` installs them)");
        }
        Fmax::default()
    } else {
        let (ecp5, up5k) = (synth::fpga::ECP5_25F, synth::fpga::UP5K);
        let d = dir.join("table_builder").join(ecp5.name);
        let five = synth::fpga::Seeds::FIVE;
        let placed_line = |r: &Result<synth::fpga::SynthReport, String>| r.as_ref().ok().map(placed);
        let one = crate::progress::step(&format!("table_builder on the {}", ecp5.name), placed_line, || {
            synth::fpga::synth_and_place(
                &synth::Unit::of::<rtl::table_builder::TableBuilder>(),
                &d,
                ecp5,
                ecp5.default_freq(),
                "",
                five,
            )
        })?;
        let d = dir.join("palette_pipeline_shared").join(up5k.name);
        let shared =
            crate::progress::step(&format!("palette_pipeline_shared on the {}", up5k.name), placed_line, || {
                synth::fpga::synth_and_place(
                    &synth::Unit::of::<rtl::palette_pipeline_shared::PalettePipelineShared>(),
                    &d,
                    up5k,
                    up5k.default_freq(),
                    "",
                    five,
                )
            })?;
        Fmax {
            builder_mhz: one.fmax_mhz,
            shared_mhz: shared.fmax_mhz,
            builder_placed: placed(&one),
            shared_placed: placed(&shared),
        }
    };
    run(fmax, out)
}

pub fn run(fmax: Fmax, out: &std::path::Path) -> Result<(), String> {
    let normals = crate::progress::step(
        "the 512 x 512 normal map (plane fit)",
        |n: &Vec<[f64; 3]>| Some(format!("{} normals", n.len())),
        normal_map,
    );
    let view = [0.0, 1.0, 0.0];
    let light = unit([0.5, 0.8, 0.3]);
    let half = unit([0, 1, 2].map(|c| light[c] + view[c]));
    let (lq, hq) = (table_builder::sq1_10(light), table_builder::sq1_10(half));
    let (conc, spec) = (96, [255, 240, 200]);
    let models = ["Lambert", "Lambert + specular", "chrome", "environment"];
    let f64_model = |m: usize| if m == 2 { tables::Shading::Chrome } else { tables::Shading::Environment };
    // an entry from a palette normal: `normed` is the builder's normaliser output (Sq1.10) of the normal as the
    // palette stores it (S10); Lambert alone reads α, Lambert + specular the whole entry
    let entry = |m: usize, n: [f64; 3], normed: [i64; 3]| -> [i64; 4] {
        match m {
            0 => [0, 0, 0, vectors::dot3::exact(normed, lq) >> 2], // the builder's α path alone
            1 => table_builder::exact_normalised(normed, lq, hq, conc, spec),
            _ => tables::entry(&f64_model(m), n, view).map(|c| (c * 255.0).round().clamp(0.0, 255.0) as i64),
        }
    };
    let own = |m: usize, n: [f64; 3]| entry(m, n, vectors::normalise::exact(s10(n)));

    // the quantizer at every size, timed
    let mut sweep = vec![];
    let step = crate::progress::Step::new("the quantizer, 16 … 16,384 normals", Some(SWEEP.len() as u64));
    for (k, &s_n) in SWEEP.iter().enumerate() {
        step.tick(k as u64);
        let t = Instant::now();
        let q = quantize::quantize(&normals, s_n);
        let secs = t.elapsed().as_secs_f64();
        let angle = quantize::angular_error(&normals, &q.index, &q.palette);
        sweep.push((s_n, q, secs, angle));
    }
    step.done(&format!("{} palette sizes", SWEEP.len()));

    println!(
        "Table 1 of Tarini et al. (2000) on this machine: a 512 x 512 normal map (the demo's heights, plane fit q = 8)"
    );
    println!("per-frame table for s_N normals; paper: Pentium 300 MHz (its 16,384 row says 16348); model: one core here, the");
    println!("bit-exact table_builder with the palette's normals normalised once per map (the palette changes per map, not per");
    println!("frame: the same normaliser output the builder computes), chrome and environment in f64 (no rtl);");
    let at = |f: Option<f64>, place: &str, placed: &str| match f {
        Some(f) => format!("{f:.1} MHz (on the {place}, the median of {placed} placements)"),
        None if !placed.is_empty() => format!("its fmax (on the {place}: {placed})"),
        None => "its fmax (not measured: --no-synth, or the tools missing)".into(),
    };
    println!(
        "rtl µs: table_builder, one normal a clock (s_N + {} clocks) at {}",
        vectors_latency(),
        at(fmax.builder_mhz, "ECP5-25F", &fmax.builder_placed)
    );
    println!(
        "UP5K µs: palette_pipeline_shared's builder, one normal every two clocks (2·s_N + {} clocks) at {}; s_N ≤ {SHARED_MAX}",
        rtl::table_builder_shared::LATENCY,
        at(fmax.shared_mhz, "UP5K", &fmax.shared_placed)
    );
    println!(
        "{:<20} {:>6} {:>9} {:>11} {:>10} {:>9} {:>9} {:>16} {:>18}",
        "lighting",
        "s_N",
        "paper ms",
        "model ms",
        "speed-up",
        "rtl µs",
        "UP5K µs",
        "angle mean/max °",
        "image LSB mean/max"
    );
    let step = crate::progress::Step::new("the per-frame tables, timed", Some(SIZES.len() as u64));
    for (k, &s_n) in SIZES.iter().enumerate() {
        step.tick(k as u64);
        let (_, q, _, angle) = sweep.iter().find(|s| s.0 == s_n).expect("the sweep holds Table 1's sizes");
        let t = Instant::now();
        // the normaliser's outputs as a palette keeps them (Sq1.10 fits 16 bits), once per map
        let normed: Vec<[i16; 3]> =
            q.palette.iter().map(|&n| vectors::normalise::exact(s10(n)).map(|c| c as i16)).collect();
        let per_map = t.elapsed().as_secs_f64();
        let wide = |nn: [i16; 3]| nn.map(i64::from);
        for (m, name) in models.iter().enumerate() {
            // the table is rewritten in place every frame as the RAM holds it, a 32-bit RGBA word an entry
            let mut buf = vec![[0u8; 4]; q.palette.len()];
            let word = |e: [i64; 4]| e.map(|c| c as u8); // each U8 already

            // each model's loop on its own, compiled for its closure (no match and no indirect call per entry)
            let secs = match m {
                0 => fill(&mut buf, |k| [0, 0, 0, (vectors::dot3::exact(wide(normed[k]), lq) >> 2) as u8]),
                1 => fill(&mut buf, |k| word(table_builder::exact_normalised(wide(normed[k]), lq, hq, conc, spec))),
                _ => fill(&mut buf, |k| word(entry(m, q.palette[k], wide(normed[k])))),
            };
            let table: Vec<[i64; 4]> = buf.iter().map(|e| e.map(i64::from)).collect();
            // the image: each texel's entry against its own normal shaded the same way
            let mut img = vectors::stats::ErrorStats::default();
            for (t, (n, &i)) in normals.iter().zip(&q.index).enumerate().step_by(7) {
                let (a, b) = (table[i as usize], own(m, *n));
                img.add((0..4).map(|c| (a[c] - b[c]).abs()).max().unwrap_or(0) as f64, || format!("texel {t}"));
            }
            let paper = PAPER_MS[m][k];
            let rtl = match (m, fmax.builder_mhz) {
                (0 | 1, Some(f)) => format!("{:.1}", (s_n + vectors_latency()) as f64 / f),
                (0 | 1, None) => "-".into(),
                _ => "no rtl".into(),
            };
            let up5k = match (m, fmax.shared_mhz) {
                (0 | 1, _) if s_n > SHARED_MAX => "no RAM".into(),
                (0 | 1, Some(f)) => format!("{:.1}", (2 * s_n + rtl::table_builder_shared::LATENCY) as f64 / f),
                (0 | 1, None) => "-".into(),
                _ => "no rtl".into(),
            };
            let speedup = if paper > 0.0 { format!("{:.0}x", paper / (secs * 1e3)) } else { "(0.0)".into() };
            println!(
                "{:<20} {:>6} {:>9.1} {:>11.4} {:>10} {:>9} {:>9} {:>16} {:>18}",
                name,
                s_n,
                paper,
                secs * 1e3,
                speedup,
                rtl,
                up5k,
                format!("{:.3}/{:.3}", angle.mean(), angle.max.max(0.0)),
                format!("{:.3}/{:.0}", img.mean(), img.max.max(0.0))
            );
        }
        println!("{:<20} {:>6} per map: the palette normalised in {:.3} ms", "", s_n, per_map * 1e3);
    }
    step.done(&format!("{} palette sizes × {} lighting models", SIZES.len(), models.len()));
    println!("(image: every 7th texel, the largest channel difference; Lambert compares α alone)");

    println!(
        "\nthe quantizer on the same map ({} distinct normals): median cut, then k-means on the sphere",
        sweep[0].1.distinct
    );
    println!("{:>6} {:>10} {:>9} {:>18}", "s_N", "ms", "bits", "angle mean/max °");
    for (s_n, q, secs, angle) in &sweep {
        println!(
            "{s_n:>6} {:>10.0} {:>9} {:>18}",
            secs * 1e3,
            q.index_bits(),
            format!("{:.3}/{:.3}", angle.mean(), angle.max.max(0.0))
        );
    }

    // Figure 3: the map shaded through its palette at 16 … 2048 normals, and unquantized; equation (1) blends
    let shade = |e: [i64; 4]| -> [u8; 3] {
        let c = tables::blend_exact_specular(MATERIAL, e.map(|x| x as f64 / 255.0));
        [c[0], c[1], c[2]].map(|x| (x * 255.0).round().clamp(0.0, 255.0) as u8)
    };
    let picture = |name: String, rgb: &dyn Fn(usize) -> [u8; 3]| -> Result<String, String> {
        let img =
            image::RgbImage::from_fn(MAP as u32, MAP as u32, |x, y| image::Rgb(rgb(y as usize * MAP + x as usize)));
        sim::render::save_png(&out.join(&name), &img).map(|_| name)
    };
    let step = crate::progress::Step::new("Figure 3's pictures", Some(FIGURE_3 as u64 + 1));
    let mut written = vec![picture("figure3_unquantized.png".into(), &|k| shade(own(1, normals[k])))?];
    for (s_n, q, ..) in &sweep[..FIGURE_3] {
        step.tick(written.len() as u64);
        let table: Vec<[i64; 4]> = q.palette.iter().map(|&n| own(1, n)).collect();
        written.push(picture(format!("figure3_{s_n}.png"), &|k| shade(table[q.index[k] as usize]))?);
    }
    step.done(&format!("{} pictures", written.len()));
    println!("\nFigure 3 (Lambert + specular, equation (1)) in {}: {}", out.display(), written.join(", "));
    Ok(())
}

/// Seconds to fill the table once with `f` (entry k from palette normal k), as `per_call` measures.
fn fill(buf: &mut [[u8; 4]], f: impl Fn(usize) -> [u8; 4]) -> f64 {
    per_call(|| {
        for (k, e) in buf.iter_mut().enumerate() {
            *e = f(k);
        }
        std::hint::black_box(&*buf);
    })
}

fn vectors_latency() -> usize {
    rtl::table_builder::LATENCY
}
