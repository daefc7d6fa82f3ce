//! `cart_encode` (software only): unit normal → 8+8-bit texel. Three encoders, each with the decode that reads it:
//! - `Seed`: the seed's `TexelX = (int)(Xs·127) + 127`, `(int)` truncating toward zero, read by `cart_decode`;
//! - `Rounding`: the same with round-to-nearest, a permitted improvement, read by `cart_decode`;
//! - `HemiOct`: the L1 diamond rotated 45° onto the whole square, `u = xs + zs`, `v = xs − zs`, so every one of the
//!   65,536 texels is legal; read by `cart_decode_hemi_oct` (two adders, no guard needed).

use crate::{cart_decode, cart_decode_hemi_oct};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoder {
    Seed,
    Rounding,
    HemiOct,
}

impl Encoder {
    pub const ALL: [Encoder; 3] = [Encoder::Seed, Encoder::Rounding, Encoder::HemiOct];
    pub fn name(self) -> &'static str {
        match self {
            Encoder::Seed => "seed (truncating)",
            Encoder::Rounding => "rounding",
            Encoder::HemiOct => "hemi-octahedral 8+8",
        }
    }
}

/// Scale so that |x| + |y| + |z| = 1 (y ≥ 0 is the caller's promise: a hemisphere direction).
pub fn l1_scale(n: [f64; 3]) -> [f64; 3] {
    let s = n[0].abs() + n[1].abs() + n[2].abs();
    [n[0] / s, n[1] / s, n[2] / s]
}

/// Encode a hemisphere direction (y ≥ 0) as (TexelX, TexelZ).
pub fn encode(enc: Encoder, n: [f64; 3]) -> (u8, u8) {
    let [xs, _, zs] = l1_scale(n);
    match enc {
        Encoder::Seed => (((xs * 127.0) as i64 + 127) as u8, ((zs * 127.0) as i64 + 127) as u8),
        Encoder::Rounding => (((xs * 127.0).round() as i64 + 127) as u8, ((zs * 127.0).round() as i64 + 127) as u8),
        Encoder::HemiOct => {
            let q = |t: f64| ((t * 127.5 + 127.5).round() as i64).clamp(0, 255) as u8;
            (q(xs + zs), q(xs - zs))
        }
    }
}

/// Decode a texel with the decode that belongs to the encoder (for the seed's two: the rtl's `cart_decode`).
pub fn decode(enc: Encoder, t: (u8, u8)) -> [f64; 3] {
    match enc {
        Encoder::Seed | Encoder::Rounding => {
            let b = cart_decode::exact(t.0, t.1);
            [b.x as f64, b.y as f64, b.z as f64]
        }
        Encoder::HemiOct => {
            let v = cart_decode_hemi_oct::exact(t.0, t.1);
            [v[0] as f64, v[1] as f64, v[2] as f64]
        }
    }
}

/// Decode with the L1 length the encoder actually used (254 = 2·127), to measure what the seed's 255 costs.
pub fn decode_consistent(t: (u8, u8)) -> [f64; 3] {
    let b = cart_decode::exact_with_l1(t.0, t.1, 254);
    [b.x as f64, b.y as f64, b.z as f64]
}

/// A direction uniform on the upper hemisphere (y ≥ 0).
pub fn random_hemisphere<R: rand::Rng + ?Sized>(rng: &mut R) -> [f64; 3] {
    let y: f64 = rng.gen_range(0.0..=1.0);
    let phi: f64 = rng.gen_range(0.0..std::f64::consts::TAU);
    let r = (1.0 - y * y).max(0.0).sqrt();
    [r * phi.cos(), y, r * phi.sin()]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::angle_deg;

    #[test]
    fn seed_encoder_matches_the_printed_formula_and_its_typo_fix() {
        // (1, 0, 0) → TexelX = 127 + 127 = 254; TexelZ = 127 (the printed "− 127" would give 0 − 127 + ... = −127).
        assert_eq!(encode(Encoder::Seed, [1.0, 0.0, 0.0]), (254, 127));
        assert_eq!(encode(Encoder::Seed, [0.0, 0.0, -1.0]), (127, 0));
        assert_eq!(encode(Encoder::Seed, [0.0, 1.0, 0.0]), (127, 127));
        // truncation toward zero: 0.999·127 = 126.87 → 126
        assert_eq!(encode(Encoder::Seed, [0.999, 0.001, 0.0]).0, 126 + 127);
        assert_eq!(encode(Encoder::Rounding, [0.999, 0.001, 0.0]).0, 127 + 127);
    }

    #[test]
    fn all_three_encoders_round_trip_within_three_degrees() {
        let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(1);
        for _ in 0..10_000 {
            let n = random_hemisphere(&mut rng);
            for e in Encoder::ALL {
                let a = angle_deg(n, decode(e, encode(e, n)));
                assert!(a < 3.0, "{e:?} {n:?}: {a}°");
            }
        }
    }
}
