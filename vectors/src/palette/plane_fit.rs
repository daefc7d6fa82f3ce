//! Tarini et al. §4.1: a displacement (height) map to a normal map, each texel's normal that of the plane fitted by
//! least
//! squares through it and q of its neighbours: q = 4 (left, right, above, below) or q = 8 (the whole 3×3). Heights
//! and positions in texel units; the map's edges repeat (clamp). Software, run once per map.
//!
//! With z = a0·x + a1·y + a2 over the q + 1 points, the normal is (−a0, −a1, 1) in the plane's frame; in the
//! project's tangent frame (x along u, y up, z along v) it is (−a0, 1, −a1), normalised.

/// The neighbourhoods: (dx, dy) of the q texels besides the centre.
pub fn neighbours(q: usize) -> &'static [(i64, i64)] {
    match q {
        4 => &[(-1, 0), (1, 0), (0, -1), (0, 1)],
        8 => &[(-1, -1), (0, -1), (1, -1), (-1, 0), (1, 0), (-1, 1), (0, 1), (1, 1)],
        _ => panic!("the plane fit takes q = 4 or q = 8 neighbours, not {q}"),
    }
}

/// The least-squares plane (a0, a1, a2) through points (x, y, z): the 3 × 3 normal equations solved by Cramer's rule.
pub fn fit(points: &[(f64, f64, f64)]) -> [f64; 3] {
    let mut m = [[0.0f64; 3]; 3];
    let mut r = [0.0f64; 3];
    for &(x, y, z) in points {
        let row = [x, y, 1.0];
        for i in 0..3 {
            for j in 0..3 {
                m[i][j] += row[i] * row[j];
            }
            r[i] += row[i] * z;
        }
    }
    let det3 = |a: [[f64; 3]; 3]| {
        a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
    };
    let d = det3(m);
    std::array::from_fn(|k| {
        let mut a = m;
        for i in 0..3 {
            a[i][k] = r[i];
        }
        det3(a) / d
    })
}

/// The normal map of a `w` × `h` height map (texel units, row-major), fitting each texel and its q neighbours.
pub fn normals(heights: &[f64], w: usize, h: usize, q: usize) -> Vec<[f64; 3]> {
    let at = |x: i64, y: i64| heights[(y.clamp(0, h as i64 - 1) as usize) * w + x.clamp(0, w as i64 - 1) as usize];
    (0..w * h)
        .map(|t| {
            let (x, y) = ((t % w) as i64, (t / w) as i64);
            let mut pts = vec![(0.0, 0.0, at(x, y))];
            pts.extend(neighbours(q).iter().map(|&(dx, dy)| (dx as f64, dy as f64, at(x + dx, y + dy))));
            let [a0, a1, _] = fit(&pts);
            let l = (a0 * a0 + 1.0 + a1 * a1).sqrt();
            [-a0 / l, 1.0 / l, -a1 / l]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_plane_is_fitted_exactly_by_either_neighbourhood() {
        // z = 0.3x − 0.2y + 5 on a 6 × 5 map: every interior texel's normal is the plane's
        let (w, h) = (6, 5);
        let hm: Vec<f64> = (0..w * h).map(|t| 0.3 * (t % w) as f64 - 0.2 * (t / w) as f64 + 5.0).collect();
        let l = (0.09f64 + 1.0 + 0.04).sqrt();
        for q in [4, 8] {
            let n = normals(&hm, w, h, q);
            let c = n[2 * w + 2];
            for (got, want) in c.iter().zip([-0.3 / l, 1.0 / l, 0.2 / l]) {
                assert!((got - want).abs() < 1e-12, "q = {q}: {c:?}");
            }
        }
    }

    #[test]
    fn q4_is_the_central_difference_and_q8_the_prewitt_kernel() {
        let hm = [1.0, 4.0, 2.0, 7.0, 3.0, 9.0, 5.0, 6.0, 8.0];
        let g = |q| {
            let mut pts = vec![(0.0, 0.0, hm[4])];
            pts.extend(
                neighbours(q).iter().map(|&(dx, dy)| (dx as f64, dy as f64, hm[((1 + dy) * 3 + 1 + dx) as usize])),
            );
            fit(&pts)
        };
        let [a0, a1, _] = g(4);
        assert!((a0 - (9.0 - 7.0) / 2.0).abs() < 1e-12 && (a1 - (6.0 - 4.0) / 2.0).abs() < 1e-12);
        let [b0, b1, _] = g(8);
        let prewitt_x = ((2.0 + 9.0 + 8.0) - (1.0 + 7.0 + 5.0)) / 6.0;
        let prewitt_y = ((5.0 + 6.0 + 8.0) - (1.0 + 4.0 + 2.0)) / 6.0;
        assert!((b0 - prewitt_x).abs() < 1e-12 && (b1 - prewitt_y).abs() < 1e-12);
    }
}
