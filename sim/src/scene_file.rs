//! Scene files: a scene as TOML (through serde, unknown fields refused), read into a `Scene` and the pipeline that
//! renders it. Every value is range-checked as it is read, so a bad one is reported at its own line and column;
//! what depends on several fields (a path only for a map read from a file, gloss only where a pipeline has the
//! gloss unit) is checked after, and reported at the field that cannot stay. Every failure is one line:
//! `FILE:LINE:COLUMN: what is wrong`, or for a map the scene names, the scene's line and the map's file.
//!
//! ```toml
//! name = "bumps under a point light"
//! size = 256                      # output side, pixels (16 to 1024)
//!
//! [surface]
//! shape = "quad"                  # quad | sphere | torus
//! # segments = [64, 32]           # sphere, torus: cells along u and v, two triangles each (3 to 512)
//! # minor = 0.3                   # torus: the tube's radius, the outer radius 1 (0.05 to 0.5)
//! # repeat = [4, 1]               # sphere, torus: the map's repeats along u and v (1 to 64)
//! # tilt = 25.0                   # sphere, torus: the camera's tilt and spin, degrees
//! # spin = 20.0
//!
//! [bump]
//! source = "procedural"           # procedural | height_map | normal_map
//! texels = 128                    # procedural: the map's side (a power of two, 4 to 256)
//! relief = 6.0                    # procedural, height_map: texels of rise from the lowest to the highest
//! # path = "maps/rock.png"        # height_map (8- or 16-bit grey), normal_map (8-bit RGB)
//! # green = "opengl"              # normal_map: opengl (green up the image) | directx (green down)
//! encoding = "seed"               # seed | hemi_oct | polar | polar_dc255 | heights | palette
//! # palette = 256                 # palette: s_N, 1 to 4,096
//! # filter = "bilinear"           # seed, hemi_oct: nearest | nearest_mip | bilinear | trilinear | trilinear_two_pass;
//!                                 # polar: bilinear | trilinear; palette: nearest | nearest_mip (the unit's)
//! # lod_bias = -1.0               # the MIP filters: levels added to λ, −8 to 8 − 1/256 in 1/256
//! # fetch = "unit"                # seed, hemi_oct, polar, palette: unit (the texture unit's memory) | host
//! # wrap = "repeat"               # repeat | clamp, or [u, v] one each; default: the surface's own (all but heights)
//!
//! [light]
//! kind = "point"                  # point | directional
//! position = [0.2, 0.45, 0.25]    # point: over the quad [0, 1]², y up (sphere, torus: in the world, y up, the
//!                                 # object at the origin, radius 1)
//! # direction = [0.3, 1.0, 0.2]   # directional: towards the light, any length but 0
//! per = "vertex"                  # vertex (interpolated) | surface (one light, at the centre)
//!
//! [material]
//! gloss = 96                      # C, 0 to 255 (Cartesian and palette pipelines)
//! src = [236, 196, 140]           # the blend's colours, lit and unlit
//! dst = [16, 20, 36]
//! # colour_map = "maps/tiles.png" # seed, hemi_oct on the texture unit: the destination colour per pixel from an
//!                                 # 8-bit RGB(A) PNG (in place of dst), filtered with the bump map
//! # power = 4.0                   # polar: p, 0 to 63.75 in quarters
//! # weight = 1.0                  # polar: h, 0 to 1
//! ```

use crate::pipelines::{Choices, Row, Settings};
pub use crate::pipelines::{Encoding, Fetch, Filter, Per};
use crate::scene::Scene;
use serde::Deserialize;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use toml::Spanned;

/// An integer range-checked as it is read; the error names the range and the value.
macro_rules! ranged {
    ($(#[$doc:meta])* $name:ident, $lo:expr, $hi:expr, $what:expr) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
        #[serde(try_from = "i64")]
        pub struct $name(pub i64);

        impl TryFrom<i64> for $name {
            type Error = String;
            fn try_from(v: i64) -> Result<Self, String> {
                if ($lo..=$hi).contains(&v) {
                    Ok(Self(v))
                } else {
                    Err(format!("{} is {} to {}, not {v}", $what, $lo, $hi))
                }
            }
        }
    };
}

ranged!(
    /// The output image's side, pixels.
    Side, 16, 1024, "the image side (pixels)");
ranged!(
    /// An 8-bit value: a colour channel, the gloss concentration C.
    Byte, 0, 255, "an 8-bit value");
ranged!(
    /// The palette's size s_N: the palette pipelines hold 256 (8-bit indices) or 4,096 (12-bit) entries.
    PaletteSize, 1, 4096, "the palette size s_N");

/// A procedural map's side: a power of two the height path's memory holds.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "i64")]
pub struct Texels(pub usize);

impl TryFrom<i64> for Texels {
    type Error = String;
    fn try_from(v: i64) -> Result<Self, String> {
        if (4..=crate::heightmap::MAX_SIDE as i64).contains(&v) && (v as u64).is_power_of_two() {
            Ok(Self(v as usize))
        } else {
            Err(format!("the map's side is a power of two from 4 to {}, not {v}", crate::heightmap::MAX_SIDE))
        }
    }
}

/// A finite number in [lo, hi].
fn finite_in(v: f64, lo: f64, hi: f64, what: &str) -> Result<f64, String> {
    if !v.is_finite() {
        return Err(format!("{what} must be a finite number, not {v}"));
    }
    if !(lo..=hi).contains(&v) {
        return Err(format!("{what} is {lo} to {hi}, not {v}"));
    }
    Ok(v)
}

/// The relief: texels of rise from the map's lowest to its highest, above 0.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "f64")]
pub struct Relief(pub f64);

impl TryFrom<f64> for Relief {
    type Error = String;
    fn try_from(v: f64) -> Result<Self, String> {
        let v = finite_in(v, 0.0, 1024.0, "the relief (texels)")?;
        if v == 0.0 {
            return Err("the relief must be above 0: a flat map has no bumps to shade".into());
        }
        Ok(Self(v))
    }
}

/// The texture unit's LOD bias, levels, a multiple of 1/256 in −8 … 8 − 1/256 (the LOD unit's Sq3.8 port).
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "f64")]
pub struct LodBias(pub f64);

impl TryFrom<f64> for LodBias {
    type Error = String;
    fn try_from(v: f64) -> Result<Self, String> {
        let v = finite_in(v, -8.0, 8.0 - 1.0 / 256.0, "the LOD bias (levels)")?;
        if (v * 256.0).fract() != 0.0 {
            return Err(format!("the LOD bias is a multiple of 1/256 of a level (the LOD unit's Sq3.8), not {v}"));
        }
        Ok(Self(v))
    }
}

/// The polar power p, in quarters (the power unit's pw = 4p is U8).
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "f64")]
pub struct Power(pub f64);

impl TryFrom<f64> for Power {
    type Error = String;
    fn try_from(v: f64) -> Result<Self, String> {
        let v = finite_in(v, 0.0, 63.75, "the power p")?;
        if (v * 4.0).fract() != 0.0 {
            return Err(format!("the power p is a multiple of 0.25 (the power unit's pw = 4p is an integer), not {v}"));
        }
        Ok(Self(v))
    }
}

/// A finite number in a range, checked as it is read.
macro_rules! finite {
    ($(#[$doc:meta])* $name:ident, $lo:expr, $hi:expr, $what:expr) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
        #[serde(try_from = "f64")]
        pub struct $name(pub f64);

        impl TryFrom<f64> for $name {
            type Error = String;
            fn try_from(v: f64) -> Result<Self, String> {
                finite_in(v, $lo, $hi, $what).map(Self)
            }
        }
    };
}

finite!(
    /// The polar weight h of N·L against the ambient 1 − h.
    Weight, 0.0, 1.0, "the weight h");
finite!(
    /// The torus's tube radius, the outer radius being 1.
    Minor, 0.05, 0.5, "the tube radius (the outer radius is 1)");
finite!(
    /// A camera angle in degrees.
    Degrees, -360.0, 360.0, "an angle (degrees)");

/// Three finite numbers: a position.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "Vec<f64>")]
pub struct Vec3(pub [f64; 3]);

impl TryFrom<Vec<f64>> for Vec3 {
    type Error = String;
    fn try_from(v: Vec<f64>) -> Result<Self, String> {
        let [x, y, z] = v[..] else { return Err(format!("three numbers [x, y, z], not {}", v.len())) };
        for c in [x, y, z] {
            finite_in(c, -1e6, 1e6, "a coordinate")?;
        }
        Ok(Self([x, y, z]))
    }
}

/// A direction: three finite numbers, not all zero (normalised where it is used).
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "Vec<f64>")]
pub struct Direction(pub [f64; 3]);

impl TryFrom<Vec<f64>> for Direction {
    type Error = String;
    fn try_from(v: Vec<f64>) -> Result<Self, String> {
        let Vec3(d) = Vec3::try_from(v)?;
        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        if l < 1e-9 {
            return Err(format!("a light direction of zero length {d:?} points nowhere"));
        }
        Ok(Self(d.map(|c| c / l)))
    }
}

/// How the map is addressed past its edge along u and v: `"repeat"` or `"clamp"` for both, or `[u, v]` one each
/// (true repeats).
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "toml::Value")]
pub struct Wrap(pub [bool; 2]);

impl TryFrom<toml::Value> for Wrap {
    type Error = String;
    fn try_from(v: toml::Value) -> Result<Self, String> {
        let one = |x: &toml::Value| match x.as_str() {
            Some("repeat") => Ok(true),
            Some("clamp") => Ok(false),
            _ => Err(format!("the wrap is \"repeat\" or \"clamp\", or one for each axis [u, v], not {x}")),
        };
        match &v {
            toml::Value::Array(a) if a.len() == 2 => Ok(Self([one(&a[0])?, one(&a[1])?])),
            toml::Value::Array(a) => Err(format!("the wrap for each axis is two words [u, v], not {}", a.len())),
            x => one(x).map(|w| Self([w, w])),
        }
    }
}

#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq)]
#[serde(rename_all = "snake_case")]
pub enum Shape {
    #[default]
    Quad,
    Sphere,
    Torus,
}

/// Two whole numbers in a range: a curved surface's cells along u and v, the map's repeats.
macro_rules! pair {
    ($(#[$doc:meta])* $name:ident, $lo:expr, $hi:expr, $what:expr) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
        #[serde(try_from = "Vec<i64>")]
        pub struct $name(pub [usize; 2]);

        impl TryFrom<Vec<i64>> for $name {
            type Error = String;
            fn try_from(v: Vec<i64>) -> Result<Self, String> {
                let [a, b] = v[..] else { return Err(format!("{}: two whole numbers [u, v], not {}", $what, v.len())) };
                for x in [a, b] {
                    if !($lo..=$hi).contains(&x) {
                        return Err(format!("{} are {} to {}, not {x}", $what, $lo, $hi));
                    }
                }
                Ok(Self([a as usize, b as usize]))
            }
        }
    };
}

pair!(
    /// Cells along u and v (two triangles a cell).
    Segments, 3, 512, "the segments");
pair!(
    /// The map's repeats along u and v round a curved surface.
    Repeat, 1, 64, "the repeats");

#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(rename_all = "snake_case")]
pub enum Source {
    Procedural,
    HeightMap,
    NormalMap,
}

#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(rename_all = "snake_case")]
pub enum Green {
    /// green up the image (OpenGL, Blender)
    Opengl,
    /// green down the image (DirectX, Unreal)
    Directx,
}

#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq)]
#[serde(rename_all = "snake_case")]
pub enum LightKind {
    #[default]
    Point,
    Directional,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SurfaceSpec {
    #[serde(default)]
    pub shape: Shape,
    pub segments: Option<Spanned<Segments>>,
    pub minor: Option<Spanned<Minor>>,
    pub repeat: Option<Spanned<Repeat>>,
    pub tilt: Option<Spanned<Degrees>>,
    pub spin: Option<Spanned<Degrees>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BumpSpec {
    pub source: Spanned<Source>,
    pub path: Option<Spanned<PathBuf>>,
    pub green: Option<Spanned<Green>>,
    pub texels: Option<Spanned<Texels>>,
    pub relief: Option<Spanned<Relief>>,
    pub encoding: Option<Spanned<Encoding>>,
    pub palette: Option<Spanned<PaletteSize>>,
    pub filter: Option<Spanned<Filter>>,
    pub lod_bias: Option<Spanned<LodBias>>,
    pub fetch: Option<Spanned<Fetch>>,
    pub wrap: Option<Spanned<Wrap>>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightSpec {
    pub kind: Option<Spanned<LightKind>>,
    pub position: Option<Spanned<Vec3>>,
    pub direction: Option<Spanned<Direction>>,
    pub per: Option<Spanned<Per>>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    pub gloss: Option<Spanned<Byte>>,
    pub src: Option<[Byte; 3]>,
    pub dst: Option<[Byte; 3]>,
    pub colour_map: Option<Spanned<PathBuf>>,
    pub power: Option<Spanned<Power>>,
    pub weight: Option<Spanned<Weight>>,
}

/// A scene file as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    pub name: Option<String>,
    pub size: Side,
    #[serde(default)]
    pub surface: SurfaceSpec,
    pub bump: Spanned<BumpSpec>,
    pub light: Option<Spanned<LightSpec>>,
    #[serde(default)]
    pub material: MaterialSpec,
}

/// A scene read and checked: the scene, the pipeline for it (its row of the table, and what it is built with), and
/// what the reading has to tell.
pub struct SceneSpec {
    pub name: String,
    pub scene: Scene,
    pub pipeline: &'static Row,
    pub settings: Settings,
    pub notes: Vec<String>,
}

impl SceneSpec {
    /// The scene's pipeline, built for it.
    pub fn build(&self) -> Box<dyn crate::pipeline::Pipeline> {
        crate::pipeline::build(self.pipeline, &self.scene, &self.settings)
    }
}

/// A curved surface's point light where the scene gives none: above, to the left and in front of the object.
pub const DEFAULT_WORLD_LIGHT: [f64; 3] = [-2.0, 2.5, 3.0];

/// 1-based line and column of a byte offset.
pub fn line_col(text: &str, at: usize) -> (usize, usize) {
    let at = at.min(text.len());
    let before = &text[..at];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

/// Where a checked value sits, for its error.
struct At<'a> {
    file: &'a str,
    text: &'a str,
}

impl At<'_> {
    fn err(&self, span: Range<usize>, msg: impl std::fmt::Display) -> String {
        let (l, c) = line_col(self.text, span.start);
        format!("{}:{l}:{c}: {msg}", self.file)
    }
}

/// Parse a scene's text (`file` names it in errors; maps it names are read relative to `dir`).
pub fn parse(text: &str, file: &str, dir: &Path) -> Result<SceneSpec, String> {
    let at = At { file, text };
    let f: SceneFile = toml::from_str(text).map_err(|e| {
        let msg = e.message().trim().replace('\n', " ");
        match e.span() {
            Some(s) => at.err(s, msg),
            None => format!("{file}: {msg}"),
        }
    })?;
    resolve(f, &at, dir)
}

/// Read and check a scene file.
pub fn load(path: &Path) -> Result<SceneSpec, String> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| format!("{name}: cannot read the scene: {e}"))?;
    let text = String::from_utf8(bytes)
        .map_err(|e| format!("{name}: not UTF-8 text (byte {})", e.utf8_error().valid_up_to()))?;
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    parse(&text, &name, &dir)
}

fn resolve(f: SceneFile, at: &At, dir: &Path) -> Result<SceneSpec, String> {
    let (bump_span, bump) = (f.bump.span(), f.bump.into_inner());
    let (light_span, light) = f.light.map_or((0..0, LightSpec::default()), |l| (l.span(), l.into_inner()));
    let mat = f.material;
    let source = *bump.source.get_ref();
    let encoding = bump.encoding.as_ref().map_or(Encoding::Seed, |e| *e.get_ref());
    let mut notes = vec![];
    // a field the scene's other choices leave no use for
    let unused = |field: Option<Range<usize>>, why: &str| -> Result<(), String> {
        match field {
            Some(s) => Err(at.err(s, why)),
            None => Ok(()),
        }
    };

    // the bump source
    let is_map = matches!(source, Source::HeightMap | Source::NormalMap);
    if !is_map {
        unused(bump.path.as_ref().map(|p| p.span()), "[bump] path: a procedural map reads no file")?;
    }
    if source != Source::NormalMap {
        unused(bump.green.as_ref().map(|g| g.span()), "[bump] green: only a normal map has a green convention")?;
    } else {
        unused(
            bump.relief.as_ref().map(|r| r.span()),
            "[bump] relief: a normal map's slopes are its own (relief is for heights)",
        )?;
    }
    if source != Source::Procedural {
        unused(bump.texels.as_ref().map(|t| t.span()), "[bump] texels: a map read from a file has its own size")?;
    }
    if encoding != Encoding::Palette {
        unused(
            bump.palette.as_ref().map(|p| p.span()),
            "[bump] palette: only encoding = \"palette\" has a palette size",
        )?;
    }
    let mut scene = Scene { size: f.size.0 as usize, ..Scene::default() };
    match source {
        Source::Procedural => {
            if let Some(t) = &bump.texels {
                scene.tex = t.get_ref().0;
            }
            if let Some(r) = &bump.relief {
                scene.relief = r.get_ref().0;
            }
        }
        Source::HeightMap | Source::NormalMap => {
            let Some(p) = &bump.path else {
                return Err(at.err(
                    bump_span,
                    format!(
                        "[bump] a {} needs path = \"FILE.png\"",
                        if source == Source::HeightMap { "height map" } else { "normal map" }
                    ),
                ));
            };
            let file = dir.join(p.get_ref());
            let map_err = |e: String| at.err(p.span(), format!("[bump] path: {e}"));
            if source == Source::HeightMap {
                let loaded = crate::heightmap::load(&file).map_err(map_err)?;
                if encoding == Encoding::Heights && loaded.depth == 16 {
                    return Err(at.err(p.span(), format!(
                        "[bump] path: {}: a 16-bit height map where 8 bits are required (US 2004/0207631's path stores 8-bit heights); save it as 8-bit",
                        file.display()
                    )));
                }
                notes.extend(loaded.notes);
                let side = loaded.map.side;
                scene.tex = side;
                scene.relief = bump.relief.as_ref().map_or(side as f64 / 16.0, |r| r.get_ref().0);
                scene.map = Some(Arc::new(loaded.map));
            } else {
                let green_down = bump.green.as_ref().is_some_and(|g| *g.get_ref() == Green::Directx);
                let loaded = crate::heightmap::load_normal_map(&file, green_down).map_err(map_err)?;
                notes.extend(loaded.notes);
                scene.tex = loaded.map.side;
                scene.normal_map = Some(Arc::new(loaded.map));
            }
        }
    }
    if encoding == Encoding::Heights && source == Source::NormalMap {
        return Err(at.err(bump.encoding.as_ref().map_or(bump_span.clone(), |e| e.span()), "[bump] encoding = \"heights\": a normal map has no heights (US 2004/0207631's path needs a height map or a procedural one)"));
    }

    // the light
    let kind = light.kind.as_ref().map_or(LightKind::Point, |k| *k.get_ref());
    match kind {
        LightKind::Point => {
            unused(
                light.direction.as_ref().map(|d| d.span()),
                "[light] direction: a point light has a position (kind = \"directional\" has a direction)",
            )?;
            if let Some(p) = &light.position {
                scene.light_pos = p.get_ref().0;
            }
        }
        LightKind::Directional => {
            unused(
                light.position.as_ref().map(|p| p.span()),
                "[light] position: a directional light has a direction (kind = \"point\" has a position)",
            )?;
            let Some(d) = &light.direction else {
                return Err(
                    at.err(light_span, "[light] a directional light needs direction = [x, y, z] (towards the light)")
                );
            };
            scene.directional = Some(d.get_ref().0);
        }
    }
    // the surface
    let surf = &f.surface;
    if surf.shape == Shape::Quad {
        unused(
            surf.segments.as_ref().map(|x| x.span()),
            "[surface] segments: the quad is two triangles (segments are for a sphere or a torus)",
        )?;
        unused(surf.repeat.as_ref().map(|x| x.span()), "[surface] repeat: the quad holds the map once")?;
        unused(surf.tilt.as_ref().map(|x| x.span()), "[surface] tilt: the quad fills the screen (no camera)")?;
        unused(surf.spin.as_ref().map(|x| x.span()), "[surface] spin: the quad fills the screen (no camera)")?;
    }
    if surf.shape != Shape::Torus {
        unused(surf.minor.as_ref().map(|x| x.span()), "[surface] minor: only a torus has a tube radius")?;
    }
    if surf.shape != Shape::Quad {
        let shape = match surf.shape {
            Shape::Sphere => crate::surface::Shape::Sphere,
            _ => crate::surface::Shape::Torus { minor: surf.minor.as_ref().map_or(0.3, |m| m.get_ref().0) },
        };
        let default_segments = if surf.shape == Shape::Sphere { [48, 24] } else { [64, 32] };
        let default_repeat = if surf.shape == Shape::Sphere { [2, 1] } else { [4, 1] };
        scene.curved = Some(crate::scene::Curved {
            shape,
            segments: surf.segments.as_ref().map_or(default_segments, |x| x.get_ref().0),
            view: crate::surface::View {
                tilt_deg: surf.tilt.as_ref().map_or(25.0, |x| x.get_ref().0),
                spin_deg: surf.spin.as_ref().map_or(20.0, |x| x.get_ref().0),
            },
            repeat: surf.repeat.as_ref().map_or(default_repeat, |x| x.get_ref().0),
        });
        if kind == LightKind::Point && light.position.is_none() {
            scene.light_pos = DEFAULT_WORLD_LIGHT;
        }
        let quad_only = |what: &str| {
            at.err(
                bump.encoding.as_ref().map_or(bump_span.clone(), |e| e.span()),
                format!(
                    "[bump] encoding = \"{what}\": its pipeline renders the quad only ({}); shape = \"quad\"",
                    if what == "palette" {
                        "its colour table holds one light direction a frame, a flat surface's"
                    } else {
                        "its address unit walks one flat map"
                    }
                ),
            )
        };
        match encoding {
            Encoding::Palette => return Err(quad_only("palette")),
            Encoding::Heights => return Err(quad_only("heights")),
            _ => {}
        }
    }
    let per = light.per.as_ref().map(|p| *p.get_ref());
    let per_span = light.per.as_ref().map(|p| p.span());

    // the pipeline, and what it can take
    let one_light = |name: &str| -> Result<(), String> {
        match (per, &per_span) {
            (Some(Per::Vertex), Some(s)) => Err(at.err(
                s.clone(),
                format!(
                    "[light] per = \"vertex\": the {name} pipeline lights a surface with one light (per = \"surface\")"
                ),
            )),
            _ => Ok(()),
        }
    };
    let no = |field: Option<Range<usize>>, what: &str, name: &str| {
        unused(field, &format!("[material] {what}: the {name} pipeline has no {what}"))
    };
    let gloss = mat.gloss.as_ref().map(|g| g.span());
    let (power, weight) = (mat.power.as_ref().map(|p| p.span()), mat.weight.as_ref().map(|w| w.span()));
    let filter = bump.filter.as_ref().map_or(Filter::Bilinear, |f| *f.get_ref());
    let nearest = filter == Filter::Nearest;
    let filter_span = bump.filter.as_ref().map(|f| f.span());
    let fetch = bump.fetch.as_ref().map(|f| *f.get_ref());
    let fetch_span = bump.fetch.as_ref().map(|f| f.span());
    let polar = matches!(encoding, Encoding::Polar | Encoding::PolarDc255);
    let palette = encoding == Encoding::Palette;
    // a palette's index is never filtered: it takes the nearest texel, of level 0 or of the nearest MIP level
    let palette_filter = palette && matches!(filter, Filter::Nearest | Filter::NearestMip);
    if filter != Filter::Bilinear
        && !matches!(encoding, Encoding::Seed | Encoding::HemiOct)
        && !polar
        && !palette_filter
    {
        let what = if palette {
            "the palette pipelines read an index, which cannot be blended: filter = \"nearest\" or \"nearest_mip\" (on the texture unit)"
        } else {
            "only the Cartesian and polar encodings (seed, hemi_oct, polar) have that filter"
        };
        return Err(at.err(
            filter_span.clone().unwrap_or(bump_span.clone()),
            format!("[bump] filter = \"{}\": {what}", filter.name()),
        ));
    }
    if let Some(b) = &bump.lod_bias {
        if !filter.front().mip() {
            return Err(at.err(
                b.span(),
                format!(
                    "[bump] lod_bias: only a MIP filter (nearest_mip, trilinear, trilinear_two_pass) reads a level of detail; filter = \"{}\"",
                    filter.name()
                ),
            ));
        }
        scene.lod_bias = b.get_ref().0;
    }
    if let Some(w) = &bump.wrap {
        if encoding == Encoding::Heights {
            return Err(at.err(
                w.span(),
                "[bump] wrap: the height pipeline's fetch clamps its 3×3 window at the map's borders (US 2004/0207631 [151])",
            ));
        }
        scene.wrap = Some(w.get_ref().0);
    }
    if fetch.is_some() && !matches!(encoding, Encoding::Seed | Encoding::HemiOct) && !polar && !palette {
        return Err(at.err(
            fetch_span.clone().unwrap_or(bump_span.clone()),
            "[bump] fetch: only the Cartesian, polar and palette encodings (seed, hemi_oct, polar, palette) have pipelines on the texture unit yet",
        ));
    }
    // the choices that pick the pipeline, as the pipeline holds them (`Choices`)
    let mut settings = Settings::default();
    if !matches!(encoding, Encoding::Seed | Encoding::HemiOct) {
        unused(
            mat.colour_map.as_ref().map(|c| c.span()),
            "[material] colour_map: only the Cartesian pipelines (seed, hemi_oct) on the texture unit have a colour map's memory",
        )?;
    }
    let choices = match encoding {
        Encoding::Seed | Encoding::HemiOct => {
            no(power, "power", "Cartesian")?;
            no(weight, "weight", "Cartesian")?;
            // a gloss unit only where the material has gloss (C = 0 gives P = X)
            let gloss = mat.gloss.as_ref().map_or(Scene::default().conc, |g| g.get_ref().0) != 0;
            let per = per.unwrap_or(Per::Vertex);
            let host = Choices { encoding, per, gloss, filter, index_bits: 0, fetch: Fetch::Host, colour: false };
            let colour = mat.colour_map.as_ref().map(|c| c.span());
            let unit = Choices { fetch: Fetch::Unit, colour: colour.is_some(), ..host };
            // the texture unit's memory holds a map of side 2^0 … 2^7 and its chain
            let side = scene.tex;
            let fits = side.is_power_of_two() && side <= 1 << vectors::tex_fetch::MAX_LOG_SIDE;
            let on_unit = crate::pipelines::choose(&unit).is_some();
            if let Some(c) = &colour {
                let why = match fetch {
                    Some(Fetch::Host) => Some("the host-fed pipelines (fetch = \"host\") take one destination colour; the texture unit holds the colour map".to_string()),
                    _ if !on_unit => Some(format!("no pipeline on the texture unit with a colour map serves {}; the colour map's pipelines filter with the nearest texel, the nearest MIP level's, bilinear or trilinear in one clock (no two-pass one)", unit.describe())),
                    _ if !fits => Some(format!("the texture unit's memory holds maps of side 1, 2, 4 … 128; this bump map's side is {side}")),
                    _ => None,
                };
                if let Some(why) = why {
                    return Err(at.err(c.clone(), format!("[material] colour_map: {why}")));
                }
            }
            match fetch {
                Some(Fetch::Unit) if !on_unit => {
                    return Err(at.err(
                        fetch_span.unwrap_or(bump_span.clone()),
                        format!("[bump] fetch = \"unit\": no pipeline on the texture unit serves {}", unit.describe()),
                    ));
                }
                Some(Fetch::Unit) if !fits => {
                    return Err(at.err(fetch_span.unwrap_or(bump_span.clone()), format!("[bump] fetch = \"unit\": the texture unit's pipelines hold maps of side 1, 2, 4 … 128 (its memory built for 256 needs more block RAM than the ECP5-45F has, and no pipeline holds it); this map's side is {side}")));
                }
                Some(Fetch::Unit) => unit,
                None if on_unit && fits => unit,
                _ if filter.front().mip() => {
                    return Err(at.err(filter_span.unwrap_or(bump_span.clone()), format!("[bump] filter = \"{}\": only the texture unit has MIP levels, and none of its pipelines serves {}{}", filter.name(), unit.describe(), if fits { "" } else { " (or the map's side is not a power of two up to 128)" })));
                }
                _ if per == Per::Vertex && nearest => {
                    return Err(at.err(filter_span.unwrap_or(bump_span.clone()), "[bump] filter = \"nearest\": the host-fed nearest-texel pipelines light a surface with one light (per = \"surface\" under [light])"));
                }
                _ => host,
            }
        }
        Encoding::Polar | Encoding::PolarDc255 => {
            one_light("polar")?;
            unused(gloss.clone(), "[material] gloss: the polar pipeline has no gloss unit (its power unit is the specular term: set power)")?;
            if let Some(p) = &mat.power {
                settings.pw = (p.get_ref().0 * 4.0) as i64;
            }
            if let Some(w) = &mat.weight {
                settings.h = w.get_ref().0;
            }
            if !matches!(filter, Filter::Bilinear | Filter::Trilinear) {
                return Err(at.err(
                    filter_span.clone().unwrap_or(bump_span.clone()),
                    format!("[bump] filter = \"{}\": the polar pipelines filter bilinearly, or trilinearly on the texture unit (only the Cartesian encodings have that filter)", filter.name()),
                ));
            }
            // on the texture unit where one of its pipelines serves the scene and its memory holds the map (the
            // default, as for the Cartesian encodings: the angle scale of US 6,819,319, a side up to 128), else fed
            // by the host (bilinear); fetch = "host" takes the host-fed one
            let host = crate::pipelines::one_light(encoding, false, 0);
            let unit = Choices { filter, fetch: Fetch::Unit, ..host };
            let side = scene.tex;
            let fits = side.is_power_of_two() && side <= 1 << vectors::tex_fetch::MAX_LOG_SIDE;
            let on_unit = crate::pipelines::choose(&unit).is_some();
            let span = || fetch_span.clone().or(filter_span.clone()).unwrap_or(bump_span.clone());
            match fetch {
                Some(Fetch::Host) if filter != Filter::Bilinear => {
                    return Err(at.err(filter_span.clone().unwrap_or(bump_span.clone()), format!("[bump] filter = \"{}\": the host-fed polar pipeline filters bilinearly; its other filters are the texture unit's (fetch = \"unit\")", filter.name())));
                }
                Some(Fetch::Host) => host,
                None if filter == Filter::Bilinear && !(on_unit && fits) => host,
                _ if !on_unit => {
                    return Err(at.err(span(), format!("[bump] fetch = \"unit\": no pipeline on the texture unit serves {} (the polar ones take US 6,819,319's angle scale, encoding = \"polar\", bilinear or trilinear)", unit.describe())));
                }
                _ if !fits => {
                    return Err(at.err(span(), format!("[bump] fetch = \"unit\": the texture unit's pipelines hold maps of side 1, 2, 4 … 128; this map's side is {side}")));
                }
                _ => unit,
            }
        }
        Encoding::Heights => {
            one_light("height")?;
            no(gloss.clone(), "gloss", "height")?;
            no(power, "power", "height")?;
            no(weight, "weight", "height")?;
            crate::pipelines::one_light(encoding, false, 0)
        }
        Encoding::Palette => {
            one_light("palette")?;
            no(power, "power", "palette")?;
            no(weight, "weight", "palette")?;
            let Some(n) = &bump.palette else {
                return Err(at.err(bump_span, "[bump] encoding = \"palette\" needs palette = s_N (1 to 4,096)"));
            };
            let s_n = n.get_ref().0 as usize;
            settings.palette = Some(s_n);
            let host = crate::pipelines::one_light(encoding, true, crate::pipelines::palette_index_bits(s_n));
            // on the texture unit where the scene asks for it (a filter of its, or fetch = "unit"): the index map
            // and its §5.2 levels in its memory; else fed by the host, the nearest texel of level 0, as before
            let on_unit = match (fetch, &bump.filter) {
                (Some(Fetch::Host), Some(f)) if palette_filter => {
                    return Err(at.err(f.span(), format!("[bump] filter = \"{}\": the host-fed palette pipelines take the nearest texel of level 0 themselves; the filters are the texture unit's (fetch = \"unit\")", filter.name())));
                }
                (Some(Fetch::Host), _) => false,
                (Some(Fetch::Unit), _) => true,
                (None, _) => palette_filter,
            };
            if !on_unit {
                host
            } else {
                let span = || fetch_span.clone().or(filter_span.clone()).unwrap_or(bump_span.clone());
                let side = scene.tex;
                if s_n > 256 {
                    return Err(at.err(span(), format!("the palette pipelines on the texture unit take 8-bit indices (palette up to 256, the texel's low byte); palette = {s_n} is fed by the host (leave out filter and fetch)")));
                }
                if !(side.is_power_of_two() && side <= 1 << vectors::tex_fetch::MAX_LOG_SIDE) {
                    return Err(at.err(
                        span(),
                        format!(
                            "the texture unit's pipelines hold maps of side 1, 2, 4 … 128; this map's side is {side}"
                        ),
                    ));
                }
                let filter = if filter == Filter::Bilinear { Filter::Nearest } else { filter };
                Choices { filter, fetch: Fetch::Unit, ..host }
            }
        }
    };
    let pipeline = crate::pipelines::choose(&choices)
        .ok_or_else(|| at.err(bump_span.clone(), format!("no pipeline serves these choices: {choices:?}")))?;
    if let Some(g) = &mat.gloss {
        scene.conc = g.get_ref().0;
    }
    if let Some(c) = mat.src {
        scene.src = c.map(|b| b.0);
    }
    if let Some(c) = mat.dst {
        scene.dst = c.map(|b| b.0);
    }
    if let Some(p) = &mat.colour_map {
        if mat.dst.is_some() {
            return Err(at.err(
                p.span(),
                "[material] colour_map: the colour map gives the blend's destination colour; leave dst out",
            ));
        }
        let loaded = crate::heightmap::load_colour_map(&dir.join(p.get_ref()), scene.tex)
            .map_err(|e| at.err(p.span(), format!("[material] colour_map: {e}")))?;
        notes.extend(loaded.notes);
        scene.colour_map = Some(Arc::new(loaded.map));
    }
    scene.per_surface = pipeline.serves.per == Per::Surface;
    let name = f.name.unwrap_or_else(|| at.file.to_string());
    Ok(SceneSpec { name, scene, pipeline, settings, notes })
}

/// The demo's scene, embedded: `scenes/demo.toml`, a torus.
pub const DEMO: &str = include_str!("../../scenes/demo.toml");
/// The quad every pipeline is compared on (the height-map and palette pipelines draw the quad only):
/// `scenes/quad.toml`.
pub const QUAD: &str = include_str!("../../scenes/quad.toml");

/// The embedded demo scene as read, with the pipeline it names.
pub fn demo() -> Result<SceneSpec, String> {
    parse(DEMO, "scenes/demo.toml (embedded)", Path::new("."))
}

/// The embedded quad as read.
pub fn quad() -> Result<SceneSpec, String> {
    parse(QUAD, "scenes/quad.toml (embedded)", Path::new("."))
}
