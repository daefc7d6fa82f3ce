//! `polar_encode` (software only): US 6,819,319's first embodiment stores a bump normal as two angles, S (elevation
//! from the surface plane, 0 to 90°) and R (rotation about the surface normal, 0 to 360°, R = 0 along +u), each a
//! U8; a surface's light as T (elevation) and Q (rotation) folded with a weight h into k1 = 1 − h, k2 = h·sin T,
//! k3 = h·cos T (equation 4). The light cannot be below the horizon (shortcoming 3 of the seed): T < 0 is moved
//! onto it, T = 0, keeping its rotation Q.
//!
//! Two scales, a named option ([`Scale`]):
//! - `Seed` (default): 0..255 means 0 to *almost* 90° / 360° (256 would be exact); the encoder rounds to nearest
//!   and saturates S at 255. k's are round(·255).
//! - `Dc255`: the convention of the Dreamcast (PowerVR2) toolchains: 255 means exactly 90° / 360°, every value is
//!   truncated, K1 = 255 − trunc(h·255), K2 = trunc(h·255·sin T), K3 = trunc(h·255·cos T), Q = trunc(Q/2π·255).
//!
//! Axes: the normal is (x, y, z) with y out of the surface, x along u and z along v, as in the Cartesian path.

use std::f64::consts::{FRAC_PI_2, TAU};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Scale {
    /// the seed's: 256 steps per quarter / full turn
    #[default]
    Seed,
    /// the Dreamcast toolchains': 255 steps per quarter / full turn, truncating
    Dc255,
}

impl Scale {
    pub fn name(self) -> &'static str {
        match self {
            Scale::Seed => "seed (256 = 90°/360°, rounded)",
            Scale::Dc255 => "Dreamcast (255 = 90°/360°, truncated)",
        }
    }
    /// Steps in a quarter turn (S, T) and in a full turn (R, Q).
    pub fn steps(self) -> f64 {
        match self {
            Scale::Seed => 256.0,
            Scale::Dc255 => 255.0,
        }
    }
    /// The elevation an S (or T) code stands for, in radians.
    pub fn elevation(self, s: i64) -> f64 {
        s as f64 * FRAC_PI_2 / self.steps()
    }
    /// The rotation an R (or Q, or R − Q) code stands for, in radians.
    pub fn rotation(self, r: i64) -> f64 {
        r as f64 * TAU / self.steps()
    }
    fn quantise(self, x: f64) -> i64 {
        match self {
            Scale::Seed => x.round() as i64,
            Scale::Dc255 => x.trunc() as i64,
        }
    }
}

/// Elevation (radians, ≥ 0 after the horizon clamp) and rotation (radians, 0..2π) of a direction; y < 0 is moved
/// onto the horizon, keeping its rotation (a direction straight down has none: it gets rotation 0). Returns whether
/// it was moved.
pub fn angles(v: [f64; 3]) -> (f64, f64, bool) {
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let below = v[1] < 0.0;
    let y = if below { 0.0 } else { v[1] / len };
    let elev = y.clamp(0.0, 1.0).asin();
    let mut rot = v[2].atan2(v[0]);
    if rot < 0.0 {
        rot += TAU;
    }
    (elev, rot, below)
}

/// A unit normal (y ≥ 0) → (S, R).
pub fn encode_normal(sc: Scale, n: [f64; 3]) -> (i64, i64) {
    let (elev, rot, _) = angles(n);
    let s = sc.quantise(elev / FRAC_PI_2 * sc.steps()).clamp(0, 255);
    let r = sc.quantise(rot / TAU * sc.steps());
    (s, r.rem_euclid(256))
}

/// An 8-bit height map (row-major, `w`×`h`; `relief` texels of rise for a height step of 255) → (S, R) per texel,
/// as the normal-map tools do it: central differences with wrap (`height::normals`), then `encode_normal`.
pub fn encode_height_map(sc: Scale, heights: &[u8], w: usize, h: usize, relief: f64) -> Vec<(i64, i64)> {
    let hf: Vec<f64> = heights.iter().map(|&x| x as f64 / 255.0 * relief).collect();
    crate::normal_map::normals(&hf, w, h).into_iter().map(|n| encode_normal(sc, n)).collect()
}

/// (S, R) → the unit normal it stands for.
pub fn decode_normal(sc: Scale, s: i64, r: i64) -> [f64; 3] {
    let (e, a) = (sc.elevation(s), sc.rotation(r));
    [e.cos() * a.cos(), e.sin(), e.cos() * a.sin()]
}

/// A surface's light parameters, as the polar shade unit takes them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    pub k1: i64,
    pub k2: i64,
    pub k3: i64,
    pub q: i64,
    /// T in radians after the horizon clamp
    pub t: f64,
    /// the light was below the horizon and was moved onto it
    pub moved: bool,
}

/// Light direction (towards the light) and weight h ∈ [0, 1] → T, Q and k1, k2, k3 (equation 4).
pub fn encode_light(sc: Scale, l: [f64; 3], h: f64) -> Light {
    let (t, rot, moved) = angles(l);
    let h = h.clamp(0.0, 1.0);
    let (k1, k2, k3) = match sc {
        Scale::Seed => (((1.0 - h) * 255.0).round(), (h * t.sin() * 255.0).round(), (h * t.cos() * 255.0).round()),
        Scale::Dc255 => (255.0 - (h * 255.0).trunc(), (h * 255.0 * t.sin()).trunc(), (h * 255.0 * t.cos()).trunc()),
    };
    let q = sc.quantise(rot / TAU * sc.steps()).rem_euclid(256);
    Light { k1: k1 as i64, k2: k2 as i64, k3: k3 as i64, q, t, moved }
}

/// The angle (degrees) between a direction and its polar encoding, decoded.
pub fn round_trip_error_deg(sc: Scale, n: [f64; 3]) -> f64 {
    let (s, r) = encode_normal(sc, n);
    crate::stats::angle_deg(n, decode_normal(sc, s, r))
}

/// Mean and max round-trip angular error over `count` random hemisphere directions, and the worst direction.
pub fn encoding_error(sc: Scale, count: usize, seed: u64) -> crate::stats::ErrorStats {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut st = crate::stats::ErrorStats::default();
    for _ in 0..count {
        let n = crate::cart_encode::random_hemisphere(&mut rng);
        let e = round_trip_error_deg(sc, n);
        st.add(e, || format!("n = ({:.4}, {:.4}, {:.4})", n[0], n[1], n[2]));
    }
    st
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_out_is_s_255_in_both_scales_and_exact_only_in_the_dreamcast_one() {
        let up = [0.0, 1.0, 0.0];
        assert_eq!(encode_normal(Scale::Seed, up).0, 255);
        assert_eq!(encode_normal(Scale::Dc255, up).0, 255);
        // the seed's 255 is 255/256 of 90°: 0.35° short of straight out
        assert!((round_trip_error_deg(Scale::Seed, up) - 90.0 / 256.0).abs() < 1e-9);
        assert!(round_trip_error_deg(Scale::Dc255, up) < 1e-6);
    }

    #[test]
    fn r_is_zero_along_plus_u_and_wraps_at_a_full_turn() {
        let n = [0.6, 0.8, 0.0];
        assert_eq!(encode_normal(Scale::Seed, n).1, 0);
        // just below +u (negative z, rotation just under 360°) rounds to 256 ≡ 0 in the seed's scale
        let n = [0.6, 0.8, -1e-4];
        assert_eq!(encode_normal(Scale::Seed, n).1, 0);
        // and truncates to 254 in the Dreamcast scale (255 would be 360° itself)
        assert_eq!(encode_normal(Scale::Dc255, n).1, 254);
    }

    #[test]
    fn lights_below_the_horizon_are_moved_onto_it_keeping_their_rotation() {
        let below = encode_light(Scale::Seed, [0.0, -0.5, 1.0], 1.0);
        assert!(below.moved);
        assert_eq!(below.t, 0.0);
        assert_eq!((below.k1, below.k2, below.k3), (0, 0, 255));
        assert_eq!(below.q, 64); // +v is a quarter turn
        let on = encode_light(Scale::Seed, [0.0, 0.0, 1.0], 1.0);
        assert!(!on.moved);
        assert_eq!((on.k2, on.k3, on.q), (0, 255, 64));
        // the seed's minimal step off the horizon, [2, 254, 0] as a direction, is still above it
        let step = encode_light(Scale::Seed, [254.0, 2.0, 0.0], 1.0);
        assert!(!step.moved && step.k2 == 2);
    }

    #[test]
    fn an_8_bit_height_map_encodes_flat_as_straight_out_and_a_ramp_as_leaning_downhill() {
        let flat = encode_height_map(Scale::Dc255, &[77; 9], 3, 3, 4.0);
        assert!(flat.iter().all(|&(s, _)| s == 255));
        // heights rising along +v: the normal leans towards −v, a rotation of 270° (R = 192 in the seed's scale)
        let ramp: Vec<u8> = (0..16).map(|k| (k / 4 * 60) as u8).collect();
        let (s, r) = encode_height_map(Scale::Seed, &ramp, 4, 4, 255.0 / 60.0)[5];
        assert_eq!(r, 192);
        assert_eq!(s, 128); // a slope of 1: 45°
    }

    #[test]
    fn dreamcast_light_bytes_follow_the_toolchains_formulas() {
        // h = 0.5, T = 30°: K1 = 255 − 127 = 128, K2 = trunc(127.5·0.5) = 63, K3 = trunc(127.5·0.866) = 110
        let t = 30f64.to_radians();
        let l = encode_light(Scale::Dc255, [t.cos(), t.sin(), 0.0], 0.5);
        assert_eq!((l.k1, l.k2, l.k3, l.q), (128, 63, 110, 0));
    }
}
