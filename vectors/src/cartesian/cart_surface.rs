//! `cart_surface`: the Cartesian pipeline for a scene with one light per surface. The light comes in already a
//! unit vector (Sq1.10, the normaliser's own output format), so there is no light interpolation and no light
//! normaliser per pixel:
//! bilinear(TexelX, TexelZ) → cart_decode → normalise → dot3(·, L) → gloss(C) → α = P >> 2 → blend(src, dst).
//! `cart_surface_matte` leaves the gloss unit out (C = 0, where it passes X through) and has no C port; the
//! `_hemi_oct` variants decode hemi-octahedral texels. The surface's light is made once, off the pipeline, by the
//! same units the full pipeline runs per pixel (`light`): with three equal vertex lights, `cart_pipeline` and
//! `cart_surface` compute the same pixels, and that is tested.

use crate::cart_pipeline::Decode;
use crate::unit::{Port, UnitModel};
use crate::{bilinear, blend, cart_decode, cart_decode_hemi_oct, dot3, gloss, light_iter, normalise};

/// With the bilinear filter and a gloss unit (C is an input).
pub mod glossy {
    crate::ports! {
        inputs: [
            t00_x: u 8, t00_z: u 8, t10_x: u 8, t10_z: u 8, t01_x: u 8, t01_z: u 8, t11_x: u 8, t11_z: u 8,
            ublend: u 8, vblend: u 8, l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
            src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
        ],
        outputs: [
            p: u 10, out_r: u 8, out_g: u 8, out_b: u 8,
        ],
    }
}

/// With the bilinear filter, without a gloss unit (C = 0).
pub mod matte {
    crate::ports! {
        inputs: [
            t00_x: u 8, t00_z: u 8, t10_x: u 8, t10_z: u 8, t01_x: u 8, t01_z: u 8, t11_x: u 8, t11_z: u 8,
            ublend: u 8, vblend: u 8, l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
            src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
        ],
        outputs: [
            p: u 10, out_r: u 8, out_g: u 8, out_b: u 8,
        ],
    }
}

/// The nearest texel (x or u, z or v), with a gloss unit.
pub mod nearest_glossy {
    crate::ports! {
        inputs: [
            t_x: u 8, t_z: u 8, l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
            src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
        ],
        outputs: [
            p: u 10, out_r: u 8, out_g: u 8, out_b: u 8,
        ],
    }
}

/// The nearest texel, without a gloss unit.
pub mod nearest_matte {
    crate::ports! {
        inputs: [
            t_x: u 8, t_z: u 8, l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
            src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
        ],
        outputs: [
            p: u 10, out_r: u 8, out_g: u 8, out_b: u 8,
        ],
    }
}

/// The outputs are the same ports in all.
pub use glossy::{output, OUTPUTS};

/// How the texel comes in.
#[derive(Clone, Copy, Debug)]
pub enum Texels {
    /// four texels t00, t10, t01, t11, each (x or u, z or v), and the blend factors: the bilinear filter
    Bilinear { corners: [[usize; 2]; 4], ublend: usize, vblend: usize },
    /// the nearest texel, (x or u, z or v)
    Nearest([usize; 2]),
}

/// Where a variant's inputs sit in its vector.
#[derive(Clone, Copy, Debug)]
pub struct Layout {
    pub texels: Texels,
    pub light: [usize; 3],
    pub conc: Option<usize>,
    pub mode: usize,
    pub src: [usize; 3],
    pub dst: [usize; 3],
    pub inputs: &'static [Port],
}

macro_rules! layout {
    ($m:ident, $texels:expr, $conc:expr) => {{
        use $m::input as i;
        Layout {
            texels: $texels,
            light: [i::l_x, i::l_y, i::l_z],
            conc: $conc,
            mode: i::mode,
            src: [i::src_r, i::src_g, i::src_b],
            dst: [i::dst_r, i::dst_g, i::dst_b],
            inputs: $m::INPUTS,
        }
    }};
}

macro_rules! bilinear_texels {
    ($m:ident) => {{
        use $m::input as i;
        Texels::Bilinear {
            corners: [[i::t00_x, i::t00_z], [i::t10_x, i::t10_z], [i::t01_x, i::t01_z], [i::t11_x, i::t11_z]],
            ublend: i::ublend,
            vblend: i::vblend,
        }
    }};
}

pub const GLOSSY: Layout = layout!(glossy, bilinear_texels!(glossy), Some(glossy::input::conc));
pub const MATTE: Layout = layout!(matte, bilinear_texels!(matte), None);
pub const NEAREST_GLOSSY: Layout = layout!(
    nearest_glossy,
    Texels::Nearest([nearest_glossy::input::t_x, nearest_glossy::input::t_z]),
    Some(nearest_glossy::input::conc)
);
pub const NEAREST_MATTE: Layout =
    layout!(nearest_matte, Texels::Nearest([nearest_matte::input::t_x, nearest_matte::input::t_z]), None);

/// A variant: its texel decode, its filter, and whether it has the gloss unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Variant {
    pub decode: Decode,
    pub nearest: bool,
    pub gloss: bool,
}

impl Variant {
    pub const ALL: [Variant; 8] = {
        let (s, h) = (Decode::Seed, Decode::HemiOct);
        [
            Variant { decode: s, nearest: false, gloss: true },
            Variant { decode: s, nearest: false, gloss: false },
            Variant { decode: h, nearest: false, gloss: true },
            Variant { decode: h, nearest: false, gloss: false },
            Variant { decode: s, nearest: true, gloss: true },
            Variant { decode: s, nearest: true, gloss: false },
            Variant { decode: h, nearest: true, gloss: true },
            Variant { decode: h, nearest: true, gloss: false },
        ]
    };

    pub const fn layout(self) -> Layout {
        match (self.nearest, self.gloss) {
            (false, true) => GLOSSY,
            (false, false) => MATTE,
            (true, true) => NEAREST_GLOSSY,
            (true, false) => NEAREST_MATTE,
        }
    }

    pub fn model(self) -> &'static UnitModel {
        let k =
            (self.nearest as usize) * 4 + matches!(self.decode, Decode::HemiOct) as usize * 2 + !self.gloss as usize;
        MODELS[k]
    }
}

/// The surface's light as the pipeline takes it: an S8 vertex light (`light_iter::quantise_vertex`'s) through the
/// light interpolator at one vertex and the normaliser, as `cart_pipeline` does per pixel; Sq1.10.
pub fn light(q: [i64; 3]) -> [i64; 3] {
    normalise::exact(q.map(|c| light_iter::exact_component(c, c, c, 0, 0)))
}

/// Every intermediate value, for waveforms and for reports.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Trace {
    pub texel: [i64; 2],
    pub bump: [i64; 3],
    pub normal: [i64; 3],
    pub x: i64,
    pub p: i64,
    pub alpha: i64,
    pub out: [i64; 3],
}

/// The width knobs of the units inside: the bump normaliser's seed table (2^table_bits entries) and Newton steps,
/// the bilinear units' blend-factor bits (the top `blend_bits` of each 8-bit factor, floor) and the bits dropped
/// between their stages. The rtl blocks are built at `UNIT_KNOBS`; the others are the units' own swept settings
/// (`Normalise<T, N>`, `Bilinear<F, D>`), here in the pipeline's model.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Knobs {
    pub table_bits: u32,
    pub newton: u32,
    pub blend_bits: u32,
    pub drop: u32,
}

pub const UNIT_KNOBS: Knobs = Knobs { table_bits: 10, newton: 0, blend_bits: bilinear::F, drop: 0 };

pub fn exact_trace(v: Variant, i: &[i64]) -> Trace {
    exact_trace_knobs(v, UNIT_KNOBS, i)
}

pub fn exact_trace_knobs(v: Variant, k: Knobs, i: &[i64]) -> Trace {
    let at = v.layout();
    let texel = match at.texels {
        Texels::Bilinear { corners, ublend, vblend } => std::array::from_fn(|c| {
            let [t00, t10, t01, t11] = corners.map(|t| i[t[c]]);
            let (u, w) = (i[ublend] >> (8 - k.blend_bits), i[vblend] >> (8 - k.blend_bits)); // U8 → U(blend_bits), floor
            bilinear::exact_channel_with(t00, t10, t01, t11, u, w, k.blend_bits, k.drop)
        }),
        Texels::Nearest(t) => t.map(|k| i[k]),
    };
    let bump = match v.decode {
        Decode::Seed => {
            let b = cart_decode::exact(texel[0] as u8, texel[1] as u8);
            [b.x, b.y, b.z]
        }
        Decode::HemiOct => cart_decode_hemi_oct::exact(texel[0] as u8, texel[1] as u8),
    };
    let normal = normalise::exact_with(bump, k.table_bits, k.newton);
    let x = dot3::exact(normal, at.light.map(|k| i[k]));
    let p = match at.conc {
        Some(c) => gloss::exact(i[c], x),
        None => x, // no gloss unit: the gloss unit's own C = 0, P = X
    };
    let alpha = crate::fixed::truncate(p, 2); // U10 → U8, the two fraction bits dropped (floor)
    let out = std::array::from_fn(|c| blend::exact_channel(alpha, i[at.mode], i[at.src[c]], i[at.dst[c]]));
    Trace { texel, bump, normal, x, p, alpha, out }
}

/// The same method in reals on the same codes: the texels filtered without rounding, their meaning as a unit
/// vector (the decode's `ideal_real`), N·L against the light's Sq1.10 code read as a real, clamped, and the gloss
/// curve in reals; P in 10-bit units. Against `exact_trace`'s P it is the error the datapath's arithmetic adds.
pub fn float_p(v: Variant, i: &[i64]) -> f64 {
    let at = v.layout();
    let texel: [f64; 2] = match at.texels {
        Texels::Bilinear { corners, ublend, vblend } => std::array::from_fn(|c| {
            let [t00, t10, t01, t11] = corners.map(|t| i[t[c]] as f64);
            bilinear::ideal_channel(t00, t10, t01, t11, i[ublend] as f64 / 256.0, i[vblend] as f64 / 256.0)
        }),
        Texels::Nearest(t) => t.map(|k| i[k] as f64),
    };
    let n = match v.decode {
        Decode::Seed => cart_decode::ideal_real(texel[0], texel[1]),
        Decode::HemiOct => cart_decode_hemi_oct::ideal_real(texel[0], texel[1]),
    };
    let l = at.light.map(|k| i[k] as f64 / 1024.0);
    let x = (n[0] * l[0] + n[1] * l[1] + n[2] * l[2]).max(0.0) * 1023.0;
    match at.conc {
        Some(c) => gloss::ideal_real(i[c], x),
        None => x,
    }
}

/// P against `float_p`, 10-bit LSB, over random vectors.
fn accuracy_with(v: Variant, samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut s = crate::stats::ErrorStats::default();
    for _ in 0..samples {
        let i = (v.model().random)(&mut rng);
        let e = (exact_trace(v, &i).p as f64 - float_p(v, &i)).abs();
        s.add(e, || format!("{i:?}"));
    }
    vec![crate::unit::Accuracy::new("P, 10-bit LSB vs the same method in reals on the same codes", s)]
}

fn ports(v: Variant, i: &[i64]) -> Vec<i64> {
    let t = exact_trace(v, i);
    vec![t.p, t.out[0], t.out[1], t.out[2]]
}

/// Every port drawn over its range, except the light: a random S8 vertex light made into the surface's light as
/// the renderer makes it (zero included: the normaliser's zero, no light).
fn random_with(at: Layout, rng: &mut dyn rand::RngCore) -> Vec<i64> {
    let mut v: Vec<i64> = at.inputs.iter().map(|p| crate::unit::draw(rng, p)).collect();
    let q: [i64; 3] = std::array::from_fn(|_| crate::unit::draw(rng, &Port::s("l", 8)));
    for (k, c) in at.light.iter().zip(light(q)) {
        v[*k] = c;
    }
    v
}

/// The texel ports of a surface variant's vector `x` from a `cart_pipeline` vector `f`: the four texels and the
/// blend factors, or the texel nearest the sample (the blend factors, 1/256 texel, rounded to the nearer corner).
pub fn set_texels(at: Layout, x: &mut [i64], f: &[i64]) {
    use crate::cart_pipeline::{input as full, TEXELS};
    match at.texels {
        Texels::Bilinear { corners, ublend, vblend } => {
            for (t, ft) in corners.iter().zip(TEXELS) {
                (x[t[0]], x[t[1]]) = (f[ft[0]], f[ft[1]]);
            }
            (x[ublend], x[vblend]) = (f[full::ublend], f[full::vblend]);
        }
        Texels::Nearest(t) => {
            let k = (f[full::ublend] >= 128) as usize + 2 * (f[full::vblend] >= 128) as usize;
            (x[t[0]], x[t[1]]) = (f[TEXELS[k][0]], f[TEXELS[k][1]]);
        }
    }
}

/// The hard cases of `cart_pipeline` with its three vertex lights made into one surface light (the case of
/// opposite vertex lights interpolated to zero becomes the zero light), then the light's own ends: each axis at
/// ±1.0 exactly (±1024) against the pole and the texel-255 guard, and every component at its most negative code.
fn hard_cases_with(v: Variant) -> Vec<Vec<i64>> {
    use crate::cart_pipeline::{input as full, DST, LIGHTS, SRC, TEXELS};
    let at = v.layout();
    let full_cases = match v.decode {
        Decode::Seed => crate::cart_pipeline::hard_cases(),
        Decode::HemiOct => crate::cart_pipeline::hard_cases_hemi_oct(),
    };
    let mut out = vec![];
    for f in &full_cases {
        let mut x = vec![0; at.inputs.len()];
        set_texels(at, &mut x, f);
        x[at.mode] = f[full::mode];
        if let Some(c) = at.conc {
            x[c] = f[full::conc];
        }
        for c in 0..3 {
            (x[at.src[c]], x[at.dst[c]]) = (f[SRC[c]], f[DST[c]]);
        }
        // the light the full pipeline sees at this pixel, made once
        let l: [i64; 3] = std::array::from_fn(|c| {
            let [l0, l1, l2] = LIGHTS.map(|k| f[k[c]]);
            light_iter::exact_component(l0, l1, l2, f[full::w1], f[full::w2])
        });
        for (k, c) in at.light.iter().zip(normalise::exact(l)) {
            x[*k] = c;
        }
        out.push(x);
    }
    let base = out[0].clone();
    for (texel, light) in [
        (127, [0, 1024, 0]),
        (127, [0, -1024, 0]),
        (255, [1024, 0, 0]),
        (255, [0, 0, -1024]),
        (127, [-2048, -2048, -2048]),
    ] {
        let mut x = base.clone();
        let mut f = vec![0; crate::cart_pipeline::INPUTS.len()];
        for t in TEXELS {
            (f[t[0]], f[t[1]]) = (texel, texel);
        }
        set_texels(at, &mut x, &f);
        for (k, c) in at.light.iter().zip(light) {
            x[*k] = c;
        }
        out.push(x);
    }
    out
}

macro_rules! variant {
    ($model:ident, $name:literal, $k:literal, $exact:ident, $random:ident, $hard:ident, $acc:ident) => {
        fn $exact(i: &[i64]) -> Vec<i64> {
            ports(Variant::ALL[$k], i)
        }
        fn $random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
            random_with(Variant::ALL[$k].layout(), rng)
        }
        fn $hard() -> Vec<Vec<i64>> {
            hard_cases_with(Variant::ALL[$k])
        }
        fn $acc(samples: usize, seed: u64) -> Vec<crate::unit::Accuracy> {
            accuracy_with(Variant::ALL[$k], samples, seed)
        }
        pub static $model: UnitModel =
            UnitModel::new($name, (Variant::ALL[$k].layout().inputs, OUTPUTS), $exact, $random, $hard)
                .with_accuracy($acc);
    };
}

variant!(MODEL, "cart_surface", 0, exact_0, random_0, hard_0, accuracy_0);
variant!(MODEL_MATTE, "cart_surface_matte", 1, exact_1, random_1, hard_1, accuracy_1);
variant!(MODEL_HEMI_OCT, "cart_surface_hemi_oct", 2, exact_2, random_2, hard_2, accuracy_2);
variant!(MODEL_HEMI_OCT_MATTE, "cart_surface_hemi_oct_matte", 3, exact_3, random_3, hard_3, accuracy_3);
variant!(MODEL_NEAREST, "cart_surface_nearest", 4, exact_4, random_4, hard_4, accuracy_4);
variant!(MODEL_NEAREST_MATTE, "cart_surface_nearest_matte", 5, exact_5, random_5, hard_5, accuracy_5);
variant!(MODEL_NEAREST_HEMI_OCT, "cart_surface_nearest_hemi_oct", 6, exact_6, random_6, hard_6, accuracy_6);
variant!(MODEL_NEAREST_HEMI_OCT_MATTE, "cart_surface_nearest_hemi_oct_matte", 7, exact_7, random_7, hard_7, accuracy_7);

/// The models in `Variant::ALL`'s order.
static MODELS: [&UnitModel; 8] = [
    &MODEL,
    &MODEL_MATTE,
    &MODEL_HEMI_OCT,
    &MODEL_HEMI_OCT_MATTE,
    &MODEL_NEAREST,
    &MODEL_NEAREST_MATTE,
    &MODEL_NEAREST_HEMI_OCT,
    &MODEL_NEAREST_HEMI_OCT_MATTE,
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cart_pipeline;
    use rand::SeedableRng;

    /// The full pipeline's random vector with its three vertex lights set equal, and the same pixel as a surface
    /// variant's vector.
    fn pair(v: Variant, rng: &mut rand_chacha::ChaCha8Rng) -> (Vec<i64>, Vec<i64>) {
        use cart_pipeline::{input as full, DST, LIGHTS, SRC, TEXELS};
        let mut f = (cart_pipeline::MODEL.random)(rng);
        let q: [i64; 3] = std::array::from_fn(|c| f[LIGHTS[0][c]]);
        for k in LIGHTS {
            for c in 0..3 {
                f[k[c]] = q[c];
            }
        }
        let at = v.layout();
        if at.conc.is_none() {
            f[full::conc] = 0;
        }
        let mut s = vec![0; at.inputs.len()];
        set_texels(at, &mut s, &f);
        if let Texels::Nearest(t) = at.texels {
            // the full pipeline filtering four copies of the nearest texel reads that texel exactly
            for ft in TEXELS {
                (f[ft[0]], f[ft[1]]) = (s[t[0]], s[t[1]]);
            }
        }
        s[at.mode] = f[full::mode];
        if let Some(c) = at.conc {
            s[c] = f[full::conc];
        }
        for c in 0..3 {
            (s[at.src[c]], s[at.dst[c]]) = (f[SRC[c]], f[DST[c]]);
        }
        for (k, c) in at.light.iter().zip(light(q)) {
            s[*k] = c;
        }
        (f, s)
    }

    #[test]
    fn equal_vertex_lights_make_the_full_pipeline_and_the_surface_pipeline_agree() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(41);
        for v in Variant::ALL {
            {
                let decode = v.decode;
                let mut lit = 0;
                for _ in 0..20_000 {
                    let (f, s) = pair(v, &mut rng);
                    let full = cart_pipeline::exact_trace_with(decode, &f);
                    let t = exact_trace(v, &s);
                    assert_eq!((t.p, t.out), (full.p, full.out), "{v:?}: full {f:?}, surface {s:?}");
                    lit += (t.p > 0) as usize;
                }
                assert!(lit > 1_000, "{v:?}: only {lit} of 20,000 pixels lit, the comparison says little");
            }
        }
    }

    #[test]
    fn the_matte_variant_is_the_glossy_one_at_c_0() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(43);
        for v in Variant::ALL.into_iter().filter(|v| !v.gloss) {
            let g = Variant { gloss: true, ..v };
            for _ in 0..20_000 {
                let m = (v.model().random)(&mut rng);
                let mut x = m.clone();
                x.insert(g.layout().conc.unwrap(), 0);
                assert_eq!(ports(v, &m), ports(g, &x));
            }
        }
    }

    #[test]
    fn the_unit_knobs_are_the_blocks_own_arithmetic() {
        // the rtl is checked against `exact_trace`; its knobs must be what the plain unit calls compute
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(47);
        for _ in 0..20_000 {
            let i = (MODEL.random)(&mut rng);
            let t = exact_trace(Variant::ALL[0], &i);
            let at = GLOSSY;
            let Texels::Bilinear { corners, ublend, vblend } = at.texels else { unreachable!() };
            let f = |c: usize| {
                let [a, b, cc, d] = corners.map(|k| i[k[c]]);
                bilinear::exact_channel(a, b, cc, d, i[ublend], i[vblend], bilinear::F)
            };
            assert_eq!(t.texel, [f(0), f(1)]);
            assert_eq!(t.normal, normalise::exact(t.bump));
        }
        // and a coarser table moves some pixels
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(48);
        let coarse = Knobs { table_bits: 6, ..UNIT_KNOBS };
        let moved = (0..2_000).filter(|_| {
            let i = (MODEL_MATTE.random)(&mut rng);
            exact_trace_knobs(Variant::ALL[1], coarse, &i).p != exact_trace(Variant::ALL[1], &i).p
        });
        assert!(moved.count() > 100);
    }

    #[test]
    fn the_layouts_name_the_ports_they_index() {
        for v in Variant::ALL {
            let at = v.layout();
            let name = |k: usize| at.inputs[k].name;
            assert_eq!(at.light.map(name), ["l_x", "l_y", "l_z"]);
            assert_eq!(
                (name(at.mode), at.conc.map(name)),
                ("mode", at.inputs.iter().any(|p| p.name == "conc").then_some("conc"))
            );
            assert_eq!(at.src.map(name), ["src_r", "src_g", "src_b"]);
            match at.texels {
                Texels::Bilinear { corners, ublend, vblend } => {
                    assert_eq!(
                        (corners[3].map(name), name(ublend), name(vblend)),
                        (["t11_x", "t11_z"], "ublend", "vblend")
                    )
                }
                Texels::Nearest(t) => assert_eq!(t.map(name), ["t_x", "t_z"]),
            }
            assert_eq!(v.model().inputs.len(), at.inputs.len());
            assert_eq!(v.model().name.contains("nearest"), v.nearest);
            assert_eq!(v.model().name.contains("hemi_oct"), v.decode == Decode::HemiOct);
            assert_eq!(v.model().name.contains("matte"), !v.gloss);
        }
    }
}
