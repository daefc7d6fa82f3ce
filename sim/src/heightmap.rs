//! A user's height map from a PNG: 8- or 16-bit greyscale as it is, colour read as its luma (and said so), any
//! size from 2 × 2 up, brought to the square power-of-two side the height path's memory holds (2^n texels, n ≤ 8)
//! by bilinear resampling when it is not one already (and said so). Heights come out in [0, 1], white the highest.
//! Every failure is one line naming the file and what is wrong with it. A user's normal map (RGB PNG) is read here
//! too, into a `NormalMap`.

use std::path::Path;

/// Square, `side` = 2^n texels, row-major heights in [0, 1].
#[derive(Clone, Debug, PartialEq)]
pub struct HeightMap {
    pub side: usize,
    pub h: Vec<f64>,
}

/// A tangent-space normal map in the project's frame (x along u, y out of the surface, z along v, down the image):
/// `side` × `side` unit normals, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct NormalMap {
    pub side: usize,
    pub n: Vec<[f64; 3]>,
}

/// A colour map: `side` × `side` texels (the bump map's side), row-major, each channel in 0..=255 (real where the
/// file was resampled).
#[derive(Clone, Debug, PartialEq)]
pub struct ColourMap {
    pub side: usize,
    pub rgb: Vec<[f64; 3]>,
}

/// A colour map and the lines to tell the user about how it was read.
pub struct LoadedColour {
    pub map: ColourMap,
    pub notes: Vec<String>,
}

/// The largest side the height path's memory (`height_fetch`) holds.
pub const MAX_SIDE: usize = 256;

/// A map and the lines to tell the user about how it was read.
pub struct Loaded {
    pub map: HeightMap,
    /// bits per channel of the file (8 or 16)
    pub depth: u16,
    pub notes: Vec<String>,
}

/// A normal map and the lines to tell the user about how it was read.
pub struct LoadedNormals {
    pub map: NormalMap,
    pub notes: Vec<String>,
}

impl HeightMap {
    /// The height at (u, v) ∈ [0, 1]², bilinear between texel centres (at (i + ½)/side), clamped at the border.
    pub fn at(&self, u: f64, v: f64) -> f64 {
        bilinear(&self.h, self.side, self.side, u * self.side as f64 - 0.5, v * self.side as f64 - 0.5)
    }
}

/// Bilinear sample of a w × h grid at (x, y) in texel units (centres at integers), clamped at the border.
fn bilinear(g: &[f64], w: usize, h: usize, x: f64, y: f64) -> f64 {
    let (x, y) = (x.clamp(0.0, (w - 1) as f64), y.clamp(0.0, (h - 1) as f64));
    let (i0, j0) = (x.floor() as usize, y.floor() as usize);
    let (i1, j1) = ((i0 + 1).min(w - 1), (j0 + 1).min(h - 1));
    let (fx, fy) = (x - i0 as f64, y - j0 as f64);
    let at = |i: usize, j: usize| g[j * w + i];
    vectors::bilinear::ideal_channel(at(i0, j0), at(i1, j0), at(i0, j1), at(i1, j1), fx, fy)
}

/// A w × h grid brought to side × side, bilinear between the texel centres (the pixel centres of the new grid
/// mapped onto the old one).
fn resample(g: &[f64], w: usize, h: usize, side: usize) -> Vec<f64> {
    let s = side as f64;
    (0..side * side)
        .map(|k| {
            let (x, y) = ((k % side) as f64 + 0.5, (k / side) as f64 + 0.5);
            bilinear(g, w, h, x * w as f64 / s - 0.5, y * h as f64 / s - 0.5)
        })
        .collect()
}

const PNG_SIGNATURE: &[u8] = b"\x89PNG\r\n\x1a\n";

/// A PNG of at least 2 × 2 pixels, or one line naming the file and what is wrong (`what`: "height map", …).
pub fn read_png(path: &Path, what: &str) -> Result<image::DynamicImage, String> {
    let name = path.display();
    let bytes = std::fs::read(path).map_err(|e| format!("{name}: cannot read the {what}: {e}"))?;
    png_from_bytes(&bytes, &name.to_string(), what)
}

/// The same from bytes in memory (`name` for the errors).
pub fn png_from_bytes(bytes: &[u8], name: &str, what: &str) -> Result<image::DynamicImage, String> {
    if bytes.is_empty() {
        return Err(format!("{name}: the {what} is an empty file"));
    }
    if !bytes.starts_with(PNG_SIGNATURE) {
        return Err(format!("{name}: not a PNG file (it does not start with the PNG signature)"));
    }
    let img = image::load_from_memory_with_format(bytes, image::ImageFormat::Png)
        .map_err(|e| format!("{name}: not a readable PNG: {}", e.to_string().replace('\n', " ")))?;
    let (w, h) = (img.width() as usize, img.height() as usize);
    if w < 2 || h < 2 {
        return Err(format!("{name}: {w} × {h} pixels; a {what} needs at least 2 × 2"));
    }
    Ok(img)
}

/// Bits a channel of the image holds (8 or 16).
pub fn depth(img: &image::DynamicImage) -> u16 {
    img.color().bits_per_pixel() / img.color().channel_count() as u16
}

/// Whether the image is greyscale (with or without alpha).
pub fn is_grey(img: &image::DynamicImage) -> bool {
    use image::ColorType::*;
    matches!(img.color(), L8 | L16 | La8 | La16)
}

/// A grey image's values in [0, 1] (8 or 16 bits), row-major.
pub fn grey_values(img: &image::DynamicImage) -> Vec<f64> {
    if depth(img) == 16 {
        img.to_luma16().pixels().map(|p| p.0[0] as f64 / 65_535.0).collect()
    } else {
        img.to_luma8().pixels().map(|p| p.0[0] as f64 / 255.0).collect()
    }
}

/// A colour image's channels as they are stored (0..=255 or 0..=65,535), row-major, and the largest value.
fn rgb_values(img: &image::DynamicImage) -> (Vec<[f64; 3]>, f64) {
    if depth(img) == 16 {
        (img.to_rgb16().pixels().map(|p| p.0.map(|c| c as f64)).collect(), 65_535.0)
    } else {
        (img.to_rgb8().pixels().map(|p| p.0.map(|c| c as f64)).collect(), 255.0)
    }
}

/// A tangent-space normal map's normals from an RGB(A) image, in the OpenGL frame (x right, y up the image, z out):
/// each channel c in 0..=max read as 2c/max − 1, green negated for a DirectX (green-down) map, then normalised.
/// A zero-length texel (all channels at the middle) comes out straight out of the surface, and is counted.
pub fn normal_values(img: &image::DynamicImage, green_down: bool) -> (Vec<[f64; 3]>, usize) {
    let (raw, top) = rgb_values(img);
    let rgb: Vec<[f64; 3]> = raw.iter().map(|p| p.map(|c| 2.0 * c / top - 1.0)).collect();
    let mut zero = 0;
    let n = rgb
        .into_iter()
        .map(|[x, y, z]| {
            let y = if green_down { -y } else { y };
            let l = (x * x + y * y + z * z).sqrt();
            if l < 1e-6 {
                zero += 1;
                [0.0, 0.0, 1.0]
            } else {
                [x / l, y / l, z / l]
            }
        })
        .collect();
    (n, zero)
}

pub fn load(path: &Path) -> Result<Loaded, String> {
    let name = path.display();
    let img = read_png(path, "height map")?;
    let (w, h) = (img.width() as usize, img.height() as usize);
    let mut notes = vec![];
    let depth = depth(&img);
    let grey: Vec<f64> = match is_grey(&img) {
        true => {
            if img.color().has_alpha() {
                notes.push(format!("{name}: its alpha channel is ignored"));
            }
            grey_values(&img)
        }
        false => {
            notes.push(format!(
                "{name}: a colour PNG ({} channels, {depth}-bit), read as its luma 0.2126 R + 0.7152 G + 0.0722 B",
                img.color().channel_count()
            ));
            let (rgb, top) = rgb_values(&img);
            rgb.iter().map(|&[r, g, b]| (0.2126 * r + 0.7152 * g + 0.0722 * b) / top).collect()
        }
    };
    if depth == 16 {
        notes.push(format!(
            "{name}: 16-bit heights: the Cartesian and polar normals use all 16 bits, the height path stores 8"
        ));
    }
    let side = w.max(h).next_power_of_two().min(MAX_SIDE);
    let map = if w == side && h == side {
        HeightMap { side, h: grey }
    } else {
        notes.push(format!(
            "{name}: {w} × {h} resampled (bilinear) to {side} × {side}: the height path holds square maps of 2^n texels up to {MAX_SIDE}"
        ));
        HeightMap { side, h: resample(&grey, w, h, side) }
    };
    Ok(Loaded { map, depth, notes })
}

/// A user's tangent-space normal map: an 8-bit RGB(A) PNG (the texel encodings hold 8 bits a component; a 16-bit
/// map is refused rather than silently cut), OpenGL's green up the image unless `green_down` (DirectX), into the
/// project's frame (x along u, y out, z down the image); brought to a square power-of-two side up to `MAX_SIDE`
/// like a height map (each component bilinear, then renormalised), and said so.
pub fn load_normal_map(path: &Path, green_down: bool) -> Result<LoadedNormals, String> {
    let name = path.display();
    let img = read_png(path, "normal map")?;
    if is_grey(&img) {
        return Err(format!("{name}: a grey PNG is a height map, not a normal map (source = \"height_map\" reads it)"));
    }
    if depth(&img) != 8 {
        return Err(format!("{name}: a {}-bit normal map where 8 bits are required (the texel encodings hold 8 bits a component); save it as 8-bit", depth(&img)));
    }
    let mut notes = vec![];
    if img.color().has_alpha() {
        notes.push(format!("{name}: its alpha channel is ignored"));
    }
    let (w, h) = (img.width() as usize, img.height() as usize);
    let (gl, zero) = normal_values(&img, green_down);
    if zero > 0 {
        notes.push(format!("{name}: {zero} zero-length texels read as straight out of the surface"));
    }
    // OpenGL's (x, y up the image, z out) → the project's (x, y out, z down the image)
    let n: Vec<[f64; 3]> = gl.iter().map(|g| [g[0], g[2], -g[1]]).collect();
    let side = w.max(h).next_power_of_two().min(MAX_SIDE);
    if w == side && h == side {
        return Ok(LoadedNormals { map: NormalMap { side, n }, notes });
    }
    notes.push(format!("{name}: {w} × {h} resampled (bilinear, renormalised) to {side} × {side}: maps are square, 2^n texels up to {MAX_SIDE}"));
    let comp: Vec<Vec<f64>> =
        (0..3).map(|c| resample(&n.iter().map(|v| v[c]).collect::<Vec<_>>(), w, h, side)).collect();
    let out = (0..side * side)
        .map(|k| {
            let v = [comp[0][k], comp[1][k], comp[2][k]];
            let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            if l < 1e-9 {
                [0.0, 1.0, 0.0]
            } else {
                v.map(|c| c / l)
            }
        })
        .collect();
    Ok(LoadedNormals { map: NormalMap { side, n: out }, notes })
}

const JPEG_SIGNATURE: &[u8] = b"\xff\xd8\xff";

/// A colour map (`[material] colour_map`): an 8-bit RGB(A) or grey PNG (alpha ignored, and said so), brought to the
/// bump map's side × side (each channel bilinear between texel centres) when it is not that already, and said so.
/// A JPEG is refused in one line: the project reads PNG only.
pub fn load_colour_map(path: &Path, side: usize) -> Result<LoadedColour, String> {
    let name = path.display();
    let bytes = std::fs::read(path).map_err(|e| format!("{name}: cannot read the colour map: {e}"))?;
    if bytes.starts_with(JPEG_SIGNATURE) {
        return Err(format!("{name}: a JPEG; colour maps are read from PNG files only (save it as an 8-bit RGB PNG)"));
    }
    let img = png_from_bytes(&bytes, &name.to_string(), "colour map")?;
    if depth(&img) != 8 {
        return Err(format!(
            "{name}: a {}-bit colour map where 8 bits are required (the blend's colours are 8 bits a channel); save it as 8-bit",
            depth(&img)
        ));
    }
    let mut notes = vec![];
    if img.color().has_alpha() {
        notes.push(format!("{name}: its alpha channel is ignored"));
    }
    let (w, h) = (img.width() as usize, img.height() as usize);
    let rgb: Vec<[f64; 3]> = img.to_rgb8().pixels().map(|p| p.0.map(f64::from)).collect();
    if w == side && h == side {
        return Ok(LoadedColour { map: ColourMap { side, rgb }, notes });
    }
    notes.push(format!(
        "{name}: {w} × {h} resampled (bilinear) to {side} × {side}: the colour map takes the bump map's side"
    ));
    let comp: Vec<Vec<f64>> =
        (0..3).map(|c| resample(&rgb.iter().map(|v| v[c]).collect::<Vec<_>>(), w, h, side)).collect();
    let rgb = (0..side * side).map(|k| [comp[0][k], comp[1][k], comp[2][k]]).collect();
    Ok(LoadedColour { map: ColourMap { side, rgb }, notes })
}

impl ColourMap {
    /// A built-in colour map of `side` × `side` texels for the tests and the tables that run every pipeline on one
    /// scene: 4 × 4 tiles of six glazes, each shaded from its top-left corner to its bottom-right (so a filter
    /// has gradients to blend as well as edges), and one-texel grey joints where the side allows.
    pub fn tiles(side: usize) -> ColourMap {
        const GLAZES: [[f64; 3]; 6] = [
            [176.0, 64.0, 48.0],
            [40.0, 112.0, 160.0],
            [224.0, 184.0, 72.0],
            [64.0, 144.0, 88.0],
            [136.0, 80.0, 152.0],
            [232.0, 224.0, 208.0],
        ];
        let tile = (side / 4).max(1);
        let rgb = (0..side * side)
            .map(|k| {
                let (x, y) = (k % side, k / side);
                let (tx, ty, ix, iy) = (x / tile, y / tile, x % tile, y % tile);
                if tile >= 4 && (ix == 0 || iy == 0) {
                    return [120.0, 116.0, 110.0];
                }
                let g = GLAZES[(tx + 2 * ty + ty / 2) % GLAZES.len()];
                let shade = 1.0 - 0.35 * (ix + iy) as f64 / (2 * tile) as f64;
                g.map(|c| (c * shade).round())
            })
            .collect();
        ColourMap { side, rgb }
    }

    /// The colour at (x, y) in texels (centres at i + ½), bilinear, each axis repeating (`wrap`) or clamped.
    pub fn at(&self, x: f64, y: f64, wrap: [bool; 2]) -> [f64; 3] {
        let n = self.side as i64;
        let (x, y) = (x - 0.5, y - 0.5);
        let (fx, fy) = (x - x.floor(), y - y.floor());
        let idx = |c: f64, k: i64, w: bool| {
            let i = c.floor() as i64 + k;
            if w {
                i.rem_euclid(n)
            } else {
                i.clamp(0, n - 1)
            }
        };
        let (i0, i1, j0, j1) = (idx(x, 0, wrap[0]), idx(x, 1, wrap[0]), idx(y, 0, wrap[1]), idx(y, 1, wrap[1]));
        let t = |i: i64, j: i64| self.rgb[(j * n + i) as usize];
        std::array::from_fn(|c| {
            vectors::bilinear::ideal_channel(t(i0, j0)[c], t(i1, j0)[c], t(i0, j1)[c], t(i1, j1)[c], fx, fy)
        })
    }

    /// The MIP chain, level 0 first, down to 1 × 1: each texel the mean of the four under it.
    pub fn chain(&self) -> Vec<Vec<[f64; 3]>> {
        let mut chain = vec![self.rgb.clone()];
        let mut side = self.side;
        while side > 1 {
            let (up, half) = (chain.last().unwrap(), side / 2);
            let level = (0..half * half)
                .map(|k| {
                    let (x, y) = (k % half, k / half);
                    std::array::from_fn(|c| {
                        [(0, 0), (1, 0), (0, 1), (1, 1)]
                            .iter()
                            .map(|(dx, dy)| up[(2 * y + dy) * side + 2 * x + dx][c])
                            .sum::<f64>()
                            / 4.0
                    })
                })
                .collect();
            chain.push(level);
            side = half;
        }
        chain
    }
}
