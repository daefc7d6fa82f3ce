//! The rasteriser: for every pixel of a scene, the four texels and blend factors the texture filter reads, the
//! light triangle and its weights, and the ideal (filtered float) normal and light beside them.

use crate::scene::Scene;

/// One pixel's rasterisation.
pub struct Pixel {
    /// The four texels (i, j) in the bilinear unit's order: 00, 10, 01, 11.
    pub corners: [(usize, usize); 4],
    /// Blend factors, U8 (1/256), truncated.
    pub ub: i64,
    pub vb: i64,
    /// The light triangle's vertices (indices into `Scene::vertex_lights`) and the weights of its second and third.
    pub tri: [usize; 3],
    pub w1: f64,
    pub w2: f64,
    /// The ideal normal (the float normals blended with the same factors, renormalised) and the ideal light (the
    /// vertex lights interpolated linearly and renormalised, as the seed does).
    pub normal: [f64; 3],
    pub light: [f64; 3],
}

/// Every pixel of `scene`, row by row; `normals` are the height map's, one per texel.
pub fn pixels(scene: &Scene, normals: &[[f64; 3]]) -> Vec<Pixel> {
    let t = scene.tex;
    let corner = scene.vertex_lights();
    let n = scene.size;
    let mut out = Vec::with_capacity(n * n);
    for py in 0..n {
        for px in 0..n {
            let (u, v) = ((px as f64 + 0.5) / n as f64, (py as f64 + 0.5) / n as f64);
            // texture address: texel centres at (i + 0.5)/t, clamped at the borders
            let su = (u * t as f64 - 0.5).clamp(0.0, (t - 1) as f64);
            let sv = (v * t as f64 - 0.5).clamp(0.0, (t - 1) as f64);
            let (i0, j0) = (su.floor() as usize, sv.floor() as usize);
            let (i1, j1) = ((i0 + 1).min(t - 1), (j0 + 1).min(t - 1));
            let ub = (((su - i0 as f64) * 256.0) as i64).min(255); // U8 blend factor, truncated
            let vb = (((sv - j0 as f64) * 256.0) as i64).min(255);
            // triangle (00, 10, 11) where u ≥ v, else (00, 11, 01)
            let (tri, w1, w2) = if u >= v { ([0, 1, 3], u - v, v) } else { ([0, 3, 2], u, v - u) };
            let (fu, fv) = (ub as f64 / 256.0, vb as f64 / 256.0);
            let nn = |i: usize, j: usize| normals[j * t + i];
            let mut nrm = [0.0; 3];
            for c in 0..3 {
                nrm[c] = (1.0 - fv) * ((1.0 - fu) * nn(i0, j0)[c] + fu * nn(i1, j0)[c])
                    + fv * ((1.0 - fu) * nn(i0, j1)[c] + fu * nn(i1, j1)[c]);
            }
            let ln = (nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]).sqrt();
            nrm = nrm.map(|c| c / ln);
            let lf = tri.map(|k| corner[k]);
            let mut ld = [0.0; 3];
            for c in 0..3 {
                ld[c] = lf[0][c] + (lf[1][c] - lf[0][c]) * w1 + (lf[2][c] - lf[0][c]) * w2;
            }
            let ll = (ld[0] * ld[0] + ld[1] * ld[1] + ld[2] * ld[2]).sqrt().max(1e-12);
            ld = ld.map(|c| c / ll);
            out.push(Pixel { corners: [(i0, j0), (i1, j0), (i0, j1), (i1, j1)], ub, vb, tri, w1, w2, normal: nrm, light: ld });
        }
    }
    out
}
