//! `light_iter`: per-vertex light directions, signed 8 bits each (`(int)(LightDir·127) & 0xFF`, US 6,819,319),
//! interpolated across a triangle from barycentric weights, one pixel per clock.
//!
//! exact: `L = l0·256 + (l1 − l0)·w1 + (l2 − l0)·w2` (S20, Sq11.8), then `truncate` 6 bits (floor) to Sq7.2 and
//! `saturate` to S10. `w1`, `w2` are U9 weights in 1/256 (256 = the vertex itself; w1 + w2 ≤ 256 inside the
//! triangle; outside it the saturation keeps the S10 output defined).

use crate::fixed::{saturate, signed_range, truncate};
use crate::unit::UnitModel;

crate::ports! {
    inputs: [
        l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8, w1: u 9,
        w2: u 9,
    ],
    outputs: [
        light_x: s 10, light_y: s 10, light_z: s 10,
    ],
}

/// The seed's per-vertex quantisation of a unit light direction: `(int)(d·127)`, truncating toward zero.
pub fn quantise_vertex(d: [f64; 3]) -> [i64; 3] {
    [(d[0] * 127.0) as i64, (d[1] * 127.0) as i64, (d[2] * 127.0) as i64]
}

/// One component: S8 vertices, U9 weights → Sq7.2 (S10).
pub fn exact_component(l0: i64, l1: i64, l2: i64, w1: i64, w2: i64) -> i64 {
    let acc = l0 * 256 + (l1 - l0) * w1 + (l2 - l0) * w2; // S20, Sq11.8 (±293,378 at most)
    let (lo, hi) = signed_range(10);
    saturate(truncate(acc, 6), lo, hi) // Sq11.8 → Sq7.2, floor; S10
}

/// The same interpolation in reals, in Sq7.2 units.
pub fn ideal_component(l0: f64, l1: f64, l2: f64, w1: f64, w2: f64) -> f64 {
    4.0 * (l0 + (l1 - l0) * w1 / 256.0 + (l2 - l0) * w2 / 256.0)
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    (0..3).map(|c| exact_component(i[c], i[3 + c], i[6 + c], i[9], i[10])).collect()
}

fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    use rand::Rng;
    let mut v: Vec<i64> = INPUTS[..9].iter().map(|p| crate::unit::draw(rng, p)).collect();
    if rng.gen_range(0..8) == 0 {
        // outside the triangle too: the contract is saturation, and it is tested
        v.push(rng.gen_range(0..512));
        v.push(rng.gen_range(0..512));
    } else {
        let w1 = rng.gen_range(0..=256);
        v.push(w1);
        v.push(rng.gen_range(0..=256 - w1));
    }
    v
}

/// Opposite vertex lights (interpolation through zero length), lights 120° apart, the most negative component,
/// weights at 0 and 256, weights outside the triangle.
pub fn hard_cases() -> Vec<Vec<i64>> {
    let mut v = vec![];
    let opp = [127, 0, 0, -127, 0, 0, 127, 0, 0];
    for w in [0, 64, 128, 129, 192, 256] {
        v.push([opp.to_vec(), vec![w, 0]].concat());
    }
    let neg = [-128, -128, -128, 127, 127, 127, -128, 127, -128];
    for (w1, w2) in [(0, 0), (256, 0), (0, 256), (128, 128), (511, 511), (511, 0), (0, 511)] {
        v.push([neg.to_vec(), vec![w1, w2]].concat());
    }
    // 120° apart in the x-y plane, both above the horizon ends: (cos 30°, sin 30°) and (−cos 30°, sin 30°)
    let a = quantise_vertex([0.866_025_403_784_438_6, 0.5, 0.0]);
    let b = quantise_vertex([-0.866_025_403_784_438_6, 0.5, 0.0]);
    v.push([a.to_vec(), b.to_vec(), a.to_vec(), vec![128, 0]].concat());
    v
}

pub static MODEL: UnitModel =
    UnitModel::new("light_iter", (INPUTS, OUTPUTS), exact_ports, random, hard_cases).with_accuracy(accuracy);

/// Random vectors against the reals, every component (the ideal clamped to the output's range).
fn accuracy(samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
    vec![crate::unit::Accuracy::over_random("Sq7.2 LSB", samples, seed, random, |v| {
        (0..3)
            .map(|k| {
                let e = exact_component(v[k], v[3 + k], v[6 + k], v[9], v[10]) as f64;
                let i = ideal_component(v[k] as f64, v[3 + k] as f64, v[6 + k] as f64, v[9] as f64, v[10] as f64);
                (e - i.clamp(-512.0, 511.0)).abs()
            })
            .collect()
    })]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vertices_come_back_exactly_at_weight_256() {
        for l in [-128, -1, 0, 1, 127] {
            assert_eq!(exact_component(l, 5, -7, 0, 0), 4 * l);
            assert_eq!(exact_component(3, l, -7, 256, 0), 4 * l);
            assert_eq!(exact_component(3, 5, l, 0, 256), 4 * l);
        }
    }

    #[test]
    fn exact_is_floor_of_ideal_inside_the_triangle() {
        for (l0, l1, l2) in [(-128, 127, 0), (127, -127, 64), (-3, -4, -5)] {
            for w1 in (0..=256).step_by(7) {
                for w2 in (0..=256 - w1).step_by(5) {
                    let e = exact_component(l0, l1, l2, w1, w2) as f64;
                    let i = ideal_component(l0 as f64, l1 as f64, l2 as f64, w1 as f64, w2 as f64);
                    assert!(e <= i && i - e < 1.0, "{e} {i}");
                }
            }
        }
    }

    #[test]
    fn outside_the_triangle_saturates() {
        assert_eq!(exact_component(-128, 127, 127, 511, 511), 511);
        assert_eq!(exact_component(127, -128, -128, 511, 511), -512);
    }
}
