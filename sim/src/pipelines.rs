//! The table of pipelines: one row per rtl pipeline the project builds, with everything that names it (its unit
//! name, family, label, the units it holds) and the scene choices it serves; its bit-exact model and its rtl block
//! are its unit's row in the table of units (`crate::units`).
//! Every consumer chooses through it: the scene reader (`crate::scene_file`) turns a scene's choices into a row
//! with `choose`, the command line's `render`, `demo`, `verilog --scene`, `synth --scene` and `report` read the
//! row, and `crate::pipeline::build` makes a row's `Pipeline` (the family's behaviour: set-up, shade, colour).
//!
//! A new pipeline is its rtl top, its model, its test, its row in the table of units and its row here (and, for a
//! new family, its `Pipeline` implementation). A test keeps every row reachable from exactly one combination of scene
//! choices.

use crate::rtl_paths::RtlPaths;
use crate::scene::Scene;
use crate::units::Unit;
use serde::Deserialize;
use vectors::cart_pipeline::Decode;
use vectors::cart_surface::Variant;
use vectors::polar_encode::Scale;
use vectors::UnitModel;

/// The bump map's encoding, which chooses the family: US 6,819,319's Cartesian texels (the seed's, or hemi-oct with
/// its decode), US 6,819,319's polar texels (the seed's 256 steps or the Dreamcast toolchains' 255), US 2004/0207631's
/// 8-bit
/// heights, Tarini et al.'s palette.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum Encoding {
    #[default]
    Seed,
    HemiOct,
    Polar,
    PolarDc255,
    Heights,
    Palette,
}

/// How the texels are filtered.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum Filter {
    #[default]
    Bilinear,
    /// the texel nearest the sample, no filter (the Cartesian pipelines with one light per surface, and on the
    /// texture unit)
    Nearest,
    /// the nearest texel of the nearest MIP level (the texture unit's LOD unit picks it)
    NearestMip,
    /// bilinear on the two MIP levels round λ, blended by its fraction (the texture unit's LOD unit)
    Trilinear,
    /// trilinear, its two levels read in two passes of one set of the texture unit's blocks: a pixel every other
    /// clock, for fewer units (the same pixels as `Trilinear`)
    TrilinearTwoPass,
}

impl Filter {
    /// Its name in a scene file.
    pub const fn name(self) -> &'static str {
        match self {
            Filter::Bilinear => "bilinear",
            Filter::Nearest => "nearest",
            Filter::NearestMip => "nearest_mip",
            Filter::Trilinear => "trilinear",
            Filter::TrilinearTwoPass => "trilinear_two_pass",
        }
    }

    /// The texture unit's front for this filter.
    pub const fn front(self) -> vectors::texture::front::Filter {
        use vectors::texture::front::Filter as F;
        match self {
            Filter::Bilinear => F::Bilinear,
            Filter::Nearest => F::Nearest,
            Filter::NearestMip => F::NearestMip,
            Filter::Trilinear | Filter::TrilinearTwoPass => F::Trilinear,
        }
    }
}

/// Who fetches the texels: the texture unit from its memory (u, v and their derivatives in), or the host (texels
/// and blend factors in).
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum Fetch {
    #[default]
    Unit,
    Host,
}

/// Where the light is taken.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum Per {
    /// one light direction per vertex, interpolated per pixel (the light iterator)
    #[default]
    Vertex,
    /// one light for the whole surface, its direction at the surface's centre
    Surface,
}

/// The scene choices that pick a pipeline. The scene reader fills them as the chosen pipeline holds them: the
/// polar, height and palette pipelines light a surface with one light and filter bilinearly (the palette's
/// nearest texel is its own method, not a choice), the palette pipelines always hold the gloss unit, the polar and
/// height ones never; `index_bits` is the palette's (8: s_N ≤ 256, 12: ≤ 4,096) and 0 elsewhere; `colour`: the
/// blend's destination colour from a colour map (`[material] colour_map`, on the texture unit) rather than a
/// constant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Choices {
    pub encoding: Encoding,
    pub per: Per,
    pub gloss: bool,
    pub filter: Filter,
    pub index_bits: u32,
    pub fetch: Fetch,
    pub colour: bool,
}

impl Choices {
    /// The choices in a scene file's words.
    pub fn describe(&self) -> String {
        let enc = match self.encoding {
            Encoding::Seed => "seed",
            Encoding::HemiOct => "hemi_oct",
            Encoding::Polar => "polar",
            Encoding::PolarDc255 => "polar_dc255",
            Encoding::Heights => "heights",
            Encoding::Palette => "palette",
        };
        let per = if self.per == Per::Vertex { "vertex" } else { "surface" };
        let gloss = if self.gloss { "a gloss" } else { "gloss = 0" };
        let colour = if self.colour { ", a colour map" } else { "" };
        format!("encoding {enc}, per = \"{per}\", {gloss}, filter = \"{}\"{colour}", self.filter.name())
    }
}

/// A pipeline family: the rows that share one `Pipeline` implementation, with the family's own parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// US 6,819,319's second embodiment, lights per vertex
    Cartesian(Decode),
    /// US 6,819,319's Cartesian path with one light per surface
    CartSurface(Variant),
    /// a Cartesian pipeline (the host-fed row named `host`) on the texture unit, with this filter
    CartTex { host: &'static str, filter: Filter },
    /// US 6,819,319's first embodiment (FIG. 3)
    Polar(Scale),
    /// US 2004/0207631's height map
    Height,
    /// Tarini et al.
    Palette,
}

/// One pipeline.
pub struct Row {
    /// its unit's name in the table of units (the model's and the block's)
    pub name: &'static str,
    pub family: Family,
    /// a short name for tables
    pub label: &'static str,
    /// the units it holds, in dataflow order, by their names in the unit table
    pub units: &'static [&'static str],
    /// the one combination of scene choices it serves
    pub serves: Choices,
}

impl std::fmt::Debug for Row {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Row({})", self.name)
    }
}

impl PartialEq for Row {
    fn eq(&self, other: &Row) -> bool {
        self.name == other.name
    }
}

impl Row {
    /// Its row in the table of units.
    pub fn unit(&self) -> &'static Unit {
        crate::units::find(self.name).expect("every pipeline is a unit of the table (a test holds it)")
    }

    /// The bit-exact model of the whole pipeline.
    pub fn model(&self) -> &'static UnitModel {
        self.unit().model
    }

    /// The rtl block, behind the paths that need its type.
    pub fn rtl(&self) -> &'static dyn RtlPaths {
        self.unit().rtl
    }

    /// Whether the pipeline can render the scene as the scene asks: the height and palette pipelines only a quad
    /// (an address unit walking one flat map; a colour table of one light a frame), a Cartesian pipeline without
    /// the gloss unit only a matte material (C = 0), a pipeline with a colour path only a scene with a colour map.
    pub fn renders(&self, scene: &Scene) -> bool {
        match self.family {
            Family::Cartesian(_) | Family::CartSurface(_) => self.serves.gloss || scene.conc == 0,
            // the memory holds a map of side 2^0 … 2^7 and its chain
            Family::CartTex { host, .. } => {
                // a polar host has no gloss unit and takes no C (its power unit is the specular term)
                let polar = named(host).is_some_and(|h| matches!(h.family, Family::Polar(_)));
                // a palette host's table holds one light a frame: a flat surface's, as the host-fed one
                let palette = named(host).is_some_and(|h| h.family == Family::Palette);
                (self.serves.gloss || scene.conc == 0 || polar)
                    && !(palette && scene.curved.is_some())
                    && scene.tex.is_power_of_two()
                    && scene.tex <= 1 << vectors::tex_fetch::MAX_LOG_SIDE
                    && (!self.serves.colour || scene.colour_map.as_ref().is_some_and(|c| c.side == scene.tex))
            }
            Family::Polar(_) => true,
            Family::Height | Family::Palette => scene.curved.is_none(),
        }
    }
}

/// The row that serves these choices, if one does.
pub fn choose(c: &Choices) -> Option<&'static Row> {
    PIPELINES.iter().find(|r| r.serves == *c)
}

/// The row of the pipeline called `name`.
pub fn named(name: &str) -> Option<&'static Row> {
    PIPELINES.iter().find(|r| r.name == name)
}

/// A Cartesian pipeline's choices: its texels, where its light is taken, its gloss unit, its filter.
pub const fn cartesian(decode: Decode, per: Per, gloss: bool, filter: Filter) -> Choices {
    let encoding = match decode {
        Decode::Seed => Encoding::Seed,
        Decode::HemiOct => Encoding::HemiOct,
    };
    Choices { encoding, per, gloss, filter, index_bits: 0, fetch: Fetch::Host, colour: false }
}

/// A Cartesian pipeline with one light per surface: its variant's choices.
pub const fn surface(v: Variant) -> Choices {
    cartesian(v.decode, Per::Surface, v.gloss, if v.nearest { Filter::Nearest } else { Filter::Bilinear })
}

/// The choices of a pipeline that lights a surface with one light and filters bilinearly, fed by the host (the
/// polar, height and palette pipelines).
pub const fn one_light(encoding: Encoding, gloss: bool, index_bits: u32) -> Choices {
    Choices {
        encoding,
        per: Per::Surface,
        gloss,
        filter: Filter::Bilinear,
        index_bits,
        fetch: Fetch::Host,
        colour: false,
    }
}

/// The polar pipeline's choices at this angle scale.
pub const fn polar(scale: Scale) -> Choices {
    let encoding = match scale {
        Scale::Seed => Encoding::Polar,
        Scale::Dc255 => Encoding::PolarDc255,
    };
    one_light(encoding, false, 0)
}

/// The height pipeline's choices.
pub const fn height() -> Choices {
    one_light(Encoding::Heights, false, 0)
}

/// The palette pipeline's choices for a palette of `s_n` normals.
pub fn palette(s_n: usize) -> Choices {
    one_light(Encoding::Palette, true, palette_index_bits(s_n))
}

const fn cart(
    name: &'static str,
    label: &'static str,
    decode: Decode,
    gloss: bool,
    units: &'static [&'static str],
) -> Row {
    let serves = cartesian(decode, Per::Vertex, gloss, Filter::Bilinear);
    Row { name, family: Family::Cartesian(decode), label, units, serves }
}

const fn surf(name: &'static str, label: &'static str, v: Variant, units: &'static [&'static str]) -> Row {
    Row { name, family: Family::CartSurface(v), label, units, serves: surface(v) }
}

/// A pipeline on the texture unit (Cartesian, polar or palette): its host-fed row's choices, fetched by the unit
/// with this filter.
const fn tex(
    name: &'static str,
    label: &'static str,
    host: &'static str,
    host_serves: Choices,
    filter: Filter,
    units: &'static [&'static str],
) -> Row {
    let serves = Choices { filter, fetch: Fetch::Unit, ..host_serves };
    Row { name, family: Family::CartTex { host, filter }, label, units, serves }
}

/// The same with a colour map: the blend's destination colour from the front's second memory.
const fn tex_colour(
    name: &'static str,
    label: &'static str,
    host: &'static str,
    host_serves: Choices,
    filter: Filter,
    units: &'static [&'static str],
) -> Row {
    let row = tex(name, label, host, host_serves, filter, units);
    Row { serves: Choices { colour: true, ..row.serves }, ..row }
}

const S: Decode = Decode::Seed;
const H: Decode = Decode::HemiOct;
const fn v(decode: Decode, nearest: bool, gloss: bool) -> Variant {
    Variant { decode, nearest, gloss }
}

/// Every pipeline, in the report's order.
pub static PIPELINES: &[Row] = &[
    cart(
        "cart_pipeline",
        "Cartesian",
        S,
        true,
        &["bilinear", "cart_decode", "normalise", "light_iter", "dot3", "gloss", "blend"],
    ),
    cart(
        "cart_pipeline_hemi_oct",
        "hemi-oct",
        H,
        true,
        &["bilinear", "cart_decode_hemi_oct", "normalise", "light_iter", "dot3", "gloss", "blend"],
    ),
    cart(
        "cart_pipeline_matte",
        "Cartesian, matte",
        S,
        false,
        &["bilinear", "cart_decode", "normalise", "light_iter", "dot3", "blend"],
    ),
    cart(
        "cart_pipeline_hemi_oct_matte",
        "hemi-oct, matte",
        H,
        false,
        &["bilinear", "cart_decode_hemi_oct", "normalise", "light_iter", "dot3", "blend"],
    ),
    surf(
        "cart_surface",
        "Cartesian, one light",
        v(S, false, true),
        &["bilinear", "cart_decode", "normalise", "dot3", "gloss", "blend"],
    ),
    surf(
        "cart_surface_matte",
        "Cartesian, one light, matte",
        v(S, false, false),
        &["bilinear", "cart_decode", "normalise", "dot3", "blend"],
    ),
    surf(
        "cart_surface_hemi_oct",
        "hemi-oct, one light",
        v(H, false, true),
        &["bilinear", "cart_decode_hemi_oct", "normalise", "dot3", "gloss", "blend"],
    ),
    surf(
        "cart_surface_hemi_oct_matte",
        "hemi-oct, one light, matte",
        v(H, false, false),
        &["bilinear", "cart_decode_hemi_oct", "normalise", "dot3", "blend"],
    ),
    surf(
        "cart_surface_nearest",
        "Cartesian, nearest, one light",
        v(S, true, true),
        &["cart_decode", "normalise", "dot3", "gloss", "blend"],
    ),
    surf(
        "cart_surface_nearest_matte",
        "Cartesian, nearest, one light, matte",
        v(S, true, false),
        &["cart_decode", "normalise", "dot3", "blend"],
    ),
    surf(
        "cart_surface_nearest_hemi_oct",
        "hemi-oct, nearest, one light",
        v(H, true, true),
        &["cart_decode_hemi_oct", "normalise", "dot3", "gloss", "blend"],
    ),
    surf(
        "cart_surface_nearest_hemi_oct_matte",
        "hemi-oct, nearest, one light, matte",
        v(H, true, false),
        &["cart_decode_hemi_oct", "normalise", "dot3", "blend"],
    ),
    tex(
        "cart_tex_bilinear",
        "Cartesian, texture unit, bilinear",
        "cart_pipeline",
        cartesian(S, Per::Vertex, true, Filter::Bilinear),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "light_iter", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_bilinear_matte",
        "Cartesian, matte, texture unit, bilinear",
        "cart_pipeline_matte",
        cartesian(S, Per::Vertex, false, Filter::Bilinear),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex(
        "cart_tex_nearest_matte",
        "Cartesian, matte, texture unit, nearest",
        "cart_pipeline_matte",
        cartesian(S, Per::Vertex, false, Filter::Bilinear),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex(
        "cart_tex_nearest_mip_matte",
        "Cartesian, matte, texture unit, nearest MIP level",
        "cart_pipeline_matte",
        cartesian(S, Per::Vertex, false, Filter::Bilinear),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex(
        "cart_tex_trilinear_matte",
        "Cartesian, matte, texture unit, trilinear",
        "cart_pipeline_matte",
        cartesian(S, Per::Vertex, false, Filter::Bilinear),
        Filter::Trilinear,
        &["lod", "tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex(
        "cart_tex_trilinear",
        "Cartesian, texture unit, trilinear",
        "cart_pipeline",
        cartesian(S, Per::Vertex, true, Filter::Bilinear),
        Filter::Trilinear,
        &[
            "lod",
            "tex_addr",
            "tex_fetch",
            "bilinear",
            "cart_decode",
            "normalise",
            "light_iter",
            "dot3",
            "gloss",
            "blend",
        ],
    ),
    tex(
        "cart_tex_trilinear_hemi_oct",
        "hemi-oct, texture unit, trilinear",
        "cart_pipeline_hemi_oct",
        cartesian(H, Per::Vertex, true, Filter::Bilinear),
        Filter::Trilinear,
        &[
            "lod",
            "tex_addr",
            "tex_fetch",
            "bilinear",
            "cart_decode_hemi_oct",
            "normalise",
            "light_iter",
            "dot3",
            "gloss",
            "blend",
        ],
    ),
    tex(
        "cart_tex_trilinear_surface",
        "Cartesian, one light, texture unit, trilinear",
        "cart_surface",
        surface(v(S, false, true)),
        Filter::Trilinear,
        &["lod", "tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_trilinear_two_pass_matte",
        "Cartesian, matte, texture unit, trilinear in two passes (2 clocks a pixel)",
        "cart_pipeline_matte",
        cartesian(S, Per::Vertex, false, Filter::Bilinear),
        Filter::TrilinearTwoPass,
        &["lod", "tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex(
        "cart_tex_bilinear_hemi_oct",
        "hemi-oct, texture unit, bilinear",
        "cart_pipeline_hemi_oct",
        cartesian(H, Per::Vertex, true, Filter::Bilinear),
        Filter::Bilinear,
        &[
            "tex_addr",
            "tex_fetch",
            "bilinear",
            "cart_decode_hemi_oct",
            "normalise",
            "light_iter",
            "dot3",
            "gloss",
            "blend",
        ],
    ),
    tex(
        "cart_tex_bilinear_surface",
        "Cartesian, one light, texture unit, bilinear",
        "cart_surface",
        surface(v(S, false, true)),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_bilinear_surface_matte",
        "Cartesian, one light, matte, texture unit, bilinear",
        "cart_surface_matte",
        surface(v(S, false, false)),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "dot3", "blend"],
    ),
    tex(
        "cart_tex_nearest_surface_matte",
        "Cartesian, one light, matte, texture unit, nearest",
        "cart_surface_matte",
        surface(v(S, false, false)),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode", "normalise", "dot3", "blend"],
    ),
    tex(
        "cart_tex_nearest_surface_hemi_oct_matte",
        "hemi-oct, one light, matte, texture unit, nearest",
        "cart_surface_hemi_oct_matte",
        surface(v(H, false, false)),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "dot3", "blend"],
    ),
    tex(
        "cart_tex_nearest",
        "Cartesian, texture unit, nearest",
        "cart_pipeline",
        cartesian(S, Per::Vertex, true, Filter::Bilinear),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode", "normalise", "light_iter", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_nearest_mip",
        "Cartesian, texture unit, nearest MIP level",
        "cart_pipeline",
        cartesian(S, Per::Vertex, true, Filter::Bilinear),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode", "normalise", "light_iter", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_bilinear_hemi_oct_matte",
        "hemi-oct, matte, texture unit, bilinear",
        "cart_pipeline_hemi_oct_matte",
        cartesian(H, Per::Vertex, false, Filter::Bilinear),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode_hemi_oct", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex(
        "cart_tex_trilinear_hemi_oct_matte",
        "hemi-oct, matte, texture unit, trilinear",
        "cart_pipeline_hemi_oct_matte",
        cartesian(H, Per::Vertex, false, Filter::Bilinear),
        Filter::Trilinear,
        &[
            "lod",
            "tex_addr",
            "tex_fetch",
            "bilinear",
            "cart_decode_hemi_oct",
            "normalise",
            "light_iter",
            "dot3",
            "blend",
        ],
    ),
    tex(
        "cart_tex_trilinear_surface_matte",
        "Cartesian, one light, matte, texture unit, trilinear",
        "cart_surface_matte",
        surface(v(S, false, false)),
        Filter::Trilinear,
        &["lod", "tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_bilinear_colour",
        "Cartesian, texture unit, bilinear, colour map",
        "cart_pipeline",
        cartesian(S, Per::Vertex, true, Filter::Bilinear),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "light_iter", "dot3", "gloss", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_colour",
        "Cartesian, texture unit, nearest, colour map",
        "cart_pipeline",
        cartesian(S, Per::Vertex, true, Filter::Bilinear),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode", "normalise", "light_iter", "dot3", "gloss", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_mip_colour",
        "Cartesian, texture unit, nearest MIP level, colour map",
        "cart_pipeline",
        cartesian(S, Per::Vertex, true, Filter::Bilinear),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode", "normalise", "light_iter", "dot3", "gloss", "blend"],
    ),
    tex_colour(
        "cart_tex_bilinear_surface_colour",
        "Cartesian, one light, texture unit, bilinear, colour map",
        "cart_surface",
        surface(v(S, false, true)),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_nearest_hemi_oct",
        "hemi-oct, texture unit, nearest",
        "cart_pipeline_hemi_oct",
        cartesian(H, Per::Vertex, true, Filter::Bilinear),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "light_iter", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_nearest_hemi_oct_matte",
        "hemi-oct, matte, texture unit, nearest",
        "cart_pipeline_hemi_oct_matte",
        cartesian(H, Per::Vertex, false, Filter::Bilinear),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex(
        "cart_tex_nearest_surface",
        "Cartesian, one light, texture unit, nearest",
        "cart_surface",
        surface(v(S, false, true)),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode", "normalise", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_nearest_surface_hemi_oct",
        "hemi-oct, one light, texture unit, nearest",
        "cart_surface_hemi_oct",
        surface(v(H, false, true)),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_nearest_mip_hemi_oct",
        "hemi-oct, texture unit, nearest MIP level",
        "cart_pipeline_hemi_oct",
        cartesian(H, Per::Vertex, true, Filter::Bilinear),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "light_iter", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_nearest_mip_hemi_oct_matte",
        "hemi-oct, matte, texture unit, nearest MIP level",
        "cart_pipeline_hemi_oct_matte",
        cartesian(H, Per::Vertex, false, Filter::Bilinear),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex(
        "cart_tex_nearest_mip_surface",
        "Cartesian, one light, texture unit, nearest MIP level",
        "cart_surface",
        surface(v(S, false, true)),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode", "normalise", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_nearest_mip_surface_matte",
        "Cartesian, one light, matte, texture unit, nearest MIP level",
        "cart_surface_matte",
        surface(v(S, false, false)),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode", "normalise", "dot3", "blend"],
    ),
    tex(
        "cart_tex_nearest_mip_surface_hemi_oct",
        "hemi-oct, one light, texture unit, nearest MIP level",
        "cart_surface_hemi_oct",
        surface(v(H, false, true)),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_nearest_mip_surface_hemi_oct_matte",
        "hemi-oct, one light, matte, texture unit, nearest MIP level",
        "cart_surface_hemi_oct_matte",
        surface(v(H, false, false)),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "dot3", "blend"],
    ),
    tex(
        "cart_tex_bilinear_surface_hemi_oct",
        "hemi-oct, one light, texture unit, bilinear",
        "cart_surface_hemi_oct",
        surface(v(H, false, true)),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode_hemi_oct", "normalise", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_bilinear_surface_hemi_oct_matte",
        "hemi-oct, one light, matte, texture unit, bilinear",
        "cart_surface_hemi_oct_matte",
        surface(v(H, false, false)),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode_hemi_oct", "normalise", "dot3", "blend"],
    ),
    tex(
        "cart_tex_trilinear_surface_hemi_oct",
        "hemi-oct, one light, texture unit, trilinear",
        "cart_surface_hemi_oct",
        surface(v(H, false, true)),
        Filter::Trilinear,
        &["lod", "tex_addr", "tex_fetch", "bilinear", "cart_decode_hemi_oct", "normalise", "dot3", "gloss", "blend"],
    ),
    tex(
        "cart_tex_trilinear_surface_hemi_oct_matte",
        "hemi-oct, one light, matte, texture unit, trilinear",
        "cart_surface_hemi_oct_matte",
        surface(v(H, false, false)),
        Filter::Trilinear,
        &["lod", "tex_addr", "tex_fetch", "bilinear", "cart_decode_hemi_oct", "normalise", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_matte_colour",
        "Cartesian, matte, texture unit, nearest, colour map",
        "cart_pipeline_matte",
        cartesian(S, Per::Vertex, false, Filter::Bilinear),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_hemi_oct_colour",
        "hemi-oct, texture unit, nearest, colour map",
        "cart_pipeline_hemi_oct",
        cartesian(H, Per::Vertex, true, Filter::Bilinear),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "light_iter", "dot3", "gloss", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_hemi_oct_matte_colour",
        "hemi-oct, matte, texture unit, nearest, colour map",
        "cart_pipeline_hemi_oct_matte",
        cartesian(H, Per::Vertex, false, Filter::Bilinear),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_surface_colour",
        "Cartesian, one light, texture unit, nearest, colour map",
        "cart_surface",
        surface(v(S, false, true)),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode", "normalise", "dot3", "gloss", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_surface_matte_colour",
        "Cartesian, one light, matte, texture unit, nearest, colour map",
        "cart_surface_matte",
        surface(v(S, false, false)),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode", "normalise", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_surface_hemi_oct_colour",
        "hemi-oct, one light, texture unit, nearest, colour map",
        "cart_surface_hemi_oct",
        surface(v(H, false, true)),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "dot3", "gloss", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_surface_hemi_oct_matte_colour",
        "hemi-oct, one light, matte, texture unit, nearest, colour map",
        "cart_surface_hemi_oct_matte",
        surface(v(H, false, false)),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_mip_matte_colour",
        "Cartesian, matte, texture unit, nearest MIP level, colour map",
        "cart_pipeline_matte",
        cartesian(S, Per::Vertex, false, Filter::Bilinear),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_mip_hemi_oct_colour",
        "hemi-oct, texture unit, nearest MIP level, colour map",
        "cart_pipeline_hemi_oct",
        cartesian(H, Per::Vertex, true, Filter::Bilinear),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "light_iter", "dot3", "gloss", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_mip_hemi_oct_matte_colour",
        "hemi-oct, matte, texture unit, nearest MIP level, colour map",
        "cart_pipeline_hemi_oct_matte",
        cartesian(H, Per::Vertex, false, Filter::Bilinear),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_mip_surface_colour",
        "Cartesian, one light, texture unit, nearest MIP level, colour map",
        "cart_surface",
        surface(v(S, false, true)),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode", "normalise", "dot3", "gloss", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_mip_surface_matte_colour",
        "Cartesian, one light, matte, texture unit, nearest MIP level, colour map",
        "cart_surface_matte",
        surface(v(S, false, false)),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode", "normalise", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_mip_surface_hemi_oct_colour",
        "hemi-oct, one light, texture unit, nearest MIP level, colour map",
        "cart_surface_hemi_oct",
        surface(v(H, false, true)),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "dot3", "gloss", "blend"],
    ),
    tex_colour(
        "cart_tex_nearest_mip_surface_hemi_oct_matte_colour",
        "hemi-oct, one light, matte, texture unit, nearest MIP level, colour map",
        "cart_surface_hemi_oct_matte",
        surface(v(H, false, false)),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "cart_decode_hemi_oct", "normalise", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_bilinear_matte_colour",
        "Cartesian, matte, texture unit, bilinear, colour map",
        "cart_pipeline_matte",
        cartesian(S, Per::Vertex, false, Filter::Bilinear),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_bilinear_hemi_oct_colour",
        "hemi-oct, texture unit, bilinear, colour map",
        "cart_pipeline_hemi_oct",
        cartesian(H, Per::Vertex, true, Filter::Bilinear),
        Filter::Bilinear,
        &[
            "tex_addr",
            "tex_fetch",
            "bilinear",
            "cart_decode_hemi_oct",
            "normalise",
            "light_iter",
            "dot3",
            "gloss",
            "blend",
        ],
    ),
    tex_colour(
        "cart_tex_bilinear_hemi_oct_matte_colour",
        "hemi-oct, matte, texture unit, bilinear, colour map",
        "cart_pipeline_hemi_oct_matte",
        cartesian(H, Per::Vertex, false, Filter::Bilinear),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode_hemi_oct", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_bilinear_surface_matte_colour",
        "Cartesian, one light, matte, texture unit, bilinear, colour map",
        "cart_surface_matte",
        surface(v(S, false, false)),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_bilinear_surface_hemi_oct_colour",
        "hemi-oct, one light, texture unit, bilinear, colour map",
        "cart_surface_hemi_oct",
        surface(v(H, false, true)),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode_hemi_oct", "normalise", "dot3", "gloss", "blend"],
    ),
    tex_colour(
        "cart_tex_bilinear_surface_hemi_oct_matte_colour",
        "hemi-oct, one light, matte, texture unit, bilinear, colour map",
        "cart_surface_hemi_oct_matte",
        surface(v(H, false, false)),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "cart_decode_hemi_oct", "normalise", "dot3", "blend"],
    ),
    Row {
        name: "polar_pipeline",
        family: Family::Polar(Scale::Seed),
        label: "polar",
        units: &["polar_shade", "power", "blend"],
        serves: one_light(Encoding::Polar, false, 0),
    },
    Row {
        name: "polar_pipeline_dc",
        family: Family::Polar(Scale::Dc255),
        label: "polar",
        units: &["polar_shade_dc", "power", "blend"],
        serves: one_light(Encoding::PolarDc255, false, 0),
    },
    tex(
        "polar_tex_bilinear",
        "polar, texture unit, bilinear",
        "polar_pipeline",
        polar(Scale::Seed),
        Filter::Bilinear,
        &["tex_addr", "tex_fetch", "bilinear", "polar_shade", "power", "blend"],
    ),
    tex(
        "polar_tex_trilinear",
        "polar, texture unit, trilinear",
        "polar_pipeline",
        polar(Scale::Seed),
        Filter::Trilinear,
        &["lod", "tex_addr", "tex_fetch", "bilinear", "polar_shade", "power", "blend"],
    ),
    Row {
        name: "height_pipeline",
        family: Family::Height,
        label: "height map",
        units: &["replicate", "blend_adjust", "bilinear", "tangent", "height_normal", "normalise"],
        serves: one_light(Encoding::Heights, false, 0),
    },
    Row {
        name: "palette_pipeline",
        family: Family::Palette,
        label: "palette 256",
        units: &["normalise", "dot3", "gloss", "palette_lookup"],
        serves: one_light(Encoding::Palette, true, 8),
    },
    Row {
        name: "palette_pipeline_12",
        family: Family::Palette,
        label: "palette 4096",
        units: &["normalise", "dot3", "gloss", "palette_lookup"],
        serves: one_light(Encoding::Palette, true, 12),
    },
    tex(
        "palette_tex_nearest",
        "palette 256, texture unit, nearest",
        "palette_pipeline",
        one_light(Encoding::Palette, true, 8),
        Filter::Nearest,
        &["tex_addr", "tex_fetch", "normalise", "dot3", "gloss", "palette_lookup"],
    ),
    tex(
        "palette_tex_nearest_mip",
        "palette 256, texture unit, nearest MIP level",
        "palette_pipeline",
        one_light(Encoding::Palette, true, 8),
        Filter::NearestMip,
        &["lod", "tex_addr", "tex_fetch", "normalise", "dot3", "gloss", "palette_lookup"],
    ),
    tex_colour(
        "cart_tex_trilinear_colour",
        "Cartesian, texture unit, trilinear, colour map",
        "cart_pipeline",
        cartesian(S, Per::Vertex, true, Filter::Bilinear),
        Filter::Trilinear,
        &[
            "lod",
            "tex_addr",
            "tex_fetch",
            "bilinear",
            "cart_decode",
            "normalise",
            "light_iter",
            "dot3",
            "gloss",
            "blend",
        ],
    ),
    tex_colour(
        "cart_tex_trilinear_matte_colour",
        "Cartesian, matte, texture unit, trilinear, colour map",
        "cart_pipeline_matte",
        cartesian(S, Per::Vertex, false, Filter::Bilinear),
        Filter::Trilinear,
        &["lod", "tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "light_iter", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_trilinear_hemi_oct_colour",
        "hemi-oct, texture unit, trilinear, colour map",
        "cart_pipeline_hemi_oct",
        cartesian(H, Per::Vertex, true, Filter::Bilinear),
        Filter::Trilinear,
        &[
            "lod",
            "tex_addr",
            "tex_fetch",
            "bilinear",
            "cart_decode_hemi_oct",
            "normalise",
            "light_iter",
            "dot3",
            "gloss",
            "blend",
        ],
    ),
    tex_colour(
        "cart_tex_trilinear_hemi_oct_matte_colour",
        "hemi-oct, matte, texture unit, trilinear, colour map",
        "cart_pipeline_hemi_oct_matte",
        cartesian(H, Per::Vertex, false, Filter::Bilinear),
        Filter::Trilinear,
        &[
            "lod",
            "tex_addr",
            "tex_fetch",
            "bilinear",
            "cart_decode_hemi_oct",
            "normalise",
            "light_iter",
            "dot3",
            "blend",
        ],
    ),
    tex_colour(
        "cart_tex_trilinear_surface_colour",
        "Cartesian, one light, texture unit, trilinear, colour map",
        "cart_surface",
        surface(v(S, false, true)),
        Filter::Trilinear,
        &["lod", "tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "dot3", "gloss", "blend"],
    ),
    tex_colour(
        "cart_tex_trilinear_surface_matte_colour",
        "Cartesian, one light, matte, texture unit, trilinear, colour map",
        "cart_surface_matte",
        surface(v(S, false, false)),
        Filter::Trilinear,
        &["lod", "tex_addr", "tex_fetch", "bilinear", "cart_decode", "normalise", "dot3", "blend"],
    ),
    tex_colour(
        "cart_tex_trilinear_surface_hemi_oct_colour",
        "hemi-oct, one light, texture unit, trilinear, colour map",
        "cart_surface_hemi_oct",
        surface(v(H, false, true)),
        Filter::Trilinear,
        &["lod", "tex_addr", "tex_fetch", "bilinear", "cart_decode_hemi_oct", "normalise", "dot3", "gloss", "blend"],
    ),
    tex_colour(
        "cart_tex_trilinear_surface_hemi_oct_matte_colour",
        "hemi-oct, one light, matte, texture unit, trilinear, colour map",
        "cart_surface_hemi_oct_matte",
        surface(v(H, false, false)),
        Filter::Trilinear,
        &["lod", "tex_addr", "tex_fetch", "bilinear", "cart_decode_hemi_oct", "normalise", "dot3", "blend"],
    ),
];

/// A palette of `s_n` normals: the index bits of the pipeline that holds it (8 up to 256 entries, else 12).
pub fn palette_index_bits(s_n: usize) -> u32 {
    if s_n <= 256 {
        8
    } else {
        12
    }
}

/// What a pipeline is built with beside its row: the polar power (pw = 4p) and weight h, the height map's bits
/// (8, or 4 read doubled: the same block), the palette's size s_N (where the scene names one; else the row's
/// largest, 2^index bits).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub pw: i64,
    pub h: f64,
    pub height_bits: u32,
    pub palette: Option<usize>,
}

impl Default for Settings {
    /// The polar surface of the demo and a scene's default: h = 1 (a pure dot product, k1 = 0) and p = 4; 8-bit
    /// heights.
    fn default() -> Settings {
        Settings { pw: 16, h: 1.0, height_bits: 8, palette: None }
    }
}
