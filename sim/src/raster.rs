//! The rasteriser: for every pixel of a scene the surface covers, the four texels and blend factors the texture
//! filter reads, the light triangle and its weights, and the ideal (filtered float) normal and light beside them.
//! The quad fills the screen; a sphere or a torus (`crate::surface`) covers part of it, the rest is background.
//!
//! Vertex lights are listed per triangle corner (`Frame::lights`, three a triangle), so that one light per surface
//! can give a triangle's three corners its own light while another triangle at the same vertex has another.

use crate::scene::Scene;
use crate::surface::{self, dot, Mesh};

/// One pixel's rasterisation.
pub struct Pixel {
    /// The four texels (i, j) in the bilinear unit's order: 00, 10, 01, 11.
    pub corners: [(usize, usize); 4],
    /// Blend factors, U8 (1/256), truncated.
    pub ub: i64,
    pub vb: i64,
    /// The light triangle's corners (indices into `Frame::lights`) and the weights of its second and third.
    pub tri: [usize; 3],
    pub w1: f64,
    pub w2: f64,
    /// The ideal normal (the float normals blended with the same factors, renormalised) and the ideal light (the
    /// vertex lights interpolated linearly and renormalised, as the seed does).
    pub normal: [f64; 3],
    pub light: [f64; 3],
    /// The pixel's place in the frame (row by row).
    pub at: usize,
    /// The sample's position in texels of level 0 (texel i spans [i, i + 1), its centre at i + ½), unwrapped, and
    /// its screen derivatives du/dx, dv/dx, du/dy, dv/dy (texels a pixel): what a rasteriser gives the texture unit.
    pub pos: [f64; 2],
    pub deriv: [f64; 4],
    /// Whether the map repeats along u and along v (else it is clamped at its edges).
    pub wrap: [bool; 2],
    /// The one light of the pixel's surface, in its tangent frame: the quad's centre's; a curved surface's
    /// triangle's, at its centre.
    pub surface: [f64; 3],
}

/// A frame rasterised: its covered pixels in frame order, and the lights of every triangle's corners.
pub struct Frame {
    pub pixels: Vec<Pixel>,
    pub lights: Vec<[f64; 3]>,
}

/// The scene's frame: the quad's, or the curved surface's.
pub fn frame(scene: &Scene, normals: &[[f64; 3]]) -> Frame {
    match &scene.curved {
        None => quad(scene, normals),
        Some(c) => curved(scene, c, normals),
    }
}

/// Every pixel the scene's surface covers, row by row; `normals` are the map's, one per texel.
pub fn pixels(scene: &Scene, normals: &[[f64; 3]]) -> Vec<Pixel> {
    frame(scene, normals).pixels
}

/// The bilinear blend of the four corner texels' normals with the blend factors, renormalised.
fn filtered(normals: &[[f64; 3]], t: usize, corners: [(usize, usize); 4], ub: i64, vb: i64) -> [f64; 3] {
    let (fu, fv) = (ub as f64 / 256.0, vb as f64 / 256.0);
    let nn = |(i, j): (usize, usize)| normals[j * t + i];
    let mut nrm = [0.0; 3];
    for c in 0..3 {
        nrm[c] = (1.0 - fv) * ((1.0 - fu) * nn(corners[0])[c] + fu * nn(corners[1])[c])
            + fv * ((1.0 - fu) * nn(corners[2])[c] + fu * nn(corners[3])[c]);
    }
    surface::unit(nrm)
}

/// The corner lights interpolated linearly with the weights of the second and third, renormalised (as the seed).
fn interpolated(lf: [[f64; 3]; 3], w1: f64, w2: f64) -> [f64; 3] {
    let ld: [f64; 3] = std::array::from_fn(|c| lf[0][c] + (lf[1][c] - lf[0][c]) * w1 + (lf[2][c] - lf[0][c]) * w2);
    let ll = dot(ld, ld).sqrt().max(1e-12);
    ld.map(|c| c / ll)
}

/// A texel coordinate x (in map widths; texel centres at (k + 0.5)/t) on an axis of t texels: the corner pair and
/// the U8 blend factor (truncated), repeating the map or clamped to its edge texels.
fn axis(x: f64, t: usize, wrap: bool) -> (usize, usize, i64) {
    let s = x * t as f64 - 0.5;
    if wrap {
        let f = s.floor();
        let i0 = (f as i64).rem_euclid(t as i64) as usize;
        (i0, (i0 + 1) % t, (((s - f) * 256.0) as i64).min(255))
    } else {
        let s = s.clamp(0.0, (t - 1) as f64);
        let i0 = s.floor() as usize;
        (i0, (i0 + 1).min(t - 1), (((s - i0 as f64) * 256.0) as i64).min(255))
    }
}

/// The quad: the screen is the quad, its four vertices carry the lights, two triangles.
fn quad(scene: &Scene, normals: &[[f64; 3]]) -> Frame {
    let t = scene.tex;
    let wrap = scene.wrap.unwrap_or([false, false]);
    let corner = scene.vertex_lights();
    let surface_light = scene.light_dir(0.5, 0.5);
    // the corners of triangles (00, 10, 11) and (00, 11, 01)
    let lights = vec![corner[0], corner[1], corner[3], corner[0], corner[3], corner[2]];
    let n = scene.size;
    let mut out = Vec::with_capacity(n * n);
    for py in 0..n {
        for px in 0..n {
            let (u, v) = ((px as f64 + 0.5) / n as f64, (py as f64 + 0.5) / n as f64);
            // texture address: texel centres at (i + 0.5)/t, clamped at the borders unless the scene repeats
            let ((i0, i1, ub), (j0, j1, vb)) = (axis(u, t, wrap[0]), axis(v, t, wrap[1]));
            // triangle (00, 10, 11) where u ≥ v, else (00, 11, 01)
            let (tri, w1, w2) = if u >= v { ([0, 1, 2], u - v, v) } else { ([3, 4, 5], u, v - u) };
            let corners = [(i0, j0), (i1, j0), (i0, j1), (i1, j1)];
            let normal = filtered(normals, t, corners, ub, vb);
            let light = interpolated(tri.map(|k| lights[k]), w1, w2);
            let (pos, d) = ([u * t as f64, v * t as f64], t as f64 / n as f64);
            out.push(Pixel {
                corners,
                ub,
                vb,
                tri,
                w1,
                w2,
                normal,
                light,
                at: py * n + px,
                surface: surface_light,
                pos,
                deriv: [d, 0.0, 0.0, d],
                wrap,
            });
        }
    }
    Frame { pixels: out, lights }
}

/// A sphere or a torus: its triangles seen through the camera, the map repeated round it (wrapping along u, and
/// along v on the torus; clamped at the sphere's poles), each corner's light in its own tangent frame.
fn curved(scene: &Scene, c: &crate::scene::Curved, normals: &[[f64; 3]]) -> Frame {
    let t = scene.tex;
    let mesh: Mesh = surface::tessellate(c.shape, c.segments[0], c.segments[1]);
    let light_at = |u: f64, v: f64| c.shape.frame(u, v).to_tangent(scene.light_from(c.shape.point(u, v)));
    // each triangle's one light, at its centre; and its corners' lights (that one again, with one light per surface)
    let centre: Vec<[f64; 3]> = mesh
        .tris
        .iter()
        .map(|tri| {
            light_at(
                tri.iter().map(|&i| mesh.uv[i][0]).sum::<f64>() / 3.0,
                tri.iter().map(|&i| mesh.uv[i][1]).sum::<f64>() / 3.0,
            )
        })
        .collect();
    let mut lights = Vec::with_capacity(mesh.tris.len() * 3);
    for (tri, &own) in mesh.tris.iter().zip(&centre) {
        if scene.per_surface {
            lights.extend([own; 3]);
        } else {
            lights.extend(tri.map(|i| light_at(mesh.uv[i][0], mesh.uv[i][1])));
        }
    }
    let wrap = scene.wrap.unwrap_or([true, matches!(c.shape, surface::Shape::Torus { .. })]);
    let mut out = vec![];
    for cv in surface::rasterise(&mesh, c.view, scene.size) {
        let tri = mesh.tris[cv.tri];
        let uv: [f64; 2] = std::array::from_fn(|k| (0..3).map(|i| cv.bary[i] * mesh.uv[tri[i]][k]).sum());
        // texels of level 0 along each axis per unit of (u, v), and the position's screen derivatives
        let scale = [c.repeat[0] as f64 * t as f64, c.repeat[1] as f64 * t as f64];
        let d = |axis: usize, k: usize| (0..3).map(|i| cv.dbary[axis][i] * mesh.uv[tri[i]][k]).sum::<f64>() * scale[k];
        let (pos, deriv) = ([uv[0] * scale[0], uv[1] * scale[1]], [d(0, 0), d(0, 1), d(1, 0), d(1, 1)]);
        let (i0, i1, ub) = axis(uv[0] * c.repeat[0] as f64, t, wrap[0]);
        let (j0, j1, vb) = axis(uv[1] * c.repeat[1] as f64, t, wrap[1]);
        let corners = [(i0, j0), (i1, j0), (i0, j1), (i1, j1)];
        let k = 3 * cv.tri;
        let (w1, w2) = (cv.bary[1], cv.bary[2]);
        let normal = filtered(normals, t, corners, ub, vb);
        let light = interpolated([lights[k], lights[k + 1], lights[k + 2]], w1, w2);
        out.push(Pixel {
            corners,
            ub,
            vb,
            tri: [k, k + 1, k + 2],
            w1,
            w2,
            normal,
            light,
            at: cv.at,
            surface: centre[cv.tri],
            pos,
            deriv,
            wrap,
        });
    }
    Frame { pixels: out, lights }
}
