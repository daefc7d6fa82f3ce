//! `cart_decode_hemi_oct`: the rotated hemi-octahedral decode, the counterpart of `cart_decode` for texels written
//! by `cart_encode`'s `HemiOct` encoder. The L1 diamond |x| + |z| ≤ 1 is turned 45° onto the whole texel square:
//! `U = round((xs + zs)·127.5 + 127.5)`, `V = round((xs − zs)·127.5 + 127.5)`. Decoding is two adders and two
//! magnitudes, exact in integers (Q8.0, L1 length 255):
//! `BumpX = U + V − 255` (INT9, −255..255), `BumpZ = U − V` (INT9, −255..255), `BumpY = 255 − |BumpX| − |BumpZ|`
//! (UINT8, 0..255). Every one of the 65,536 texels is a legal hemisphere vector: |BumpX| + |BumpZ| =
//! max(|2U − 255|, |2V − 255|) ≤ 255, so no guard is needed and none is built.

use crate::unit::UnitModel;

crate::ports! {
    inputs: [
        texel_u: u 8, texel_v: u 8,
    ],
    outputs: [
        bump_x: s 9, bump_y: u 8, bump_z: s 9,
    ],
}

/// The decode as the rtl does it: [BumpX, BumpY, BumpZ], exact (no rounding anywhere).
pub fn exact(u: u8, v: u8) -> [i64; 3] {
    let x = u as i64 + v as i64 - 255;
    let z = u as i64 - v as i64;
    [x, 255 - x.abs() - z.abs(), z]
}

/// What the texel means: a = U/127.5 − 1 = xs + zs, b = V/127.5 − 1 = xs − zs, so xs = (a + b)/2, zs = (a − b)/2,
/// y = 1 − |xs| − |zs|; as a unit vector.
pub fn ideal(u: u8, v: u8) -> [f64; 3] {
    ideal_real(u as f64, v as f64)
}

/// The same meaning of (U, V) read between codes (a filtered texel in reals).
pub fn ideal_real(u: f64, v: f64) -> [f64; 3] {
    let a = u / 127.5 - 1.0;
    let b = v / 127.5 - 1.0;
    let (xs, zs) = ((a + b) / 2.0, (a - b) / 2.0);
    let d = [xs, 1.0 - xs.abs() - zs.abs(), zs];
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    d.map(|c| c / l)
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    exact(i[0] as u8, i[1] as u8).to_vec()
}

fn exhaustive() -> Vec<Vec<i64>> {
    (0..65536i64).map(|t| vec![t & 255, t >> 8]).collect()
}

/// The square's corners and edge midpoints (the diamond's rim: BumpY = 0, the horizon), the pole and its
/// neighbours (the smallest tilts), and the two centre-most texels (U + V = 255: BumpX = 0).
pub fn hard_cases() -> Vec<Vec<i64>> {
    [
        (0, 0),
        (255, 255),
        (0, 255),
        (255, 0), // corners: (∓1, 0, 0) and (0, 0, ±1), on the horizon
        (127, 0),
        (0, 127),
        (255, 128),
        (128, 255), // edge midpoints, also on the horizon
        (127, 127),
        (128, 128),
        (127, 128),
        (128, 127), // around the pole
        (129, 126),
        (1, 254),
        (254, 1),
    ]
    .iter()
    .map(|&(u, v)| vec![u, v])
    .collect()
}

pub static MODEL: UnitModel =
    UnitModel::new("cart_decode_hemi_oct", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases)
        .with_exhaustive(exhaustive)
        .with_accuracy(accuracy);

/// Every texel, the angle of the decoded vector against what it means (the decode is exact: this is a check).
fn accuracy(_samples: usize, _seed: u64) -> Vec<crate::unit::Accuracy> {
    let mut h = crate::stats::ErrorStats::default();
    for u in 0..=255u8 {
        for v in 0..=255u8 {
            let b = exact(u, v).map(|c| c as f64);
            h.add(crate::stats::angle_deg(b, ideal(u, v)), || format!("texel ({u}, {v})"));
        }
    }
    vec![crate::unit::Accuracy::new("degrees, all texels", h)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_texel_is_a_legal_hemisphere_vector_of_l1_length_255() {
        for u in 0..=255u8 {
            for v in 0..=255u8 {
                let d = exact(u, v);
                assert!(d[1] >= 0 && d[0].abs() + d[2].abs() + d[1] == 255, "{u},{v}: {d:?}");
                assert!((-255..=255).contains(&d[0]) && (-255..=255).contains(&d[2]), "INT9 at {u},{v}");
            }
        }
    }

    #[test]
    fn the_exact_decode_is_the_ideal_scaled_by_255() {
        for (u, v) in [(0u8, 0u8), (200, 31), (128, 127), (255, 0), (17, 240)] {
            let e = exact(u, v).map(|c| c as f64);
            let l = (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).sqrt();
            let i = ideal(u, v);
            for c in 0..3 {
                assert!((e[c] / l - i[c]).abs() < 1e-12, "{u},{v}");
            }
        }
    }

    #[test]
    fn corners_and_edges_lie_on_the_horizon() {
        assert_eq!(exact(0, 0), [-255, 0, 0]);
        assert_eq!(exact(255, 255), [255, 0, 0]);
        assert_eq!(exact(255, 0), [0, 0, 255]);
        assert_eq!(exact(0, 255), [0, 0, -255]);
        assert_eq!(exact(127, 128), [0, 254, -1]);
    }
}
