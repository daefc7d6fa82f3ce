//! Height map → unit normals, the way normal-map tools do it: central differences with wrap-around at the borders,
//! n = normalise(−∂h/∂u, 1, −∂h/∂v) with heights in texel units (y out of the surface, x along u, z along v).
//! Both encoders take their normals from here: the demo scene's procedural map, and `polar_encode`'s 8-bit maps.

/// Unit normals of a `w`×`h` height map (row-major, heights in texel units).
pub fn normals(heights: &[f64], w: usize, h: usize) -> Vec<[f64; 3]> {
    assert_eq!(heights.len(), w * h, "a {w}x{h} height map has {} values", w * h);
    let at = |i: isize, j: isize| heights[j.rem_euclid(h as isize) as usize * w + i.rem_euclid(w as isize) as usize];
    (0..w * h)
        .map(|k| {
            let (i, j) = ((k % w) as isize, (k / w) as isize);
            let dx = (at(i + 1, j) - at(i - 1, j)) / 2.0;
            let dz = (at(i, j + 1) - at(i, j - 1)) / 2.0;
            let l = (dx * dx + 1.0 + dz * dz).sqrt();
            [-dx / l, 1.0 / l, -dz / l]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_flat_map_points_straight_out_and_a_slope_leans_downhill() {
        assert!(normals(&[3.0; 16], 4, 4).iter().all(|n| *n == [0.0, 1.0, 0.0]));
        // rising by 1 per texel along u (wrapping at the border, so look at an inner texel): leans towards −u
        let ramp: Vec<f64> = (0..16).map(|k| (k % 4) as f64).collect();
        let n = normals(&ramp, 4, 4)[5];
        let s = 0.5f64.sqrt();
        assert!((n[0] + s).abs() < 1e-12 && (n[1] - s).abs() < 1e-12 && n[2] == 0.0, "{n:?}");
    }
}
