//! The table of units: one row per unit with an rtl block (its bit-exact model and its rtl block, which names the
//! signals its Verilog leaves unused on purpose, `rtl::StreamUnit::waivers`), the software-only units, and one row per swept
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
}

impl Unit {
    pub const fn new(model: &'static UnitModel, rtl: &'static dyn RtlPaths, axis: &'static dyn AxisPaths) -> Unit {
        Unit { model, rtl, axis }
    }

    /// The signals the block's Verilog leaves unused on purpose, each with why (`rtl::StreamUnit::waivers`).
    pub fn waivers(&self) -> Vec<rtl::stream::Waiver> {
        self.rtl.waivers()
    }

    /// The unit's name (its model's and its block's: a test holds them alike).
    pub fn name(&self) -> &'static str {
        self.model.name
    }
}

/// Every unit with an rtl block, in the order the command line lists them and `bumprtl accuracy` prints them.
pub static UNITS: &[Unit] = &[
    unit!(&vectors::cart_decode::MODEL, rtl::cart_decode::CartDecode),
    unit!(&vectors::cart_decode_hemi_oct::MODEL, rtl::cart_decode_hemi_oct::CartDecodeHemiOct),
    unit!(&vectors::bilinear::MODEL, rtl::bilinear::Bilinear),
    unit!(&vectors::light_iter::MODEL, rtl::light_iter::LightIter),
    unit!(&vectors::normalise::MODEL, rtl::normalise::Normalise),
    unit!(&vectors::dot3::MODEL, rtl::dot3::Dot3),
    unit!(&vectors::gloss::MODEL, rtl::gloss::Gloss),
    unit!(&vectors::blend::MODEL, rtl::blend::Blend),
    unit!(&vectors::cart_pipeline::MODEL, rtl::cart_pipeline::CartPipeline),
    unit!(&vectors::cart_pipeline::MODEL_HEMI_OCT, rtl::cart_pipeline::CartPipelineHemiOct),
    unit!(&vectors::cart_pipeline::MODEL_MATTE, rtl::cart_pipeline::CartPipelineMatte),
    unit!(&vectors::cart_pipeline::MODEL_HEMI_OCT_MATTE, rtl::cart_pipeline::CartPipelineHemiOctMatte),
    unit!(&vectors::cart_surface::MODEL, rtl::cart_surface::CartSurface),
    unit!(&vectors::cart_surface::MODEL_MATTE, rtl::cart_surface::CartSurfaceMatte),
    unit!(&vectors::cart_surface::MODEL_HEMI_OCT, rtl::cart_surface::CartSurfaceHemiOct),
    unit!(&vectors::cart_surface::MODEL_HEMI_OCT_MATTE, rtl::cart_surface::CartSurfaceHemiOctMatte),
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
    unit!(&vectors::height_pipeline::MODEL, rtl::height_pipeline::HeightPipeline),
    unit!(&vectors::texture_filter::MODEL, rtl::texture_filter::TextureFilter),
    unit!(&vectors::blinn_pipeline::MODEL, rtl::blinn_pipeline::BlinnPipeline),
    unit!(&vectors::palette_lookup::MODEL, rtl::palette_lookup::PaletteLookup<8, 9>),
    unit!(&vectors::table_builder::MODEL, rtl::table_builder::TableBuilder),
    unit!(&vectors::palette_pipeline::MODEL, rtl::palette_pipeline::PalettePipeline<8, 9>),
    unit!(&vectors::palette_pipeline::MODEL_12, rtl::palette_pipeline::PalettePipeline<12, 13>),
    unit!(&vectors::palette_pipeline_shared::MODEL, rtl::palette_pipeline_shared::PalettePipelineShared),
    unit!(&vectors::sincos::MODEL, rtl::sincos::SinCosUnit),
    unit!(&vectors::cos_sign::MODEL, rtl::cos_sign::CosSignUnit),
    unit!(&vectors::polar_shade::MODEL, rtl::polar_shade::PolarShade<false>),
    unit!(&vectors::polar_shade::MODEL_DC, rtl::polar_shade::PolarShade<true>),
    unit!(&vectors::power::MODEL, rtl::power::Power),
    unit!(&vectors::polar_pipeline::MODEL, rtl::polar_pipeline::PolarPipelineSeed),
    unit!(&vectors::polar_pipeline::MODEL_DC, rtl::polar_pipeline::PolarPipelineDc),
    unit!(&vectors::lod::MODEL, rtl::lod::Lod),
    unit!(&vectors::tex_addr::MODEL, rtl::tex_addr::TexAddr),
    unit!(map: &vectors::tex_fetch::MODEL, rtl::tex_fetch::TexFetch),
    unit!(map: &vectors::cart_tex::bilinear::MODEL, rtl::cart_tex::CartTexBilinear),
    unit!(map: &vectors::cart_tex::bilinear_matte::MODEL, rtl::cart_tex::CartTexBilinearMatte),
    unit!(map: &vectors::cart_tex::nearest_matte::MODEL, rtl::cart_tex::CartTexNearestMatte),
    unit!(map: &vectors::cart_tex::nearest_mip_matte::MODEL, rtl::cart_tex::CartTexNearestMipMatte),
    unit!(map: &vectors::cart_tex::trilinear_matte::MODEL, rtl::cart_tex::CartTexTrilinearMatte),
    unit!(map: &vectors::cart_tex::trilinear::MODEL, rtl::cart_tex::CartTexTrilinear),
    unit!(map: &vectors::cart_tex::trilinear_hemi_oct::MODEL, rtl::cart_tex::CartTexTrilinearHemiOct),
    unit!(map: &vectors::cart_tex::trilinear_surface::MODEL, rtl::cart_tex::CartTexTrilinearSurface),
    unit!(map: &vectors::cart_tex::trilinear_two_pass_matte::MODEL, rtl::cart_tex::CartTexTrilinearTwoPassMatte),
    unit!(map: &vectors::cart_tex::bilinear_hemi_oct::MODEL, rtl::cart_tex::CartTexBilinearHemiOct),
    unit!(map: &vectors::cart_tex::bilinear_surface::MODEL, rtl::cart_tex::CartTexBilinearSurface),
    unit!(map: &vectors::cart_tex::bilinear_surface_matte::MODEL, rtl::cart_tex::CartTexBilinearSurfaceMatte),
    unit!(map: &vectors::cart_tex::nearest::MODEL, rtl::cart_tex::CartTexNearest),
    unit!(map: &vectors::cart_tex::nearest_mip::MODEL, rtl::cart_tex::CartTexNearestMip),
    unit!(map: &vectors::cart_tex::bilinear_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexBilinearHemiOctMatte),
    unit!(map: &vectors::cart_tex::trilinear_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexTrilinearHemiOctMatte),
    unit!(map: &vectors::cart_tex::trilinear_surface_matte::MODEL, rtl::cart_tex::CartTexTrilinearSurfaceMatte),
    unit!(map: &vectors::cart_tex::bilinear_colour::MODEL, rtl::cart_tex::CartTexBilinearColour),
    unit!(map: &vectors::cart_tex::bilinear_surface_colour::MODEL, rtl::cart_tex::CartTexBilinearSurfaceColour),
    unit!(map: &vectors::cart_tex::nearest_colour::MODEL, rtl::cart_tex::CartTexNearestColour),
    unit!(map: &vectors::cart_tex::nearest_mip_colour::MODEL, rtl::cart_tex::CartTexNearestMipColour),
    unit!(map: &vectors::cart_tex::nearest_matte_colour::MODEL, rtl::cart_tex::CartTexNearestMatteColour),
    unit!(map: &vectors::cart_tex::nearest_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexNearestHemiOctColour),
    unit!(map: &vectors::cart_tex::nearest_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexNearestHemiOctMatteColour),
    unit!(map: &vectors::cart_tex::nearest_surface_colour::MODEL, rtl::cart_tex::CartTexNearestSurfaceColour),
    unit!(map: &vectors::cart_tex::nearest_surface_matte_colour::MODEL, rtl::cart_tex::CartTexNearestSurfaceMatteColour),
    unit!(map: &vectors::cart_tex::nearest_surface_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexNearestSurfaceHemiOctColour),
    unit!(map: &vectors::cart_tex::nearest_surface_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexNearestSurfaceHemiOctMatteColour),
    unit!(map: &vectors::cart_tex::nearest_mip_matte_colour::MODEL, rtl::cart_tex::CartTexNearestMipMatteColour),
    unit!(map: &vectors::cart_tex::nearest_mip_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexNearestMipHemiOctColour),
    unit!(map: &vectors::cart_tex::nearest_mip_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexNearestMipHemiOctMatteColour),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_colour::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceColour),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_matte_colour::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceMatteColour),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceHemiOctColour),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceHemiOctMatteColour),
    unit!(map: &vectors::cart_tex::bilinear_matte_colour::MODEL, rtl::cart_tex::CartTexBilinearMatteColour),
    unit!(map: &vectors::cart_tex::bilinear_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexBilinearHemiOctColour),
    unit!(map: &vectors::cart_tex::bilinear_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexBilinearHemiOctMatteColour),
    unit!(map: &vectors::cart_tex::bilinear_surface_matte_colour::MODEL, rtl::cart_tex::CartTexBilinearSurfaceMatteColour),
    unit!(map: &vectors::cart_tex::bilinear_surface_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexBilinearSurfaceHemiOctColour),
    unit!(map: &vectors::cart_tex::bilinear_surface_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexBilinearSurfaceHemiOctMatteColour),
    unit!(map: &vectors::cart_tex::nearest_surface_matte::MODEL, rtl::cart_tex::CartTexNearestSurfaceMatte),
    unit!(map: &vectors::cart_tex::nearest_surface_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexNearestSurfaceHemiOctMatte),
    unit!(map: &vectors::cart_tex::nearest_hemi_oct::MODEL, rtl::cart_tex::CartTexNearestHemiOct),
    unit!(map: &vectors::cart_tex::nearest_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexNearestHemiOctMatte),
    unit!(map: &vectors::cart_tex::nearest_surface::MODEL, rtl::cart_tex::CartTexNearestSurface),
    unit!(map: &vectors::cart_tex::nearest_surface_hemi_oct::MODEL, rtl::cart_tex::CartTexNearestSurfaceHemiOct),
    unit!(map: &vectors::cart_tex::nearest_mip_hemi_oct::MODEL, rtl::cart_tex::CartTexNearestMipHemiOct),
    unit!(map: &vectors::cart_tex::nearest_mip_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexNearestMipHemiOctMatte),
    unit!(map: &vectors::cart_tex::nearest_mip_surface::MODEL, rtl::cart_tex::CartTexNearestMipSurface),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_matte::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceMatte),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_hemi_oct::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceHemiOct),
    unit!(map: &vectors::cart_tex::nearest_mip_surface_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexNearestMipSurfaceHemiOctMatte),
    unit!(map: &vectors::cart_tex::bilinear_surface_hemi_oct::MODEL, rtl::cart_tex::CartTexBilinearSurfaceHemiOct),
    unit!(map: &vectors::cart_tex::bilinear_surface_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexBilinearSurfaceHemiOctMatte),
    unit!(map: &vectors::cart_tex::trilinear_surface_hemi_oct::MODEL, rtl::cart_tex::CartTexTrilinearSurfaceHemiOct),
    unit!(map: &vectors::cart_tex::trilinear_surface_hemi_oct_matte::MODEL, rtl::cart_tex::CartTexTrilinearSurfaceHemiOctMatte),
    unit!(map: &vectors::cart_tex::trilinear_colour::MODEL, rtl::cart_tex::CartTexTrilinearColour),
    unit!(map: &vectors::cart_tex::trilinear_matte_colour::MODEL, rtl::cart_tex::CartTexTrilinearMatteColour),
    unit!(map: &vectors::cart_tex::trilinear_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexTrilinearHemiOctColour),
    unit!(map: &vectors::cart_tex::trilinear_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexTrilinearHemiOctMatteColour),
    unit!(map: &vectors::cart_tex::trilinear_surface_colour::MODEL, rtl::cart_tex::CartTexTrilinearSurfaceColour),
    unit!(map: &vectors::cart_tex::trilinear_surface_matte_colour::MODEL, rtl::cart_tex::CartTexTrilinearSurfaceMatteColour),
    unit!(map: &vectors::cart_tex::trilinear_surface_hemi_oct_colour::MODEL, rtl::cart_tex::CartTexTrilinearSurfaceHemiOctColour),
    unit!(map: &vectors::cart_tex::trilinear_surface_hemi_oct_matte_colour::MODEL, rtl::cart_tex::CartTexTrilinearSurfaceHemiOctMatteColour),
    unit!(map: &vectors::polar_tex::bilinear::MODEL, rtl::polar_tex::PolarTexBilinear),
    unit!(map: &vectors::polar_tex::trilinear::MODEL, rtl::polar_tex::PolarTexTrilinear),
    unit!(map: &vectors::palette_tex::nearest::MODEL, rtl::palette_tex::PaletteTexNearest),
    unit!(map: &vectors::palette_tex::nearest_mip::MODEL, rtl::palette_tex::PaletteTexNearestMip),
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
