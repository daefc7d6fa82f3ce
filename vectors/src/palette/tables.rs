//! Tarini et al. §5.1, §6 and §7: the per-frame colour table C = f(N) over the palette, with the light and view moved
//! into object space first (the inverse of the modelling rotation, its transpose), and the three ways of blending
//! the table's entry with the object's own colour. The functions are the paper's list; each is its own f64
//! reference. The hardware builder (`table_builder`, to come) computes the Lambert and specular terms through the
//! project's `normalise`, `dot3` and `gloss` units; `exact_lambert_specular` is that arithmetic.

use crate::stats::{dot, unit};

/// A rotation as its three rows; `to_object` applies its inverse (the transpose).
pub type Rotation = [[f64; 3]; 3];

pub const IDENTITY: Rotation = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// A world-space direction in the object's frame, for an object rotated by `m` (world = m · object).
pub fn to_object(m: &Rotation, v: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| m[0][i] * v[0] + m[1][i] * v[1] + m[2][i] * v[2])
}

/// The rotation by `angle` radians about the y axis (up).
pub fn about_y(angle: f64) -> Rotation {
    let (s, c) = angle.sin_cos();
    [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]]
}

/// One light: a direction towards it (object space after `to_object`) and its colour (0..1 per channel).
#[derive(Clone, Copy, Debug)]
pub struct Light {
    pub dir: [f64; 3],
    pub colour: [f64; 3],
}

/// The lighting models of §5.1.
#[derive(Clone, Debug)]
pub enum Shading {
    /// ambient plus Lambert over any number of lights, times a diffuse colour
    Lambert { ambient: f64, diffuse: [f64; 3], lights: Vec<Light> },
    /// Blinn–Phong specular over the lights, exponent p, with the Lambert term under it
    Specular { ambient: f64, diffuse: [f64; 3], specular: [f64; 3], p: f64, lights: Vec<Light> },
    /// the reflected view direction looked up in an environment (`environment`)
    Environment,
    /// Lambert of the first light cut into `bands` flat tones of the diffuse colour
    Toon { bands: u32, diffuse: [f64; 3], light: [f64; 3] },
    /// the reflected view direction coloured by a landscape: brown below the horizon, blue above (Figure 7)
    Chrome,
    /// the paper's non-photorealistic shade (Figure 6): Phong with the angle between the reflected light and the
    /// view doubled, max(0, cos 2θ)^p
    DoubleAngle { p: f64, light: [f64; 3] },
}

/// A procedural environment in every direction: a sky gradient, a sun, a chequered ground.
pub fn environment(d: [f64; 3]) -> [f64; 3] {
    let d = unit(d);
    if d[1] >= 0.0 {
        let sun = dot(d, unit([0.4, 0.6, -0.7])).max(0.0).powf(64.0);
        [0.35 + 0.4 * d[1] + sun, 0.55 + 0.3 * d[1] + sun, 0.9 + 0.1 * d[1] + 0.6 * sun].map(|c| c.min(1.0))
    } else {
        let (u, v) = (d[0] / -d[1], d[2] / -d[1]);
        let check = ((u.floor() + v.floor()) as i64).rem_euclid(2) as f64;
        [0.25 + 0.2 * check, 0.3 + 0.15 * check, 0.15 + 0.05 * check]
    }
}

/// The mirror direction of `v` (towards the viewer) about `n`.
fn reflect(v: [f64; 3], n: [f64; 3]) -> [f64; 3] {
    let k = 2.0 * dot(n, v);
    [0, 1, 2].map(|c| k * n[c] - v[c])
}

/// One entry: f(n) as RGBA in 0..1. `view` is the direction towards the viewer (object space). Alpha carries the
/// Lambert intensity (what equations (1) and (2) blend the object's colour by); the colour the model's.
pub fn entry(s: &Shading, n: [f64; 3], view: [f64; 3]) -> [f64; 4] {
    let n = unit(n);
    let lambert = |lights: &[Light], ambient: f64| {
        let mut c = [ambient; 3];
        let mut a = ambient;
        for l in lights {
            let d = dot(n, unit(l.dir)).max(0.0);
            a += d;
            for k in 0..3 {
                c[k] += d * l.colour[k];
            }
        }
        (c.map(|x| x.min(1.0)), a.min(1.0))
    };
    match s {
        Shading::Lambert { ambient, diffuse, lights } => {
            let (c, a) = lambert(lights, *ambient);
            [c[0] * diffuse[0], c[1] * diffuse[1], c[2] * diffuse[2], a]
        }
        Shading::Specular { ambient, diffuse, specular, p, lights } => {
            let (c, a) = lambert(lights, *ambient);
            let mut rgb = [c[0] * diffuse[0], c[1] * diffuse[1], c[2] * diffuse[2]];
            for l in lights {
                let h = unit([0, 1, 2].map(|k| unit(l.dir)[k] + unit(view)[k]));
                let sp = if dot(n, unit(l.dir)) > 0.0 { dot(n, h).max(0.0).powf(*p) } else { 0.0 };
                for k in 0..3 {
                    rgb[k] += sp * specular[k] * l.colour[k];
                }
            }
            [rgb[0].min(1.0), rgb[1].min(1.0), rgb[2].min(1.0), a]
        }
        Shading::Environment => {
            let c = environment(reflect(unit(view), n));
            [c[0], c[1], c[2], 1.0]
        }
        Shading::Toon { bands, diffuse, light } => {
            let d = dot(n, unit(*light)).max(0.0);
            let b = (*bands).max(1) as f64;
            let tone = ((d * b).floor().min(b - 1.0) + 0.5) / b;
            [diffuse[0] * tone, diffuse[1] * tone, diffuse[2] * tone, tone]
        }
        Shading::Chrome => {
            let r = reflect(unit(view), n);
            let c = if r[1] >= 0.0 {
                [0.3 + 0.2 * r[1], 0.5 + 0.3 * r[1], 0.85 + 0.15 * r[1]]
            } else {
                [0.45 + 0.2 * r[1], 0.3 + 0.1 * r[1], 0.15]
            };
            [c[0], c[1], c[2], 1.0]
        }
        Shading::DoubleAngle { p, light } => {
            // θ between the reflected light and the view; cos 2θ = 2cos²θ − 1
            let r = reflect(unit(*light), n);
            let c = dot(unit(r), unit(view));
            let s = if c > 0.0 { (2.0 * c * c - 1.0).max(0.0).powf(*p) } else { 0.0 };
            [s, s, s, s]
        }
    }
}

/// The table over a palette: one RGBA entry per normal, 8 bits a channel (rounded).
pub fn table(s: &Shading, palette: &[[f64; 3]], view: [f64; 3]) -> Vec<[u8; 4]> {
    palette.iter().map(|&n| entry(s, n, view).map(|c| (c * 255.0).round().clamp(0.0, 255.0) as u8)).collect()
}

/// Several materials (§6): the (material, normal) pairs sorted by material and kept as intervals of the one table:
/// material m's normals are entries `starts[m]..starts[m + 1]`, each shaded by its material's model.
pub struct Materials {
    pub starts: Vec<usize>,
    pub normals: Vec<[f64; 3]>,
}

impl Materials {
    /// From (material, normal) pairs in any order; a material with no normals gets an empty interval.
    pub fn new(count: usize, pairs: &[(usize, [f64; 3])]) -> Materials {
        let mut sorted: Vec<(usize, [f64; 3])> = pairs.to_vec();
        sorted.sort_by_key(|p| p.0);
        let mut starts = vec![0; count + 1];
        for (m, s) in starts.iter_mut().enumerate().skip(1) {
            *s = sorted.iter().filter(|p| p.0 < m).count();
        }
        Materials { starts, normals: sorted.iter().map(|p| p.1).collect() }
    }

    /// The material of table entry `i`.
    pub fn material_of(&self, i: usize) -> usize {
        self.starts.partition_point(|&s| s <= i) - 1
    }

    /// The table: each interval shaded by its material's model.
    pub fn table(&self, models: &[Shading], view: [f64; 3]) -> Vec<[u8; 4]> {
        (0..self.normals.len())
            .map(|i| {
                entry(&models[self.material_of(i)], self.normals[i], view)
                    .map(|c| (c * 255.0).round().clamp(0.0, 255.0) as u8)
            })
            .collect()
    }
}

/// §7.1, equation (1): the object's colour o (RGBA 0..1) with an entry c whose alpha is the Lambert shade and whose
/// colour is the reflected light: o·α + (1 − o·α)·c per channel, the object's alpha kept.
pub fn blend_exact_specular(o: [f64; 4], c: [f64; 4]) -> [f64; 4] {
    let f = |k: usize| o[k] * c[3] + (1.0 - o[k] * c[3]) * c[k];
    [f(0), f(1), f(2), o[3]]
}

/// §7.2, equation (2): o·α + (1 − o)·c per channel, one pass.
pub fn blend_approximate(o: [f64; 4], c: [f64; 4]) -> [f64; 4] {
    let f = |k: usize| o[k] * c[3] + (1.0 - o[k]) * c[k];
    [f(0), f(1), f(2), o[3]]
}

/// §7.3: colour stored as a material: the entry is the final colour, nothing to blend.
pub fn blend_material(c: [f64; 4]) -> [f64; 4] {
    c
}

#[cfg(test)]
mod tests {
    use super::*;

    const UP: [f64; 3] = [0.0, 1.0, 0.0];

    #[test]
    fn lights_are_moved_into_object_space() {
        // an object turned 90° about y (its +z now along world +x): a world light along +x is along its own +z
        let m = about_y(std::f64::consts::FRAC_PI_2);
        let l = to_object(&m, [1.0, 0.0, 0.0]);
        assert!(l[0].abs() < 1e-12 && l[1].abs() < 1e-12 && (l[2] - 1.0).abs() < 1e-12, "{l:?}");
        // and back: m · l is the world light again
        let back: [f64; 3] = std::array::from_fn(|i| m[i][0] * l[0] + m[i][1] * l[1] + m[i][2] * l[2]);
        assert!((back[0] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn lambert_adds_its_lights_and_a_normal_below_the_horizon_gets_the_ambient() {
        let white = [1.0; 3];
        let s = Shading::Lambert {
            ambient: 0.1,
            diffuse: white,
            lights: vec![Light { dir: UP, colour: [0.5; 3] }, Light { dir: [1.0, 1.0, 0.0], colour: [0.5; 3] }],
        };
        let e = entry(&s, UP, UP);
        assert!((e[0] - (0.1 + 0.5 + 0.5 * 0.5f64.sqrt())).abs() < 1e-12, "{e:?}");
        let below = entry(&s, [0.0, -1.0, 0.0], UP);
        assert!((below[0] - 0.1).abs() < 1e-12);
    }

    #[test]
    fn specular_peaks_at_the_half_vector_and_the_npr_shade_at_a_quarter_of_the_angle() {
        let l = unit([1.0, 1.0, 0.0]);
        let v = unit([-1.0, 1.0, 0.0]);
        let s = Shading::Specular {
            ambient: 0.0,
            diffuse: [0.0; 3],
            specular: [1.0; 3],
            p: 50.0,
            lights: vec![Light { dir: l, colour: [1.0; 3] }],
        };
        assert!((entry(&s, UP, v)[0] - 1.0).abs() < 1e-12);
        assert!(entry(&s, unit([0.3, 1.0, 0.0]), v)[0] < 0.5);
        // doubling the angle: a mirror one angle off is dimmer than Phong would make it
        let d = Shading::DoubleAngle { p: 1.0, light: l };
        let n = unit([0.1, 1.0, 0.0]);
        let r = reflect(l, n);
        let c = dot(unit(r), v);
        assert!((entry(&d, n, v)[0] - (2.0 * c * c - 1.0)).abs() < 1e-12 && entry(&d, n, v)[0] < c);
    }

    #[test]
    fn toon_has_its_bands_and_chrome_its_horizon() {
        let t = Shading::Toon { bands: 3, diffuse: [1.0; 3], light: UP };
        let tones: std::collections::BTreeSet<u64> =
            (0..200).map(|k| entry(&t, [((k as f64) / 100.0 - 1.0), 1.0, 0.3], UP)[0].to_bits()).collect();
        assert!(tones.len() <= 3, "{}", tones.len());
        // looking straight down at an upward normal the reflection points up: sky
        assert!(entry(&Shading::Chrome, UP, UP)[2] > 0.8);
        assert!(entry(&Shading::Chrome, unit([1.0, 0.3, 0.0]), UP)[2] < 0.3);
    }

    #[test]
    fn materials_are_sorted_into_intervals_and_an_empty_material_is_an_empty_interval() {
        let pairs = [(2, UP), (0, [1.0, 0.0, 0.0]), (2, [0.0, 0.0, 1.0]), (0, UP)];
        let m = Materials::new(3, &pairs);
        assert_eq!(m.starts, vec![0, 2, 2, 4]);
        assert_eq!((0..4).map(|i| m.material_of(i)).collect::<Vec<_>>(), [0, 0, 2, 2]);
        let models = [Shading::Chrome, Shading::Environment, Shading::Toon { bands: 2, diffuse: [1.0; 3], light: UP }];
        assert_eq!(m.table(&models, UP).len(), 4);
    }

    #[test]
    fn the_blends_agree_where_they_should() {
        let o = [0.8, 0.5, 0.2, 0.7];
        // no reflected light: (1) and (2) are both o·α
        let c = [0.0, 0.0, 0.0, 0.6];
        assert_eq!(blend_exact_specular(o, c), blend_approximate(o, c));
        // a white object: (2) drops the reflected light, (1) keeps (1 − α) of it
        let c = [0.5, 0.5, 0.5, 0.6];
        let w = [1.0, 1.0, 1.0, 1.0];
        assert!((blend_approximate(w, c)[0] - 0.6).abs() < 1e-12);
        assert!((blend_exact_specular(w, c)[0] - (0.6 + 0.4 * 0.5)).abs() < 1e-12);
        assert_eq!(blend_material(c), c);
    }
}
