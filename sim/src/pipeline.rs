//! A pipeline, as the demo and the renderers see it: its row of the table (`crate::pipelines`: the units it holds,
//! its model and its rtl block), how it builds its per-pixel inputs from a scene (with the f64 ideal of every pixel
//! beside them), and how it reads a shade and a colour off its outputs. One implementation per family: US 6,819,319's
//! Cartesian pipelines (lights per vertex, or one light per surface) and polar pipelines, US 2004/0207631's height-map
//! pipeline and Tarini et al.'s palette pipelines; `build` makes a row's.

use crate::pipelines::{self, Choices, Family, Per, Row, Settings};
use crate::prepared::{Ideal, Prepared};
use crate::raster;
use crate::render::{self, Image};
use crate::rtl_paths::RtlPaths;
use crate::scene::Scene;
use vectors::cart_encode::{self, Encoder};
use vectors::cart_pipeline::{self, Decode};
use vectors::polar_encode::{self, Scale};
use vectors::{
    bilinear, blend, cart_surface, gloss, height_addr, height_pipeline, light_iter, palette_pipeline, polar_pipeline,
    UnitModel,
};

/// A family's behaviour on a scene; its row of the table of pipelines (`crate::pipelines::PIPELINES`) names the
/// pipeline, its units, its model and its rtl block.
pub trait Pipeline: Sync {
    fn row(&self) -> &'static Row;
    /// A short name for tables ("Cartesian").
    fn label(&self) -> &'static str {
        self.row().label
    }
    /// The bit-exact model of the whole pipeline; its name is the rtl block's.
    fn model(&self) -> &'static UnitModel {
        self.row().model()
    }
    /// The rtl block, behind the paths that need its type.
    fn rtl(&self) -> &'static dyn RtlPaths {
        self.row().rtl()
    }
    /// The units the pipeline holds, in dataflow order, by their names in the unit table.
    fn units(&self) -> &'static [&'static str] {
        self.row().units
    }
    /// One line saying what the pipeline does with the scene.
    fn describe(&self, scene: &Scene) -> String;
    fn prepare(&self, scene: &Scene) -> Prepared;
    /// The shade in 8-bit units, read off one output vector; `shade_name` says which output and how.
    fn shade(&self, out: &[i64]) -> f64;
    fn shade_name(&self) -> &'static str;
    /// The blended colour, read off one output vector.
    fn colour(&self, out: &[i64]) -> [u8; 3];
    /// The unit normal the model computes for one input vector, where the pipeline has one.
    fn normal(&self, _input: &[i64]) -> Option<[f64; 3]> {
        None
    }
    /// Where the pipeline lights a surface with one light but its ideal uses the pixel's own, the ideal shade (as
    /// `Ideal::shade`) under that one light: the error against it leaves the one light out and shows the rest.
    fn surface_ideal(&self, _scene: &Scene, _ideal: &Ideal) -> Option<f64> {
        None
    }
    /// The vectors the demo's waveform traces: the prologue and the first 64 pixels.
    fn waveform(&self, p: &Prepared) -> Vec<Vec<i64>> {
        p.inputs.iter().take(p.prologue + 64).cloned().collect()
    }
    /// A share of a frame (a window's) with its prologue cut to what its pixels need: the texture unit's
    /// pipelines keep the writes of the texels their pixels read; the others keep it whole.
    fn trim(&self, p: Prepared) -> Prepared {
        p
    }
    /// Bits of texture memory per texel of the bump source.
    /// The map as the texture unit's memory holds it, level 0 first, where the pipeline's texels are not normals
    /// encoded one by one: the palette's indices and their §5.2 levels (each the index nearest the average of the
    /// four normals below it), from the last `prepare`.
    fn texel_levels(&self) -> Option<Vec<Vec<i64>>> {
        None
    }
    fn bits_per_texel(&self) -> u32 {
        16
    }
}

/// The ideal shade of a unit normal under a unit light, 8-bit units (real): N·L clamped at 0, through the gloss
/// curve in reals at C.
pub fn gloss_shade(conc: i64, n: [f64; 3], l: [f64; 3]) -> f64 {
    let x = (n[0] * l[0] + n[1] * l[1] + n[2] * l[2]).max(0.0) * 1023.0;
    gloss::ideal_real(conc, x) / 1023.0 * 255.0
}

/// US 6,819,319's second embodiment: the height map's normals encoded as Cartesian texels (the seed's offset binary,
/// or hemi-octahedral with the decode that reads it), bilinear, the vertex lights interpolated per pixel; with the
/// gloss unit, or for a material with C = 0 without it (`cart_pipeline_matte`, `cart_pipeline_hemi_oct_matte`).
#[derive(Clone, Copy, Debug)]
pub struct Cartesian {
    pub decode: Decode,
    pub gloss: bool,
    pub(crate) row: &'static Row,
}

/// The row that serves these choices (a test of `crate::pipelines` keeps every family's choices served).
fn row_for(c: Choices) -> &'static Row {
    pipelines::choose(&c).unwrap_or_else(|| panic!("no pipeline serves {c:?}"))
}

impl Cartesian {
    pub fn new(decode: Decode, gloss: bool) -> Cartesian {
        let row = row_for(pipelines::cartesian(decode, Per::Vertex, gloss, pipelines::Filter::Bilinear));
        Cartesian { decode, gloss, row }
    }

    /// The full pipeline, gloss unit and all.
    pub fn glossy(decode: Decode) -> Cartesian {
        Cartesian::new(decode, true)
    }
}

impl Pipeline for Cartesian {
    fn row(&self) -> &'static Row {
        self.row
    }
    fn describe(&self, scene: &Scene) -> String {
        let texels = match self.decode {
            Decode::Seed => "seed-encoded texels",
            Decode::HemiOct => "hemi-octahedral texels",
        };
        let gloss =
            if self.gloss { format!("gloss C = {}", scene.conc) } else { "matte (C = 0: no gloss unit)".into() };
        format!("{texels}, bilinear, lights interpolated per pixel, {gloss}")
    }
    /// The full pipeline's vectors; the matte one's are the same without C (a matte pipeline's scene has C = 0, so
    /// its pixels are the full pipeline's at C = 0).
    fn prepare(&self, scene: &Scene) -> Prepared {
        use cart_pipeline::input;
        let mut p = cartesian_prepare(scene, self.decode, cart_pipeline::INPUTS.len(), &|x, texel, px, q| {
            for (slot, k) in cart_pipeline::TEXELS.iter().zip(0..4) {
                (x[slot[0]], x[slot[1]]) = texel(k);
            }
            (x[input::ublend], x[input::vblend]) = (px.ub, px.vb);
            for (l, k) in cart_pipeline::LIGHTS.iter().zip(px.tri) {
                for c in 0..3 {
                    x[l[c]] = q[k][c];
                }
            }
            // weights in 1/256, rounded
            (x[input::w1], x[input::w2]) = ((px.w1 * 256.0).round() as i64, (px.w2 * 256.0).round() as i64);
            (x[input::conc], x[input::mode]) = (scene.conc, 1);
            for c in 0..3 {
                (x[cart_pipeline::SRC[c]], x[cart_pipeline::DST[c]]) = (scene.src[c], scene.dst[c]);
            }
        });
        if !self.gloss {
            assert_eq!(scene.conc, 0, "the matte pipeline is built for C = 0 only");
            p.inputs = p.inputs.into_iter().map(cart_pipeline::without_conc).collect();
        }
        p
    }
    fn shade(&self, out: &[i64]) -> f64 {
        out[cart_pipeline::output::p] as f64 / 4.0
    }
    fn shade_name(&self) -> &'static str {
        "P/4"
    }
    fn colour(&self, out: &[i64]) -> [u8; 3] {
        use cart_pipeline::output;
        [out[output::out_r], out[output::out_g], out[output::out_b]].map(|c| c as u8)
    }
    fn normal(&self, input: &[i64]) -> Option<[f64; 3]> {
        let full = if self.gloss { input.to_vec() } else { cart_pipeline::with_zero_conc(input) };
        Some(cart_pipeline::exact_trace_with(self.decode, &full).normal.map(|c| c as f64))
    }
}

/// A Cartesian pipeline's pixels: the scene's normals encoded as texels, the frame rasterised, and for each covered
/// pixel its input vector (`fill` sets the ports from the pixel, its four texels by the bilinear unit's order and
/// the frame's vertex lights quantised) beside the ideal: the filtered float normal against the pixel's own light,
/// through the gloss curve in reals.
type FillCartesian<'a> = &'a dyn Fn(&mut [i64], &dyn Fn(usize) -> (i64, i64), &raster::Pixel, &[[i64; 3]]);

fn cartesian_prepare(scene: &Scene, decode: Decode, ports: usize, fill: FillCartesian) -> Prepared {
    let encoder = match decode {
        Decode::Seed => Encoder::Seed,
        Decode::HemiOct => Encoder::HemiOct,
    };
    let t = scene.tex;
    let normals = scene.normals();
    let texels: Vec<(u8, u8)> = normals.iter().map(|&n| cart_encode::encode(encoder, n)).collect();
    let frame = raster::frame(scene, &normals);
    let q: Vec<[i64; 3]> = frame.lights.iter().map(|&d| light_iter::quantise_vertex(d)).collect();
    let mut p = Prepared::new(scene.size);
    for px in frame.pixels {
        p.at.push(px.at);
        let mut x = vec![0; ports];
        let texel = |k: usize| {
            let (i, j) = px.corners[k];
            (texels[j * t + i].0 as i64, texels[j * t + i].1 as i64)
        };
        fill(&mut x, &texel, &px, &q);
        p.inputs.push(x);
        let (nrm, ld) = (px.normal, px.light);
        let shade = gloss_shade(scene.conc, nrm, ld);
        p.ideal.push(Ideal { shade, rgb: scene.blend_ideal(shade), normal: nrm, light: ld });
    }
    p
}

/// US 6,819,319's Cartesian pipeline built for a scene with one light per surface (`cart_surface` and its variants):
/// the surface's light made a unit vector once (as the full pipeline's light path would make it) and sent with
/// each pixel; no gloss unit when C = 0; the texels bilinear or the nearest one.
#[derive(Clone, Copy, Debug)]
pub struct CartSurface {
    pub variant: cart_surface::Variant,
    pub(crate) row: &'static Row,
}

impl CartSurface {
    pub fn new(variant: cart_surface::Variant) -> CartSurface {
        CartSurface { variant, row: row_for(pipelines::surface(variant)) }
    }
}

impl Pipeline for CartSurface {
    fn row(&self) -> &'static Row {
        self.row
    }
    fn describe(&self, scene: &Scene) -> String {
        let v = self.variant;
        format!(
            "{} texels, {}, one light per surface (a unit vector per surface, no light interpolation or light normaliser), {}",
            if v.decode == Decode::Seed { "seed-encoded" } else { "hemi-octahedral" },
            if v.nearest { "the nearest texel (no filter)" } else { "bilinear" },
            if v.gloss { format!("gloss C = {}", scene.conc) } else { "matte (C = 0: no gloss unit)".into() }
        )
    }
    fn prepare(&self, scene: &Scene) -> Prepared {
        let at = self.variant.layout();
        cartesian_prepare(scene, self.variant.decode, at.inputs.len(), &|x, texel, px, _| {
            match at.texels {
                cart_surface::Texels::Bilinear { corners, ublend, vblend } => {
                    for (slot, k) in corners.iter().zip(0..4) {
                        (x[slot[0]], x[slot[1]]) = texel(k);
                    }
                    (x[ublend], x[vblend]) = (px.ub, px.vb);
                }
                // the texel nearest the sample: the corner the blend factors round to
                cart_surface::Texels::Nearest(t) => {
                    (x[t[0]], x[t[1]]) = texel((px.ub >= 128) as usize + 2 * (px.vb >= 128) as usize)
                }
            }
            for (k, c) in at.light.iter().zip(cart_surface::light(light_iter::quantise_vertex(px.surface))) {
                x[*k] = c;
            }
            if let Some(c) = at.conc {
                x[c] = scene.conc;
            }
            x[at.mode] = 1;
            for c in 0..3 {
                (x[at.src[c]], x[at.dst[c]]) = (scene.src[c], scene.dst[c]);
            }
        })
    }
    fn shade(&self, out: &[i64]) -> f64 {
        out[cart_surface::output::p] as f64 / 4.0
    }
    fn shade_name(&self) -> &'static str {
        "P/4"
    }
    fn colour(&self, out: &[i64]) -> [u8; 3] {
        use cart_surface::output;
        [out[output::out_r], out[output::out_g], out[output::out_b]].map(|c| c as u8)
    }
    fn normal(&self, input: &[i64]) -> Option<[f64; 3]> {
        Some(cart_surface::exact_trace(self.variant, input).normal.map(|c| c as f64))
    }
}

/// A pipeline on the texture unit (a Cartesian or a polar one): the host-fed pipeline it is built on prepares the
/// frame (its lights, material and ideals); each pixel's texels and blend factors (a polar host's filtered S and R)
/// give way to what a rasteriser gives, the sample's position (Sq11.8, texels of level 0) and its screen
/// derivatives (Sq8.8), and the frame begins with a prologue that loads the map and its MIP chain into the unit's
/// memory, one texel a clock. The levels: each texel of a level the four texels under it of the level above
/// averaged as unit vectors and made unit length again (a polar map's: the average direction), then encoded as the
/// host's texels are.
pub struct CartTex {
    row: &'static Row,
    host: Box<dyn Pipeline>,
    settings: Settings,
    filter: pipelines::Filter,
    /// the front with the last prepared frame's prologue written into its memory: what `normal` reads
    loaded: std::sync::RwLock<Option<std::sync::Arc<vectors::texture::front::Front>>>,
}

impl CartTex {
    /// The row's pipeline on the host row's, the host built for the scene with these settings (a polar host's
    /// power and weight).
    pub fn new(
        row: &'static Row,
        host_row: &'static Row,
        filter: pipelines::Filter,
        scene: &Scene,
        settings: &Settings,
    ) -> CartTex {
        let host = build(host_row, scene, settings);
        CartTex { row, host, settings: *settings, filter, loaded: Default::default() }
    }

    /// The scene's colour map where the pipeline holds a colour path (a pipeline with one needs one: `renders`).
    fn colour_map(&self, scene: &Scene) -> Option<std::sync::Arc<crate::heightmap::ColourMap>> {
        if !self.row.serves.colour {
            return None;
        }
        let c = scene.colour_map.clone().expect("a colour map's pipeline renders a scene with a colour map");
        assert_eq!(c.side, scene.tex, "the colour map has the bump map's side");
        Some(c)
    }

    /// The texels of the host-fed pipeline it is built on: a Cartesian decode's, or polar in an angle scale.
    fn texels(&self) -> Texels {
        match self.host.row().family {
            Family::Cartesian(d) => Texels::Cartesian(d),
            Family::CartSurface(v) => Texels::Cartesian(v.decode),
            Family::Polar(scale) => Texels::Polar(scale),
            Family::Palette => Texels::Palette,
            _ => unreachable!(
                "a texture-unit pipeline is built on a Cartesian, polar or palette host (the table's rows)"
            ),
        }
    }

    /// A unit normal as the host's 16-bit texel: the low byte TexelX, U or S, the high byte TexelZ, V or R.
    fn texel(&self, n: [f64; 3]) -> i64 {
        let (lo, hi) = match self.texels() {
            Texels::Cartesian(Decode::Seed) => cart_encode::encode(Encoder::Seed, n),
            Texels::Cartesian(Decode::HemiOct) => cart_encode::encode(Encoder::HemiOct, n),
            Texels::Polar(scale) => {
                let (s, r) = polar_encode::encode_normal(scale, n);
                (s as u8, r as u8)
            }
            Texels::Palette => unreachable!("a palette's texels are its host's indices (`texel_levels`)"),
        };
        lo as i64 | ((hi as i64) << 8)
    }
}

/// The texels a pipeline on the texture unit reads: its host's.
#[derive(Clone, Copy, Debug)]
enum Texels {
    Cartesian(Decode),
    Polar(Scale),
    /// palette indices (the host's quantization: `Pipeline::texel_levels`)
    Palette,
}

/// The map's MIP chain as unit normals, level 0 (side t) first, down to 1 × 1: each texel the normalised mean of
/// the four under it.
pub fn mip_chain(normals: &[[f64; 3]], t: usize) -> Vec<Vec<[f64; 3]>> {
    let mut chain = vec![normals.to_vec()];
    let mut side = t;
    while side > 1 {
        let (up, half) = (chain.last().unwrap(), side / 2);
        let mut level = Vec::with_capacity(half * half);
        for y in 0..half {
            for x in 0..half {
                let mut m = [0.0; 3];
                for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    let n = up[(2 * y + dy) * side + 2 * x + dx];
                    for c in 0..3 {
                        m[c] += n[c];
                    }
                }
                level.push(crate::surface::unit(m));
            }
        }
        chain.push(level);
        side = half;
    }
    chain
}

/// A value in texels (or texels a pixel) as a signed fixed-point code with 8 fraction bits, rounded and saturated
/// to `bits`.
fn fixed8(x: f64, bits: u32) -> i64 {
    let lim = 1i64 << (bits - 1);
    ((x * 256.0).round() as i64).clamp(-lim, lim - 1)
}

/// The same, truncated toward −∞.
fn floor8(x: f64, bits: u32) -> i64 {
    let lim = 1i64 << (bits - 1);
    ((x * 256.0).floor() as i64).clamp(-lim, lim - 1)
}

impl Pipeline for CartTex {
    fn row(&self) -> &'static Row {
        self.row
    }
    fn describe(&self, scene: &Scene) -> String {
        let f = match self.filter {
            pipelines::Filter::Bilinear => "bilinear on level 0",
            pipelines::Filter::Nearest => "the nearest texel of level 0",
            pipelines::Filter::NearestMip => "the nearest texel of the nearest MIP level (the LOD unit's)",
            pipelines::Filter::Trilinear => {
                "bilinear on the two MIP levels round the LOD unit's λ, blended by its fraction"
            }
            pipelines::Filter::TrilinearTwoPass => {
                "bilinear on the two MIP levels round the LOD unit's λ, read in two passes (two clocks a pixel), \
                 blended by its fraction"
            }
        };
        let texels = match self.texels() {
            Texels::Cartesian(Decode::HemiOct) => "hemi-octahedral texels",
            Texels::Cartesian(Decode::Seed) => "seed-encoded texels",
            Texels::Polar(scale) => {
                return format!(
                    "the texture unit ({f}; the map and its MIP chain in its memory), polar texels ({}): S and R \
                     filtered as numbers, {}",
                    scale.name(),
                    polar_light(scale, self.settings.pw, self.settings.h, scene)
                );
            }
            Texels::Palette => {
                return format!(
                    "the texture unit ({f}; the index map and its §5.2 MIP levels in its memory), palette indices: {}",
                    self.host.describe(scene)
                );
            }
        };
        let light = match self.row.serves.per {
            pipelines::Per::Vertex => "lights interpolated per pixel",
            pipelines::Per::Surface => "one light per surface",
        };
        let gloss = if self.row.serves.gloss {
            format!("gloss C = {}", scene.conc)
        } else {
            "matte (C = 0: no gloss unit)".into()
        };
        format!("the texture unit ({f}; the map and its MIP chain in its memory), {texels}, {light}, {gloss}")
    }
    fn prepare(&self, scene: &Scene) -> Prepared {
        use vectors::texture::front::{self, At};
        let host = self.host.prepare(scene);
        let model = self.model();
        let at = At::of(model.inputs, self.filter.front().mip());
        let t = scene.tex;
        assert!(
            self.row.renders(scene),
            "{}: a map of side {t} (a power of two up to 128?), a colour map of its side where the row has one",
            self.row.name
        );
        let log_side = t.trailing_zeros() as i64;
        let from_host = |h: &[i64]| vectors::textured::from_host(self.host.model(), model.inputs, h);
        // the prologue: every level of the chain, the smallest first, encoded as the host encodes its texels (a
        // palette host: its quantization's indices and their levels)
        let chain: Vec<Vec<i64>> = match self.texels() {
            Texels::Palette => self.host.texel_levels().expect("the palette host's prepare quantized the map"),
            _ => mip_chain(&scene.normals(), t).iter().map(|l| l.iter().map(|&n| self.texel(n)).collect()).collect(),
        };
        let blank = vec![0; model.inputs.len()];
        let mut inputs = vec![];
        for (k, level) in chain.iter().enumerate().rev() {
            let (m, side) = (log_side - k as i64, t >> k);
            for (i, &texel) in level.iter().enumerate() {
                let mut v = blank.clone();
                front::put_write(&mut v, &at, m, (i % side) as i64, (i / side) as i64, texel);
                inputs.push(v);
            }
        }
        // with a colour map, its chain into the second memory likewise: each channel rounded to a byte, then to
        // RGB565 (`front::pack565`)
        let colour = self.colour_map(scene);
        if let Some(c) = &colour {
            for (k, level) in c.chain().iter().enumerate().rev() {
                let (m, side) = (log_side - k as i64, t >> k);
                for (i, rgb) in level.iter().enumerate() {
                    let texel = front::pack565(rgb.map(|x| x.round().clamp(0.0, 255.0) as u8));
                    let mut v = blank.clone();
                    front::put_colour_write(&mut v, &at, m, (i % side) as i64, (i / side) as i64, texel);
                    inputs.push(v);
                }
            }
        }
        // the host's own prologue after the map (a palette host's table builds), its vectors' other ports as given
        inputs.extend(host.inputs[..host.prologue].iter().map(|h| from_host(h)));
        let prologue = inputs.len();
        let mut loaded = match colour {
            Some(_) => front::Front::with_colour(self.filter.front()),
            None => front::Front::new(self.filter.front()),
        };
        for v in &inputs {
            loaded.step(v, &at);
        }
        if let Ok(mut l) = self.loaded.write() {
            *l = Some(std::sync::Arc::new(loaded));
        }
        let frame = raster::frame(scene, &scene.normals());
        assert_eq!(frame.pixels.len(), host.pixels().len(), "the host's frame and the rasteriser's");
        let mut ideal = host.ideal.clone();
        for (k, (px, h)) in frame.pixels.iter().zip(host.pixels()).enumerate() {
            // with a colour map the ideal's destination colour is the map's, bilinear in f64 at the sample
            if let Some(c) = &colour {
                let dst = c.at(px.pos[0], px.pos[1], px.wrap);
                let a = ideal[k].shade;
                ideal[k].rgb = std::array::from_fn(|i| (scene.src[i] as f64 * a + dst[i] * (255.0 - a)) / 255.0);
            }
            let mut v = from_host(h);
            // a repeating axis taken modulo the map's side (as a rasteriser keeps its coordinates small), so that
            // any repeat count stays inside Sq11.8's ±2,048 texels; a clamped axis lies within the map already
            let pos = [0, 1].map(|k| if px.wrap[k] { px.pos[k].rem_euclid(t as f64) } else { px.pos[k] });
            // the position truncated to 1/256 texel, as the host-fed path truncates its blend factors
            let uv = [floor8(pos[0], 20), floor8(pos[1], 20)];
            front::put_read(&mut v, &at, uv, log_side, px.wrap, px.deriv.map(|d| fixed8(d, 17)));
            front::put_bias(&mut v, &at, (scene.lod_bias * 256.0) as i64); // a multiple of 1/256 (the scene file's)
            inputs.push(v);
        }
        Prepared { size: host.size, inputs, prologue, ideal, at: host.at }
    }
    fn trim(&self, mut p: Prepared) -> Prepared {
        use vectors::texture::front::{At, Front};
        let at = At::of(self.model().inputs, self.filter.front().mip());
        // a colour map's texels are read where the bump map's are: one set of places serves both memories
        let front = Front::new(self.filter.front());
        let read: std::collections::HashSet<_> = p.pixels().iter().flat_map(|v| front.reads(v, &at)).collect();
        let keep: Vec<Vec<i64>> = p.inputs[..p.prologue]
            .iter()
            // (a vector that writes no texel is the host's: a palette's table build, kept)
            .filter(|v| Front::writes(v, &at).is_none_or(|t| read.contains(&t)))
            .cloned()
            .collect();
        let n = keep.len();
        p.inputs.splice(..p.prologue, keep);
        p.prologue = n;
        p
    }
    fn waveform(&self, p: &Prepared) -> Vec<Vec<i64>> {
        let first = Prepared {
            size: p.size,
            inputs: p.inputs.iter().take(p.prologue + 64).cloned().collect(),
            prologue: p.prologue,
            ideal: p.ideal.iter().take(64).copied().collect(),
            at: p.at.iter().take(64).copied().collect(),
        };
        self.trim(first).inputs
    }
    fn shade(&self, out: &[i64]) -> f64 {
        self.host.shade(out)
    }
    fn shade_name(&self) -> &'static str {
        self.host.shade_name()
    }
    fn colour(&self, out: &[i64]) -> [u8; 3] {
        self.host.colour(out)
    }
    /// The host's normal for the texel the front reads from the prepared frame's memory.
    fn normal(&self, input: &[i64]) -> Option<[f64; 3]> {
        use vectors::texture::front::At;
        let front = self.loaded.read().ok()?.clone()?;
        let model = self.model();
        let at = At::of(model.inputs, self.filter.front().mip());
        let (t, c) = (front.read(input, &at), front.read_colour(input, &at));
        self.host.normal(&vectors::textured::host_vector(self.host.model(), model.inputs, input, t, c))
    }
    fn surface_ideal(&self, scene: &Scene, ideal: &Ideal) -> Option<f64> {
        self.host.surface_ideal(scene, ideal)
    }
}

/// US 6,819,319's first embodiment (FIG. 3): the same height map's normals polar-encoded (S, R) in `scale`; the texture
/// filtered the way the colour filter would, S and R bilinearly blended as plain numbers (the seed's shortcoming 2:
/// across R's 255 → 0 wrap this is wrong); one light per surface (shortcoming 1: the hardware cannot interpolate
/// polar lights), the direction at the quad's centre, moved onto the horizon if below it (shortcoming 3), weight
/// `h`; the shade raised to p = pw/4. The ideal is the Cartesian path's: the filtered float normal against the
/// pixel's own light, max(0, (1 − h) + h·N·L)^p.
#[derive(Clone, Copy, Debug)]
pub struct Polar {
    pub scale: Scale,
    pub pw: i64,
    pub h: f64,
    pub(crate) row: &'static Row,
}

/// The polar set-up's own findings beside the common ones: the surface's light and which pixels filter across R's
/// wrap.
pub struct PolarSetup {
    pub prepared: Prepared,
    /// the surface's one light, as encoded, and the direction it was encoded from (the quad centre's)
    pub light: polar_encode::Light,
    pub surface_dir: [f64; 3],
    pub straddles: Vec<bool>,
}

impl Polar {
    pub fn new(scale: Scale, pw: i64, h: f64) -> Polar {
        let row = row_for(pipelines::polar(scale));
        Polar { scale, pw, h, row }
    }

    pub fn set_up(&self, scene: &Scene) -> PolarSetup {
        use polar_pipeline::input;
        let t = scene.tex;
        let normals = scene.normals();
        let codes: Vec<(i64, i64)> = normals.iter().map(|&n| polar_encode::encode_normal(self.scale, n)).collect();
        let surface_dir = scene.light_dir(0.5, 0.5);
        let light = polar_encode::encode_light(self.scale, surface_dir, self.h);
        let mut p = Prepared::new(scene.size);
        let mut straddles = vec![];
        for px in raster::pixels(scene, &normals) {
            p.at.push(px.at);
            // the pixel's surface's one light (the quad's is `light`; a curved surface's, its triangle's)
            let light =
                if scene.curved.is_some() { polar_encode::encode_light(self.scale, px.surface, self.h) } else { light };
            let c = px.corners.map(|(i, j)| codes[j * t + i]);
            let s = bilinear::exact_channel(c[0].0, c[1].0, c[2].0, c[3].0, px.ub, px.vb, bilinear::F);
            let r = bilinear::exact_channel(c[0].1, c[1].1, c[2].1, c[3].1, px.ub, px.vb, bilinear::F);
            let (rmin, rmax) = c.iter().fold((255, 0), |(lo, hi), &(_, r)| (lo.min(r), hi.max(r)));
            straddles.push(rmax - rmin > 128);
            let mut x = vec![0; polar_pipeline::INPUTS.len()];
            (x[input::s], x[input::r], x[input::q]) = (s, r, light.q);
            (x[input::k1], x[input::k2], x[input::k3], x[input::pw], x[input::mode]) =
                (light.k1, light.k2, light.k3, self.pw, 1);
            (x[input::src_r], x[input::src_g], x[input::src_b]) = (scene.src[0], scene.src[1], scene.src[2]);
            (x[input::dst_r], x[input::dst_g], x[input::dst_b]) = (scene.dst[0], scene.dst[1], scene.dst[2]);
            p.inputs.push(x);
            let (nrm, ld) = (px.normal, px.light);
            let a = polar_ideal(self.pw, self.h, nrm, ld);
            p.ideal.push(Ideal { shade: a, rgb: scene.blend_ideal(a), normal: nrm, light: ld });
        }
        PolarSetup { prepared: p, light, surface_dir, straddles }
    }
}

/// The polar pipelines' ideal shade of normal n under light l: 255·max(0, (1 − h) + h·N·L)^p, p = pw / 4 (clamped
/// to 1 above as the shade is).
pub fn polar_ideal(pw: i64, h: f64, n: [f64; 3], l: [f64; 3]) -> f64 {
    let d = (1.0 - h) + h * (n[0] * l[0] + n[1] * l[1] + n[2] * l[2]);
    255.0 * d.clamp(0.0, 1.0).powf(pw as f64 / 4.0)
}

/// The polar pipelines' light and power in words: the surface's one light as encoded (at the quad's centre) and p.
fn polar_light(scale: Scale, pw: i64, h: f64, scene: &Scene) -> String {
    let l = polar_encode::encode_light(scale, scene.light_dir(0.5, 0.5), h);
    format!(
        "one light per surface (T {:.1}°, Q {}, k = {}, {}, {}), p = {}",
        l.t.to_degrees(),
        l.q,
        l.k1,
        l.k2,
        l.k3,
        pw as f64 / 4.0
    )
}

impl Pipeline for Polar {
    fn row(&self) -> &'static Row {
        self.row
    }
    fn describe(&self, scene: &Scene) -> String {
        format!(
            "({}): S, R bilinear as numbers, {}",
            self.scale.name(),
            polar_light(self.scale, self.pw, self.h, scene)
        )
    }
    fn prepare(&self, scene: &Scene) -> Prepared {
        self.set_up(scene).prepared
    }
    fn shade(&self, out: &[i64]) -> f64 {
        out[polar_pipeline::output::alpha] as f64
    }
    fn shade_name(&self) -> &'static str {
        "α"
    }
    fn colour(&self, out: &[i64]) -> [u8; 3] {
        use polar_pipeline::output;
        [out[output::out_r], out[output::out_g], out[output::out_b]].map(|c| c as u8)
    }
}

/// US 2004/0207631 (FIG. 7): the scene's height map itself, 8-bit UQ6.2 heights (the scale factor k of ¶82 making up
/// the
/// range), through the normal generator on the colour filter's bilinear units. The address unit's work (height
/// mode: no half-texel subtraction, clamped) and the 3×3 fetch are done here, in the set-up; the shade is
/// max(0, N·L) with the surface's one light (the light at the quad's centre), so that its error against the
/// surface's true normal under the same light is the normal generator's alone.
#[derive(Clone, Copy, Debug)]
pub struct Height {
    /// the surface's light, and the material's colours (blended by the shade)
    pub light: [f64; 3],
    pub src: [i64; 3],
    pub dst: [i64; 3],
    /// the map's height bits: 8 (UQ6.2), or 4 (UQ3.1, ¶50), whose codes q enter the 8-bit datapath as 2q
    pub bits: u32,
    pub(crate) row: &'static Row,
}

impl Height {
    pub fn new(scene: &Scene) -> Height {
        Height::with_bits(scene, 8)
    }

    pub fn with_bits(scene: &Scene, bits: u32) -> Height {
        let row = row_for(pipelines::height());
        Height { light: scene.light_dir(0.5, 0.5), src: scene.src, dst: scene.dst, bits, row }
    }

    /// The scene's true heights at the texel centres (row-major), in texels.
    pub fn heights(scene: &Scene) -> Vec<f64> {
        let t = scene.tex;
        (0..t * t)
            .map(|k| scene.height_at(((k % t) as f64 + 0.5) / t as f64, ((k / t) as f64 + 0.5) / t as f64))
            .collect()
    }

    /// The 8-bit heights of the scene's map (row-major, one per texel) and the scale factor (UQ4.4) that brings
    /// them back to texel units.
    pub fn codes(scene: &Scene) -> (Vec<i64>, i64) {
        Height::codes_in(scene, 8)
    }

    /// The same in `bits` (8 or 4), as the 8-bit datapath reads them (4-bit codes doubled).
    pub fn codes_in(scene: &Scene, bits: u32) -> (Vec<i64>, i64) {
        let h = Height::heights(scene);
        let (lo, hi) = h.iter().fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
        let (codes, k) = vectors::height_normal::encode_heights_in(&h, lo, hi, bits);
        (codes.into_iter().map(|q| if bits == 4 { 2 * q } else { q }).collect(), k)
    }

    /// Where pixel (px, py) of an n × n frame samples a map of side t: the address unit [150] in height mode,
    /// clamped (texel i, blend factor ub; texel j, vb).
    pub fn sample(px: usize, py: usize, n: usize, t: usize) -> (i64, i64, i64, i64) {
        let (u, v) = ((px as f64 + 0.5) / n as f64, (py as f64 + 0.5) / n as f64);
        // UQ8.8 texel coordinates
        let coord = |x: f64| ((x * t as f64 * 256.0).round() as i64).clamp(0, 65_535);
        let size_log2 = t.trailing_zeros() as i64;
        let (i, ub) = height_addr::exact(coord(u), size_log2, false, true);
        let (j, vb) = height_addr::exact(coord(v), size_log2, false, true);
        (i, ub, j, vb)
    }

    pub fn shade_of(&self, n: [f64; 3]) -> f64 {
        255.0 * (n[0] * self.light[0] + n[1] * self.light[1] + n[2] * self.light[2]).max(0.0)
    }
}

impl Pipeline for Height {
    fn row(&self) -> &'static Row {
        self.row
    }
    fn describe(&self, scene: &Scene) -> String {
        let (_, k) = Height::codes_in(scene, self.bits);
        format!(
            "{}-bit heights (k = {k}/16), B-spline normals on the bilinear units, one light per surface, N·L",
            self.bits
        )
    }
    fn prepare(&self, scene: &Scene) -> Prepared {
        let t = scene.tex;
        let (codes, k) = Height::codes_in(scene, self.bits);
        let size_log2 = t.trailing_zeros() as i64;
        assert!(t.is_power_of_two(), "the height path's address unit takes power-of-two textures");
        let n = scene.size;
        let map = vectors::height_fetch::Map::from_heights(&codes, t, t);
        let mut p = Prepared::new(n);
        for py in 0..n {
            for px in 0..n {
                let (i, ub, j, vb) = Height::sample(px, py, n, t);
                // the fetch [151]: the 3×3 window around (i, j) from the 2×2-interleaved map, clamped at the borders
                let mut x = map.window(i, j, size_log2, size_log2, false, false).to_vec();
                x.extend([ub, vb, k]);
                p.inputs.push(x);
                // the ideal: the true surface's normal at the pixel (its gradient in texel units), the same light
                let (xt, zt) = (i as f64 + ub as f64 / 256.0, j as f64 + vb as f64 / 256.0);
                let e = 1e-3;
                let hf = |x: f64, z: f64| scene.height_at(x / t as f64, z / t as f64);
                let (gx, gz) =
                    ((hf(xt + e, zt) - hf(xt - e, zt)) / (2.0 * e), (hf(xt, zt + e) - hf(xt, zt - e)) / (2.0 * e));
                let l = (gx * gx + 1.0 + gz * gz).sqrt();
                let nrm = [-gx / l, 1.0 / l, -gz / l];
                let shade = self.shade_of(nrm);
                p.ideal.push(Ideal { shade, rgb: scene.blend_ideal(shade), normal: nrm, light: self.light });
            }
        }
        p
    }
    fn shade(&self, out: &[i64]) -> f64 {
        use height_pipeline::output;
        self.shade_of([out[output::norm_x], out[output::norm_y], out[output::norm_z]].map(|c| c as f64 / 1024.0))
    }
    fn shade_name(&self) -> &'static str {
        "255·N·L"
    }
    fn colour(&self, out: &[i64]) -> [u8; 3] {
        let a = (self.shade(out).round() as i64).clamp(0, 255);
        std::array::from_fn(|c| blend::exact_channel(a, 1, self.src[c], self.dst[c]) as u8)
    }
    fn normal(&self, input: &[i64]) -> Option<[f64; 3]> {
        Some(height_pipeline::exact_trace(input).normal.map(|c| c as f64))
    }
    fn bits_per_texel(&self) -> u32 {
        self.bits
    }
}

/// Tarini et al.: the scene's normal map quantized to a palette of `s_n` normals (median cut and k-means
/// on the sphere), an index per texel, point-sampled (indices cannot be blended: the texel nearest the pixel's
/// sample point); the frame's colour table built by the table builder from the palette's normals (S10, rounded),
/// one entry a clock, as the frame's prologue, then one table read a pixel. One light per surface (the light at the
/// quad's centre, as the paper's directional light), H = L so that the entry's colour is gloss(C, N·L) times white:
/// the Cartesian path's shade with its light fixed. The ideal is the Cartesian path's (the filtered float normal
/// against the pixel's own light), so the error counts what the palette, the point sampling and the one light cost.
/// `s_n` ≤ 256 runs on `palette_pipeline`, ≤ 4,096 on `palette_pipeline_12`.
pub struct Palette {
    pub s_n: usize,
    /// the material's colours (blended by the shade)
    pub src: [i64; 3],
    pub dst: [i64; 3],
    /// what the last `prepare` built: the palette's codes (for `normal`) and its quantization
    built: std::sync::RwLock<Option<std::sync::Arc<PaletteBuilt>>>,
    pub(crate) row: &'static Row,
}

/// The quantization a `Palette` prepared: its codes, the map's distinct normals, the angle from each texel's normal
/// to its palette normal (degrees), and the quantizer's time.
pub struct PaletteBuilt {
    pub codes: Vec<[i64; 3]>,
    /// the index map and its §5.2 MIP levels, level 0 first (`quantize::mip_chain`)
    pub levels: Vec<Vec<u32>>,
    pub distinct: usize,
    pub error: vectors::stats::ErrorStats,
    pub quantize_s: f64,
}

impl Palette {
    pub fn new(s_n: usize, scene: &Scene) -> Palette {
        assert!((1..=4096).contains(&s_n), "the palette pipelines hold 1 to 4,096 normals (s_N = {s_n})");
        let row = row_for(pipelines::palette(s_n));
        Palette { s_n, src: scene.src, dst: scene.dst, built: Default::default(), row }
    }

    /// The quantization of the last `prepare`.
    pub fn built(&self) -> Option<std::sync::Arc<PaletteBuilt>> {
        self.built.read().ok()?.clone()
    }

    /// The vector that builds palette entry `e` from its code while pixel 0 of frame 0 is read (the prologue's).
    fn build_vector(e: usize, n: [i64; 3], l: [i64; 3], conc: i64) -> Vec<i64> {
        use palette_pipeline::input;
        let mut x = vec![0; palette_pipeline::INPUTS.len()];
        (x[input::frame], x[input::idx], x[input::build], x[input::b_idx]) = (0, 0, 1, e as i64);
        for c in 0..3 {
            (x[input::n_x + c], x[input::l_x + c], x[input::h_x + c]) = (n[c], l[c], l[c]);
        }
        (x[input::conc], x[input::spec_r], x[input::spec_g], x[input::spec_b]) = (conc, 255, 255, 255);
        x
    }
}

impl Pipeline for Palette {
    fn row(&self) -> &'static Row {
        self.row
    }
    fn describe(&self, scene: &Scene) -> String {
        let what = match self.built() {
            Some(b) => format!(
                "{} of the map's {} distinct normals (quantized in {:.2} s, {:.2}° mean / {:.2}° max to the texels' normals)",
                b.codes.len(), b.distinct, b.quantize_s, b.error.mean(), b.error.max
            ),
            None => format!("up to {} normals", self.s_n),
        };
        format!(
            "s_N = {}: {what}; nearest texel; the table built a frame, one light per surface, gloss C = {}",
            self.s_n, scene.conc
        )
    }
    fn prepare(&self, scene: &Scene) -> Prepared {
        use palette_pipeline::input;
        let t = scene.tex;
        let normals = scene.normals();
        let clock = std::time::Instant::now();
        let q = vectors::palette::quantize::quantize(&normals, self.s_n);
        let quantize_s = clock.elapsed().as_secs_f64();
        let error = vectors::palette::quantize::angular_error(&normals, &q.index, &q.palette);
        // the palette as the table RAM's builder takes it: S10 (Sq9.0), rounded
        let codes: Vec<[i64; 3]> =
            q.palette.iter().map(|n| n.map(|c| ((c * 511.0).round() as i64).clamp(-512, 511))).collect();
        let l = vectors::table_builder::sq1_10(scene.light_dir(0.5, 0.5));
        let mut p = Prepared::new(scene.size);
        for (e, &n) in codes.iter().enumerate() {
            p.inputs.push(Palette::build_vector(e, n, l, scene.conc)); // table 1 built while frame 0 is shown
        }
        p.prologue = codes.len();
        for px in raster::pixels(scene, &normals) {
            p.at.push(px.at);
            // the texel nearest the sample point: of the bilinear corners, the one the blend factors lean to
            let (i, j) = px.corners[(px.ub >= 128) as usize + 2 * (px.vb >= 128) as usize];
            let mut x = vec![0; palette_pipeline::INPUTS.len()];
            (x[input::frame], x[input::idx]) = (1, q.index[j * t + i] as i64); // frame 1 reads table 1
            p.inputs.push(x);
            let (nrm, ld) = (px.normal, px.light);
            let shade = gloss_shade(scene.conc, nrm, ld);
            p.ideal.push(Ideal { shade, rgb: scene.blend_ideal(shade), normal: nrm, light: ld });
        }
        if let Ok(mut b) = self.built.write() {
            let levels = vectors::palette::quantize::mip_chain(&q.index, t, t, &q.palette).into_iter().map(|l| l.0);
            let levels = levels.collect();
            *b = Some(std::sync::Arc::new(PaletteBuilt { codes, levels, distinct: q.distinct, error, quantize_s }));
        }
        p
    }
    fn shade(&self, out: &[i64]) -> f64 {
        out[palette_pipeline::output::out_r] as f64
    }
    fn shade_name(&self) -> &'static str {
        "entry r, P·255/1023"
    }
    fn colour(&self, out: &[i64]) -> [u8; 3] {
        let a = out[palette_pipeline::output::out_r];
        std::array::from_fn(|c| blend::exact_channel(a, 1, self.src[c], self.dst[c]) as u8)
    }
    fn normal(&self, input: &[i64]) -> Option<[f64; 3]> {
        let b = self.built()?;
        Some(
            vectors::normalise::exact(b.codes[input[palette_pipeline::input::idx] as usize]).map(|c| c as f64 / 1024.0),
        )
    }
    fn surface_ideal(&self, scene: &Scene, ideal: &Ideal) -> Option<f64> {
        let (n, l) = (ideal.normal, scene.light_dir(0.5, 0.5));
        Some(gloss_shade(scene.conc, n, l))
    }
    /// The builds of the entries the first 64 pixels read, then those pixels: their frame as the hardware sees it,
    /// in a file of a size a viewer opens (the whole prologue of 4,096 builds would be tens of megabytes).
    fn waveform(&self, p: &Prepared) -> Vec<Vec<i64>> {
        use palette_pipeline::input;
        let first = &p.pixels()[..p.pixels().len().min(64)];
        let read: std::collections::BTreeSet<i64> = first.iter().map(|x| x[input::idx]).collect();
        let builds = p.inputs[..p.prologue].iter().filter(|x| read.contains(&x[input::b_idx]));
        builds.chain(first).cloned().collect()
    }
    /// ⌈log2 s_N⌉
    fn bits_per_texel(&self) -> u32 {
        vectors::palette::quantize::index_bits(self.s_n)
    }
    fn texel_levels(&self) -> Option<Vec<Vec<i64>>> {
        Some(self.built()?.levels.iter().map(|l| l.iter().map(|&i| i as i64).collect()).collect())
    }
}

/// A frame's errors against the scene's ideal: the shade (8-bit units), the blended colour (worst channel), the
/// normal's angle where the pipeline has one, and the shade against the ideal under the pipeline's one light where
/// it lights a surface with one.
pub struct Errors {
    pub shade: vectors::stats::ErrorStats,
    pub colour: vectors::stats::ErrorStats,
    pub normal: Option<vectors::stats::ErrorStats>,
    pub surface: Option<vectors::stats::ErrorStats>,
}

/// The model's frame against the ideal.
pub fn errors(pipe: &dyn Pipeline, scene: &Scene, prep: &Prepared, model: &Image) -> Errors {
    use vectors::stats::{angle_deg, ErrorStats};
    let place = render::pixel_at(prep.size);
    let where_ = |k: usize| place(prep.frame_index(k));
    let (mut shade, mut colour) = (ErrorStats::default(), ErrorStats::default());
    let mut normal = pipe.normal(&prep.pixels()[0]).map(|_| ErrorStats::default());
    let mut surface = pipe.surface_ideal(scene, &prep.ideal[0]).map(|_| ErrorStats::default());
    for (k, (o, ideal)) in model.outs.iter().zip(&prep.ideal).enumerate() {
        shade.add((pipe.shade(o) - ideal.shade).abs(), || where_(k));
        colour.add(render::colour_err(pipe.colour(o), ideal.rgb), || where_(k));
        if let (Some(s), Some(n)) = (normal.as_mut(), pipe.normal(&prep.pixels()[k])) {
            s.add(angle_deg(n, ideal.normal), || where_(k));
        }
        if let (Some(s), Some(i)) = (surface.as_mut(), pipe.surface_ideal(scene, ideal)) {
            s.add((pipe.shade(o) - i).abs(), || where_(k));
        }
    }
    Errors { shade, colour, normal, surface }
}

/// A row's pipeline, built for a scene with these settings.
pub fn build(row: &'static Row, scene: &Scene, s: &Settings) -> Box<dyn Pipeline> {
    match row.family {
        Family::Cartesian(decode) => Box::new(Cartesian { decode, gloss: row.serves.gloss, row }),
        Family::CartSurface(variant) => Box::new(CartSurface { variant, row }),
        Family::CartTex { host, filter } => {
            Box::new(CartTex::new(row, pipelines::named(host).expect("a host row"), filter, scene, s))
        }
        Family::Polar(scale) => Box::new(Polar { scale, pw: s.pw, h: s.h, row }),
        Family::Height => Box::new(Height { row, ..Height::with_bits(scene, s.height_bits) }),
        Family::Palette => {
            let p = Palette::new(s.palette.unwrap_or(1 << row.serves.index_bits), scene);
            Box::new(Palette { row, ..p })
        }
    }
}
