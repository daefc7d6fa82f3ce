//! A pipeline's per-pixel inputs through the three bit-exact paths: the model, the rust-hdl block and Verilator on
//! the block's exported Verilog. They must agree bit for bit; the pipeline reads shade and colour off the outputs.
//! A frame's inputs may begin with a prologue (`Prepared::prologue`: vectors that set up the block's state, a
//! palette's colour table): every path runs it first and leaves its outputs out of the image.

use crate::prepared::Prepared;
use rtl::stream::Runner;
use rtl::StreamUnit;
use std::path::Path;
use std::time::Instant;
use synth::cosim::{self, Simulator};
use vectors::fixed::from_pattern;
use vectors::UnitModel;

/// One path's frame: per pixel the pipeline's output vector (values, signed where the port is), and the time the
/// path took. A pipeline turns an output vector into a shade and a colour.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub size: usize,
    pub outs: Outs,
    pub seconds: f64,
}

/// A frame's output vectors one after another in one buffer, `width` values a pixel (no allocation is kept a pixel,
/// so a frame made on several threads does not wait on the allocator); `outs[k]` is pixel k's vector.
#[derive(Clone, Debug, Default)]
pub struct Outs {
    width: usize,
    values: Vec<i64>,
}

impl Outs {
    /// `values` holds a whole number of `width`-value vectors.
    pub fn new(width: usize, values: Vec<i64>) -> Outs {
        assert!(width > 0 && values.len().is_multiple_of(width), "{} values are not vectors of {width}", values.len());
        Outs { width, values }
    }
    pub fn len(&self) -> usize {
        self.values.len().checked_div(self.width).unwrap_or(0)
    }
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }
    pub fn iter(&self) -> std::slice::ChunksExact<'_, i64> {
        self.values.chunks_exact(self.width.max(1))
    }
}

impl PartialEq for Outs {
    fn eq(&self, other: &Outs) -> bool {
        self.len() == other.len() && self.values == other.values
    }
}

impl std::ops::Index<usize> for Outs {
    type Output = [i64];
    fn index(&self, k: usize) -> &[i64] {
        &self.values[k * self.width..(k + 1) * self.width]
    }
}

impl<'a> IntoIterator for &'a Outs {
    type Item = &'a [i64];
    type IntoIter = std::slice::ChunksExact<'a, i64>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl<V: AsRef<[i64]>> FromIterator<V> for Outs {
    /// Vectors of one width (the first's).
    fn from_iter<I: IntoIterator<Item = V>>(vs: I) -> Outs {
        let mut o = Outs::default();
        for v in vs {
            let v = v.as_ref();
            if o.width == 0 {
                o.width = v.len();
            }
            assert_eq!(v.len(), o.width, "output vectors of one width");
            o.values.extend_from_slice(v);
        }
        o
    }
}

impl Image {
    pub fn pixels_per_second(&self) -> f64 {
        self.outs.len() as f64 / self.seconds.max(1e-9)
    }

    /// Pixels whose output vector differs from `other`'s.
    pub fn mismatches(&self, other: &Image) -> usize {
        self.outs.iter().zip(&other.outs).filter(|(a, b)| a != b).count() + self.outs.len().abs_diff(other.outs.len())
    }
}

/// The inputs as the unit's clock slots (a vector every `INTERVAL` clocks).
fn patterns<U: StreamUnit>(m: &UnitModel, inputs: &[Vec<i64>]) -> Vec<Option<Vec<u64>>> {
    rtl::stream::paced::<U>(inputs.iter().map(|v| vectors::unit::to_patterns(v, m.inputs))).collect()
}

fn from_outputs(m: &UnitModel, size: usize, outs: &[Vec<u64>], seconds: f64) -> Image {
    Image { size, outs: outs.iter().map(|o| vectors::unit::from_patterns(o, m.outputs)).collect(), seconds }
}

/// The model over the frame on one thread (the prologue's time counted: it is the frame's work too).
pub fn model(m: &UnitModel, p: &Prepared) -> Image {
    model_on(m, p, 1)
}

/// The model over the frame, its pixels cut into `threads` runs at once (`UnitModel::frame`: the prologue loaded
/// once, each run from a copy of the state it left); the same outputs on any number of threads.
pub fn model_on(m: &UnitModel, p: &Prepared, threads: usize) -> Image {
    timed(p.size, || Outs::new(m.outputs.len(), m.frame(&p.inputs, p.prologue, threads)))
}

/// Runs of a path whose speed is reported, the fastest kept: a frame takes milliseconds, and one run may pay alone
/// for a cold cache or a core that was asleep.
pub const RUNS: usize = 5;

/// A path run `RUNS` times, its fastest run kept.
pub fn fastest(path: impl Fn() -> Image) -> Image {
    (1..RUNS).map(|_| path()).fold(path(), |best, i| if i.seconds < best.seconds { i } else { best })
}

/// One run of a path, timed: its output vectors and the seconds they took.
pub fn timed(size: usize, run: impl FnOnce() -> Outs) -> Image {
    let t = Instant::now();
    let outs = run();
    Image { size, outs, seconds: t.elapsed().as_secs_f64() }
}

/// The machine's cores, for the paths that split a frame (one where the count is not known).
pub fn cores() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// A path's label with its thread count: "bit-exact model, 1 thread", "…, 2 threads".
pub fn on_threads(path: &str, threads: usize) -> String {
    format!("{path}, {threads} thread{}", if threads == 1 { "" } else { "s" })
}

/// rust-hdl, loop-driven; `tick` is called every 1,024 vectors.
pub fn rust_hdl<U: StreamUnit>(m: &UnitModel, p: &Prepared, tick: &dyn Fn(usize)) -> Image {
    let t = Instant::now();
    let mut r = Runner::<U>::new();
    let slots = patterns::<U>(m, &p.inputs);
    let got = r.run(slots.into_iter().enumerate().map(|(k, s)| {
        if k % 1024 == 0 {
            tick(k);
        }
        s
    }));
    from_outputs(m, p.size, &got.outputs[p.prologue..], t.elapsed().as_secs_f64())
}

/// The frame's records from `skip` on as output vectors (values, signed where the port is), flat.
fn outs_of(m: &UnitModel, f: &cosim::Frame, skip: usize) -> Vec<i64> {
    let mut out = Vec::with_capacity(f.len().saturating_sub(skip) * m.outputs.len());
    for r in f.records.chunks_exact(1 + f.n_out).skip(skip) {
        out.extend(r[1..].iter().zip(m.outputs).map(|(&x, p)| from_pattern(x, p.bits, p.signed)));
    }
    out
}

/// A frame through the exported Verilog under Verilator, twice, beside the simulator's own speed.
pub struct VerilatorRun {
    pub image: Image,
    /// the frame on one thread (its pixels must equal `image`'s)
    pub single: Image,
    pub threads: usize,
    /// cycles/s of the library's bare loop (inputs generated in C++, no memory traffic), as many cycles as the
    /// frame's slots and its flush
    pub bare_cycles_per_second: f64,
}

/// The exported Verilog under Verilator (built in `dir`, run in this process), whole frame, on one thread and then
/// split across `threads` models at once; `image` is the split run's (the demo checks both against the model).
/// The bare loop's speed on the same build is measured in the same call. Each of the three is run `RUNS` times
/// and its fastest run kept, so that none of them pays alone for a cold cache; the times count the runs (the
/// inputs' encoding, the simulation, the outputs into the image), not the build.
pub fn verilator<U: StreamUnit>(
    m: &UnitModel,
    p: &Prepared,
    dir: &Path,
    threads: usize,
) -> Result<VerilatorRun, String> {
    let built = cosim::build(&synth::Unit::of::<U>(), Simulator::Verilator, dir)?;
    let slots = patterns::<U>(m, &p.inputs);
    let prologue = p.prologue * U::INTERVAL; // its slots
                                             // one run timed from the slots to the image's output vectors, the fastest of RUNS kept
    let fastest = |run: &dyn Fn() -> Result<Vec<i64>, String>| -> Result<Image, String> {
        let mut best: Option<Image> = None;
        for _ in 0..RUNS {
            let t = Instant::now();
            let outs = Outs::new(m.outputs.len(), run()?);
            let i = Image { size: p.size, outs, seconds: t.elapsed().as_secs_f64() };
            if best.as_ref().is_none_or(|b| i.seconds < b.seconds) {
                best = Some(i);
            }
        }
        Ok(best.expect("RUNS > 0"))
    };
    let mut bare_cycles_per_second = 0.0f64;
    for _ in 0..RUNS {
        bare_cycles_per_second = bare_cycles_per_second.max(built.bare((slots.len() + U::LATENCY + 1) as u64)?);
    }
    // the prologue's records left out of the image; on several threads each part's records become output vectors in
    // its own thread
    let single = fastest(&|| Ok(outs_of(m, &built.run_frame(&slots)?, p.prologue)))?;
    let image = fastest(&|| {
        let parts = built.run_split_with(&slots, threads, prologue, |f| outs_of(m, &f, 0))?;
        Ok(parts.concat())
    })?;
    Ok(VerilatorRun { image, single, threads, bare_cycles_per_second })
}

/// Names pixel k of a `size`-wide frame, for error reports: "pixel (x, y)".
pub fn pixel_at(size: usize) -> impl Fn(usize) -> String {
    move |k| format!("pixel ({}, {})", k % size, k / size)
}

/// The colour of the frame's places the surface does not cover.
pub const BACKGROUND: [u8; 3] = [12, 12, 16];

/// Write an RGB image as PNG, whole or not at all.
pub fn write_png(path: &Path, size: usize, rgb: impl Fn(usize) -> [u8; 3]) -> Result<(), String> {
    let mut img = image::RgbImage::new(size as u32, size as u32);
    for k in 0..size * size {
        img.put_pixel((k % size) as u32, (k / size) as u32, image::Rgb(rgb(k)));
    }
    save_png(path, &img)
}

/// Any image as PNG, whole or not at all: written beside the path, then renamed onto it.
pub fn save_png<P: image::Pixel<Subpixel = S> + image::PixelWithColorType, S: image::Primitive>(
    path: &Path,
    img: &image::ImageBuffer<P, Vec<S>>,
) -> Result<(), String>
where
    [S]: image::EncodableLayout,
{
    let tmp = path.with_extension("png.partial");
    img.save_with_format(&tmp, image::ImageFormat::Png).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        format!("cannot write {}: {e}", path.display())
    })
}

/// Heat map of an error in [0, max]: black → red → yellow → white.
pub fn heat(e: f64, max: f64) -> [u8; 3] {
    let t = (e / max.max(1e-9)).clamp(0.0, 1.0) * 3.0;
    let c = |x: f64| (x.clamp(0.0, 1.0) * 255.0) as u8;
    [c(t), c(t - 1.0), c(t - 2.0)]
}

/// The end of a heat map's bar for these errors: their 99th percentile rounded up to a whole unit, at least 1, so a
/// few outliers do not leave the rest of the map black; the errors above it are drawn white.
pub fn heat_scale(errors: impl Iterator<Item = f64>) -> f64 {
    let mut v: Vec<f64> = errors.collect();
    if v.is_empty() {
        return 1.0;
    }
    v.sort_by(f64::total_cmp);
    v[((v.len() - 1) as f64 * 0.99).round() as usize].ceil().max(1.0)
}

/// A heat map's colour bar as drawn under it: `bar_height(size)` rows below a `size`-wide picture, the gradient of
/// `heat` from 0 at its left end to `max` at its right, "0" under the left end and `max` with its unit under the
/// right.
pub fn bar_height(size: usize) -> usize {
    19 * bar_scale(size)
}

fn bar_scale(size: usize) -> usize {
    (size / 128).clamp(1, 4)
}

/// The label of a heat map's top: `max` to two decimals and its unit ("LSB", "deg").
pub fn bar_label(max: f64, unit: &str) -> String {
    format!("{max:.2} {unit}")
}

/// A heat map of errors in [0, `max`] (`heat`) as PNG, whole or not at all, with its colour bar under the frame in
/// the picture itself: `err(place)` is the error at each place of the `size` × `size` frame, `None` where the
/// surface does not cover it (background); `unit` names what the bar counts ("LSB", "deg").
pub fn write_heat_png(
    path: &Path,
    size: usize,
    err: impl Fn(usize) -> Option<f64>,
    max: f64,
    unit: &str,
) -> Result<(), String> {
    save_png(path, &heat_image(size, err, max, unit)?)
}

/// The picture `write_heat_png` writes: `size` wide, `size + bar_height(size)` high.
pub fn heat_image(
    size: usize,
    err: impl Fn(usize) -> Option<f64>,
    max: f64,
    unit: &str,
) -> Result<image::RgbImage, String> {
    let s = bar_scale(size);
    let mut img = image::RgbImage::from_pixel(size as u32, (size + bar_height(size)) as u32, image::Rgb(BACKGROUND));
    for k in 0..size * size {
        img.put_pixel((k % size) as u32, (k / size) as u32, image::Rgb(err(k).map_or(BACKGROUND, |e| heat(e, max))));
    }
    let (x0, x1) = (2 * s, size - 2 * s);
    for x in x0..x1 {
        let c = heat((x - x0) as f64 / (x1 - x0 - 1).max(1) as f64 * max, max);
        for y in size + 2 * s..size + 8 * s {
            img.put_pixel(x as u32, y as u32, image::Rgb(c));
        }
    }
    let (w, h) = (img.width() as usize, img.height() as usize);
    let mut dot = |x: usize, y: usize| {
        if x < w && y < h {
            img.put_pixel(x as u32, y as u32, image::Rgb([230, 230, 230]));
        }
    };
    let y = size + 10 * s;
    let top = bar_label(max, unit);
    // the labels where both fit under the bar apart (a frame a few dozen pixels wide has the bar alone; its page
    // gives the ends beside it)
    if crate::glyphs::width(&format!("0 {top}"), s) <= x1 - x0 + s {
        crate::glyphs::draw("0", x0, y, s, &mut dot)?;
        // the label's last glyph column ends at the bar's right end (a glyph's trailing space column left off)
        let x = (x1 + s).saturating_sub(crate::glyphs::width(&top, s));
        crate::glyphs::draw(&top, x, y, s, &mut dot)?;
    }
    Ok(img)
}

/// Worst channel error of a blended colour against the ideal, 8-bit LSB.
pub fn colour_err(a: [u8; 3], ideal: [f64; 3]) -> f64 {
    (0..3).map(|c| (a[c] as f64 - ideal[c]).abs()).fold(0.0, f64::max)
}

/// A rectangle of a frame, in pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    pub x: usize,
    pub y: usize,
    pub w: usize,
    pub h: usize,
}

impl Window {
    /// The frame's places inside the window, row by row.
    pub fn places(&self, size: usize) -> Vec<usize> {
        (self.y..self.y + self.h).flat_map(|y| (self.x..self.x + self.w).map(move |x| y * size + x)).collect()
    }

    /// The pixels of a prepared frame inside the window (the places the surface covers), in frame order.
    pub fn pixels(&self, p: &Prepared) -> Vec<usize> {
        let by = p.by_place();
        self.places(p.size).into_iter().filter_map(|at| by[at]).collect()
    }

    /// The window's share of a prepared frame: the prologue, then the window's pixels (their ideals beside them).
    pub fn of(&self, p: &Prepared) -> Prepared {
        let px = self.pixels(p);
        let mut inputs: Vec<Vec<i64>> = p.inputs[..p.prologue].to_vec();
        inputs.extend(px.iter().map(|&k| p.inputs[p.prologue + k].clone()));
        let at = px.iter().map(|&k| p.frame_index(k)).collect();
        Prepared { size: p.size, inputs, prologue: p.prologue, ideal: px.iter().map(|&k| p.ideal[k]).collect(), at }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bar ends at the 99th percentile, rounded up, not at an outlier; never below 1.
    #[test]
    fn a_heat_scale_ends_at_the_99th_percentile_not_at_an_outlier() {
        let mut e: Vec<f64> = (0..1000).map(|k| (k % 100) as f64 / 40.0).collect(); // 0 … 2.475
        e.push(500.0);
        assert_eq!(heat_scale(e.iter().copied()), 3.0);
        assert_eq!(heat_scale([0.0, 0.2].into_iter()), 1.0);
        assert_eq!(heat_scale(std::iter::empty()), 1.0);
        assert_eq!(heat(3.0, 3.0), [255, 255, 255]);
        assert_eq!(heat(500.0, 3.0), [255, 255, 255]);
        assert_eq!(heat(0.0, 3.0), [0, 0, 0]);
    }

    /// The bar's labels are drawn where both fit under it apart, and left off a frame too narrow for them.
    #[test]
    fn a_heat_maps_bar_is_labelled_where_its_labels_fit() {
        let labelled = |size: usize| {
            let img = heat_image(size, |_| Some(0.0), 7.0, "LSB").unwrap();
            assert_eq!(img.height() as usize, size + bar_height(size));
            img.pixels().any(|p| p.0 == [230, 230, 230])
        };
        assert!(!labelled(16));
        assert!(!labelled(32));
        assert!(labelled(128));
        assert!(labelled(256));
        // at 128 wide the bar runs from x = 2 to 125, rows 130 to 135, black at 0 through red at a third of the way
        // to white at its end; the frame above it is coloured by the same scale (an error of 7 is white, 0 black)
        let img = heat_image(128, |k| Some(if k < 128 { 7.0 } else { 0.0 }), 7.0, "LSB").unwrap();
        let at = |x: u32, y: u32| img.get_pixel(x, y).0;
        assert_eq!((at(5, 0), at(5, 1)), ([255, 255, 255], [0, 0, 0]));
        assert_eq!((at(2, 130), at(125, 135)), ([0, 0, 0], [255, 255, 255]));
        let red = at(43, 132);
        assert!(red[0] >= 250 && red[1] <= 5 && red[2] == 0, "{red:?}");
        assert_eq!((at(1, 132), at(126, 132)), (BACKGROUND, BACKGROUND), "the bar's margins");
    }
}
