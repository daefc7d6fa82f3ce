//! Exact against ideal, for every unit: mean and max error and where the max occurs; the three encoders' angular
//! error over random hemisphere directions; the normaliser's table-size / Newton trade-off.

use rand::SeedableRng;
use vectors::cart_encode::{self, Encoder};
use vectors::stats::{angle_deg, ErrorStats};
use vectors::polar_encode::{self, Scale};
use vectors::{bilinear, blend, cart_decode, dot3, gloss, light_iter, normalise, polar_shade, power, sincos};

pub struct Row {
    pub unit: String,
    pub metric: String,
    pub stats: ErrorStats,
}

fn row(unit: &str, metric: &str, stats: ErrorStats) -> Row {
    Row { unit: unit.into(), metric: metric.into(), stats }
}

pub fn units(samples: usize, seed: u64) -> Vec<Row> {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut rows = vec![];
    // cart_decode: every texel, angle against what it means
    let mut s = ErrorStats::default();
    let mut c = ErrorStats::default();
    for tx in 0..=255u8 {
        for tz in 0..=255u8 {
            let b = cart_decode::exact(tx, tz);
            let i = cart_decode::ideal(tx, tz);
            s.add(angle_deg([b.x as f64, b.y as f64, b.z as f64], i), || format!("texel ({tx}, {tz})"));
            let b = cart_decode::exact_with_l1(tx, tz, 254);
            c.add(angle_deg([b.x as f64, b.y as f64, b.z as f64], i), || format!("texel ({tx}, {tz})"));
        }
    }
    rows.push(row("cart_decode", "degrees, seed decode (L1 = 255), all texels", s));
    rows.push(row("cart_decode", "degrees, consistent decode (L1 = 254)", c));
    // cart_decode_hemi_oct: every texel, angle against what it means (the decode is exact: this is a check)
    let mut h = ErrorStats::default();
    for u in 0..=255u8 {
        for v in 0..=255u8 {
            let b = vectors::cart_decode_hemi_oct::exact(u, v).map(|c| c as f64);
            h.add(angle_deg(b, vectors::cart_decode_hemi_oct::ideal(u, v)), || format!("texel ({u}, {v})"));
        }
    }
    rows.push(row("cart_decode_hemi_oct", "degrees, all texels", h));
    // gloss: every (C, X)
    let mut s = ErrorStats::default();
    for cc in 0..256 {
        for x in 0..1024 {
            s.add((gloss::exact(cc, x) as f64 - gloss::ideal(cc, x)).abs(), || format!("C={cc} X={x}"));
        }
    }
    rows.push(row("gloss", "10-bit LSB vs the recipe in reals, all 2^18", s));
    // normalise: component and angle error, random vectors of every scale (the rtl's table, no Newton step)
    let (l, a) = normalise_error(normalise::TABLE_BITS, normalise::NEWTON, samples, seed);
    rows.push(row("normalise", "component error, Sq1.10 LSB (1/1024)", l));
    rows.push(row("normalise", "degrees", a));
    // dot3, light_iter, bilinear, blend: random vectors against the reals
    let mut d = ErrorStats::default();
    let mut li = ErrorStats::default();
    let mut bi = ErrorStats::default();
    let mut bl = ErrorStats::default();
    for _ in 0..samples {
        let v = (dot3::MODEL.random)(&mut rng);
        let (n, lv) = ([v[0], v[1], v[2]], [v[3], v[4], v[5]]);
        d.add((dot3::exact(n, lv) as f64 - dot3::ideal(n, lv).min(1023.0)).abs(), || format!("{v:?}"));
        let v = (light_iter::MODEL.random)(&mut rng);
        for k in 0..3 {
            let e = light_iter::exact_component(v[k], v[3 + k], v[6 + k], v[9], v[10]) as f64;
            let i = light_iter::ideal_component(v[k] as f64, v[3 + k] as f64, v[6 + k] as f64, v[9] as f64, v[10] as f64);
            li.add((e - i.clamp(-512.0, 511.0)).abs(), || format!("{v:?}"));
        }
        let v = (bilinear::MODEL.random)(&mut rng);
        let e = bilinear::exact_channel(v[0], v[4], v[8], v[12], v[16], v[17], 8) as f64;
        let i = bilinear::ideal_channel(v[0] as f64, v[4] as f64, v[8] as f64, v[12] as f64, v[16] as f64 / 256.0, v[17] as f64 / 256.0);
        bi.add((e - i).abs(), || format!("{v:?}"));
        let v = (blend::MODEL.random)(&mut rng);
        bl.add((blend::exact_channel(v[0], v[1], v[2], v[5]) as f64 - blend::ideal_channel(v[0], v[1], v[2], v[5])).abs(), || format!("{v:?}"));
    }
    rows.push(row("dot3", "10-bit LSB", d));
    rows.push(row("light_iter", "Sq7.2 LSB", li));
    rows.push(row("bilinear", "8-bit LSB", bi));
    rows.push(row("blend", "8-bit LSB", bl));
    rows.extend(polar_units(samples, seed));
    rows
}

/// The polar path's units against their ideals: the sine/cosine table on every 10-bit angle, the shade (S11
/// before the clamp, and the clamped U8) against equation 3 on the angles the codes stand for, the power unit
/// against `powf` on every (x, p).
fn polar_units(samples: usize, seed: u64) -> Vec<Row> {
    let mut rows = vec![];
    let mut sc = ErrorStats::default();
    for a in 0..1i64 << sincos::ANGLE_BITS {
        let (s, c) = sincos::exact_with(Scale::Seed, sincos::TABLE_BITS, sincos::WIDTH, a);
        let (is, ic) = sincos::ideal(a);
        sc.add((s as f64 - is).abs().max((c as f64 - ic).abs()), || format!("angle {a}"));
    }
    rows.push(row("sincos", "8-bit LSB, every 10-bit angle, 256 entries", sc));
    let mut cs = ErrorStats::default();
    for d in 0..256 {
        let (m, neg) = vectors::cos_sign::exact_with(vectors::cos_sign::TABLE_BITS, vectors::cos_sign::WIDTH, d);
        let v = if neg { -m } else { m } as f64;
        cs.add((v - vectors::cos_sign::ideal(d)).abs(), || format!("d {d}"));
    }
    rows.push(row("cos_sign", "8-bit LSB, signed cosine, every d, 256 entries", cs));
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed ^ 0x9e37);
    for scale in [Scale::Seed, Scale::Dc255] {
        let (mut pre, mut clamped) = (ErrorStats::default(), ErrorStats::default());
        for _ in 0..samples {
            let v = (polar_shade::MODEL.random)(&mut rng);
            let (sum, shade) = polar_shade::exact(scale, v[0], v[1], v[2], v[3], v[4], v[5]);
            let i = polar_shade::ideal(scale, v[0], v[1], v[2], v[3], v[4], v[5]);
            pre.add((sum as f64 - i).abs(), || format!("{v:?}"));
            clamped.add((shade as f64 - i.clamp(0.0, 255.0)).abs(), || format!("{v:?}"));
        }
        let tag = if scale == Scale::Seed { "seed scale" } else { "Dreamcast scale" };
        rows.push(row("polar_shade", &format!("8-bit LSB, S11 before the clamp, {tag}"), pre));
        rows.push(row("polar_shade", &format!("8-bit LSB, clamped shade, {tag}"), clamped));
    }
    let mut pw = ErrorStats::default();
    for x in 0..256 {
        for p in 0..256 {
            pw.add((power::exact(x, p) as f64 - power::ideal(x, p)).abs(), || format!("x={x} p={}", p as f64 / 4.0));
        }
    }
    rows.push(row("power", "8-bit LSB against powf, all 2^16 (x, p)", pw));
    rows
}

/// Polar S8 R8 encoding, both scales: encode then decode `n` random hemisphere directions, degrees.
pub fn polar_encoders(n: usize, seed: u64) -> Vec<Row> {
    [Scale::Seed, Scale::Dc255]
        .into_iter()
        .map(|sc| row("polar_encode", &format!("degrees, {}", sc.name()), polar_encode::encoding_error(sc, n, seed)))
        .collect()
}

/// The sine/cosine LUT sizes and widths of the LUT-size table, model error only (the cost comes from `synth`).
pub fn cos_sign_sizes() -> Vec<sincos::SizeRow> {
    vectors::cos_sign::LUT_SIZES.iter().map(|&(tb, w)| vectors::cos_sign::size_error(tb, w)).collect()
}

pub fn sincos_sizes() -> Vec<sincos::SizeRow> {
    sincos::LUT_SIZES.iter().map(|&(tb, w)| sincos::size_error(tb, w)).collect()
}

/// How many random hemisphere directions `bumprtl accuracy` draws per encoder, and the seed of their stream.
pub const DIRECTIONS: usize = 1_000_000;
pub const ENCODER_SEED: u64 = 2;

/// Encode then decode `n` random hemisphere directions with each encoder: degrees against the original.
pub fn encoders(n: usize, seed: u64) -> Vec<Row> {
    let mut rows = vec![];
    for e in Encoder::ALL {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let mut s = ErrorStats::default();
        for _ in 0..n {
            let d = cart_encode::random_hemisphere(&mut rng);
            s.add(angle_deg(d, cart_encode::decode(e, cart_encode::encode(e, d))), || format!("{d:.4?}"));
        }
        rows.push(row("cart_encode", &format!("degrees, {}", e.name()), s));
    }
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut s = ErrorStats::default();
    for _ in 0..n {
        let d = cart_encode::random_hemisphere(&mut rng);
        s.add(angle_deg(d, cart_encode::decode_consistent(cart_encode::encode(Encoder::Seed, d))), || format!("{d:.4?}"));
    }
    rows.push(row("cart_encode", "degrees, seed encoder + consistent L1 = 254 decode", s));
    rows
}

/// The normaliser with a `t`-bit seed table and `newton` steps against the ideal, over `samples` random vectors
/// of every scale: the worst component error per vector (Sq1.10 LSB) and the angle (degrees).
fn normalise_error(t: u32, newton: u32, samples: usize, seed: u64) -> (ErrorStats, ErrorStats) {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let (mut comp, mut angle) = (ErrorStats::default(), ErrorStats::default());
    for _ in 0..samples {
        let v = (normalise::MODEL.random)(&mut rng);
        let v = [v[0], v[1], v[2]];
        if v == [0, 0, 0] {
            continue;
        }
        let e = normalise::exact_with(v, t, newton).map(|c| c as f64);
        let i = normalise::ideal(v);
        comp.add((0..3).map(|k| (e[k] - i[k]).abs()).fold(0.0, f64::max), || format!("{v:?}"));
        angle.add(angle_deg(e, i), || format!("{v:?}"));
    }
    (comp, angle)
}

/// The normaliser's seed-table size and Newton steps against its error (model only; the rtl is T = 10, N = 0).
pub fn normaliser_tradeoff(samples: usize, seed: u64) -> Vec<(u32, u32, ErrorStats)> {
    [(6, 0), (8, 0), (10, 0), (12, 0), (6, 1), (8, 1)]
        .into_iter()
        .map(|(t, n)| (t, n, normalise_error(t, n, samples, seed).0))
        .collect()
}
