//! `bumprtl palette-table`: the paper's Table 1 (Tarini et al. 2000, §8) on this machine. For s_N = 256, 2048 and
//! 16,384 normals quantized from one 512 × 512 normal map (the demo's procedural heights, §4.1's plane fit), the
//! per-frame table under Lambert, Lambert + specular, chrome and environment: the paper's Pentium-300 milliseconds,
//! this machine's (the bit-exact model of `table_builder` where the hardware builds the table, the f64 table where it
//! does not), the rtl builder's clocks and microseconds at its fmax, and two columns the paper lacks: the quantization's
//! angular error and the image error of the table against shading the unquantized normals the same way.

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
    let h: Vec<f64> = (0..MAP * MAP).map(|k| sim::scene::height(((k % MAP) as f64 + 0.5) / MAP as f64, ((k / MAP) as f64 + 0.5) / MAP as f64) * relief).collect();
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

pub fn run(fmax_mhz: Option<f64>) -> Result<(), String> {
    let normals = normal_map();
    let view = [0.0, 1.0, 0.0];
    let light = unit([0.5, 0.8, 0.3]);
    let half = unit([0, 1, 2].map(|c| light[c] + view[c]));
    let (lq, hq) = (table_builder::sq1_10(light), table_builder::sq1_10(half));
    let (conc, spec) = (96, [255, 240, 200]);
    // the builder's entry from a palette normal as the palette stores it (S10, once per map): Lambert alone reads α,
    // Lambert + specular the whole entry
    let built = |n: [i64; 3]| table_builder::exact(n, lq, hq, conc, spec);
    let models = ["Lambert", "Lambert + specular", "chrome", "environment"];
    let f64_model = |m: usize| if m == 2 { tables::Shading::Chrome } else { tables::Shading::Environment };
    let entry = |m: usize, n: [f64; 3], stored: [i64; 3]| -> [i64; 4] {
        match m {
            0 => [0, 0, 0, vectors::dot3::exact(vectors::normalise::exact(stored), lq) >> 2], // the builder's α path alone
            1 => built(stored),
            _ => tables::entry(&f64_model(m), n, view).map(|c| (c * 255.0).round().clamp(0.0, 255.0) as i64),
        }
    };
    println!("Table 1 of Tarini et al. (2000) on this machine: a 512 x 512 normal map (the demo's heights, plane fit q = 8)");
    println!("per-frame table for s_N normals; paper: Pentium 300 MHz (its 16,384 row says 16348); model: one core here;");
    println!("rtl: table_builder, one normal a clock (s_N + {} clocks) at {}", vectors_latency(), match fmax_mhz {
        Some(f) => format!("{f:.1} MHz (its ECP5 placement)"),
        None => "its fmax (not measured: --no-synth, or the tools missing)".into(),
    });
    println!(
        "{:<20} {:>6} {:>9} {:>11} {:>10} {:>9} {:>16} {:>18}",
        "lighting", "s_N", "paper ms", "model ms", "speed-up", "rtl µs", "angle mean/max °", "image LSB mean/max"
    );
    for (k, &s_n) in SIZES.iter().enumerate() {
        let t = Instant::now();
        let q = quantize::quantize(&normals, s_n);
        let quant_s = t.elapsed().as_secs_f64();
        let angle = quantize::angular_error(&normals, &q.index, &q.palette);
        let stored: Vec<[i64; 3]> = q.palette.iter().map(|&n| s10(n)).collect();
        for (m, name) in models.iter().enumerate() {
            // the table is rewritten in place every frame, as a palette's storage is
            let mut buf = vec![[0i64; 4]; q.palette.len()];
            let secs = per_call(|| {
                for ((e, &n), &st) in buf.iter_mut().zip(&q.palette).zip(&stored) {
                    *e = entry(m, n, st);
                }
                std::hint::black_box(&buf);
            });
            let table = buf;
            // the image: each texel's entry against its own normal shaded the same way
            let mut img = vectors::stats::ErrorStats::default();
            for (t, (n, &i)) in normals.iter().zip(&q.index).enumerate().step_by(7) {
                let (a, b) = (table[i as usize], entry(m, *n, s10(*n)));
                img.add((0..4).map(|c| (a[c] - b[c]).abs()).max().unwrap_or(0) as f64, || format!("texel {t}"));
            }
            let paper = PAPER_MS[m][k];
            let rtl = match (m, fmax_mhz) {
                (0 | 1, Some(f)) => format!("{:.1}", (s_n + vectors_latency()) as f64 / f),
                (0 | 1, None) => "-".into(),
                _ => "no rtl".into(),
            };
            let speedup = if paper > 0.0 { format!("{:.0}x", paper / (secs * 1e3)) } else { "(0.0)".into() };
            println!(
                "{:<20} {:>6} {:>9.1} {:>11.4} {:>10} {:>9} {:>16} {:>18}",
                name, s_n, paper, secs * 1e3, speedup, rtl,
                format!("{:.3}/{:.3}", angle.mean(), angle.max.max(0.0)), format!("{:.3}/{:.0}", img.mean(), img.max.max(0.0))
            );
        }
        println!("{:<20} {:>6} quantization itself: {:.0} ms ({} distinct normals in the map)", "", s_n, quant_s * 1e3, q.distinct);
    }
    println!("(image: every 7th texel, the largest channel difference; Lambert compares α alone)");
    Ok(())
}

fn vectors_latency() -> usize {
    rtl::table_builder::LATENCY
}
