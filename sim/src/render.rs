//! A scene through the four paths. The ideal and the model are computed here; rust-hdl runs the `cart_pipeline`
//! block; Verilator runs its exported Verilog. The last three must agree bit for bit.

use rtl::cart_pipeline::CartPipeline;
use rtl::stream::Runner;
use std::path::Path;
use std::time::Instant;
use synth::cosim::{self, Simulator};
use vectors::cart_pipeline::MODEL;
use vectors::fixed::to_pattern;
use vectors::scene::Prepared;

/// One path's image: per pixel P (U10) and the blended colour.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub size: usize,
    pub p: Vec<i64>,
    pub rgb: Vec<[i64; 3]>,
    pub seconds: f64,
}

impl Image {
    pub fn pixels_per_second(&self) -> f64 {
        (self.size * self.size) as f64 / self.seconds.max(1e-9)
    }
}

fn patterns(p: &Prepared) -> Vec<Option<Vec<u64>>> {
    p.inputs.iter().map(|v| Some(v.iter().zip(MODEL.inputs).map(|(&x, port)| to_pattern(x, port.bits)).collect())).collect()
}

fn from_outputs(size: usize, outs: &[Vec<u64>], seconds: f64) -> Image {
    Image {
        size,
        p: outs.iter().map(|o| o[0] as i64).collect(),
        rgb: outs.iter().map(|o| [o[1] as i64, o[2] as i64, o[3] as i64]).collect(),
        seconds,
    }
}

pub fn model(p: &Prepared) -> Image {
    let t = Instant::now();
    let outs: Vec<Vec<u64>> = p.inputs.iter().map(|v| (MODEL.exact)(v).iter().map(|&x| x as u64).collect()).collect();
    from_outputs(p.size, &outs, t.elapsed().as_secs_f64())
}

/// rust-hdl, loop-driven; `tick` is called every 1,024 pixels.
pub fn rust_hdl(p: &Prepared, tick: &dyn Fn(usize)) -> Image {
    let t = Instant::now();
    let mut r = Runner::<CartPipeline>::new();
    let slots = patterns(p);
    let got = r.run(slots.into_iter().enumerate().map(|(k, s)| {
        if k % 1024 == 0 {
            tick(k);
        }
        s
    }));
    from_outputs(p.size, &got.outputs, t.elapsed().as_secs_f64())
}

/// The exported Verilog under Verilator (built in `dir`); the time counts the run, not the build.
pub fn verilator(p: &Prepared, dir: &Path) -> Result<Image, String> {
    let built = cosim::build::<CartPipeline>(Simulator::Verilator, dir)?;
    let slots = patterns(p);
    let t = Instant::now();
    let got = built.run(&slots)?;
    Ok(from_outputs(p.size, &got.outputs, t.elapsed().as_secs_f64()))
}

/// Write an RGB image as PNG, whole or not at all.
pub fn write_png(path: &Path, size: usize, rgb: impl Fn(usize) -> [u8; 3]) -> Result<(), String> {
    let mut img = image::RgbImage::new(size as u32, size as u32);
    for k in 0..size * size {
        img.put_pixel((k % size) as u32, (k / size) as u32, image::Rgb(rgb(k)));
    }
    let tmp = path.with_extension("png.partial");
    img.save_with_format(&tmp, image::ImageFormat::Png).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    std::fs::rename(&tmp, path).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// Heat map of an error in [0, max]: black → red → yellow → white.
pub fn heat(e: f64, max: f64) -> [u8; 3] {
    let t = (e / max.max(1e-9)).clamp(0.0, 1.0) * 3.0;
    let c = |x: f64| (x.clamp(0.0, 1.0) * 255.0) as u8;
    [c(t), c(t - 1.0), c(t - 2.0)]
}
