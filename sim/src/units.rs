//! The table of units: one row per unit with an rtl block (its bit-exact model, its rtl block, and the signals its
//! Verilog leaves unused on purpose with the reason each is), the software-only units, and one row per swept
//! setting of a unit's width parameters. Every consumer reads it: the command line (`vectors`, `wave`, `verilog`,
//! `synth`, `widths`, `accuracy`, `hardcases`, `report`), the tests, the golden files, the lint, the accuracy
//! table, the width sweep; the table of pipelines (`crate::pipelines`) names its rows.
//!
//! A new unit is its model (`vectors`), its block (`rtl`), its test file (`testbench/tests`) and its row here; its
//! golden file is generated (`bumprtl vectors <unit>`). The table names both crates, so it lives above them.

use crate::rtl_paths::{AxisPaths, AxisRtl, Rtl, RtlBlock, RtlPaths};

/// A row of the table: the model, the block `T`'s paths, and `T` behind its AXI4-Stream wrapper with the widths
/// worked out from `T`'s ports and latency (a const expression needs the concrete type, hence a macro).
macro_rules! unit {
    ($model:expr, $t:ty) => {
        Unit::new($model, &Rtl::<$t>::PATHS, &AxisRtl::<rtl::axis_of!($t)>::PATHS)
    };
    (map: $model:expr, $t:ty) => {
        Unit::new($model, &Rtl::<$t>::PATHS, &AxisRtl::<rtl::axis_map_of!($t)>::PATHS)
    };
}
use vectors::UnitModel;

/// One unit with an rtl block.
pub struct Unit {
    pub model: &'static UnitModel,
    pub rtl: &'static dyn RtlPaths,
    /// The block behind its AXI4-Stream wrapper.
    pub axis: &'static dyn AxisPaths,
    /// The design's own lint waivers: (signal as `instance$port`, why the Verilog leaves it unused); `waivers()`
    /// reads them with the shared ones.
    own: &'static [(&'static str, &'static str)],
    /// Lists of waivers the unit shares with others (the parts it holds): see `waivers()`.
    shared: &'static [&'static [(&'static str, &'static str)]],
}

impl Unit {
    pub const fn new(model: &'static UnitModel, rtl: &'static dyn RtlPaths, axis: &'static dyn AxisPaths) -> Unit {
        Unit { model, rtl, axis, own: &[], shared: &[] }
    }

    pub const fn waiving(self, own: &'static [(&'static str, &'static str)]) -> Unit {
        Unit { own, ..self }
    }

    /// The waivers of the parts the unit holds, each list written once for every unit holding that part.
    pub const fn sharing(self, shared: &'static [&'static [(&'static str, &'static str)]]) -> Unit {
        Unit { shared, ..self }
    }

    /// Every waiver: the shared lists' and the unit's own.
    pub fn waivers(&self) -> Vec<(&'static str, &'static str)> {
        self.shared.iter().flat_map(|l| l.iter()).chain(self.own).copied().collect()
    }

    /// The unit's name (its model's and its block's: a test holds them alike).
    pub fn name(&self) -> &'static str {
        self.model.name
    }
}

// The lint waivers the pipelines on the texture unit share, a list a part: each pipeline's row names the parts it
// holds (`Unit::sharing`).

/// A per-vertex light path beside the bump path (the host-fed pipelines' `light$valid_out` waiver).
const PER_VERTEX: &[(&str, &str)] = &[
    (
        "light$valid_out",
        "the light path runs in lockstep with the bump path, whose valid is used (as in cart_pipeline)",
    ),
    ("light_norm$valid_out", "as light$valid_out"),
];
/// A bilinear front (`TexBilinear`).
const BILINEAR: &[(&str, &str)] = &[
    ("filter$0$wide", "the front's bilinear units, read rounded as in cart_pipeline"),
    ("filter$1$wide", "as filter$0$wide"),
];
/// A colour map beside a bilinear front.
const COLOUR: &[(&str, &str)] = &[
    ("colour_filter$0$wide", "as filter$0$wide: the front reads each colour unit's rounded byte"),
    ("colour_filter$1$wide", "as colour_filter$0$wide"),
    ("colour_filter$2$wide", "as colour_filter$0$wide"),
    ("colour_fetch$valid_out", "the two fetches run in step: the valid chain follows the bump map's"),
];
/// A nearest-texel front (`TexNearest`, `TexNearestMip`).
const NEAREST: &[(&str, &str)] = &[
    ("addr$ublend", "the nearest texel needs no blend factors (tex_addr gives 0 for linear = 0)"),
    ("addr$vblend", "as addr$ublend"),
    ("fetch$t10", "the nearest texel is the footprint's first, t00; the other three are the bilinear fronts'"),
    ("fetch$t01", "as fetch$t10"),
    ("fetch$t11", "as fetch$t10"),
];
/// A colour map beside a nearest-texel front: the colour texel is the footprint's first, as the bump texel is.
const NEAREST_COLOUR: &[(&str, &str)] = &[
    ("colour_t$1", "the nearest colour texel is the footprint's first, colour_t[0]; the fetch reads four, as fetch"),
    ("colour_t$2", "as colour_t$1"),
    ("colour_t$3", "as colour_t$1"),
    ("colour_fetch$valid_out", "the two fetches run in step: the valid chain follows the bump map's"),
];
/// The LOD unit under a nearest-MIP front.
const NEAREST_MIP: &[(&str, &str)] = &[
    (
        "lod$level",
        "the nearest level is the LOD unit's `nearest`; the floor of lambda and its fraction are trilinear's",
    ),
    ("lod$frac", "as lod$level"),
];
/// A one-clock trilinear front (`TexTrilinear`).
const TRILINEAR: &[(&str, &str)] = &[
    ("lod$nearest", "trilinear reads the floor of lambda and its fraction; the nearest level is nearest_mip's"),
    ("filter$0$wide", "as in cart_tex_bilinear: the front reads each unit's rounded byte"),
    ("filter$1$wide", "as filter$0$wide"),
    ("filter$2$wide", "as filter$0$wide"),
    ("filter$3$wide", "as filter$0$wide"),
    ("fetch_odd$valid_out", "the two fetches run in step: the valid chain follows the even one's"),
];
/// The two-pass trilinear front (`TexTrilinearTwoPass`).
const TRILINEAR_TWO_PASS: &[(&str, &str)] = &[
    ("lod$nearest", "as in a one-clock trilinear front"),
    ("fetch$valid_out", "the front's valid follows each vector's second pass from the address unit, not the fetch's"),
    ("filter$0$wide", "as in cart_tex_bilinear: the front reads each unit's rounded byte"),
    ("filter$1$wide", "as filter$0$wide"),
];

/// Every unit with an rtl block, in the order the command line lists them and `bumprtl accuracy` prints them.
pub static UNITS: &[Unit] = &[
    unit!(&vectors::cart_decode::MODEL, rtl::cart_decode::CartDecode),
    unit!(&vectors::cart_decode_hemi_oct::MODEL, rtl::cart_decode_hemi_oct::CartDecodeHemiOct),
    unit!(&vectors::bilinear::MODEL, rtl::bilinear::Bilinear).waiving(&[
        (
            "unit$0$wide",
            "the colour filter reads each bilinear unit's rounded output; the exact one is the \
            height-map path's",
        ),
        ("unit$1$wide", "as unit$0$wide"),
        ("unit$2$wide", "as unit$0$wide"),
        ("unit$3$wide", "as unit$0$wide"),
    ]),
    unit!(&vectors::light_iter::MODEL, rtl::light_iter::LightIter),
    unit!(&vectors::normalise::MODEL, rtl::normalise::Normalise),
    unit!(&vectors::dot3::MODEL, rtl::dot3::Dot3),
    unit!(&vectors::gloss::MODEL, rtl::gloss::Gloss),
    unit!(&vectors::blend::MODEL, rtl::blend::Blend),
    unit!(&vectors::cart_pipeline::MODEL, rtl::cart_pipeline::CartPipeline).waiving(&[
        ("filter$0$wide", "the texel's components are read rounded, as the colour filter reads them"),
        ("filter$1$wide", "as filter$0$wide"),
        ("light$valid_out", "the light path runs in lockstep with the bump path, whose valid is used"),
        ("light_norm$valid_out", "as light$valid_out"),
    ]),
    unit!(&vectors::cart_pipeline::MODEL_HEMI_OCT, rtl::cart_pipeline::CartPipelineHemiOct).waiving(&[
        ("filter$0$wide", "as in cart_pipeline"),
        ("filter$1$wide", "as filter$0$wide"),
        ("light$valid_out", "as in cart_pipeline: the bump path's valid is used"),
        ("light_norm$valid_out", "as light$valid_out"),
    ]),
    unit!(&vectors::cart_pipeline::MODEL_MATTE, rtl::cart_pipeline::CartPipelineMatte).waiving(&[
        ("filter$0$wide", "as in cart_pipeline"),
        ("filter$1$wide", "as filter$0$wide"),
        ("light$valid_out", "as in cart_pipeline: the bump path's valid is used"),
        ("light_norm$valid_out", "as light$valid_out"),
    ]),
    unit!(&vectors::cart_pipeline::MODEL_HEMI_OCT_MATTE, rtl::cart_pipeline::CartPipelineHemiOctMatte).waiving(&[
        ("filter$0$wide", "as in cart_pipeline"),
        ("filter$1$wide", "as filter$0$wide"),
        ("light$valid_out", "as in cart_pipeline: the bump path's valid is used"),
        ("light_norm$valid_out", "as light$valid_out"),
    ]),
    unit!(&vectors::cart_surface::MODEL, rtl::cart_surface::CartSurface)
        .waiving(&[("filter$0$wide", "as in cart_pipeline"), ("filter$1$wide", "as filter$0$wide")]),
    unit!(&vectors::cart_surface::MODEL_MATTE, rtl::cart_surface::CartSurfaceMatte)
        .waiving(&[("filter$0$wide", "as in cart_pipeline"), ("filter$1$wide", "as filter$0$wide")]),
    unit!(&vectors::cart_surface::MODEL_HEMI_OCT, rtl::cart_surface::CartSurfaceHemiOct)
        .waiving(&[("filter$0$wide", "as in cart_pipeline"), ("filter$1$wide", "as filter$0$wide")]),
    unit!(&vectors::cart_surface::MODEL_HEMI_OCT_MATTE, rtl::cart_surface::CartSurfaceHemiOctMatte)
        .waiving(&[("filter$0$wide", "as in cart_pipeline"), ("filter$1$wide", "as filter$0$wide")]),
    unit!(&vectors::cart_surface::MODEL_NEAREST, rtl::cart_surface::CartSurfaceNearest),
    unit!(&vectors::cart_surface::MODEL_NEAREST_MATTE, rtl::cart_surface::CartSurfaceNearestMatte),
    unit!(&vectors::cart_surface::MODEL_NEAREST_HEMI_OCT, rtl::cart_surface::CartSurfaceNearestHemiOct),
    unit!(&vectors::cart_surface::MODEL_NEAREST_HEMI_OCT_MATTE, rtl::cart_surface::CartSurfaceNearestHemiOctMatte),
    unit!(&vectors::height_addr::MODEL, rtl::height_addr::HeightAddr),
    unit!(map: &vectors::height_fetch::MODEL, rtl::height_fetch::HeightFetch),
    unit!(&vectors::replicate::MODEL, rtl::replicate::Replicate),
    unit!(&vectors::blend_adjust::MODEL, rtl::blend_adjust::BlendAdjust),
    unit!(&vectors::tangent::MODEL, rtl::tangent::Tangent),
    unit!(&vectors::height_normal::MODEL, rtl::height_normal::HeightNormal),
    unit!(&vectors::height_pipeline::MODEL, rtl::height_pipeline::HeightPipeline).waiving(&[
        (
            "unit$0$out",
            "the height path reads each bilinear unit's exact result; the rounded one is the \
            colour filter's",
        ),
        ("unit$1$out", "as unit$0$out"),
        ("unit$2$out", "as unit$0$out"),
        ("unit$3$out", "as unit$0$out"),
    ]),
    unit!(&vectors::texture_filter::MODEL, rtl::texture_filter::TextureFilter),
    unit!(&vectors::blinn_pipeline::MODEL, rtl::blinn_pipeline::BlinnPipeline).waiving(&[
        (
            "unit$0$out",
            "Blinn's function reads each bilinear unit's exact result; the rounded one is the \
            colour filter's",
        ),
        ("unit$1$out", "as unit$0$out"),
        ("unit$2$out", "as unit$0$out"),
    ]),
    unit!(&vectors::palette_lookup::MODEL, rtl::palette_lookup::PaletteLookup<8, 9>),
    unit!(&vectors::table_builder::MODEL, rtl::table_builder::TableBuilder)
        .waiving(&[("diffuse$valid_out", "the two dot products run in lockstep; the highlight's valid is used")]),
    unit!(&vectors::palette_pipeline::MODEL, rtl::palette_pipeline::PalettePipeline<8, 9>)
        .waiving(&[("diffuse$valid_out", "as in table_builder")]),
    unit!(&vectors::palette_pipeline::MODEL_12, rtl::palette_pipeline::PalettePipeline<12, 13>)
        .waiving(&[("diffuse$valid_out", "as in table_builder")]),
    unit!(&vectors::palette_pipeline_shared::MODEL, rtl::palette_pipeline_shared::PalettePipelineShared),
    unit!(&vectors::sincos::MODEL, rtl::sincos::SinCosUnit),
    unit!(&vectors::cos_sign::MODEL, rtl::cos_sign::CosSignUnit),
    unit!(&vectors::polar_shade::MODEL, rtl::polar_shade::PolarShade<false>),
    unit!(&vectors::polar_shade::MODEL_DC, rtl::polar_shade::PolarShade<true>),
    unit!(&vectors::power::MODEL, rtl::power::Power),
    unit!(&vectors::polar_pipeline::MODEL, rtl::polar_pipeline::PolarPipelineSeed).waiving(&[(
        "shader$sum",
        "polar_shade's S11 before the clamp is an output for tests and waveforms; the \
            pipeline uses the clamped shade",
    )]),
    unit!(&vectors::polar_pipeline::MODEL_DC, rtl::polar_pipeline::PolarPipelineDc)
        .waiving(&[("shader$sum", "as in polar_pipeline")]),
    unit!(&vectors::lod::MODEL, rtl::lod::Lod),
    unit!(&vectors::tex_addr::MODEL, rtl::tex_addr::TexAddr),
    unit!(map: &vectors::tex_fetch::MODEL, rtl::tex_fetch::TexFetch),
    unit!(map: &vectors::cart_tex::bilinear::MODEL, rtl::cart_tex::CartTexBilinear).sharing(&[PER_VERTEX, BILINEAR]),
    unit!(map: &vectors::cart_tex::bilinear_matte::MODEL, rtl::cart_tex::CartTexBilinearMatte).sharing(&[PER_VERTEX, BILINEAR]),
    unit!(map: &vectors::cart_tex::nearest_matte::MODEL, rtl::cart_tex::CartTexNearestMatte).sharing(&[PER_VERTEX, NEAREST]),
    unit!(map: &vectors::cart_tex::nearest_mip_matte::MODEL, rtl::cart_tex::CartTexNearestMipMatte).sharing(&[PER_VERTEX, NEAREST, NEAREST_MIP]),
    unit!(map: &vectors::cart_tex::trilinear_matte::MODEL, rtl::cart_tex::CartTexTrilinearMatte).sharing(&[PER_VERTEX, TRILINEAR]),
    unit!(map: &vectors::cart_tex::trilinear::MODEL, rtl::cart_tex::CartTexTrilinear).sharing(&[PER_VERTEX, TRILINEAR]),
    unit!(map: &vectors::cart_tex::trilinear_hemi_oct::MODEL, rtl::cart_tex::CartTexTrilinearHemiOct).sharing(&[PER_VERTEX, TRILINEAR]),
    unit!(map: &vectors::cart_tex::trilinear_surface::MODEL, rtl::cart_tex::CartTexTrilinearSurface).sharing(&[TRILINEAR]),
    unit!(map: &vectors::cart_tex::trilinear_two_pass_matte::MODEL, rtl::cart_tex::CartTexTrilinearTwoPassMatte).sharing(&[PER_VERTEX, TRILINEAR_TWO_PASS]),
    unit!(map: &vectors::cart_tex::bilinear_hemi_oct::MODEL, rtl::cart_tex::CartTexBilinearHemiOct).sharing(&[PER_VERTEX, BILINEAR]),
    unit!(map: &vectors::cart_tex::bilinear_surface::MODEL, rtl::cart_tex::CartTexBilinearSurface).sharing(&[BILINEAR]),
    unit!(map: &vectors::cart_tex::bilinear_surface_matte::MODEL, rtl::cart_tex::CartTexBilinearSurfaceMatte).sharing(&[BILINEAR]),
    unit!(map: &vectors::cart_tex::nearest::MODEL, rtl::cart_tex::CartTexNearest).sharing(&[PER_VERTEX, NEAREST]),
    unit!(map: &vectors::cart_tex::nearest_mip::MODEL, rtl::cart_tex::CartTexNearestMip).sharing(&[PER_VERTEX, NEAREST, NEAREST_MIP]),
    unit!(map: &vectors::cart_tex::bilinear_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexBilinearHemiOctMatte).sharing(&[PER_VERTEX, BILINEAR]),
    unit!(map: &vectors::cart_tex::trilinear_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexTrilinearHemiOctMatte).sharing(&[PER_VERTEX, TRILINEAR]),
    unit!(map: &vectors::cart_tex::trilinear_surface_matte::MODEL, rtl::cart_tex::CartTexTrilinearSurfaceMatte).sharing(&[TRILINEAR]),
    unit!(map: &vectors::cart_tex::bilinear_colour::MODEL, rtl::cart_tex::CartTexBilinearColour).sharing(&[PER_VERTEX, BILINEAR, COLOUR]),
    unit!(map: &vectors::cart_tex::bilinear_surface_colour::MODEL, rtl::cart_tex::CartTexBilinearSurfaceColour).sharing(&[BILINEAR, COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_colour::MODEL, rtl::cart_tex::CartTexNearestColour)
        .sharing(&[PER_VERTEX, NEAREST, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_mip_colour::MODEL, rtl::cart_tex::CartTexNearestMipColour)
        .sharing(&[PER_VERTEX, NEAREST, NEAREST_MIP, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_matte_colour::MODEL, rtl::cart_tex::CartTexNearestMatteColour).sharing(&[PER_VERTEX, NEAREST, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexNearestHemiOctColour).sharing(&[PER_VERTEX, NEAREST, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexNearestHemiOctMatteColour).sharing(&[PER_VERTEX, NEAREST, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_surface_colour::MODEL, rtl::cart_tex::CartTexNearestSurfaceColour).sharing(&[NEAREST, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_surface_matte_colour::MODEL, rtl::cart_tex::CartTexNearestSurfaceMatteColour).sharing(&[NEAREST, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_surface_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexNearestSurfaceHemiOctColour).sharing(&[NEAREST, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_surface_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexNearestSurfaceHemiOctMatteColour).sharing(&[NEAREST, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_mip_matte_colour::MODEL, rtl::cart_tex::CartTexNearestMipMatteColour).sharing(&[PER_VERTEX, NEAREST, NEAREST_MIP, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_mip_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexNearestMipHemiOctColour).sharing(&[PER_VERTEX, NEAREST, NEAREST_MIP, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_mip_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexNearestMipHemiOctMatteColour).sharing(&[PER_VERTEX, NEAREST, NEAREST_MIP, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_colour::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceColour).sharing(&[NEAREST, NEAREST_MIP, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_matte_colour::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceMatteColour).sharing(&[NEAREST, NEAREST_MIP, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceHemiOctColour).sharing(&[NEAREST, NEAREST_MIP, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceHemiOctMatteColour).sharing(&[NEAREST, NEAREST_MIP, NEAREST_COLOUR]),
    unit!(map: &vectors::cart_tex::bilinear_matte_colour::MODEL, rtl::cart_tex::CartTexBilinearMatteColour).sharing(&[PER_VERTEX, BILINEAR, COLOUR]),
    unit!(map: &vectors::cart_tex::bilinear_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexBilinearHemiOctColour).sharing(&[PER_VERTEX, BILINEAR, COLOUR]),
    unit!(map: &vectors::cart_tex::bilinear_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexBilinearHemiOctMatteColour).sharing(&[PER_VERTEX, BILINEAR, COLOUR]),
    unit!(map: &vectors::cart_tex::bilinear_surface_matte_colour::MODEL, rtl::cart_tex::CartTexBilinearSurfaceMatteColour).sharing(&[BILINEAR, COLOUR]),
    unit!(map: &vectors::cart_tex::bilinear_surface_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexBilinearSurfaceHemiOctColour).sharing(&[BILINEAR, COLOUR]),
    unit!(map: &vectors::cart_tex::bilinear_surface_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexBilinearSurfaceHemiOctMatteColour).sharing(&[BILINEAR, COLOUR]),
    unit!(map: &vectors::cart_tex::nearest_surface_matte::MODEL, rtl::cart_tex::CartTexNearestSurfaceMatte).sharing(&[NEAREST]),
    unit!(map: &vectors::cart_tex::nearest_surface_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexNearestSurfaceHemiOctMatte).sharing(&[NEAREST]),
    unit!(map: &vectors::cart_tex::nearest_hemi_oct::MODEL, rtl::cart_tex::CartTexNearestHemiOct).sharing(&[PER_VERTEX, NEAREST]),
    unit!(map: &vectors::cart_tex::nearest_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexNearestHemiOctMatte).sharing(&[PER_VERTEX, NEAREST]),
    unit!(map: &vectors::cart_tex::nearest_surface::MODEL, rtl::cart_tex::CartTexNearestSurface).sharing(&[NEAREST]),
    unit!(map: &vectors::cart_tex::nearest_surface_hemi_oct::MODEL, rtl::cart_tex::CartTexNearestSurfaceHemiOct).sharing(&[NEAREST]),
    unit!(map: &vectors::cart_tex::nearest_mip_hemi_oct::MODEL, rtl::cart_tex::CartTexNearestMipHemiOct).sharing(&[PER_VERTEX, NEAREST, NEAREST_MIP]),
    unit!(map: &vectors::cart_tex::nearest_mip_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexNearestMipHemiOctMatte).sharing(&[PER_VERTEX, NEAREST, NEAREST_MIP]),
    unit!(map: &vectors::cart_tex::nearest_mip_surface::MODEL, rtl::cart_tex::CartTexNearestMipSurface).sharing(&[NEAREST, NEAREST_MIP]),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_matte::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceMatte).sharing(&[NEAREST, NEAREST_MIP]),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_hemi_oct::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceHemiOct).sharing(&[NEAREST, NEAREST_MIP]),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceHemiOctMatte).sharing(&[NEAREST, NEAREST_MIP]),
    unit!(map: &vectors::cart_tex::bilinear_surface_hemi_oct::MODEL, rtl::cart_tex::CartTexBilinearSurfaceHemiOct).sharing(&[BILINEAR]),
    unit!(map: &vectors::cart_tex::bilinear_surface_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexBilinearSurfaceHemiOctMatte).sharing(&[BILINEAR]),
    unit!(map: &vectors::cart_tex::trilinear_surface_hemi_oct::MODEL, rtl::cart_tex::CartTexTrilinearSurfaceHemiOct).sharing(&[TRILINEAR]),
    unit!(map: &vectors::cart_tex::trilinear_surface_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexTrilinearSurfaceHemiOctMatte).sharing(&[TRILINEAR]),
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
