//! A scene as plain data: the surface (a flat quad of a procedural height map), the light, the material and the
//! resolution. Every pipeline builds its own per-pixel inputs from it (`crate::pipeline`), through the rasteriser
//! (`crate::raster`). A scene file will fill the same fields.

/// The demo's scene: a procedural height map (round bumps, a ridge, a crater) on a flat quad whose four vertices
/// carry light directions towards a nearby point light, rendered at `size`×`size` with the texture magnified.
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
    /// A user's height map in place of the procedural one (`tex` is then its side).
    pub map: Option<std::sync::Arc<crate::heightmap::HeightMap>>,
    /// A user's normal map in place of the heights' normals (`tex` is then its side).
    pub normal_map: Option<std::sync::Arc<crate::heightmap::NormalMap>>,
    /// A directional light (unit, towards the light) in place of the point light at `light_pos`.
    pub directional: Option<[f64; 3]>,
    /// One light for the whole surface: every vertex gets the direction at the quad's centre (on a curved surface,
    /// every triangle's vertices get the direction at its centre, in its frame there).
    pub per_surface: bool,
    /// A sphere or a torus in place of the quad; `light_pos` is then a point of the world (y up, the object at the
    /// origin, radius 1).
    pub curved: Option<Curved>,
    /// The texture unit's LOD bias, levels (a multiple of 1/256, the LOD unit's Sq3.8): what a MIP filter adds to
    /// λ = log2 ρ before it picks its levels. 0: the isotropic rule as it is.
    pub lod_bias: f64,
    /// How the map is addressed past its edge along u and v, true repeating it and false clamping to the edge
    /// texel; None: the surface's own (the quad clamps, a sphere repeats round u and clamps at its poles, a torus
    /// repeats both ways).
    pub wrap: Option<[bool; 2]>,
    /// A colour map (`[material] colour_map`), at the bump map's side: the blend's destination colour per pixel,
    /// in place of `dst`.
    pub colour_map: Option<std::sync::Arc<crate::heightmap::ColourMap>>,
}

/// A curved surface, how finely it is cut, how it is seen and how often the map repeats round it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Curved {
    pub shape: crate::surface::Shape,
    /// cells along u and v (two triangles a cell)
    pub segments: [usize; 2],
    pub view: crate::surface::View,
    /// the map's repeats along u and v
    pub repeat: [usize; 2],
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
            map: None,
            normal_map: None,
            directional: None,
            per_surface: false,
            curved: None,
            lod_bias: 0.0,
            wrap: None,
            colour_map: None,
        }
    }
}

/// The procedural height field in [0, 1]² → height in texel units / relief.
pub fn height(u: f64, v: f64) -> f64 {
    let bump = |cu: f64, cv: f64, r: f64, h: f64| {
        let d2 = ((u - cu).powi(2) + (v - cv).powi(2)) / (r * r);
        if d2 < 1.0 {
            h * (1.0 - d2).powi(2)
        } else {
            0.0
        }
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

impl Scene {
    /// The surface's height at (u, v) ∈ [0, 1]², in texel units of rise: the user's map (bilinear between its
    /// texel centres) or the procedural field, times the relief.
    pub fn height_at(&self, u: f64, v: f64) -> f64 {
        self.relief * self.map.as_ref().map_or_else(|| height(u, v), |m| m.at(u, v))
    }

    /// Unit direction from quad point (u, v) to the light, tangent space (x along u, y up, z along v).
    pub fn light_dir(&self, u: f64, v: f64) -> [f64; 3] {
        if let Some(d) = self.directional {
            return d;
        }
        let d = [self.light_pos[0] - u, self.light_pos[1], self.light_pos[2] - v];
        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        [d[0] / l, d[1] / l, d[2] / l]
    }

    /// Unit direction from a world point of a curved surface to the light (the directional light's own).
    pub fn light_from(&self, p: [f64; 3]) -> [f64; 3] {
        match self.directional {
            Some(d) => d,
            None => {
                crate::surface::unit([self.light_pos[0] - p[0], self.light_pos[1] - p[1], self.light_pos[2] - p[2]])
            }
        }
    }

    /// The light direction at the quad's four vertices (00, 10, 01, 11); with one light per surface, its direction at
    /// the centre at all four.
    pub fn vertex_lights(&self) -> [[f64; 3]; 4] {
        if self.per_surface {
            return [self.light_dir(0.5, 0.5); 4];
        }
        [self.light_dir(0.0, 0.0), self.light_dir(1.0, 0.0), self.light_dir(0.0, 1.0), self.light_dir(1.0, 1.0)]
    }

    /// The height field sampled at texel centres (in texel units of rise), and its normals.
    pub fn normals(&self) -> Vec<[f64; 3]> {
        if let Some(m) = &self.normal_map {
            return m.n.clone();
        }
        let t = self.tex;
        let n = t as f64;
        let heights: Vec<f64> =
            (0..t * t).map(|k| self.height_at(((k % t) as f64 + 0.5) / n, ((k / t) as f64 + 0.5) / n)).collect();
        vectors::normal_map::normals(&heights, t, t)
    }

    /// The ideal blend of the material's colours at α (8-bit units, real).
    pub fn blend_ideal(&self, alpha: f64) -> [f64; 3] {
        std::array::from_fn(|c| (self.src[c] as f64 * alpha + self.dst[c] as f64 * (255.0 - alpha)) / 255.0)
    }
}
