//! `cart_pipeline`: US 6,819,319's second embodiment end to end, one pixel per clock:
//! bilinear(TexelX, TexelZ) → cart_decode → normalise ─┐
//! light_iter(l0, l1, l2; w1, w2) → normalise ─────────┴→ dot3 → gloss(C) → α = P >> 2 → blend(src, dst).
//! Every stage is the unit of the same name; this file only wires them, as the rtl top does.
//! `cart_pipeline_hemi_oct` is the same pipeline with `cart_decode_hemi_oct` in place of `cart_decode`: its texel
//! ports carry (U, V) where the seed's carry (TexelX, TexelZ).
//! `cart_pipeline_matte` and `cart_pipeline_hemi_oct_matte` are the two for a material with C = 0: no gloss unit
//! and no `conc` port (the ports of `matte`), P = X. Their model is the full one with C = 0.

use crate::unit::UnitModel;
use crate::{bilinear, blend, cart_decode, cart_decode_hemi_oct, dot3, gloss, light_iter, normalise};

crate::ports! {
    inputs: [
        t00_x: u 8, t00_z: u 8, t10_x: u 8, t10_z: u 8, t01_x: u 8, t01_z: u 8, t11_x: u 8, t11_z: u 8,
        ublend: u 8, vblend: u 8, l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8,
        l2_y: s 8, l2_z: s 8, w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
        dst_r: u 8, dst_g: u 8, dst_b: u 8,
    ],
    outputs: [
        p: u 10, out_r: u 8, out_g: u 8, out_b: u 8,
    ],
}

/// The matte pipelines' ports: the full pipeline's without `conc`.
pub mod matte {
    crate::ports! {
        inputs: [
            t00_x: u 8, t00_z: u 8, t10_x: u 8, t10_z: u 8, t01_x: u 8, t01_z: u 8, t11_x: u 8, t11_z: u 8,
            ublend: u 8, vblend: u 8, l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8,
            l2_y: s 8, l2_z: s 8, w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
            dst_r: u 8, dst_g: u 8, dst_b: u 8,
        ],
        outputs: [
            p: u 10, out_r: u 8, out_g: u 8, out_b: u 8,
        ],
    }
}

/// A matte input vector as the full pipeline's: C = 0 put in at its port.
pub fn with_zero_conc(i: &[i64]) -> Vec<i64> {
    let mut v = i.to_vec();
    v.insert(input::conc, 0);
    v
}

/// A full input vector without its C (for the matte pipelines).
pub fn without_conc(mut v: Vec<i64>) -> Vec<i64> {
    v.remove(input::conc);
    v
}

/// Every intermediate value, for waveforms and for reports.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Trace {
    pub texel: [i64; 2],
    pub bump: [i64; 3],
    pub normal: [i64; 3],
    pub light: [i64; 3],
    pub light_n: [i64; 3],
    pub x: i64,
    pub p: i64,
    pub alpha: i64,
    pub out: [i64; 3],
}

/// The texel decode a pipeline variant is built with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Decode {
    /// The seed's offset binary, `cart_decode` (for the seed's and the rounding encoder's texels).
    Seed,
    /// The rotated hemi-octahedral 8+8, `cart_decode_hemi_oct`.
    HemiOct,
}

/// The seed pipeline's trace (`cart_decode`).
pub fn exact_trace(i: &[i64]) -> Trace {
    exact_trace_with(Decode::Seed, i)
}

/// The four texels' inputs, in the bilinear unit's order (t00, t10, t01, t11), each (x or u, z or v).
pub const TEXELS: [[usize; 2]; 4] = [
    [input::t00_x, input::t00_z],
    [input::t10_x, input::t10_z],
    [input::t01_x, input::t01_z],
    [input::t11_x, input::t11_z],
];
/// The three vertex lights' inputs, (x, y, z) each.
pub const LIGHTS: [[usize; 3]; 3] = [
    [input::l0_x, input::l0_y, input::l0_z],
    [input::l1_x, input::l1_y, input::l1_z],
    [input::l2_x, input::l2_y, input::l2_z],
];
pub const SRC: [usize; 3] = [input::src_r, input::src_g, input::src_b];
pub const DST: [usize; 3] = [input::dst_r, input::dst_g, input::dst_b];

pub fn exact_trace_with(decode: Decode, i: &[i64]) -> Trace {
    let f = |c: usize| {
        let [t00, t10, t01, t11] = TEXELS.map(|t| i[t[c]]);
        bilinear::exact_channel(t00, t10, t01, t11, i[input::ublend], i[input::vblend], bilinear::F)
    };
    let texel = [f(0), f(1)];
    let bump = match decode {
        Decode::Seed => {
            let b = cart_decode::exact(texel[0] as u8, texel[1] as u8);
            [b.x, b.y, b.z]
        }
        Decode::HemiOct => cart_decode_hemi_oct::exact(texel[0] as u8, texel[1] as u8),
    };
    let normal = normalise::exact(bump);
    let light: [i64; 3] = std::array::from_fn(|c| {
        let [l0, l1, l2] = LIGHTS.map(|l| i[l[c]]);
        light_iter::exact_component(l0, l1, l2, i[input::w1], i[input::w2])
    });
    let light_n = normalise::exact(light);
    let x = dot3::exact(normal, light_n);
    let p = gloss::exact(i[input::conc], x);
    let alpha = crate::fixed::truncate(p, 2); // U10 → U8, the two fraction bits dropped (floor)
    let out = std::array::from_fn(|c| blend::exact_channel(alpha, i[input::mode], i[SRC[c]], i[DST[c]]));
    Trace { texel, bump, normal, light, light_n, x, p, alpha, out }
}

/// The same method in reals on the same codes: the texels filtered without rounding and read as a unit vector
/// (the decode's `ideal_real`), the vertex lights' codes interpolated in reals and made unit length, N·L clamped,
/// the gloss curve in reals; P in 10-bit units. Against `exact_trace`'s P it is what the datapath's arithmetic adds.
pub fn float_p(decode: Decode, i: &[i64]) -> f64 {
    let t: [f64; 2] = std::array::from_fn(|c| {
        let [t00, t10, t01, t11] = TEXELS.map(|t| i[t[c]] as f64);
        bilinear::ideal_channel(t00, t10, t01, t11, i[input::ublend] as f64 / 256.0, i[input::vblend] as f64 / 256.0)
    });
    let n = match decode {
        Decode::Seed => cart_decode::ideal_real(t[0], t[1]),
        Decode::HemiOct => cart_decode_hemi_oct::ideal_real(t[0], t[1]),
    };
    let l: [f64; 3] = std::array::from_fn(|c| {
        let [l0, l1, l2] = LIGHTS.map(|l| i[l[c]] as f64);
        light_iter::ideal_component(l0, l1, l2, i[input::w1] as f64, i[input::w2] as f64)
    });
    let len = (l[0] * l[0] + l[1] * l[1] + l[2] * l[2]).sqrt();
    if len == 0.0 {
        return 0.0; // no light: the normaliser's zero
    }
    let x = ((n[0] * l[0] + n[1] * l[1] + n[2] * l[2]) / len).max(0.0) * 1023.0;
    gloss::ideal_real(i[input::conc], x)
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    let t = exact_trace(i);
    vec![t.p, t.out[0], t.out[1], t.out[2]]
}

fn exact_ports_hemi_oct(i: &[i64]) -> Vec<i64> {
    let t = exact_trace_with(Decode::HemiOct, i);
    vec![t.p, t.out[0], t.out[1], t.out[2]]
}

/// Every port drawn over its range, except the barycentric weights, which come from `light_iter`'s generator so
/// that they stay inside the triangle (w1 + w2 ≤ 256).
fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    let mut v: Vec<i64> = INPUTS[..input::w1].iter().map(|p| crate::unit::draw(rng, p)).collect();
    let w = (light_iter::MODEL.random)(rng);
    v.extend_from_slice(&[w[light_iter::input::w1], w[light_iter::input::w2]]);
    v.extend(INPUTS[input::w2 + 1..].iter().map(|p| crate::unit::draw(rng, p)));
    v
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let base = |tx: i64, tz: i64, l: [i64; 3], w: [i64; 2], c: i64| -> Vec<i64> {
        let mut v = vec![0; INPUTS.len()];
        for t in TEXELS {
            (v[t[0]], v[t[1]]) = (tx, tz);
        }
        for k in LIGHTS {
            for c in 0..3 {
                v[k[c]] = l[c];
            }
        }
        (v[input::w1], v[input::w2], v[input::conc], v[input::mode]) = (w[0], w[1], c, 1);
        for c in 0..3 {
            (v[SRC[c]], v[DST[c]]) = ([200, 150, 100][c], [10, 20, 30][c]);
        }
        v
    };
    let mut v = vec![
        base(127, 127, [0, 127, 0], [0, 0], 0),     // pole lit from above: full
        base(127, 127, [127, 0, 0], [0, 0], 0),     // light on the horizon: 0
        base(127, 127, [0, -127, 0], [0, 0], 255),  // light below: 0
        base(255, 255, [127, 0, 127], [0, 0], 255), // texel 255 guarded, lit along its tilt
        base(127, 127, [1, 127, 0], [0, 0], 128),   // the seed's minimal step near the pole
    ];
    // opposite vertex lights interpolated through zero length
    let mut z = base(127, 127, [127, 0, 0], [128, 0], 0);
    z[input::l1_x] = -127;
    v.push(z);
    v
}

/// The seed pipeline's hard cases, and the hemi-octahedral square's corners (the horizon: BumpY = 0) lit along
/// their own direction, from above and from below.
pub fn hard_cases_hemi_oct() -> Vec<Vec<i64>> {
    let mut v = hard_cases();
    for (t, l) in [((0, 0), [-127, 0, 0]), ((255, 0), [0, 0, 127]), ((0, 0), [0, 127, 0]), ((255, 255), [0, -127, 0])] {
        let mut x = v[0].clone();
        for k in TEXELS {
            (x[k[0]], x[k[1]]) = t;
        }
        for k in LIGHTS {
            for c in 0..3 {
                x[k[c]] = l[c];
            }
        }
        v.push(x);
    }
    v
}

fn exact_ports_matte(i: &[i64]) -> Vec<i64> {
    exact_ports(&with_zero_conc(i))
}

fn exact_ports_hemi_oct_matte(i: &[i64]) -> Vec<i64> {
    exact_ports_hemi_oct(&with_zero_conc(i))
}

fn random_matte(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    without_conc(random(rng))
}

/// The full pipeline's hard cases without their C.
fn hard_cases_matte() -> Vec<Vec<i64>> {
    hard_cases().into_iter().map(without_conc).collect()
}

fn hard_cases_hemi_oct_matte() -> Vec<Vec<i64>> {
    hard_cases_hemi_oct().into_iter().map(without_conc).collect()
}

pub static MODEL: UnitModel = UnitModel::new("cart_pipeline", (INPUTS, OUTPUTS), exact_ports, random, hard_cases);

pub static MODEL_HEMI_OCT: UnitModel =
    UnitModel::new("cart_pipeline_hemi_oct", (INPUTS, OUTPUTS), exact_ports_hemi_oct, random, hard_cases_hemi_oct);

pub static MODEL_MATTE: UnitModel = UnitModel::new(
    "cart_pipeline_matte",
    (matte::INPUTS, matte::OUTPUTS),
    exact_ports_matte,
    random_matte,
    hard_cases_matte,
);

pub static MODEL_HEMI_OCT_MATTE: UnitModel = UnitModel::new(
    "cart_pipeline_hemi_oct_matte",
    (matte::INPUTS, matte::OUTPUTS),
    exact_ports_hemi_oct_matte,
    random_matte,
    hard_cases_hemi_oct_matte,
);

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn matte_ports_are_the_full_ones_without_c() {
        let full: Vec<_> = INPUTS.iter().filter(|p| p.name != "conc").collect();
        assert_eq!(full.len(), matte::INPUTS.len());
        for (f, m) in full.iter().zip(matte::INPUTS) {
            assert_eq!((f.name, f.bits, f.signed), (m.name, m.bits, m.signed));
        }
        assert_eq!(OUTPUTS.len(), matte::OUTPUTS.len());
    }

    /// At C = 0 the gloss unit gives P = X, so the pipeline without it must give the same P and colour; and a
    /// glossy C must differ somewhere, or the comparison could not fail.
    #[test]
    fn matte_is_the_full_pipeline_at_c_zero() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(41);
        let mut differs = 0;
        for _ in 0..20_000 {
            let mut f = random(&mut rng);
            let m = without_conc(f.clone());
            for (full, matte) in [(&MODEL, &MODEL_MATTE), (&MODEL_HEMI_OCT, &MODEL_HEMI_OCT_MATTE)] {
                let c = f[input::conc];
                f[input::conc] = 0;
                assert_eq!((matte.exact)(&m), (full.exact)(&f), "{} at {m:?}", matte.name);
                f[input::conc] = c;
                differs += usize::from((matte.exact)(&m) != (full.exact)(&f));
            }
            let t = exact_trace(&with_zero_conc(&m));
            assert_eq!(t.p, t.x);
        }
        assert!(differs > 1_000, "C made a difference on only {differs} pixels");
    }
}
