//! The description every unit shares: its ports (named as the rtl block names them), its bit-exact function and
//! a way to draw legal random inputs. The vector generator, the testbenches and the Verilog harnesses all read it.

use rand::Rng;

/// One port of a unit: its name in the rtl block, its width, and whether its bits are two's complement.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Port {
    pub name: &'static str,
    pub bits: u32,
    pub signed: bool,
}

impl Port {
    pub const fn u(name: &'static str, bits: u32) -> Port {
        Port { name, bits, signed: false }
    }
    pub const fn s(name: &'static str, bits: u32) -> Port {
        Port { name, bits, signed: true }
    }
    pub fn range(&self) -> (i64, i64) {
        if self.signed {
            crate::fixed::signed_range(self.bits)
        } else {
            crate::fixed::unsigned_range(self.bits)
        }
    }
}

/// Declares a unit's ports once, in order: `INPUTS` and `OUTPUTS` (`u` unsigned, `s` two's complement, and the
/// width), and modules `input` and `output` holding each port's index by its own name, so that a vector is read
/// as `v[input::conc]`, never by a number.
#[macro_export]
macro_rules! ports {
    (inputs: [$($i:ident: $ik:ident $iw:expr),* $(,)?], outputs: [$($o:ident: $ok:ident $ow:expr),* $(,)?] $(,)?) => {
        pub const INPUTS: &[$crate::unit::Port] = &[$($crate::unit::Port::$ik(stringify!($i), $iw)),*];
        pub const OUTPUTS: &[$crate::unit::Port] = &[$($crate::unit::Port::$ok(stringify!($o), $ow)),*];
        /// One random input vector: every input port drawn over its range, its ends weighted in.
        #[allow(dead_code)]
        pub fn random_inputs(rng: &mut dyn rand::RngCore) -> Vec<i64> {
            INPUTS.iter().map(|p| $crate::unit::draw(rng, p)).collect()
        }
        /// Each input port's index in an input vector.
        #[allow(non_upper_case_globals, dead_code)]
        pub mod input {
            #[allow(non_camel_case_types)]
            enum Index { $($i),* }
            $(pub const $i: usize = Index::$i as usize;)*
        }
        /// Each output port's index in an output vector.
        #[allow(non_upper_case_globals, dead_code)]
        pub mod output {
            #[allow(non_camel_case_types)]
            enum Index { $($o),* }
            $(pub const $o: usize = Index::$o as usize;)*
        }
    };
}

/// A streaming unit as the testbench sees it: inputs in, outputs out, one vector per clock.
pub struct UnitModel {
    pub name: &'static str,
    pub inputs: &'static [Port],
    pub outputs: &'static [Port],
    /// The bit-exact model: input values (in port order) → output values.
    pub exact: fn(&[i64]) -> Vec<i64>,
    /// One random input vector drawn from the legal input space (edges weighted in).
    pub random: fn(&mut dyn rand::RngCore) -> Vec<i64>,
    /// The whole input space, in order, when it is small enough to enumerate (≤ 2^20 vectors).
    pub exhaustive: Option<fn() -> Vec<Vec<i64>>>,
    /// Inputs the seeds warn about or that sit at the edge of a range; always in the golden file.
    pub hard_cases: fn() -> Vec<Vec<i64>>,
    /// The unit's error against its ideal, measured: (samples where it draws at random, seed) → one row per metric.
    /// `bumprtl accuracy` prints every unit's, in the table's order.
    pub accuracy: Option<fn(usize, u64) -> Vec<Accuracy>>,
    /// A unit with state (a memory written by some vectors and read by later ones): the model over a whole stream,
    /// from reset. `exact` is then the stream of that one vector.
    pub stream: Option<fn(&[Vec<i64>]) -> Vec<Vec<i64>>>,
}

/// One measured error of a unit against its ideal: what is measured, over which inputs, and the statistics.
pub struct Accuracy {
    pub metric: String,
    pub stats: crate::stats::ErrorStats,
}

impl Accuracy {
    pub fn new(metric: &str, stats: crate::stats::ErrorStats) -> Accuracy {
        Accuracy { metric: metric.to_string(), stats }
    }

    /// One metric over `samples` inputs drawn by `random` from a stream seeded with `seed`; `errors` gives each
    /// input's errors (one, or one per channel), all counted, the worst reported with its input.
    pub fn over_random(
        metric: &str,
        samples: usize,
        seed: u64,
        random: fn(&mut dyn rand::RngCore) -> Vec<i64>,
        errors: impl Fn(&[i64]) -> Vec<f64>,
    ) -> Accuracy {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let mut s = crate::stats::ErrorStats::default();
        for _ in 0..samples {
            let v = random(&mut rng);
            for e in errors(&v) {
                s.add(e, || format!("{v:?}"));
            }
        }
        Accuracy::new(metric, s)
    }
}

impl UnitModel {
    /// A unit whose input space is too large to enumerate (the exhaustive set is added by `with_exhaustive`).
    pub const fn new(
        name: &'static str,
        ports: (&'static [Port], &'static [Port]),
        exact: fn(&[i64]) -> Vec<i64>,
        random: fn(&mut dyn rand::RngCore) -> Vec<i64>,
        hard_cases: fn() -> Vec<Vec<i64>>,
    ) -> UnitModel {
        UnitModel {
            name,
            inputs: ports.0,
            outputs: ports.1,
            exact,
            random,
            exhaustive: None,
            hard_cases,
            accuracy: None,
            stream: None,
        }
    }

    pub const fn with_exhaustive(self, all: fn() -> Vec<Vec<i64>>) -> UnitModel {
        UnitModel { exhaustive: Some(all), ..self }
    }

    pub const fn with_accuracy(self, f: fn(usize, u64) -> Vec<Accuracy>) -> UnitModel {
        UnitModel { accuracy: Some(f), ..self }
    }

    pub const fn with_stream(self, run: fn(&[Vec<i64>]) -> Vec<Vec<i64>>) -> UnitModel {
        UnitModel { stream: Some(run), ..self }
    }

    /// The model's outputs for a stream of vectors in order: vector by vector, or through the unit's state.
    pub fn run(&self, inputs: &[Vec<i64>]) -> Vec<Vec<i64>> {
        match self.stream {
            Some(run) => run(inputs),
            None => inputs.iter().map(|v| (self.exact)(v)).collect(),
        }
    }

    pub fn header(&self) -> Vec<&'static str> {
        self.inputs.iter().chain(self.outputs.iter()).map(|p| p.name).collect()
    }
}

/// Every unit, once. Each hardware unit gives its name, its model, its rtl block (a path into the `rtl` crate: this
/// crate never expands it, only the crates that depend on `rtl` do) and the design's own lint waivers, each a
/// signal the Verilog leaves unused on purpose with the reason; the software-only units follow. Everything that
/// lists units is made from this table by a callback macro: `unit_table!(callback)` expands to
/// `callback! { [extra] rtl { name: model, block, [waivers]; ... } software { name, ... } }`, where `extra` is
/// whatever followed the callback's name (a `$` to let the callback define a macro of its own, say).
#[macro_export]
macro_rules! unit_table {
    ($then:ident $(, $extra:tt)*) => {
        $then! { [$($extra)*]
            rtl {
                cart_decode: $crate::cart_decode::MODEL, rtl::cart_decode::CartDecode, [];
                cart_decode_hemi_oct: $crate::cart_decode_hemi_oct::MODEL, rtl::cart_decode_hemi_oct::CartDecodeHemiOct, [];
                bilinear: $crate::bilinear::MODEL, rtl::bilinear::Bilinear, [
                    ("unit$0$wide", "the colour filter reads each bilinear unit's rounded output; the exact one is the \
                        height-map path's"),
                    ("unit$1$wide", "as unit$0$wide"),
                    ("unit$2$wide", "as unit$0$wide"),
                    ("unit$3$wide", "as unit$0$wide"),
                ];
                light_iter: $crate::light_iter::MODEL, rtl::light_iter::LightIter, [];
                normalise: $crate::normalise::MODEL, rtl::normalise::Normalise, [];
                dot3: $crate::dot3::MODEL, rtl::dot3::Dot3, [];
                gloss: $crate::gloss::MODEL, rtl::gloss::Gloss, [];
                blend: $crate::blend::MODEL, rtl::blend::Blend, [];
                cart_pipeline: $crate::cart_pipeline::MODEL, rtl::cart_pipeline::CartPipeline, [
                    ("filter$0$wide", "the texel's components are read rounded, as the colour filter reads them"),
                    ("filter$1$wide", "as filter$0$wide"),
                    ("light$valid_out", "the light path runs in lockstep with the bump path, whose valid is used"),
                    ("light_norm$valid_out", "as light$valid_out"),
                ];
                cart_pipeline_hemi_oct: $crate::cart_pipeline::MODEL_HEMI_OCT, rtl::cart_pipeline::CartPipelineHemiOct, [
                    ("filter$0$wide", "as in cart_pipeline"),
                    ("filter$1$wide", "as filter$0$wide"),
                    ("light$valid_out", "as in cart_pipeline: the bump path's valid is used"),
                    ("light_norm$valid_out", "as light$valid_out"),
                ];
                cart_pipeline_matte: $crate::cart_pipeline::MODEL_MATTE, rtl::cart_pipeline::CartPipelineMatte, [
                    ("filter$0$wide", "as in cart_pipeline"),
                    ("filter$1$wide", "as filter$0$wide"),
                    ("light$valid_out", "as in cart_pipeline: the bump path's valid is used"),
                    ("light_norm$valid_out", "as light$valid_out"),
                ];
                cart_pipeline_hemi_oct_matte: $crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, rtl::cart_pipeline::CartPipelineHemiOctMatte, [
                    ("filter$0$wide", "as in cart_pipeline"),
                    ("filter$1$wide", "as filter$0$wide"),
                    ("light$valid_out", "as in cart_pipeline: the bump path's valid is used"),
                    ("light_norm$valid_out", "as light$valid_out"),
                ];
                cart_surface: $crate::cart_surface::MODEL, rtl::cart_surface::CartSurface, [
                    ("filter$0$wide", "as in cart_pipeline"),
                    ("filter$1$wide", "as filter$0$wide"),
                ];
                cart_surface_matte: $crate::cart_surface::MODEL_MATTE, rtl::cart_surface::CartSurfaceMatte, [
                    ("filter$0$wide", "as in cart_pipeline"),
                    ("filter$1$wide", "as filter$0$wide"),
                ];
                cart_surface_hemi_oct: $crate::cart_surface::MODEL_HEMI_OCT, rtl::cart_surface::CartSurfaceHemiOct, [
                    ("filter$0$wide", "as in cart_pipeline"),
                    ("filter$1$wide", "as filter$0$wide"),
                ];
                cart_surface_hemi_oct_matte: $crate::cart_surface::MODEL_HEMI_OCT_MATTE, rtl::cart_surface::CartSurfaceHemiOctMatte, [
                    ("filter$0$wide", "as in cart_pipeline"),
                    ("filter$1$wide", "as filter$0$wide"),
                ];
                cart_surface_nearest: $crate::cart_surface::MODEL_NEAREST, rtl::cart_surface::CartSurfaceNearest, [];
                cart_surface_nearest_matte: $crate::cart_surface::MODEL_NEAREST_MATTE, rtl::cart_surface::CartSurfaceNearestMatte, [];
                cart_surface_nearest_hemi_oct: $crate::cart_surface::MODEL_NEAREST_HEMI_OCT, rtl::cart_surface::CartSurfaceNearestHemiOct, [];
                cart_surface_nearest_hemi_oct_matte: $crate::cart_surface::MODEL_NEAREST_HEMI_OCT_MATTE, rtl::cart_surface::CartSurfaceNearestHemiOctMatte, [];
                height_addr: $crate::height_addr::MODEL, rtl::height_addr::HeightAddr, [];
                height_fetch: $crate::height_fetch::MODEL, rtl::height_fetch::HeightFetch, [];
                replicate: $crate::replicate::MODEL, rtl::replicate::Replicate, [];
                blend_adjust: $crate::blend_adjust::MODEL, rtl::blend_adjust::BlendAdjust, [];
                tangent: $crate::tangent::MODEL, rtl::tangent::Tangent, [];
                height_normal: $crate::height_normal::MODEL, rtl::height_normal::HeightNormal, [];
                height_pipeline: $crate::height_pipeline::MODEL, rtl::height_pipeline::HeightPipeline, [
                    ("unit$0$out", "the height path reads each bilinear unit's exact result; the rounded one is the \
                        colour filter's"),
                    ("unit$1$out", "as unit$0$out"),
                    ("unit$2$out", "as unit$0$out"),
                    ("unit$3$out", "as unit$0$out"),
                ];
                texture_filter: $crate::texture_filter::MODEL, rtl::texture_filter::TextureFilter, [];
                blinn_pipeline: $crate::blinn_pipeline::MODEL, rtl::blinn_pipeline::BlinnPipeline, [
                    ("unit$0$out", "Blinn's function reads each bilinear unit's exact result; the rounded one is the \
                        colour filter's"),
                    ("unit$1$out", "as unit$0$out"),
                    ("unit$2$out", "as unit$0$out"),
                ];
                palette_lookup: $crate::palette_lookup::MODEL, rtl::palette_lookup::PaletteLookup<8, 9>, [];
                table_builder: $crate::table_builder::MODEL, rtl::table_builder::TableBuilder, [
                    ("diffuse$valid_out", "the two dot products run in lockstep; the highlight's valid is used"),
                ];
                palette_pipeline: $crate::palette_pipeline::MODEL, rtl::palette_pipeline::PalettePipeline<8, 9>, [
                    ("diffuse$valid_out", "as in table_builder"),
                ];
                palette_pipeline_12: $crate::palette_pipeline::MODEL_12, rtl::palette_pipeline::PalettePipeline<12, 13>, [
                    ("diffuse$valid_out", "as in table_builder"),
                ];
                palette_pipeline_shared: $crate::palette_pipeline_shared::MODEL, rtl::palette_pipeline_shared::PalettePipelineShared, [];
                sincos: $crate::sincos::MODEL, rtl::sincos::SinCosUnit, [];
                cos_sign: $crate::cos_sign::MODEL, rtl::cos_sign::CosSignUnit, [];
                polar_shade: $crate::polar_shade::MODEL, rtl::polar_shade::PolarShade<false>, [];
                polar_shade_dc: $crate::polar_shade::MODEL_DC, rtl::polar_shade::PolarShade<true>, [];
                power: $crate::power::MODEL, rtl::power::Power, [];
                polar_pipeline: $crate::polar_pipeline::MODEL, rtl::polar_pipeline::PolarPipelineSeed, [
                    ("shader$sum", "polar_shade's S11 before the clamp is an output for tests and waveforms; the \
                        pipeline uses the clamped shade"),
                ];
                polar_pipeline_dc: $crate::polar_pipeline::MODEL_DC, rtl::polar_pipeline::PolarPipelineDc, [
                    ("shader$sum", "as in polar_pipeline"),
                ];
            }
            software { cart_encode, polar_encode }
        }
    };
}

macro_rules! models {
    ([] rtl { $($name:ident: $model:expr, $block:ty, [$(($sig:literal, $why:literal)),* $(,)?];)* }
        software { $($soft:ident),* }) => {
        /// Every unit with an rtl block, by name, in the table's order.
        pub const UNITS: &[&UnitModel] = &[$(&$model),*];

        /// The units that are software only (no rtl block, no vectors): their errors are in `bumprtl accuracy`.
        pub const SOFTWARE_ONLY: &[&str] = &[$(stringify!($soft)),*];

        /// The design's own lint waivers of a unit: (signal, reason).
        pub fn lint_waivers(name: &str) -> &'static [(&'static str, &'static str)] {
            match name {
                $(stringify!($name) => &[$(($sig, $why)),*],)*
                _ => &[],
            }
        }
    };
}

unit_table!(models);

/// A vector's values as the bit patterns its ports carry (two's complement for signed ports), in port order.
pub fn to_patterns(values: &[i64], ports: &[Port]) -> Vec<u64> {
    values.iter().zip(ports).map(|(&v, p)| crate::fixed::to_pattern(v, p.bits)).collect()
}

pub fn find(name: &str) -> Option<&'static UnitModel> {
    UNITS.iter().copied().find(|u| u.name == name)
}

/// A value drawn uniformly from a port's range, with its two ends weighted in (1 draw in 8 is an end).
pub fn draw(rng: &mut dyn rand::RngCore, p: &Port) -> i64 {
    let (lo, hi) = p.range();
    match rng.gen_range(0..16) {
        0 => lo,
        1 => hi,
        _ => rng.gen_range(lo..=hi),
    }
}

/// The vectors for a unit: either its whole input space, each input exactly once (the hard cases are in it), or
/// its hard cases first and then `count` random vectors drawn from a ChaCha8 stream seeded with `seed` (the same
/// seed gives the same file on every machine).
pub fn generate(unit: &UnitModel, exhaustive: bool, count: usize, seed: u64) -> Result<Vec<Vec<i64>>, String> {
    use rand::SeedableRng;
    if exhaustive {
        let all = unit.exhaustive.ok_or_else(|| {
            format!("{} has no exhaustive vector set: its input space is above 2^20; use --count", unit.name)
        })?;
        return Ok(all());
    }
    let mut v = (unit.hard_cases)();
    {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        v.extend((0..count).map(|_| (unit.random)(&mut rng)));
    }
    Ok(v)
}

/// The values a vector's bit patterns stand for (sign-extended for signed ports), in port order.
pub fn from_patterns(patterns: &[u64], ports: &[Port]) -> Vec<i64> {
    patterns.iter().zip(ports).map(|(&p, port)| crate::fixed::from_pattern(p, port.bits, port.signed)).collect()
}
