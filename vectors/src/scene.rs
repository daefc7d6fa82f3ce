//! The demo scene, embedded: a procedural height map (round bumps, a ridge, a crater) encoded to Cartesian texels,
//! on a flat quad whose four vertices carry per-vertex light directions towards a nearby point light, split into
//! two triangles, rendered at `size`×`size` with the texture magnified through the bilinear unit.
//! Everything here is set-up (the rasteriser's work): it produces the per-pixel input vector of `cart_pipeline`
//! and, beside it, the f64 ideal of every pixel.

use crate::cart_encode::{self, Encoder};
use crate::{cart_pipeline, gloss, light_iter};

#[derive(Clone, Debug)]
pub struct Scene {
    /// Output image side, pixels.
    pub size: usize,
    /// Height-map / texture side, texels.
    pub tex: usize,
    /// Point light position over the quad [0,1]² (y up, in quad units).
    pub light_pos: [f64; 3],
    /// Glossiness concentration C (U8).
    pub conc: i64,
    pub src: [i64; 3],
    pub dst: [i64; 3],
    /// Height scale of the bumps, in texels of rise per texel of height-map value.
    pub relief: f64,
    pub encoder: Encoder,
}

impl Default for Scene {
    fn default() -> Self {
        Scene {
            size: 256,
            tex: 128,
            light_pos: [0.2, 0.45, 0.25],
            conc: 96,
            src: [236, 196, 140],
            dst: [16, 20, 36],
            relief: 6.0,
            encoder: Encoder::Seed,
        }
    }
}

/// The procedural height field in [0, 1]² → height in texel units / relief.
pub fn height(u: f64, v: f64) -> f64 {
    let bump = |cu: f64, cv: f64, r: f64, h: f64| {
        let d2 = ((u - cu).powi(2) + (v - cv).powi(2)) / (r * r);
        if d2 < 1.0 { h * (1.0 - d2).powi(2) } else { 0.0 }
    };
    let mut z = bump(0.25, 0.3, 0.14, 1.0) + bump(0.7, 0.25, 0.1, 0.8) + bump(0.45, 0.55, 0.06, 0.6);
    // a ridge along a diagonal line
    let d = ((v - 0.8) - 0.35 * (u - 0.2)).abs();
    if d < 0.05 && u > 0.1 && u < 0.9 {
        z += 0.7 * (1.0 - d / 0.05).powi(2);
    }
    // a crater: a rim and a bowl
    let r = ((u - 0.72).powi(2) + (v - 0.68).powi(2)).sqrt();
    if r < 0.16 {
        let rim = (-(r - 0.12).powi(2) / 0.0006).exp();
        let bowl = if r < 0.11 { -0.5 * (1.0 - (r / 0.11).powi(2)) } else { 0.0 };
        z += 0.8 * rim + bowl;
    }
    z
}

pub struct Prepared {
    pub size: usize,
    /// Per pixel: the input vector of `cart_pipeline`, in its port order.
    pub inputs: Vec<Vec<i64>>,
    /// Per pixel: the ideal shade P (Uq0.10 units, real) and the ideal colour (8-bit units, real).
    pub ideal_p: Vec<f64>,
    pub ideal_rgb: Vec<[f64; 3]>,
    /// Per pixel: the ideal unit normal and the ideal unit light (for angle errors).
    pub ideal_normal: Vec<[f64; 3]>,
}

impl Scene {
    /// Unit normal of the height field at texel (i, j), central differences, wrapping.
    pub fn texel_normal(&self, i: usize, j: usize) -> [f64; 3] {
        let n = self.tex as f64;
        let h = |a: isize, b: isize| {
            let a = a.rem_euclid(self.tex as isize) as f64;
            let b = b.rem_euclid(self.tex as isize) as f64;
            height((a + 0.5) / n, (b + 0.5) / n) * self.relief
        };
        let (i, j) = (i as isize, j as isize);
        let dx = (h(i + 1, j) - h(i - 1, j)) / 2.0;
        let dz = (h(i, j + 1) - h(i, j - 1)) / 2.0;
        let v = [-dx, 1.0, -dz];
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        [v[0] / l, v[1] / l, v[2] / l]
    }

    /// Unit direction from quad point (u, v) to the light, tangent space (x along u, y up, z along v).
    pub fn light_dir(&self, u: f64, v: f64) -> [f64; 3] {
        let d = [self.light_pos[0] - u, self.light_pos[1], self.light_pos[2] - v];
        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        [d[0] / l, d[1] / l, d[2] / l]
    }

    pub fn prepare(&self) -> Prepared {
        let t = self.tex;
        let normals: Vec<[f64; 3]> = (0..t * t).map(|k| self.texel_normal(k % t, k / t)).collect();
        let texels: Vec<(u8, u8)> = normals.iter().map(|&n| cart_encode::encode(self.encoder, n)).collect();
        let corner = [self.light_dir(0.0, 0.0), self.light_dir(1.0, 0.0), self.light_dir(0.0, 1.0), self.light_dir(1.0, 1.0)];
        let q: Vec<[i64; 3]> = corner.iter().map(|&d| light_iter::quantise_vertex(d)).collect();
        let n = self.size;
        let mut p = Prepared { size: n, inputs: vec![], ideal_p: vec![], ideal_rgb: vec![], ideal_normal: vec![] };
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
                let tx = |i: usize, j: usize| texels[j * t + i];
                let mut x = vec![];
                for (i, j) in [(i0, j0), (i1, j0), (i0, j1), (i1, j1)] {
                    x.push(tx(i, j).0 as i64);
                    x.push(tx(i, j).1 as i64);
                }
                x.push(ub);
                x.push(vb);
                // triangle (00, 10, 11) where u ≥ v, else (00, 11, 01); weights in 1/256, rounded
                let (l, lf, w1, w2) = if u >= v {
                    ([q[0], q[1], q[3]], [corner[0], corner[1], corner[3]], u - v, v)
                } else {
                    ([q[0], q[3], q[2]], [corner[0], corner[3], corner[2]], u, v - u)
                };
                for li in l {
                    x.extend_from_slice(&li);
                }
                x.push((w1 * 256.0).round() as i64);
                x.push((w2 * 256.0).round() as i64);
                x.push(self.conc);
                x.push(1);
                x.extend_from_slice(&self.src);
                x.extend_from_slice(&self.dst);
                debug_assert_eq!(x.len(), cart_pipeline::INPUTS.len());
                p.inputs.push(x);

                // the ideal: the same bilinear blend of the float normals, the exact light at this point
                let (fu, fv) = (ub as f64 / 256.0, vb as f64 / 256.0);
                let nn = |i: usize, j: usize| normals[j * t + i];
                let mut nrm = [0.0; 3];
                for c in 0..3 {
                    nrm[c] = (1.0 - fv) * ((1.0 - fu) * nn(i0, j0)[c] + fu * nn(i1, j0)[c])
                        + fv * ((1.0 - fu) * nn(i0, j1)[c] + fu * nn(i1, j1)[c]);
                }
                let ln = (nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]).sqrt();
                nrm = nrm.map(|c| c / ln);
                // the seed interpolates the vertex lights linearly and the pipeline renormalises: so does the ideal
                let mut ld = [0.0; 3];
                for c in 0..3 {
                    ld[c] = lf[0][c] + (lf[1][c] - lf[0][c]) * w1 + (lf[2][c] - lf[0][c]) * w2;
                }
                let ll = (ld[0] * ld[0] + ld[1] * ld[1] + ld[2] * ld[2]).sqrt().max(1e-12);
                ld = ld.map(|c| c / ll);
                let xd = (nrm[0] * ld[0] + nrm[1] * ld[1] + nrm[2] * ld[2]).max(0.0) * 1023.0;
                let pi = gloss::ideal_real(self.conc, xd);
                p.ideal_p.push(pi);
                let a = pi / 1023.0 * 255.0;
                p.ideal_rgb.push(std::array::from_fn(|c| {
                    (self.src[c] as f64 * a + self.dst[c] as f64 * (255.0 - a)) / 255.0
                }));
                p.ideal_normal.push(nrm);
            }
        }
        p
    }
}
