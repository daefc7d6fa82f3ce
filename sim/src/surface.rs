//! Curved surfaces: a sphere and a torus, each with its analytic tangent frame, cut into triangles, seen through an
//! orthographic camera and rasterised with a depth buffer. The quad keeps its own path (`crate::raster`): the
//! screen is the quad.
//!
//! Parameters (u, v) ∈ [0, 1]². The tangent frame at a point is the one the texture's normals are written in
//! (`vectors::normal_map`): x = T along +u, y = N out of the surface, z = B = T × N, right-handed, and B points
//! along +v, so that a normal map's (x, y, z) is T·x + N·y + B·z in the world.
//! - sphere, radius 1: θ = 2πu round the y axis, φ = π(1 − v) from the top (v = 0 the bottom pole);
//! - torus, tube radius r round a circle of radius 1 − r in the xz plane: θ = 2πu round y, ψ = 2πv round the
//!   tube (v = 0 the outer equator).
//!
//! The world has y up; the camera looks along −z after the object is turned by `spin` about y and then `tilt`
//! about x (degrees), and the unit square of the screen holds [−1.1, 1.1]².

use std::f64::consts::{PI, TAU};

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    Sphere,
    /// the tube's radius (the outer radius is 1)
    Torus {
        minor: f64,
    },
}

/// A tangent frame: T along +u, N out of the surface, B = T × N along +v (unit vectors).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    pub t: [f64; 3],
    pub n: [f64; 3],
    pub b: [f64; 3],
}

pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

pub fn unit(a: [f64; 3]) -> [f64; 3] {
    let l = dot(a, a).sqrt().max(1e-300);
    a.map(|c| c / l)
}

impl Frame {
    /// A world direction in this frame's coordinates (x along T, y along N, z along B).
    pub fn to_tangent(&self, d: [f64; 3]) -> [f64; 3] {
        [dot(d, self.t), dot(d, self.n), dot(d, self.b)]
    }
}

impl Shape {
    /// The point at (u, v).
    pub fn point(&self, u: f64, v: f64) -> [f64; 3] {
        let th = TAU * u;
        match *self {
            Shape::Sphere => {
                let ph = PI * (1.0 - v);
                [ph.sin() * th.cos(), ph.cos(), ph.sin() * th.sin()]
            }
            Shape::Torus { minor: r } => {
                let ps = TAU * v;
                let ring = 1.0 - r + r * ps.cos();
                [ring * th.cos(), r * ps.sin(), ring * th.sin()]
            }
        }
    }

    /// The tangent frame at (u, v), analytic.
    pub fn frame(&self, u: f64, v: f64) -> Frame {
        let th = TAU * u;
        let t = [-th.sin(), 0.0, th.cos()]; // ∂p/∂θ, normalised: both shapes turn round y
        let n = match *self {
            Shape::Sphere => self.point(u, v),
            Shape::Torus { .. } => {
                let ps = TAU * v;
                [ps.cos() * th.cos(), ps.sin(), ps.cos() * th.sin()]
            }
        };
        Frame { t, n, b: cross(t, n) }
    }
}

/// A surface cut into triangles: a (segments.0 + 1) × (segments.1 + 1) grid of vertices (the seam's column and
/// the last row repeated, so that u and v run 0 → 1 inside every triangle), two triangles a cell.
pub struct Mesh {
    pub uv: Vec<[f64; 2]>,
    pub p: Vec<[f64; 3]>,
    pub tris: Vec<[usize; 3]>,
}

pub fn tessellate(shape: Shape, nu: usize, nv: usize) -> Mesh {
    let (mut uv, mut p) = (vec![], vec![]);
    for j in 0..=nv {
        for i in 0..=nu {
            let (u, v) = (i as f64 / nu as f64, j as f64 / nv as f64);
            uv.push([u, v]);
            p.push(shape.point(u, v));
        }
    }
    let at = |i: usize, j: usize| j * (nu + 1) + i;
    let mut tris = vec![];
    for j in 0..nv {
        for i in 0..nu {
            tris.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            tris.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    Mesh { uv, p, tris }
}

/// The orthographic camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    pub tilt_deg: f64,
    pub spin_deg: f64,
}

impl View {
    /// World → view: turned by spin about y, then tilt about x; the camera looks along −z (larger z is nearer).
    pub fn to_view(&self, p: [f64; 3]) -> [f64; 3] {
        let (s, c) = self.spin_deg.to_radians().sin_cos();
        let q = [c * p[0] + s * p[2], p[1], -s * p[0] + c * p[2]];
        let (s, c) = self.tilt_deg.to_radians().sin_cos();
        [q[0], c * q[1] - s * q[2], s * q[1] + c * q[2]]
    }

    /// The direction from the surface towards the camera, in the world.
    pub fn towards_camera(&self) -> [f64; 3] {
        // the view's +z taken back through the inverse turns
        let (s, c) = self.tilt_deg.to_radians().sin_cos();
        let q = [0.0, s, c];
        let (s, c) = self.spin_deg.to_radians().sin_cos();
        [c * q[0] - s * q[2], q[1], s * q[0] + c * q[2]]
    }
}

/// Half the side of the screen square, in world units.
pub const SCREEN_HALF: f64 = 1.1;

/// One covered pixel: its index in the frame (row by row), its triangle and its barycentric weights (of the
/// triangle's first, second and third vertex).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cover {
    pub at: usize,
    pub tri: usize,
    pub bary: [f64; 3],
    /// The barycentric weights' screen derivatives, d/dx and d/dy a pixel (constant over the triangle).
    pub dbary: [[f64; 3]; 2],
}

/// The pixels the mesh covers at `size` × `size`, each with its nearest triangle, in frame order.
pub fn rasterise(mesh: &Mesh, view: View, size: usize) -> Vec<Cover> {
    let px = |p: [f64; 3]| {
        let v = view.to_view(p);
        // screen x right, y down; pixel centres at k + 0.5
        [(v[0] / SCREEN_HALF + 1.0) * 0.5 * size as f64, (1.0 - v[1] / SCREEN_HALF) * 0.5 * size as f64, v[2]]
    };
    let s: Vec<[f64; 3]> = mesh.p.iter().map(|&p| px(p)).collect();
    let mut depth = vec![f64::NEG_INFINITY; size * size];
    let mut hit: Vec<Option<(usize, [f64; 3], f64)>> = vec![None; size * size];
    for (k, t) in mesh.tris.iter().enumerate() {
        let [a, b, c] = t.map(|i| s[i]);
        let area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if area.abs() < 1e-12 {
            continue; // degenerate (a pole's sliver)
        }
        let (x0, x1) = (
            a[0].min(b[0]).min(c[0]).floor().max(0.0) as usize,
            a[0].max(b[0]).max(c[0]).ceil().min(size as f64) as usize,
        );
        let (y0, y1) = (
            a[1].min(b[1]).min(c[1]).floor().max(0.0) as usize,
            a[1].max(b[1]).max(c[1]).ceil().min(size as f64) as usize,
        );
        for y in y0..y1 {
            for x in x0..x1 {
                let (fx, fy) = (x as f64 + 0.5, y as f64 + 0.5);
                let w0 = ((b[0] - fx) * (c[1] - fy) - (b[1] - fy) * (c[0] - fx)) / area;
                let w1 = ((c[0] - fx) * (a[1] - fy) - (c[1] - fy) * (a[0] - fx)) / area;
                let w2 = 1.0 - w0 - w1;
                if w0 < -1e-9 || w1 < -1e-9 || w2 < -1e-9 {
                    continue;
                }
                let z = w0 * a[2] + w1 * b[2] + w2 * c[2];
                let at = y * size + x;
                if z > depth[at] {
                    depth[at] = z;
                    hit[at] = Some((k, [w0.max(0.0), w1.max(0.0), w2.max(0.0)], area));
                }
            }
        }
    }
    let dbary = |k: usize, area: f64| {
        let [a, b, c] = mesh.tris[k].map(|i| s[i]);
        [
            [(b[1] - c[1]) / area, (c[1] - a[1]) / area, (a[1] - b[1]) / area],
            [(c[0] - b[0]) / area, (a[0] - c[0]) / area, (b[0] - a[0]) / area],
        ]
    };
    hit.iter()
        .enumerate()
        .filter_map(|(at, h)| h.map(|(tri, bary, area)| Cover { at, tri, bary, dbary: dbary(tri, area) }))
        .collect()
}
