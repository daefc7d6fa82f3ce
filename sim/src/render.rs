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
use vectors::UnitModel;

/// One path's frame: per pixel the pipeline's output vector (values, signed where the port is), and the time the
/// path took. A pipeline turns an output vector into a shade and a colour.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub size: usize,
    pub outs: Vec<Vec<i64>>,
    pub seconds: f64,
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

fn patterns(m: &UnitModel, inputs: &[Vec<i64>]) -> Vec<Option<Vec<u64>>> {
    inputs.iter().map(|v| Some(vectors::unit::to_patterns(v, m.inputs))).collect()
}

fn from_outputs(m: &UnitModel, size: usize, outs: &[Vec<u64>], seconds: f64) -> Image {
    Image { size, outs: outs.iter().map(|o| vectors::unit::from_patterns(o, m.outputs)).collect(), seconds }
}

/// The model over the frame (the prologue's time counted: it is the frame's work too).
pub fn model(m: &UnitModel, p: &Prepared) -> Image {
    let t = Instant::now();
    let mut outs = m.run(&p.inputs); // vector by vector, or through the unit's state
    outs.drain(..p.prologue);
    Image { size: p.size, outs, seconds: t.elapsed().as_secs_f64() }
}

/// rust-hdl, loop-driven; `tick` is called every 1,024 vectors.
pub fn rust_hdl<U: StreamUnit>(m: &UnitModel, p: &Prepared, tick: &dyn Fn(usize)) -> Image {
    let t = Instant::now();
    let mut r = Runner::<U>::new();
    let slots = patterns(m, &p.inputs);
    let got = r.run(slots.into_iter().enumerate().map(|(k, s)| {
        if k % 1024 == 0 {
            tick(k);
        }
        s
    }));
    from_outputs(m, p.size, &got.outputs[p.prologue..], t.elapsed().as_secs_f64())
}

/// The frame's records from `skip` on as an image.
fn from_frame(m: &UnitModel, size: usize, f: &cosim::Frame, skip: usize) -> Image {
    let outs: Vec<Vec<u64>> = (skip..f.len()).map(|k| (0..m.outputs.len()).map(|j| f.value(k, j)).collect()).collect();
    from_outputs(m, size, &outs, 0.0)
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
    const RUNS: usize = 3;
    let built = cosim::build::<U>(Simulator::Verilator, dir)?;
    let slots = patterns(m, &p.inputs);
    // one run timed from the slots to the image, the fastest of RUNS kept; `skip` records are the prologue's
    let fastest = |run: &dyn Fn() -> Result<cosim::Frame, String>, skip: usize| -> Result<Image, String> {
        let mut best: Option<Image> = None;
        for _ in 0..RUNS {
            let t = Instant::now();
            let f = run()?;
            let mut i = from_frame(m, p.size, &f, skip);
            i.seconds = t.elapsed().as_secs_f64();
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
    let single = fastest(&|| built.run_frame(&slots), p.prologue)?;
    let image = fastest(&|| built.run_split(&slots, threads, p.prologue), 0)?;
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
