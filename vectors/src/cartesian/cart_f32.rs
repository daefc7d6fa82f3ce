//! `cart_f32`: the Cartesian shading of `cart_pipeline` written as a graphics programmer writes it in software, a
//! peer to measure the bit-exact model against, not a model of the rtl: f32, eight pixels a step in SIMD lanes
//! (`wide::f32x8`), the same method in reals as `cart_pipeline::float_p` on the same input vectors. Per pixel: the
//! two texel channels bilinearly filtered, decoded (US 6,819,319's L1 scaling, the texel clamped to 254 and a
//! filtered texel past the diamond projected onto it, as `cart_decode::ideal_real`) and normalised; the vertex
//! lights interpolated and normalised; N·L clamped at 0; the gloss curve of C in reals; the blend with α = P.
//! Its outputs are the output vector the pipeline reads (P in 10-bit units and the colour, each rounded to nearest),
//! so its error against a scene's ideal is measured exactly as the model's is.

use crate::cart_pipeline::{input, DST, INPUTS, LIGHTS, SRC, TEXELS};
use wide::f32x8;

/// Pixels a step: the lanes of `f32x8`.
pub const LANES: usize = 8;

/// Eight pixels' inputs, `cart_pipeline`'s ports in order, one lane a pixel.
pub type Lanes = [f32x8; INPUTS.len()];

/// A frame's input vectors as lanes, eight pixels a step (the last step's spare lanes zero: a dark, unlit pixel).
pub fn lanes(inputs: &[Vec<i64>]) -> Vec<Lanes> {
    inputs
        .chunks(LANES)
        .map(|px| {
            let mut a = [[0.0f32; LANES]; INPUTS.len()];
            for (k, v) in px.iter().enumerate() {
                for (port, &x) in v.iter().enumerate() {
                    a[port][k] = x as f32;
                }
            }
            a.map(f32x8::new)
        })
        .collect()
}

/// Eight pixels shaded: (P in 10-bit units, r, g, b), unrounded.
pub fn shade8(i: &Lanes) -> [f32x8; 4] {
    let (zero, one) = (f32x8::splat(0.0), f32x8::splat(1.0));
    let (u, v) = (i[input::ublend] * (1.0 / 256.0), i[input::vblend] * (1.0 / 256.0));
    // the texel channel c filtered: lerp of lerps, then read as the L1-scaled direction in [−1, 1]
    let axis = |c: usize| {
        let [t00, t10, t01, t11] = TEXELS.map(|t| i[t[c]]);
        let top = t00 + (t10 - t00) * u;
        let t = top + (t01 + (t11 - t01) * u - top) * v;
        (t.min(f32x8::splat(254.0)) - 127.0) * (1.0 / 127.0)
    };
    let (x, z) = (axis(0), axis(1));
    // past the diamond |x| + |z| = 1: both moved toward it by half the excess
    let d = ((x.abs() + z.abs() - one) * 0.5).max(zero);
    let (ax, az) = (x.abs() - d, z.abs() - d);
    let (nx, nz) = (x.simd_lt(zero).select(-ax, ax), z.simd_lt(zero).select(-az, az));
    let ny = one - ax - az;
    let n_inv = one / (nx * nx + ny * ny + nz * nz).sqrt();
    // the light: the vertex lights interpolated by the barycentric weights
    let (w1, w2) = (i[input::w1] * (1.0 / 256.0), i[input::w2] * (1.0 / 256.0));
    let l: [f32x8; 3] = std::array::from_fn(|c| {
        let [l0, l1, l2] = LIGHTS.map(|l| i[l[c]]);
        l0 + (l1 - l0) * w1 + (l2 - l0) * w2
    });
    let len = (l[0] * l[0] + l[1] * l[1] + l[2] * l[2]).sqrt();
    // no light (zero length) gives X = 0, as the normaliser's zero does
    let l_inv = len.simd_gt(zero).select(one / len, zero);
    let x_dot = ((nx * l[0] + ny * l[1] + nz * l[2]) * n_inv * l_inv).max(zero).min(one);
    // the gloss curve: L = max(0, 1 − k(1 − X)), k = (C + 8)/8; P = L + (C/256)(L² − L)
    let c = i[input::conc];
    let k = (c + 8.0) * 0.125;
    let big_l = (one - k * (one - x_dot)).max(zero);
    let p = big_l + c * (1.0 / 256.0) * (big_l * big_l - big_l);
    // the blend, α = P: modulate (mode 0) or lerp toward the destination (mode 1)
    let mode = i[input::mode];
    let out = |ch: usize| i[SRC[ch]] * p + i[DST[ch]] * (one - p) * mode;
    [p * 1023.0, out(0), out(1), out(2)]
}

/// Values a pixel in a frame's outputs: P, r, g, b.
pub const OUTPUTS: usize = 4;

/// A frame of `cart_pipeline` input vectors through the peer: per pixel (P, r, g, b), each rounded to nearest and
/// held to its port's range (10 and 8 bits), the output vector the pipeline reads, one after another (flat).
pub fn frame(inputs: &[Vec<i64>]) -> Vec<i64> {
    frame_of_lanes(&lanes(inputs), inputs.len())
}

/// `frame` on a frame of `n` pixels already in lanes (as a renderer keeps them: structure of arrays, f32).
pub fn frame_of_lanes(lanes: &[Lanes], n: usize) -> Vec<i64> {
    assert_eq!(lanes.len(), n.div_ceil(LANES), "{n} pixels in {} steps of {LANES}", lanes.len());
    let mut out = Vec::with_capacity(n * OUTPUTS);
    for (step, l) in lanes.iter().enumerate() {
        let [p, r, g, b] = shade8(l).map(|s| s.round().to_array());
        let hold = |x: f32, hi: f32| x.clamp(0.0, hi) as i64;
        for k in 0..(n - step * LANES).min(LANES) {
            out.extend_from_slice(&[hold(p[k], 1023.0), hold(r[k], 255.0), hold(g[k], 255.0), hold(b[k], 255.0)]);
        }
    }
    out
}

/// The same method in f64, a pixel at a time (`cart_pipeline::float_p`, then the blend with α = P): the scalar
/// float baseline beside the peer, rounded, held and laid out as `frame`'s.
pub fn frame_f64(inputs: &[Vec<i64>]) -> Vec<i64> {
    let mut out = Vec::with_capacity(inputs.len() * OUTPUTS);
    for i in inputs {
        let p = crate::cart_pipeline::float_p(crate::cart_pipeline::Decode::Seed, i);
        let a = p / 1023.0;
        let c = |ch: usize| i[SRC[ch]] as f64 * a + i[DST[ch]] as f64 * (1.0 - a) * i[input::mode] as f64;
        let hold = |x: f64, hi: f64| x.round().clamp(0.0, hi) as i64;
        out.extend_from_slice(&[hold(p, 1023.0), hold(c(0), 255.0), hold(c(1), 255.0), hold(c(2), 255.0)]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cart_pipeline::{self, Decode};
    use rand::SeedableRng;

    /// The peer is the f64 method in f32: on random vectors (the hard cases among them) its P and its colour
    /// differ from `frame_f64`'s by at most one step of their rounding, and on most pixels not at all.
    #[test]
    fn the_peer_is_the_method_in_reals_to_f32_precision() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        let mut v = cart_pipeline::hard_cases();
        v.extend((0..20_000).map(|_| (cart_pipeline::MODEL.random)(&mut rng)));
        let (got, want) = (frame(&v), frame_f64(&v));
        assert_eq!((got.len(), want.len()), (v.len() * OUTPUTS, v.len() * OUTPUTS));
        let (got, want) = (got.chunks_exact(OUTPUTS), want.chunks_exact(OUTPUTS));
        let mut differ = 0;
        for ((i, g), w) in v.iter().zip(got.clone()).zip(want.clone()) {
            assert!(g.iter().zip(w).all(|(a, b)| (a - b).abs() <= 1), "{i:?}: {g:?} against {w:?}");
            differ += usize::from(g != w);
        }
        assert!(differ < v.len() / 50, "{differ} of {} pixels differ by a step", v.len());
        // and the f64 method is float_p's
        assert!(v.iter().zip(want).all(|(i, w)| (w[0] as f64 - cart_pipeline::float_p(Decode::Seed, i)).abs() <= 0.5));
    }

    /// A frame whose length is not a multiple of the lanes: every pixel out, none from the spare lanes.
    #[test]
    fn a_frame_of_any_length_gives_one_output_a_pixel() {
        let v = cart_pipeline::hard_cases();
        for n in [0, 1, 7, 8, 9] {
            let vs: Vec<Vec<i64>> = v.iter().cycle().take(n).cloned().collect();
            assert_eq!(frame(&vs).len(), n * OUTPUTS);
        }
        // pixel 0 (the pole lit from above, mode 1, src 200/150/100): full shade, the source colour
        assert_eq!(frame(&v[..1]), [1023, 200, 150, 100]);
    }
}
