//! `cart_decode`: US 6,819,319, second embodiment. Two offset-8-bit texel components → a bump vector whose L1 length
//! is 255: `BumpX = (TexelX − 127)·2` (INT9), `BumpZ` likewise, `BumpY = 255 − |BumpX| − |BumpZ|` (UINT8).
//!
//! The seed says to guard against illegal texels and leaves the how open. The guard here, in the rtl too:
//! 1. `saturate` each texel to 254, so texel 255 means +127/127 instead of overflowing INT9 to +256;
//! 2. if `|BumpX| + |BumpZ| > 255` (a texel outside the diamond, or a filtered value just past it), project the
//!    point orthogonally onto the diamond's edge in its quadrant: with `ax = |TexelX − 127|`, `az = |TexelZ − 127|`,
//!    `|BumpX| = 127 + ax − az`, `|BumpZ| = 127 + az − ax`, `BumpY = 1`. The result is a legal hemisphere vector on
//!    the encodable boundary (|x| + |z| = 254, y = 1, the same as a legal texel on the diamond's edge).

use crate::unit::UnitModel;

crate::ports! {
    inputs: [
        texel_x: u 8, texel_z: u 8,
    ],
    outputs: [
        bump_x: s 9, bump_y: u 8, bump_z: s 9,
    ],
}

/// Decoded bump vector, Q8.0 components: x, z in INT9 (−254..254), y in UINT8 (1..255).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Bump {
    pub x: i64,
    pub y: i64,
    pub z: i64,
}

/// The decode as the rtl does it, with the seed's L1 length of 255.
pub fn exact(texel_x: u8, texel_z: u8) -> Bump {
    exact_with_l1(texel_x, texel_z, 255)
}

/// The decode with a chosen L1 length: 255 is the seed's, 254 = 2·127 is consistent with its encoder.
pub fn exact_with_l1(texel_x: u8, texel_z: u8, l1: i64) -> Bump {
    let tx = (texel_x as i64).min(254); // saturate: U8 → 0..254
    let tz = (texel_z as i64).min(254);
    let ax = (tx - 127).abs(); // U7, 0..127
    let az = (tz - 127).abs();
    let (mx, mz) = if 2 * (ax + az) > 255 {
        (127 + ax - az, 127 + az - ax) // projection onto the diamond edge, sum 254
    } else {
        (2 * ax, 2 * az)
    };
    let y = l1 - mx - mz; // ≥ 1 for l1 = 255, ≥ 0 for l1 = 254
    Bump { x: if tx < 127 { -mx } else { mx }, y, z: if tz < 127 { -mz } else { mz } }
}

/// What the texel means: the L1-scaled direction (x/127, 1 − |x| − |z|, z/127), projected onto the diamond the same
/// way when outside it, as a unit vector.
pub fn ideal(texel_x: u8, texel_z: u8) -> [f64; 3] {
    ideal_real(texel_x as f64, texel_z as f64)
}

/// The same meaning of a texel read between codes (a filtered texel in reals).
pub fn ideal_real(texel_x: f64, texel_z: f64) -> [f64; 3] {
    let x = (texel_x.min(254.0) - 127.0) / 127.0;
    let z = (texel_z.min(254.0) - 127.0) / 127.0;
    let (mut ax, mut az) = (x.abs(), z.abs());
    if ax + az > 1.0 {
        let d = (ax + az - 1.0) / 2.0;
        ax -= d;
        az -= d;
    }
    let y = 1.0 - ax - az;
    let v = [ax * x.signum(), y, az * z.signum()];
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    [v[0] / l, v[1] / l, v[2] / l]
}

/// True when the guard changed the texel (texel 255, or outside the legal diamond).
pub fn guarded(texel_x: u8, texel_z: u8) -> bool {
    let ax = ((texel_x as i64).min(254) - 127).abs();
    let az = ((texel_z as i64).min(254) - 127).abs();
    texel_x == 255 || texel_z == 255 || 2 * (ax + az) > 255
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    let b = exact(i[0] as u8, i[1] as u8);
    vec![b.x, b.y, b.z]
}

fn exhaustive() -> Vec<Vec<i64>> {
    (0..65536i64).map(|t| vec![t & 255, t >> 8]).collect()
}

/// Texel 255, the corners of the square, the diamond's edge and just past it, the pole.
pub fn hard_cases() -> Vec<Vec<i64>> {
    let mut v = vec![];
    for (x, z) in [
        (127, 127), // pole
        (255, 127),
        (127, 255),
        (255, 255),
        (0, 0),
        (0, 255),
        (255, 0),
        (254, 254),
        (254, 127),
        (0, 127),
        (127, 0),
        (127, 254), // diamond corners
        (190, 191),
        (191, 191),
        (64, 63),
        (63, 63), // on the edge and one step past it
        (128, 127),
        (127, 128),
        (126, 127), // the smallest tilts
    ] {
        v.push(vec![x, z]);
    }
    v
}

pub static MODEL: UnitModel = UnitModel::new("cart_decode", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases)
    .with_exhaustive(exhaustive)
    .with_accuracy(accuracy);

/// Every texel, the angle of the decoded bump against the direction it stands for: the seed's decode and the
/// consistent one (L1 = 254).
fn accuracy(_samples: usize, _seed: u64) -> Vec<crate::unit::Accuracy> {
    use crate::stats::{angle_deg, ErrorStats};
    let (mut s, mut c) = (ErrorStats::default(), ErrorStats::default());
    for tx in 0..=255u8 {
        for tz in 0..=255u8 {
            let i = ideal(tx, tz);
            let b = exact(tx, tz);
            s.add(angle_deg([b.x as f64, b.y as f64, b.z as f64], i), || format!("texel ({tx}, {tz})"));
            let b = exact_with_l1(tx, tz, 254);
            c.add(angle_deg([b.x as f64, b.y as f64, b.z as f64], i), || format!("texel ({tx}, {tz})"));
        }
    }
    vec![
        crate::unit::Accuracy::new("degrees, seed decode (L1 = 255), all texels", s),
        crate::unit::Accuracy::new("degrees, consistent decode (L1 = 254)", c),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_texel_decodes_to_a_legal_hemisphere_vector() {
        for tx in 0..=255u8 {
            for tz in 0..=255u8 {
                let b = exact(tx, tz);
                assert!((-256..=255).contains(&b.x) && (-256..=255).contains(&b.z), "INT9 overflow at {tx},{tz}");
                assert!((1..=255).contains(&b.y), "BumpY out of UINT8/hemisphere at {tx},{tz}: {b:?}");
                assert!(b.x.abs() + b.z.abs() + b.y <= 255, "outside the diamond at {tx},{tz}");
            }
        }
    }

    #[test]
    fn legal_texels_decode_as_the_seed_writes_it() {
        for tx in 0..=254u8 {
            for tz in 0..=254u8 {
                if guarded(tx, tz) {
                    continue;
                }
                let bx = (tx as i64 - 127) * 2;
                let bz = (tz as i64 - 127) * 2;
                assert_eq!(exact(tx, tz), Bump { x: bx, y: 255 - bx.abs() - bz.abs(), z: bz });
            }
        }
    }

    #[test]
    fn texel_255_means_plus_one_not_int9_overflow() {
        assert_eq!(exact(255, 127), Bump { x: 254, y: 1, z: 0 });
        assert_eq!(exact(127, 255), Bump { x: 0, y: 1, z: 254 });
    }

    #[test]
    fn texels_past_the_diamond_land_on_its_edge_in_their_quadrant() {
        let b = exact(191, 191); // ax = az = 64: 2·128 = 256 > 255
        assert_eq!(b, Bump { x: 127, y: 1, z: 127 });
        let b = exact(0, 254); // the square's corner (−1, +1)
        assert_eq!(b, Bump { x: -127, y: 1, z: 127 });
    }
}
