//! `cart_pipeline`: seed 000's second embodiment end to end, one pixel per clock:
//! bilinear(TexelX, TexelZ) → cart_decode → normalise ─┐
//! light_iter(l0, l1, l2; w1, w2) → normalise ─────────┴→ dot3 → gloss(C) → α = P >> 2 → blend(src, dst).
//! Every stage is the unit of the same name; this file only wires them, as the rtl top does.
//! `cart_pipeline_hemi_oct` is the same pipeline with `cart_decode_hemi_oct` in place of `cart_decode`: its texel
//! ports carry (U, V) where the seed's carry (TexelX, TexelZ).

use crate::unit::{Port, UnitModel};
use crate::{bilinear, blend, cart_decode, cart_decode_hemi_oct, dot3, gloss, light_iter, normalise};

pub const INPUTS: &[Port] = &[
    Port::u("t00_x", 8), Port::u("t00_z", 8), Port::u("t10_x", 8), Port::u("t10_z", 8),
    Port::u("t01_x", 8), Port::u("t01_z", 8), Port::u("t11_x", 8), Port::u("t11_z", 8),
    Port::u("ublend", 8), Port::u("vblend", 8),
    Port::s("l0_x", 8), Port::s("l0_y", 8), Port::s("l0_z", 8),
    Port::s("l1_x", 8), Port::s("l1_y", 8), Port::s("l1_z", 8),
    Port::s("l2_x", 8), Port::s("l2_y", 8), Port::s("l2_z", 8),
    Port::u("w1", 9), Port::u("w2", 9),
    Port::u("conc", 8), Port::u("mode", 1),
    Port::u("src_r", 8), Port::u("src_g", 8), Port::u("src_b", 8),
    Port::u("dst_r", 8), Port::u("dst_g", 8), Port::u("dst_b", 8),
];
pub const OUTPUTS: &[Port] = &[Port::u("p", 10), Port::u("out_r", 8), Port::u("out_g", 8), Port::u("out_b", 8)];

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

impl Decode {
    /// The decode that reads an encoder's texels.
    pub fn for_encoder(e: crate::cart_encode::Encoder) -> Decode {
        match e {
            crate::cart_encode::Encoder::HemiOct => Decode::HemiOct,
            _ => Decode::Seed,
        }
    }
    pub fn model(self) -> &'static UnitModel {
        match self {
            Decode::Seed => &MODEL,
            Decode::HemiOct => &MODEL_HEMI_OCT,
        }
    }
}

/// The seed pipeline's trace (`cart_decode`).
pub fn exact_trace(i: &[i64]) -> Trace {
    exact_trace_with(Decode::Seed, i)
}

pub fn exact_trace_with(decode: Decode, i: &[i64]) -> Trace {
    let f = |c: usize| bilinear::exact_channel(i[c], i[2 + c], i[4 + c], i[6 + c], i[8], i[9], bilinear::F);
    let texel = [f(0), f(1)];
    let bump = match decode {
        Decode::Seed => {
            let b = cart_decode::exact(texel[0] as u8, texel[1] as u8);
            [b.x, b.y, b.z]
        }
        Decode::HemiOct => cart_decode_hemi_oct::exact(texel[0] as u8, texel[1] as u8),
    };
    let normal = normalise::exact(bump);
    let light: [i64; 3] =
        std::array::from_fn(|c| light_iter::exact_component(i[10 + c], i[13 + c], i[16 + c], i[19], i[20]));
    let light_n = normalise::exact(light);
    let x = dot3::exact(normal, light_n);
    let p = gloss::exact(i[21], x);
    let alpha = p >> 2; // U10 → U8, truncate
    let out = std::array::from_fn(|c| blend::exact_channel(alpha, i[22], i[23 + c], i[26 + c]));
    Trace { texel, bump, normal, light, light_n, x, p, alpha, out }
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    let t = exact_trace(i);
    vec![t.p, t.out[0], t.out[1], t.out[2]]
}

fn exact_ports_hemi_oct(i: &[i64]) -> Vec<i64> {
    let t = exact_trace_with(Decode::HemiOct, i);
    vec![t.p, t.out[0], t.out[1], t.out[2]]
}

fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    let mut v: Vec<i64> = INPUTS[..19].iter().map(|p| crate::unit::draw(rng, p)).collect();
    let w = (light_iter::MODEL.random)(rng);
    v.extend_from_slice(&w[9..11]);
    v.extend(INPUTS[21..].iter().map(|p| crate::unit::draw(rng, p)));
    v
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let base = |tx: i64, tz: i64, l: [i64; 3], w: [i64; 2], c: i64| -> Vec<i64> {
        let mut v = vec![tx, tz, tx, tz, tx, tz, tx, tz, 0, 0];
        for _ in 0..3 {
            v.extend_from_slice(&l);
        }
        v.extend_from_slice(&w);
        v.extend_from_slice(&[c, 1, 200, 150, 100, 10, 20, 30]);
        v
    };
    let mut v = vec![
        base(127, 127, [0, 127, 0], [0, 0], 0),    // pole lit from above: full
        base(127, 127, [127, 0, 0], [0, 0], 0),    // light on the horizon: 0
        base(127, 127, [0, -127, 0], [0, 0], 255), // light below: 0
        base(255, 255, [127, 0, 127], [0, 0], 255), // texel 255 guarded, lit along its tilt
        base(127, 127, [1, 127, 0], [0, 0], 128),  // the seed's minimal step near the pole
    ];
    // opposite vertex lights interpolated through zero length
    let mut z = base(127, 127, [127, 0, 0], [128, 0], 0);
    z[13] = -127;
    v.push(z);
    v
}

/// The seed pipeline's hard cases, and the hemi-octahedral square's corners (the horizon: BumpY = 0) lit along
/// their own direction, from above and from below.
pub fn hard_cases_hemi_oct() -> Vec<Vec<i64>> {
    let mut v = hard_cases();
    for (t, l) in [((0, 0), [-127, 0, 0]), ((255, 0), [0, 0, 127]), ((0, 0), [0, 127, 0]), ((255, 255), [0, -127, 0])] {
        let mut x = v[0].clone();
        for k in 0..4 {
            x[2 * k] = t.0;
            x[2 * k + 1] = t.1;
        }
        for k in 0..3 {
            x[10 + 3 * k..13 + 3 * k].copy_from_slice(&l);
        }
        v.push(x);
    }
    v
}

pub static MODEL: UnitModel = UnitModel {
    name: "cart_pipeline",
    inputs: INPUTS,
    outputs: OUTPUTS,
    exact: exact_ports,
    random,
    exhaustive: None,
    hard_cases,
};

pub static MODEL_HEMI_OCT: UnitModel = UnitModel {
    name: "cart_pipeline_hemi_oct",
    inputs: INPUTS,
    outputs: OUTPUTS,
    exact: exact_ports_hemi_oct,
    random,
    exhaustive: None,
    hard_cases: hard_cases_hemi_oct,
};
