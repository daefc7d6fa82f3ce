//! Exact against ideal, for every unit (each model measures its own: `UnitModel::accuracy`, collected here from the
//! unit table): mean and max error and where the max occurs; the software-only encoders' angular error over random
//! hemisphere directions; the normaliser's table-size / Newton trade-off; the LUT-size tables.

use rand::SeedableRng;
use vectors::cart_encode::{self, Encoder};
use vectors::polar_encode::{self, Scale};
use vectors::sincos;
use vectors::stats::{angle_deg, ErrorStats};

pub struct Row {
    pub unit: String,
    pub metric: String,
    pub stats: ErrorStats,
}

fn row(unit: &str, metric: &str, stats: ErrorStats) -> Row {
    Row { unit: unit.into(), metric: metric.into(), stats }
}

/// Every unit's own accuracy (`UnitModel::accuracy`), in the unit table's order.
pub fn units(samples: usize, seed: u64) -> Vec<Row> {
    crate::units::UNITS
        .iter()
        .filter_map(|u| u.model.accuracy.map(|f| (u.name(), f)))
        .flat_map(|(name, f)| f(samples, seed).into_iter().map(move |a| row(name, &a.metric, a.stats)))
        .collect()
}

/// Polar S8 R8 encoding, both scales: encode then decode `n` random hemisphere directions, degrees.
pub fn polar_encoders(n: usize, seed: u64) -> Vec<Row> {
    [Scale::Seed, Scale::Dc255]
        .into_iter()
        .map(|sc| row("polar_encode", &format!("degrees, {}", sc.name()), polar_encode::encoding_error(sc, n, seed)))
        .collect()
}

/// The sine/cosine LUT sizes and widths of the LUT-size table (the swept settings of `crate::units`), model error
/// only (the cost comes from `synth`).
pub fn cos_sign_sizes() -> Vec<sincos::SizeRow> {
    crate::units::settings("cos_sign").map(|s| vectors::cos_sign::size_error(s.params.0, s.params.1)).collect()
}

pub fn sincos_sizes() -> Vec<sincos::SizeRow> {
    crate::units::settings("sincos").map(|s| sincos::size_error(s.params.0, s.params.1)).collect()
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
        s.add(angle_deg(d, cart_encode::decode_consistent(cart_encode::encode(Encoder::Seed, d))), || {
            format!("{d:.4?}")
        });
    }
    rows.push(row("cart_encode", "degrees, seed encoder + consistent L1 = 254 decode", s));
    rows
}

/// The normaliser's seed-table size and Newton steps against its error (model only; the rtl is T = 10, N = 0).
pub fn normaliser_tradeoff(samples: usize, seed: u64) -> Vec<(u32, u32, ErrorStats)> {
    [(6, 0), (8, 0), (10, 0), (12, 0), (6, 1), (8, 1), (10, 1), (6, 2)]
        .into_iter()
        .map(|(t, n)| (t, n, vectors::normalise::error(t, n, samples, seed).0))
        .collect()
}
