//! `bumprtl quantize MAP.png --size N`: Tarini et al.'s preprocessing on a user's map. An RGB PNG is a tangent-space
//! normal
//! map (OpenGL: green up; `--green-down` for DirectX's), a grey PNG a height map turned into normals by §4.1's plane
//! fit. Writes the palette (CSV and a swatch), the index map (16-bit grey PNG and raw little-endian u16) and its mip
//! chain, and prints what it found and how long each step took. The map is read, and refused in one line, before
//! anything is written.

use std::path::Path;
use std::time::Instant;
use vectors::palette::{plane_fit, quantize};

pub struct Args<'a> {
    pub map: &'a Path,
    pub size: usize,
    pub dither: bool,
    pub green_down: bool,
    pub relief: Option<f64>,
    pub q: usize,
    pub out: &'a Path,
}

fn index_png(path: &Path, index: &[u32], w: usize, h: usize) -> Result<(), String> {
    let img = image::ImageBuffer::<image::Luma<u16>, Vec<u16>>::from_fn(w as u32, h as u32, |x, y| {
        image::Luma([index[y as usize * w + x as usize] as u16])
    });
    sim::render::save_png(path, &img)
}

pub fn run(a: &Args) -> Result<(), String> {
    let name = a.map.display();
    let t = Instant::now();
    let img = sim::heightmap::read_png(a.map, "normal or height map")?;
    let (w, h) = (img.width() as usize, img.height() as usize);
    let load_s = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let (normals, what) = if sim::heightmap::is_grey(&img) {
        let relief = a.relief.unwrap_or(w.max(h) as f64 / 16.0);
        let heights: Vec<f64> = sim::heightmap::grey_values(&img).iter().map(|g| g * relief).collect();
        // the plane fit's frame (x right, y up out of the surface, z down the image) → OpenGL's (x, y up the image, z
        // out)
        let n = plane_fit::normals(&heights, w, h, a.q).into_iter().map(|p| [p[0], -p[2], p[1]]).collect();
        (n, format!("a grey PNG: a height map (white {relief:.2} texels above black), normals by the least-squares plane over {} neighbours", a.q))
    } else {
        let (n, zero) = sim::heightmap::normal_values(&img, a.green_down);
        let conv = if a.green_down { "DirectX, green down" } else { "OpenGL, green up" };
        let z = if zero > 0 { format!("; {zero} zero-length texels read as straight out") } else { String::new() };
        let z = if img.color().has_alpha() { format!("{z}; its alpha channel is ignored") } else { z };
        (n, format!("an RGB PNG: a tangent-space normal map ({conv}){z}"))
    };
    let normals_s = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let q = crate::progress::step(
        &format!("{name}: {} normals quantized to {}", normals.len(), a.size),
        |q: &quantize::Quantized| Some(format!("{} palette entries", q.palette.len())),
        || quantize::quantize(&normals, a.size),
    );
    let quant_s = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let index = if a.dither {
        crate::progress::step(
            &format!("{name}: dithered"),
            |i: &Vec<u32>| Some(format!("{} texels", i.len())),
            || quantize::dither(&normals, w, h, &q.palette),
        )
    } else {
        q.index.clone()
    };
    let dither_s = t.elapsed().as_secs_f64();
    let err = quantize::angular_error(&normals, &index, &q.palette);
    let t = Instant::now();
    let chain = quantize::mip_chain(&index, w, h, &q.palette);
    let mip_s = t.elapsed().as_secs_f64();

    // everything is computed: now write
    let t = Instant::now();
    std::fs::create_dir_all(a.out).map_err(|e| format!("cannot create {}: {e}", a.out.display()))?;
    let mut csv = String::from(
        "# unit normals, OpenGL tangent frame (x right, y up the image, z out of the surface)\nindex,x,y,z\n",
    );
    for (k, n) in q.palette.iter().enumerate() {
        csv.push_str(&format!("{k},{:.9},{:.9},{:.9}\n", n[0], n[1], n[2]));
    }
    synth::export::write_atomic(&a.out.join("palette.csv"), csv.as_bytes())?;
    // the swatch: one 8-pixel cell per entry, row by row, each the normal as a normal map colours it
    let cells = (q.palette.len() as f64).sqrt().ceil() as usize;
    let cell = (1024 / cells).clamp(1, 8);
    let side = (cells * cell) as u32;
    let swatch = image::RgbImage::from_fn(side, side, |x, y| {
        let k = (y as usize / cell) * cells + x as usize / cell;
        match q.palette.get(k) {
            Some(n) => image::Rgb(n.map(|c| (c * 127.5 + 127.5).round().clamp(0.0, 255.0) as u8)),
            None => image::Rgb([0, 0, 0]),
        }
    });
    sim::render::save_png(&a.out.join("palette.png"), &swatch)?;
    index_png(&a.out.join("index.png"), &index, w, h)?;
    let raw: Vec<u8> = index.iter().flat_map(|&i| (i as u16).to_le_bytes()).collect();
    synth::export::write_atomic(&a.out.join("index.raw"), &raw)?;
    let mut names = vec!["palette.csv".to_string(), "palette.png".into(), "index.png".into(), "index.raw".into()];
    for (level, (idx, lw, lh)) in chain.iter().enumerate().skip(1) {
        let f = format!("mip{level}.png");
        index_png(&a.out.join(&f), idx, *lw, *lh)?;
        names.push(f);
    }
    let write_s = t.elapsed().as_secs_f64();

    println!("{name}: {w} × {h}, {what}");
    println!("distinct normals: {}", q.distinct);
    println!(
        "palette: {} normals of {} asked, {}-bit indices{}",
        q.palette.len(),
        a.size,
        q.index_bits(),
        if a.dither { ", dithered" } else { "" }
    );
    println!(
        "angle to the input normals: mean {:.4}°, max {:.4}° ({})",
        err.mean(),
        err.max.max(0.0),
        if err.max > 0.0 { err.argmax.as_str() } else { "none" }
    );
    println!("mip chain: {} levels below the map, down to 1 × 1", chain.len() - 1);
    let ms = |s: f64| format!("{:.1} ms", s * 1e3);
    println!(
        "time: read {}, normals {}, palette {}, {} {}, mips {}, write {}",
        ms(load_s),
        ms(normals_s),
        ms(quant_s),
        if a.dither { "dither" } else { "index" },
        ms(dither_s),
        ms(mip_s),
        ms(write_s)
    );
    println!("wrote {}: {}", a.out.display(), names.join(", "));
    Ok(())
}
