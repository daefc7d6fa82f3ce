//! `polar_pipeline`: US 6,819,319's first embodiment end to end, one pixel per clock (FIG. 1 and FIG. 3):
//! texel (S, R) + surface (k1, k2, k3, Q, p) → polar_shade → power → α → blend(src, dst).
//! Every stage is the unit of the same name; this file only wires them, as the rtl top does.

use crate::polar_encode::Scale;
use crate::unit::UnitModel;
use crate::{blend, polar_shade, power};

crate::ports! {
    inputs: [
        s: u 8, r: u 8, q: u 8, k1: u 8, k2: u 8, k3: u 8, pw: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
        dst_r: u 8, dst_g: u 8, dst_b: u 8,
    ],
    outputs: [
        alpha: u 8, out_r: u 8, out_g: u 8, out_b: u 8,
    ],
}

/// The shade before the power unit, the alpha after it, and the blended colour.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Trace {
    pub sum: i64,
    pub shade: i64,
    pub alpha: i64,
    pub out: [i64; 3],
}

pub fn exact_trace(sc: Scale, i: &[i64]) -> Trace {
    exact_trace_sized(sc, crate::sincos::TABLE_BITS, i)
}

/// The pipeline with a 2^tb-entry elevation table in its shading unit (`polar_shade::exact_trace_sized`).
pub fn exact_trace_sized(sc: Scale, tb: u32, i: &[i64]) -> Trace {
    let t = polar_shade::exact_trace_sized(
        sc,
        tb,
        i[input::s],
        i[input::r],
        i[input::q],
        i[input::k1],
        i[input::k2],
        i[input::k3],
    );
    let (sum, shade) = (t.sum, t.shade);
    let alpha = power::exact(shade, i[input::pw]);
    let src = [input::src_r, input::src_g, input::src_b];
    let dst = [input::dst_r, input::dst_g, input::dst_b];
    let out = std::array::from_fn(|c| blend::exact_channel(alpha, i[input::mode], i[src[c]], i[dst[c]]));
    Trace { sum, shade, alpha, out }
}

fn ports(sc: Scale, i: &[i64]) -> Vec<i64> {
    let t = exact_trace(sc, i);
    vec![t.alpha, t.out[0], t.out[1], t.out[2]]
}

fn exact_ports(i: &[i64]) -> Vec<i64> {
    ports(Scale::Seed, i)
}

fn exact_ports_dc(i: &[i64]) -> Vec<i64> {
    ports(Scale::Dc255, i)
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    let colours = [1, 200, 150, 100, 10, 20, 30];
    let mut v = vec![];
    for shade in polar_shade::hard_cases() {
        for pw in [4, 255] {
            let mut x = shade.clone();
            x.push(pw);
            x.extend_from_slice(&colours);
            v.push(x);
        }
    }
    // modulate mode with p = 0 (α = 255 whatever the shade)
    v.push(vec![0, 128, 0, 0, 0, 255, 0, 0, 200, 150, 100, 10, 20, 30]);
    v
}

pub static MODEL: UnitModel =
    UnitModel::new("polar_pipeline", (INPUTS, OUTPUTS), exact_ports, random_inputs, hard_cases);

/// The same pipeline with the Dreamcast toolchains' angle scale in its tables: maps made by those tools shade as
/// their authors saw them.
pub static MODEL_DC: UnitModel =
    UnitModel::new("polar_pipeline_dc", (INPUTS, OUTPUTS), exact_ports_dc, random_inputs, hard_cases);

/// The pipeline's model for a scale, indexed by `Scale as usize`.
pub static MODEL_FOR: [&UnitModel; 2] = [&MODEL, &MODEL_DC];
