//! The table of units: one row per unit with an rtl block (its bit-exact model, its rtl block, and the signals its
//! Verilog leaves unused on purpose with the reason each is), the software-only units, and one row per swept
//! setting of a unit's width parameters. Every consumer reads it: the command line (`vectors`, `wave`, `verilog`,
//! `synth`, `widths`, `accuracy`, `hardcases`, `report`), the tests, the golden files, the lint, the accuracy
//! table, the width sweep; the table of pipelines (`crate::pipelines`) names its rows.
//!
//! A new unit is its model (`vectors`), its block (`rtl`), its test file (`testbench/tests`) and its row here; its
//! golden file is generated (`bumprtl vectors <unit>`). The table names both crates, so it lives above them.

use crate::rtl_paths::{Rtl, RtlBlock, RtlPaths};
use vectors::UnitModel;

/// One unit with an rtl block.
pub struct Unit {
    pub model: &'static UnitModel,
    pub rtl: &'static dyn RtlPaths,
    /// The design's own lint waivers: (signal as `instance$port`, why the Verilog leaves it unused).
    pub waivers: &'static [(&'static str, &'static str)],
}

impl Unit {
    pub const fn new(model: &'static UnitModel, rtl: &'static dyn RtlPaths) -> Unit {
        Unit { model, rtl, waivers: &[] }
    }

    pub const fn waiving(self, waivers: &'static [(&'static str, &'static str)]) -> Unit {
        Unit { waivers, ..self }
    }

    /// The unit's name (its model's and its block's: a test holds them alike).
    pub fn name(&self) -> &'static str {
        self.model.name
    }
}

/// Every unit with an rtl block, in the order the command line lists them and `bumprtl accuracy` prints them.
pub static UNITS: &[Unit] = &[
    Unit::new(&vectors::cart_decode::MODEL, &Rtl::<rtl::cart_decode::CartDecode>::PATHS),
    Unit::new(&vectors::cart_decode_hemi_oct::MODEL, &Rtl::<rtl::cart_decode_hemi_oct::CartDecodeHemiOct>::PATHS),
    Unit::new(&vectors::bilinear::MODEL, &Rtl::<rtl::bilinear::Bilinear>::PATHS).waiving(&[
        (
            "unit$0$wide",
            "the colour filter reads each bilinear unit's rounded output; the exact one is the \
            height-map path's",
        ),
        ("unit$1$wide", "as unit$0$wide"),
        ("unit$2$wide", "as unit$0$wide"),
        ("unit$3$wide", "as unit$0$wide"),
    ]),
    Unit::new(&vectors::light_iter::MODEL, &Rtl::<rtl::light_iter::LightIter>::PATHS),
    Unit::new(&vectors::normalise::MODEL, &Rtl::<rtl::normalise::Normalise>::PATHS),
    Unit::new(&vectors::dot3::MODEL, &Rtl::<rtl::dot3::Dot3>::PATHS),
    Unit::new(&vectors::gloss::MODEL, &Rtl::<rtl::gloss::Gloss>::PATHS),
    Unit::new(&vectors::blend::MODEL, &Rtl::<rtl::blend::Blend>::PATHS),
    Unit::new(&vectors::cart_pipeline::MODEL, &Rtl::<rtl::cart_pipeline::CartPipeline>::PATHS).waiving(&[
        ("filter$0$wide", "the texel's components are read rounded, as the colour filter reads them"),
        ("filter$1$wide", "as filter$0$wide"),
        ("light$valid_out", "the light path runs in lockstep with the bump path, whose valid is used"),
        ("light_norm$valid_out", "as light$valid_out"),
    ]),
    Unit::new(&vectors::cart_pipeline::MODEL_HEMI_OCT, &Rtl::<rtl::cart_pipeline::CartPipelineHemiOct>::PATHS).waiving(
        &[
            ("filter$0$wide", "as in cart_pipeline"),
            ("filter$1$wide", "as filter$0$wide"),
            ("light$valid_out", "as in cart_pipeline: the bump path's valid is used"),
            ("light_norm$valid_out", "as light$valid_out"),
        ],
    ),
    Unit::new(&vectors::cart_pipeline::MODEL_MATTE, &Rtl::<rtl::cart_pipeline::CartPipelineMatte>::PATHS).waiving(&[
        ("filter$0$wide", "as in cart_pipeline"),
        ("filter$1$wide", "as filter$0$wide"),
        ("light$valid_out", "as in cart_pipeline: the bump path's valid is used"),
        ("light_norm$valid_out", "as light$valid_out"),
    ]),
    Unit::new(
        &vectors::cart_pipeline::MODEL_HEMI_OCT_MATTE,
        &Rtl::<rtl::cart_pipeline::CartPipelineHemiOctMatte>::PATHS,
    )
    .waiving(&[
        ("filter$0$wide", "as in cart_pipeline"),
        ("filter$1$wide", "as filter$0$wide"),
        ("light$valid_out", "as in cart_pipeline: the bump path's valid is used"),
        ("light_norm$valid_out", "as light$valid_out"),
    ]),
    Unit::new(&vectors::cart_surface::MODEL, &Rtl::<rtl::cart_surface::CartSurface>::PATHS)
        .waiving(&[("filter$0$wide", "as in cart_pipeline"), ("filter$1$wide", "as filter$0$wide")]),
    Unit::new(&vectors::cart_surface::MODEL_MATTE, &Rtl::<rtl::cart_surface::CartSurfaceMatte>::PATHS)
        .waiving(&[("filter$0$wide", "as in cart_pipeline"), ("filter$1$wide", "as filter$0$wide")]),
    Unit::new(&vectors::cart_surface::MODEL_HEMI_OCT, &Rtl::<rtl::cart_surface::CartSurfaceHemiOct>::PATHS)
        .waiving(&[("filter$0$wide", "as in cart_pipeline"), ("filter$1$wide", "as filter$0$wide")]),
    Unit::new(&vectors::cart_surface::MODEL_HEMI_OCT_MATTE, &Rtl::<rtl::cart_surface::CartSurfaceHemiOctMatte>::PATHS)
        .waiving(&[("filter$0$wide", "as in cart_pipeline"), ("filter$1$wide", "as filter$0$wide")]),
    Unit::new(&vectors::cart_surface::MODEL_NEAREST, &Rtl::<rtl::cart_surface::CartSurfaceNearest>::PATHS),
    Unit::new(&vectors::cart_surface::MODEL_NEAREST_MATTE, &Rtl::<rtl::cart_surface::CartSurfaceNearestMatte>::PATHS),
    Unit::new(
        &vectors::cart_surface::MODEL_NEAREST_HEMI_OCT,
        &Rtl::<rtl::cart_surface::CartSurfaceNearestHemiOct>::PATHS,
    ),
    Unit::new(
        &vectors::cart_surface::MODEL_NEAREST_HEMI_OCT_MATTE,
        &Rtl::<rtl::cart_surface::CartSurfaceNearestHemiOctMatte>::PATHS,
    ),
    Unit::new(&vectors::height_addr::MODEL, &Rtl::<rtl::height_addr::HeightAddr>::PATHS),
    Unit::new(&vectors::height_fetch::MODEL, &Rtl::<rtl::height_fetch::HeightFetch>::PATHS),
    Unit::new(&vectors::replicate::MODEL, &Rtl::<rtl::replicate::Replicate>::PATHS),
    Unit::new(&vectors::blend_adjust::MODEL, &Rtl::<rtl::blend_adjust::BlendAdjust>::PATHS),
    Unit::new(&vectors::tangent::MODEL, &Rtl::<rtl::tangent::Tangent>::PATHS),
    Unit::new(&vectors::height_normal::MODEL, &Rtl::<rtl::height_normal::HeightNormal>::PATHS),
    Unit::new(&vectors::height_pipeline::MODEL, &Rtl::<rtl::height_pipeline::HeightPipeline>::PATHS).waiving(&[
        (
            "unit$0$out",
            "the height path reads each bilinear unit's exact result; the rounded one is the \
            colour filter's",
        ),
        ("unit$1$out", "as unit$0$out"),
        ("unit$2$out", "as unit$0$out"),
        ("unit$3$out", "as unit$0$out"),
    ]),
    Unit::new(&vectors::texture_filter::MODEL, &Rtl::<rtl::texture_filter::TextureFilter>::PATHS),
    Unit::new(&vectors::blinn_pipeline::MODEL, &Rtl::<rtl::blinn_pipeline::BlinnPipeline>::PATHS).waiving(&[
        (
            "unit$0$out",
            "Blinn's function reads each bilinear unit's exact result; the rounded one is the \
            colour filter's",
        ),
        ("unit$1$out", "as unit$0$out"),
        ("unit$2$out", "as unit$0$out"),
    ]),
    Unit::new(&vectors::palette_lookup::MODEL, &Rtl::<rtl::palette_lookup::PaletteLookup<8, 9>>::PATHS),
    Unit::new(&vectors::table_builder::MODEL, &Rtl::<rtl::table_builder::TableBuilder>::PATHS)
        .waiving(&[("diffuse$valid_out", "the two dot products run in lockstep; the highlight's valid is used")]),
    Unit::new(&vectors::palette_pipeline::MODEL, &Rtl::<rtl::palette_pipeline::PalettePipeline<8, 9>>::PATHS)
        .waiving(&[("diffuse$valid_out", "as in table_builder")]),
    Unit::new(&vectors::palette_pipeline::MODEL_12, &Rtl::<rtl::palette_pipeline::PalettePipeline<12, 13>>::PATHS)
        .waiving(&[("diffuse$valid_out", "as in table_builder")]),
    Unit::new(
        &vectors::palette_pipeline_shared::MODEL,
        &Rtl::<rtl::palette_pipeline_shared::PalettePipelineShared>::PATHS,
    ),
    Unit::new(&vectors::sincos::MODEL, &Rtl::<rtl::sincos::SinCosUnit>::PATHS),
    Unit::new(&vectors::cos_sign::MODEL, &Rtl::<rtl::cos_sign::CosSignUnit>::PATHS),
    Unit::new(&vectors::polar_shade::MODEL, &Rtl::<rtl::polar_shade::PolarShade<false>>::PATHS),
    Unit::new(&vectors::polar_shade::MODEL_DC, &Rtl::<rtl::polar_shade::PolarShade<true>>::PATHS),
    Unit::new(&vectors::power::MODEL, &Rtl::<rtl::power::Power>::PATHS),
    Unit::new(&vectors::polar_pipeline::MODEL, &Rtl::<rtl::polar_pipeline::PolarPipelineSeed>::PATHS).waiving(&[(
        "shader$sum",
        "polar_shade's S11 before the clamp is an output for tests and waveforms; the \
            pipeline uses the clamped shade",
    )]),
    Unit::new(&vectors::polar_pipeline::MODEL_DC, &Rtl::<rtl::polar_pipeline::PolarPipelineDc>::PATHS)
        .waiving(&[("shader$sum", "as in polar_pipeline")]),
    Unit::new(&vectors::lod::MODEL, &Rtl::<rtl::lod::Lod>::PATHS),
    Unit::new(&vectors::tex_addr::MODEL, &Rtl::<rtl::tex_addr::TexAddr>::PATHS),
    Unit::new(&vectors::tex_fetch::MODEL, &Rtl::<rtl::tex_fetch::TexFetch>::PATHS),
    Unit::new(&vectors::cart_tex::bilinear::MODEL, &Rtl::<rtl::cart_tex::CartTexBilinear>::PATHS).waiving(&[
        ("filter$0$wide", "the front's bilinear units, read rounded as in cart_pipeline"),
        ("filter$1$wide", "as filter$0$wide"),
        ("light$valid_out", "as in cart_pipeline"),
        ("light_norm$valid_out", "as in cart_pipeline"),
    ]),
    Unit::new(&vectors::cart_tex::bilinear_matte::MODEL, &Rtl::<rtl::cart_tex::CartTexBilinearMatte>::PATHS).waiving(
        &[
            ("filter$0$wide", "as in cart_tex_bilinear"),
            ("filter$1$wide", "as filter$0$wide"),
            ("light$valid_out", "as in cart_pipeline"),
            ("light_norm$valid_out", "as in cart_pipeline"),
        ],
    ),
    Unit::new(&vectors::cart_tex::nearest_matte::MODEL, &Rtl::<rtl::cart_tex::CartTexNearestMatte>::PATHS).waiving(&[
        ("light$valid_out", "as in cart_pipeline"),
        ("light_norm$valid_out", "as in cart_pipeline"),
        ("addr$ublend", "the nearest texel needs no blend factors (tex_addr gives 0 for linear = 0)"),
        ("addr$vblend", "as addr$ublend"),
        ("fetch$t10", "the nearest texel is the footprint's first, t00; the other three are the bilinear fronts'"),
        ("fetch$t01", "as fetch$t10"),
        ("fetch$t11", "as fetch$t10"),
    ]),
    Unit::new(&vectors::cart_tex::nearest_mip_matte::MODEL, &Rtl::<rtl::cart_tex::CartTexNearestMipMatte>::PATHS)
        .waiving(&[
            ("light$valid_out", "as in cart_pipeline"),
            ("light_norm$valid_out", "as in cart_pipeline"),
            (
                "lod$level",
                "the nearest level is the LOD unit's `nearest`; the floor of lambda and its fraction are trilinear's",
            ),
            ("lod$frac", "as lod$level"),
            ("addr$ublend", "the nearest texel needs no blend factors (tex_addr gives 0 for linear = 0)"),
            ("addr$vblend", "as addr$ublend"),
            ("fetch$t10", "the nearest texel is the footprint's first, t00; the other three are the bilinear fronts'"),
            ("fetch$t01", "as fetch$t10"),
            ("fetch$t11", "as fetch$t10"),
        ]),
    Unit::new(&vectors::cart_tex::trilinear_matte::MODEL, &Rtl::<rtl::cart_tex::CartTexTrilinearMatte>::PATHS).waiving(
        &[
            ("light$valid_out", "as in cart_pipeline"),
            ("light_norm$valid_out", "as in cart_pipeline"),
            ("lod$nearest", "trilinear reads the floor of lambda and its fraction; the nearest level is nearest_mip's"),
            ("filter$0$wide", "as in cart_tex_bilinear: the front reads each unit's rounded byte"),
            ("filter$1$wide", "as filter$0$wide"),
            ("filter$2$wide", "as filter$0$wide"),
            ("filter$3$wide", "as filter$0$wide"),
            ("fetch$1$valid_out", "the two fetches run in step: the valid chain follows the first's"),
        ],
    ),
];

/// The units that are software only (no rtl block, no vectors): the encoders that write the bump maps. Their errors
/// are in `bumprtl accuracy`.
pub const SOFTWARE_ONLY: &[&str] = &["cart_encode", "polar_encode"];

/// The unit called `name`, if it has an rtl block.
pub fn find(name: &str) -> Option<&'static Unit> {
    UNITS.iter().find(|u| u.name() == name)
}

/// The unit called `name`, or a one-line error that says why not (software only, or unknown and the units listed).
pub fn unit(name: &str) -> Result<&'static Unit, String> {
    if SOFTWARE_ONLY.contains(&name) {
        return Err(format!(
            "`{name}` is software only (no rtl block, no vectors): its errors are in `bumprtl accuracy`"
        ));
    }
    find(name).ok_or_else(|| {
        let names: Vec<&str> = UNITS.iter().map(Unit::name).collect();
        format!("unknown unit `{name}`; the units are: {}", names.join(", "))
    })
}

/// One setting of a unit's width parameters that the width sweep, the LUT-size tables and the report price: the
/// unit, its two parameters as the unit's model takes them, and the rtl block built with them. The parameters are
/// normalise's (seed-table bits, Newton steps), sincos's and cos_sign's (table bits, entry width), bilinear's
/// (blend-factor bits, low texel bits dropped) and power's (L fraction bits, E table bits).
pub struct Setting {
    pub unit: &'static str,
    pub params: (u32, u32),
    pub rtl: &'static dyn RtlBlock,
}

impl Setting {
    pub const fn new(unit: &'static str, params: (u32, u32), rtl: &'static dyn RtlBlock) -> Setting {
        Setting { unit, params, rtl }
    }
}

/// Every swept setting, each unit's in the order its tables print them.
pub static SETTINGS: &[Setting] = &[
    Setting::new("normalise", (10, 0), &Rtl::<rtl::normalise::Normalise<10, 0>>::PATHS),
    Setting::new("normalise", (10, 1), &Rtl::<rtl::normalise::Normalise<10, 1>>::PATHS),
    Setting::new("normalise", (6, 0), &Rtl::<rtl::normalise::Normalise<6, 0>>::PATHS),
    Setting::new("normalise", (6, 1), &Rtl::<rtl::normalise::Normalise<6, 1>>::PATHS),
    Setting::new("normalise", (7, 0), &Rtl::<rtl::normalise::Normalise<7, 0>>::PATHS),
    Setting::new("normalise", (7, 1), &Rtl::<rtl::normalise::Normalise<7, 1>>::PATHS),
    Setting::new("normalise", (8, 0), &Rtl::<rtl::normalise::Normalise<8, 0>>::PATHS),
    Setting::new("normalise", (8, 1), &Rtl::<rtl::normalise::Normalise<8, 1>>::PATHS),
    Setting::new("normalise", (9, 0), &Rtl::<rtl::normalise::Normalise<9, 0>>::PATHS),
    Setting::new("normalise", (9, 1), &Rtl::<rtl::normalise::Normalise<9, 1>>::PATHS),
    Setting::new("normalise", (11, 0), &Rtl::<rtl::normalise::Normalise<11, 0>>::PATHS),
    Setting::new("normalise", (11, 1), &Rtl::<rtl::normalise::Normalise<11, 1>>::PATHS),
    Setting::new("normalise", (12, 0), &Rtl::<rtl::normalise::Normalise<12, 0>>::PATHS),
    Setting::new("normalise", (12, 1), &Rtl::<rtl::normalise::Normalise<12, 1>>::PATHS),
    Setting::new("sincos", (6, 8), &Rtl::<rtl::sincos::SinCos<6, 8>>::PATHS),
    Setting::new("sincos", (8, 8), &Rtl::<rtl::sincos::SinCos<8, 8>>::PATHS),
    Setting::new("sincos", (10, 8), &Rtl::<rtl::sincos::SinCos<10, 8>>::PATHS),
    Setting::new("sincos", (6, 10), &Rtl::<rtl::sincos::SinCos<6, 10>>::PATHS),
    Setting::new("sincos", (8, 10), &Rtl::<rtl::sincos::SinCos<8, 10>>::PATHS),
    Setting::new("sincos", (10, 10), &Rtl::<rtl::sincos::SinCos<10, 10>>::PATHS),
    Setting::new("sincos", (6, 12), &Rtl::<rtl::sincos::SinCos<6, 12>>::PATHS),
    Setting::new("sincos", (8, 12), &Rtl::<rtl::sincos::SinCos<8, 12>>::PATHS),
    Setting::new("sincos", (10, 12), &Rtl::<rtl::sincos::SinCos<10, 12>>::PATHS),
    Setting::new("cos_sign", (4, 8), &Rtl::<rtl::cos_sign::CosSign<4, 8>>::PATHS),
    Setting::new("cos_sign", (6, 8), &Rtl::<rtl::cos_sign::CosSign<6, 8>>::PATHS),
    Setting::new("cos_sign", (8, 8), &Rtl::<rtl::cos_sign::CosSign<8, 8>>::PATHS),
    Setting::new("cos_sign", (4, 12), &Rtl::<rtl::cos_sign::CosSign<4, 12>>::PATHS),
    Setting::new("cos_sign", (6, 12), &Rtl::<rtl::cos_sign::CosSign<6, 12>>::PATHS),
    Setting::new("cos_sign", (8, 12), &Rtl::<rtl::cos_sign::CosSign<8, 12>>::PATHS),
    Setting::new("bilinear", (8, 0), &Rtl::<rtl::bilinear::Bilinear<8, 0>>::PATHS),
    Setting::new("bilinear", (7, 0), &Rtl::<rtl::bilinear::Bilinear<7, 0>>::PATHS),
    Setting::new("bilinear", (6, 0), &Rtl::<rtl::bilinear::Bilinear<6, 0>>::PATHS),
    Setting::new("bilinear", (5, 0), &Rtl::<rtl::bilinear::Bilinear<5, 0>>::PATHS),
    Setting::new("bilinear", (4, 0), &Rtl::<rtl::bilinear::Bilinear<4, 0>>::PATHS),
    Setting::new("bilinear", (8, 2), &Rtl::<rtl::bilinear::Bilinear<8, 2>>::PATHS),
    Setting::new("bilinear", (8, 4), &Rtl::<rtl::bilinear::Bilinear<8, 4>>::PATHS),
    Setting::new("bilinear", (6, 2), &Rtl::<rtl::bilinear::Bilinear<6, 2>>::PATHS),
    Setting::new("power", (12, 8), &Rtl::<rtl::power::Power<12, 8>>::PATHS),
    Setting::new("power", (12, 6), &Rtl::<rtl::power::Power<12, 6>>::PATHS),
    Setting::new("power", (12, 7), &Rtl::<rtl::power::Power<12, 7>>::PATHS),
    Setting::new("power", (12, 9), &Rtl::<rtl::power::Power<12, 9>>::PATHS),
    Setting::new("power", (10, 6), &Rtl::<rtl::power::Power<10, 6>>::PATHS),
    Setting::new("power", (10, 7), &Rtl::<rtl::power::Power<10, 7>>::PATHS),
    Setting::new("power", (10, 8), &Rtl::<rtl::power::Power<10, 8>>::PATHS),
    Setting::new("power", (10, 9), &Rtl::<rtl::power::Power<10, 9>>::PATHS),
    Setting::new("power", (8, 6), &Rtl::<rtl::power::Power<8, 6>>::PATHS),
    Setting::new("power", (8, 7), &Rtl::<rtl::power::Power<8, 7>>::PATHS),
    Setting::new("power", (8, 8), &Rtl::<rtl::power::Power<8, 8>>::PATHS),
    Setting::new("power", (8, 9), &Rtl::<rtl::power::Power<8, 9>>::PATHS),
];

/// The swept settings of `unit`, in order.
pub fn settings(unit: &str) -> impl Iterator<Item = &'static Setting> + '_ {
    SETTINGS.iter().filter(move |s| s.unit == unit)
}

/// The setting of `unit` with these parameters, if the table has it.
pub fn setting(unit: &str, params: (u32, u32)) -> Option<&'static Setting> {
    settings(unit).find(|s| s.params == params)
}
