//! The demo scene, embedded: a procedural height map (round bumps, a ridge, a crater) encoded to Cartesian texels,
//! on a flat quad whose four vertices carry per-vertex light directions towards a nearby point light, split into
//! two triangles, rendered at `size`×`size` with the texture magnified through the bilinear unit.
//! Everything here is set-up (the rasteriser's work): it produces the per-pixel input vector of `cart_pipeline`
//! and, beside it, the f64 ideal of every pixel.

use crate::cart_encode::{self, Encoder};
use crate::polar_encode::{self, Scale};
use crate::{bilinear, cart_pipeline, gloss, light_iter, polar_pipeline};

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
    /// Unit direction from quad point (u, v) to the light, tangent space (x along u, y up, z along v).
    pub fn light_dir(&self, u: f64, v: f64) -> [f64; 3] {
        let d = [self.light_pos[0] - u, self.light_pos[1], self.light_pos[2] - v];
        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        [d[0] / l, d[1] / l, d[2] / l]
    }

    /// The rasteriser's work for every pixel, shared by both pipelines' set-up.
    fn pixels(&self, normals: &[[f64; 3]]) -> Vec<Pixel> {
        let t = self.tex;
        let corner = [self.light_dir(0.0, 0.0), self.light_dir(1.0, 0.0), self.light_dir(0.0, 1.0), self.light_dir(1.0, 1.0)];
        let n = self.size;
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
                // the ideal normal: the same bilinear blend of the float normals, renormalised
                let (fu, fv) = (ub as f64 / 256.0, vb as f64 / 256.0);
                let nn = |i: usize, j: usize| normals[j * t + i];
                let mut nrm = [0.0; 3];
                for c in 0..3 {
                    nrm[c] = (1.0 - fv) * ((1.0 - fu) * nn(i0, j0)[c] + fu * nn(i1, j0)[c])
                        + fv * ((1.0 - fu) * nn(i0, j1)[c] + fu * nn(i1, j1)[c]);
                }
                let ln = (nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]).sqrt();
                nrm = nrm.map(|c| c / ln);
                // the seed interpolates the vertex lights linearly and renormalises: so does the ideal
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

    /// The height field sampled at texel centres (in texel units of rise), and its normals.
    fn normals(&self) -> Vec<[f64; 3]> {
        let t = self.tex;
        let n = t as f64;
        let heights: Vec<f64> =
            (0..t * t).map(|k| height(((k % t) as f64 + 0.5) / n, ((k / t) as f64 + 0.5) / n) * self.relief).collect();
        crate::height::normals(&heights, t, t)
    }

    fn blend_ideal(&self, alpha: f64) -> [f64; 3] {
        std::array::from_fn(|c| (self.src[c] as f64 * alpha + self.dst[c] as f64 * (255.0 - alpha)) / 255.0)
    }

    pub fn prepare(&self) -> Prepared {
        let t = self.tex;
        let normals = self.normals();
        let texels: Vec<(u8, u8)> = normals.iter().map(|&n| cart_encode::encode(self.encoder, n)).collect();
        let corner = [self.light_dir(0.0, 0.0), self.light_dir(1.0, 0.0), self.light_dir(0.0, 1.0), self.light_dir(1.0, 1.0)];
        let q: Vec<[i64; 3]> = corner.iter().map(|&d| light_iter::quantise_vertex(d)).collect();
        let mut p = Prepared { size: self.size, inputs: vec![], ideal_p: vec![], ideal_rgb: vec![], ideal_normal: vec![] };
        for px in self.pixels(&normals) {
            use cart_pipeline::input;
            let mut x = vec![0; cart_pipeline::INPUTS.len()];
            for (slot, (i, j)) in cart_pipeline::TEXELS.iter().zip(px.corners) {
                (x[slot[0]], x[slot[1]]) = (texels[j * t + i].0 as i64, texels[j * t + i].1 as i64);
            }
            (x[input::ublend], x[input::vblend]) = (px.ub, px.vb);
            for (l, k) in cart_pipeline::LIGHTS.iter().zip(px.tri) {
                for c in 0..3 {
                    x[l[c]] = q[k][c];
                }
            }
            // weights in 1/256, rounded
            (x[input::w1], x[input::w2]) = ((px.w1 * 256.0).round() as i64, (px.w2 * 256.0).round() as i64);
            (x[input::conc], x[input::mode]) = (self.conc, 1);
            for c in 0..3 {
                (x[cart_pipeline::SRC[c]], x[cart_pipeline::DST[c]]) = (self.src[c], self.dst[c]);
            }
            p.inputs.push(x);
            let (nrm, ld) = (px.normal, px.light);
            let xd = (nrm[0] * ld[0] + nrm[1] * ld[1] + nrm[2] * ld[2]).max(0.0) * 1023.0;
            let pi = gloss::ideal_real(self.conc, xd);
            p.ideal_p.push(pi);
            p.ideal_rgb.push(self.blend_ideal(pi / 1023.0 * 255.0));
            p.ideal_normal.push(nrm);
        }
        p
    }

    /// The same scene for the polar pipeline (seed 000, first embodiment): the same height map's normals
    /// polar-encoded (S, R) in `scale`; the texture filtered the way the colour filter would, S and R bilinearly
    /// blended as plain numbers (the seed's shortcoming 2: across R's 255 → 0 wrap this is wrong); one light per
    /// surface (shortcoming 1: the hardware cannot interpolate polar lights), the direction at the quad's centre,
    /// moved onto the horizon if below it (shortcoming 3), weight h; shade raised to p = pw/4. The ideal is the
    /// Cartesian path's: the filtered float normal against the pixel's own light, max(0, (1 − h) + h·N·L)^p.
    pub fn prepare_polar(&self, scale: Scale, pw: i64, h: f64) -> PreparedPolar {
        let t = self.tex;
        let normals = self.normals();
        let codes: Vec<(i64, i64)> = normals.iter().map(|&n| polar_encode::encode_normal(scale, n)).collect();
        let surface_dir = self.light_dir(0.5, 0.5);
        let light = polar_encode::encode_light(scale, surface_dir, h);
        let mut p = PreparedPolar {
            size: self.size, light, surface_dir, inputs: vec![], ideal_alpha: vec![], ideal_rgb: vec![], straddles: vec![],
            normal: vec![], light_dir: vec![],
        };
        for px in self.pixels(&normals) {
            let c = px.corners.map(|(i, j)| codes[j * t + i]);
            let s = bilinear::exact_channel(c[0].0, c[1].0, c[2].0, c[3].0, px.ub, px.vb, bilinear::F);
            let r = bilinear::exact_channel(c[0].1, c[1].1, c[2].1, c[3].1, px.ub, px.vb, bilinear::F);
            let (rmin, rmax) = c.iter().fold((255, 0), |(lo, hi), &(_, r)| (lo.min(r), hi.max(r)));
            p.straddles.push(rmax - rmin > 128);
            use polar_pipeline::input;
            let mut x = vec![0; polar_pipeline::INPUTS.len()];
            (x[input::s], x[input::r], x[input::q]) = (s, r, light.q);
            (x[input::k1], x[input::k2], x[input::k3], x[input::pw], x[input::mode]) = (light.k1, light.k2, light.k3, pw, 1);
            (x[input::src_r], x[input::src_g], x[input::src_b]) = (self.src[0], self.src[1], self.src[2]);
            (x[input::dst_r], x[input::dst_g], x[input::dst_b]) = (self.dst[0], self.dst[1], self.dst[2]);
            p.inputs.push(x);
            let (nrm, ld) = (px.normal, px.light);
            let d = (1.0 - h) + h * (nrm[0] * ld[0] + nrm[1] * ld[1] + nrm[2] * ld[2]);
            let a = 255.0 * d.clamp(0.0, 1.0).powf(pw as f64 / 4.0);
            p.ideal_alpha.push(a);
            p.ideal_rgb.push(self.blend_ideal(a));
            p.normal.push(nrm);
            p.light_dir.push(ld);
        }
        p
    }
}

/// One pixel's rasterisation: the four texels and blend factors, the light triangle and weights, and the ideal
/// normal and light.
struct Pixel {
    corners: [(usize, usize); 4],
    ub: i64,
    vb: i64,
    tri: [usize; 3],
    w1: f64,
    w2: f64,
    normal: [f64; 3],
    light: [f64; 3],
}

/// The polar pipeline's inputs for every pixel, the surface's light, the ideal α (8-bit units) and colour, and
/// which pixels filter across R's wrap.
pub struct PreparedPolar {
    pub size: usize,
    /// the surface's one light, as encoded, and the direction it was encoded from (the quad centre's)
    pub light: polar_encode::Light,
    pub surface_dir: [f64; 3],
    pub inputs: Vec<Vec<i64>>,
    pub ideal_alpha: Vec<f64>,
    pub ideal_rgb: Vec<[f64; 3]>,
    pub straddles: Vec<bool>,
    /// per pixel: the ideal (filtered float) normal and the pixel's own light direction
    pub normal: Vec<[f64; 3]>,
    pub light_dir: Vec<[f64; 3]>,
}
