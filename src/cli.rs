use clap::{Parser, Subcommand};
use std::path::PathBuf;

#[derive(Parser)]
#[command(
    name = "bumprtl",
    version,
    about = "Bump-mapping shading hardware: model, rtl, vectors, waveforms, Verilog, synthesis"
)]
struct Cli {
    #[command(subcommand)]
    cmd: Cmd,
}

#[derive(Subcommand)]
enum Cmd {
    /// Write a unit's test vectors as CSV (header of port names, decimal values)
    Vectors {
        unit: String,
        /// every input vector (units whose input space is at most 2^20)
        #[arg(long)]
        exhaustive: bool,
        /// random vectors after the hard cases
        #[arg(long, default_value_t = 1000)]
        count: usize,
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// output file (default, or `-`: standard output)
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Export a unit's Verilog into DIR/<unit>.v, with a self-checking testbench of its golden vectors
    /// (DIR/<unit>_tb.v, DIR/<unit>_in.hex, DIR/<unit>_out.hex)
    Verilog {
        #[arg(required_unless_present = "scene")]
        unit: Option<String>,
        /// instead of a unit: the pipeline this scene file is rendered by (its module alone)
        #[arg(long, conflicts_with = "unit")]
        scene: Option<PathBuf>,
        /// output folder; `-` prints the module alone to standard output
        #[arg(long)]
        out: PathBuf,
    },
    /// Trace a unit in rust-hdl to a VCD (hard cases, then random vectors)
    Wave {
        unit: String,
        /// the VCD file; `-` is standard output
        #[arg(long)]
        out: PathBuf,
        #[arg(long, default_value_t = 64)]
        count: usize,
    },
    /// Synthesise and place a unit (through a serial I/O wrapper): LUT, FF, DSP, BRAM, fmax, each as a share of
    /// the part
    Synth {
        #[arg(required_unless_present = "scene")]
        unit: Option<String>,
        /// instead of a unit: the pipeline this scene file is rendered by
        #[arg(long, conflicts_with = "unit")]
        scene: Option<PathBuf>,
        /// up5k, ecp5-25f, ecp5-45f or ecp5-85f; default: the UP5K if the unit fits it, else the smallest ECP5
        #[arg(long)]
        target: Option<String>,
        /// working folder for the tools' files
        #[arg(long, default_value = "target/synth")]
        dir: PathBuf,
        /// the clock target given to nextpnr, MHz (default: 50 for the UP5K, 125 for the ECP5)
        #[arg(long)]
        freq: Option<f64>,
    },
    /// Every signal of a unit's rtl block: its declared format and the range it takes over the unit's vectors in
    /// rust-hdl (every input up to 2^20, else the hard cases and --count random vectors), bits needed and spare
    Widths {
        unit: String,
        /// random vectors after the hard cases (units with more than 2^20 inputs)
        #[arg(long, default_value_t = 1_000_000)]
        count: usize,
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// also write the table as CSV
        #[arg(long)]
        csv: Option<PathBuf>,
        /// instead of the signals: sweep the unit's width parameters (normalise, sincos, bilinear, power), print
        /// error against cost with its Pareto set, and mark the cheapest setting whose max error is within this
        /// budget (Sq1.10 LSB of the worst component for normalise, 8-bit LSB for the others)
        #[arg(long, value_parser = budget, conflicts_with = "csv")]
        budget: Option<f64>,
        /// with --budget: the part whose cells yosys counts (its family): up5k, ecp5-25f, ecp5-45f or ecp5-85f
        #[arg(long, default_value = "up5k", requires = "budget")]
        target: String,
        /// with --budget: working folder for yosys's files
        #[arg(long, default_value = "target/synth/widths", requires = "budget")]
        dir: PathBuf,
    },
    /// Exact against ideal for every unit, and the encoders' angular error
    Accuracy {
        /// random hemisphere directions per encoder
        #[arg(long, default_value_t = sim::accuracy::DIRECTIONS)]
        directions: usize,
        #[arg(long, default_value_t = 200_000)]
        samples: usize,
        /// also cost every sin/cos table size with yosys (iCE40 LUT4 / FF / BRAM)
        #[arg(long)]
        lut_cost: bool,
        /// working folder for yosys's files (with --lut-cost)
        #[arg(long, default_value = "target/synth/lut-sizes")]
        dir: PathBuf,
    },
    /// Quantize a normal map (RGB PNG) or a height map (grey PNG) to a palette of N normals (seed 004): the palette,
    /// the index map and its mip chain into DIR
    Quantize {
        map: PathBuf,
        /// palette size s_N (1..=16384)
        #[arg(long, value_parser = clap::value_parser!(u32).range(1..=16384))]
        size: u32,
        /// error-diffusion dithering of the index map
        #[arg(long)]
        dither: bool,
        /// the RGB map's green channel points down the image (DirectX); default up (OpenGL)
        #[arg(long)]
        green_down: bool,
        /// a grey map's white above its black, in texels (default: a sixteenth of its larger side)
        #[arg(long, value_parser = relief)]
        relief: Option<f64>,
        /// neighbours of the plane fit for a grey map: 4 or 8
        #[arg(long, default_value_t = 8, value_parser = neighbours)]
        q: usize,
        #[arg(long)]
        out: PathBuf,
    },
    /// Table 1 of Tarini et al. (2000) on this machine: the per-frame colour table's time for 256, 2048 and 16,384
    /// normals under four lighting models, beside the paper's, with the rtl builder's and the errors; the quantizer's
    /// time at every s_N; Figure 3's pictures (16 … 2048 normals)
    PaletteTable {
        /// skip placing the table builders (their fmax gives the rtl columns)
        #[arg(long)]
        no_synth: bool,
        /// working folder for the tools' files
        #[arg(long, default_value = "target/synth")]
        dir: PathBuf,
        /// where Figure 3's pictures go
        #[arg(long, default_value = "out/palette-table")]
        out: PathBuf,
    },
    /// Render a scene file (scenes/*.toml) through the pipeline it names: the f64 ideal, the bit-exact model,
    /// Verilator for the whole frame and rust-hdl for a window (traced to a VCD); fails if the rtl and the model differ
    Render {
        scene: PathBuf,
        #[arg(long, default_value = "out/render")]
        out: PathBuf,
        /// the rust-hdl window, x,y,w,h in pixels (default: the centre 8 × 8)
        #[arg(long, value_parser = crate::render::parse_window)]
        window: Option<sim::render::Window>,
        /// skip the Verilator path (the rust-hdl window still checks the rtl)
        #[arg(long)]
        no_verilator: bool,
    },
    /// The design knobs swept over scenes: each point's error against the scene's ideal (colour, shade, normal
    /// angle; for the Cartesian pipelines the shade's error split into encoding, method and datapath) beside its
    /// cost (iCE40 cells, placement, latency) and the model's speed; a Markdown table (DIR/report.md), a Pareto
    /// plot (DIR/pareto.png) and the cheapest configuration within each --budget. Every point is independent:
    /// --plan writes one command per point and a merge step (GNU parallel, ssh, a Slurm array)
    Report {
        /// a scene to sweep over (repeatable): `demo`, `quad` (the embedded ones) or a scene file; default both
        /// embedded
        #[arg(long = "scene")]
        scenes: Vec<String>,
        #[arg(long, default_value = "out/report")]
        out: PathBuf,
        /// an error budget, mean colour error in 8-bit LSB (repeatable): the cheapest point within it, per scene
        #[arg(long = "budget", value_parser = budget)]
        budgets: Vec<f64>,
        /// skip nextpnr (yosys cells only; no logic cells or fmax)
        #[arg(long)]
        no_place: bool,
        /// only the points whose id contains this text
        #[arg(long)]
        only: Option<String>,
        /// instead of running: write one command per point into this file, the merge step into FILE.merge and a
        /// Slurm job array into FILE.slurm
        #[arg(long, conflicts_with_all = ["point", "merge"])]
        plan: Option<PathBuf>,
        /// run one point of the plan and save it under DIR/points/
        #[arg(long, conflicts_with = "merge")]
        point: Option<String>,
        /// read the saved points under DIR/points/ and write the report
        #[arg(long)]
        merge: bool,
    },
    /// The hard cases the seeds warn about, unit by unit: what they ask, what the rtl does (rust-hdl, held to the
    /// model), pass or fail, as a Markdown table; fails if any row fails
    Hardcases,
    /// The main job: the default scene through ideal, model, rust-hdl and Verilator; PNGs, VCD, Verilog, table
    Demo {
        #[arg(long, default_value = "out/demo")]
        out: PathBuf,
        /// image side in pixels (16..=1024)
        #[arg(long, default_value_t = 256, value_parser = clap::value_parser!(u32).range(16..=1024))]
        size: u32,
        /// angle scale of the polar path: the seed's (256 = 90°/360°) or the Dreamcast toolchains' (255)
        #[arg(long, value_enum, default_value_t = PolarScale::Seed)]
        polar_scale: PolarScale,
        /// skip yosys and nextpnr (the hardware-cost rows; minutes on the first run, cached after)
        #[arg(long)]
        no_synth: bool,
        /// your own height map (PNG, 8- or 16-bit grey; colour is read as luma), in place of the procedural one
        #[arg(long, value_name = "FILE.png")]
        height_map: Option<PathBuf>,
        /// the rise of the map's white above its black, in texels (default: a sixteenth of its side)
        #[arg(long, requires = "height_map", value_parser = relief)]
        relief: Option<f64>,
    },
}

/// The plane fit's neighbourhood: 4 or 8.
fn neighbours(s: &str) -> Result<usize, String> {
    match s {
        "4" => Ok(4),
        "8" => Ok(8),
        _ => Err(format!("`{s}`: the plane fit takes 4 or 8 neighbours")),
    }
}

/// A relief in texels: positive, finite, at most 64.
fn relief(s: &str) -> Result<f64, String> {
    let r: f64 = s.parse().map_err(|_| format!("`{s}` is not a number"))?;
    if r.is_finite() && r > 0.0 && r <= 64.0 {
        Ok(r)
    } else {
        Err(format!("{s} texels: the relief must be above 0 and at most 64"))
    }
}

fn budget(s: &str) -> Result<f64, String> {
    let b: f64 = s.parse().map_err(|_| format!("`{s}` is not a number"))?;
    if b.is_finite() && b >= 0.0 {
        Ok(b)
    } else {
        Err(format!("{s}: an error budget is a finite number, 0 or more"))
    }
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum PolarScale {
    Seed,
    Dc255,
}

impl From<PolarScale> for vectors::polar_encode::Scale {
    fn from(s: PolarScale) -> Self {
        match s {
            PolarScale::Seed => vectors::polar_encode::Scale::Seed,
            PolarScale::Dc255 => vectors::polar_encode::Scale::Dc255,
        }
    }
}

/// Defines `with_unit!(name, U => body)`: run `body` with `U` bound to the rtl block of the unit called `name`,
/// for every unit of `vectors::unit_table!` (the `$` passed through lets this macro write one of its own).
macro_rules! define_with_unit {
    ([$d:tt] rtl { $($name:ident: $model:expr, $block:ty, [$($waiver:tt)*];)* } software { $($soft:ident),* }) => {
        macro_rules! with_unit {
            ($d unit:expr, $d u:ident => $d body:expr) => {
                match $d unit {
                    $(stringify!($name) => {
                        type $d u = $block;
                        $d body
                    })*
                    other => Err(format!("`{other}` has no rtl block")),
                }
            };
        }
    };
}
vectors::unit_table!(define_with_unit, $);

/// A command's output folder, made and tried with a file before any work, refused in one line.
pub fn writable_folder(out: &std::path::Path) -> Result<(), String> {
    std::fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    try_a_file_in(out).map_err(|e| format!("cannot write into {}: {e}", out.display()))
}

/// A file written into `dir` and removed.
fn try_a_file_in(dir: &std::path::Path) -> std::io::Result<()> {
    let probe = dir.join(format!(".{}.write-test", std::process::id()));
    std::fs::write(&probe, b"")?;
    let _ = std::fs::remove_file(&probe);
    Ok(())
}

/// A file can be written at `path`: its folder exists and takes a file (tried with one, removed), and it is not a
/// folder itself.
pub fn writable_file(path: &std::path::Path) -> Result<(), String> {
    if path.is_dir() {
        return Err(format!("{} is a folder; name a file", path.display()));
    }
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => std::path::Path::new("."),
    };
    try_a_file_in(dir).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

pub fn unit(name: &str) -> Result<&'static vectors::UnitModel, String> {
    if vectors::unit::SOFTWARE_ONLY.contains(&name) {
        return Err(format!(
            "`{name}` is software only (no rtl block, no vectors): its errors are in `bumprtl accuracy`"
        ));
    }
    vectors::unit::find(name).ok_or_else(|| {
        let names: Vec<&str> = vectors::UNITS.iter().map(|u| u.name).collect();
        format!("unknown unit `{name}`; the units are: {}", names.join(", "))
    })
}

/// clap's own message for a bad command line, cut to one line: the error, then clap's tip if it has one.
fn one_line(e: &clap::Error) -> String {
    let text = e.render().to_string();
    let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty());
    let mut first = lines.next().unwrap_or("bad command line").trim_start_matches("error: ").to_string();
    if first.ends_with(':') {
        // "the following required arguments were not provided:" lists them on the lines after
        let missing: Vec<&str> = lines.clone().take_while(|l| !l.starts_with("Usage:")).collect();
        first = format!("{first} {}", missing.join(", "));
    }
    match lines.find(|l| l.starts_with("tip:")) {
        Some(tip) => format!("{first} ({tip})"),
        None => first,
    }
}

pub fn main() -> Result<(), String> {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e)
            if matches!(
                e.kind(),
                clap::error::ErrorKind::DisplayHelp
                    | clap::error::ErrorKind::DisplayVersion
                    | clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
            ) =>
        {
            e.exit()
        }
        Err(e) => {
            eprintln!("bumprtl: {}", one_line(&e));
            std::process::exit(2);
        }
    };
    match cli.cmd {
        Cmd::Vectors { unit: name, exhaustive, count, seed, out } => {
            let u = unit(&name)?;
            let inputs = vectors::unit::generate(u, exhaustive, count, seed)?;
            let command = if exhaustive {
                format!("bumprtl vectors {name} --exhaustive")
            } else {
                format!("bumprtl vectors {name} --count {count} --seed {seed}")
            };
            let text = vectors::csv::render(u, &inputs, &command);
            match out {
                Some(p) if p.as_os_str() != "-" => synth::export::write_atomic(&p, text.as_bytes())?,
                _ => print!("{text}"),
            }
        }
        Cmd::Verilog { scene: Some(scene), out, .. } => {
            let spec = sim::scene_file::load(&scene)?;
            let row = spec.pipeline;
            let text = row.rtl.verilog();
            if out.as_os_str() == "-" {
                print!("{text}");
            } else {
                writable_folder(&out)?;
                let p = out.join(format!("{}.v", row.name));
                synth::export::write_atomic(&p, text.as_bytes())?;
                println!("{} ({}: {})", p.display(), spec.name, row.units.join(" → "));
            }
        }
        Cmd::Verilog { unit: None, .. } => return Err("verilog: name a unit or --scene FILE".into()),
        Cmd::Verilog { unit: Some(name), out, .. } => {
            let u = unit(&name)?;
            if out.as_os_str() == "-" {
                // the module alone: a testbench and its vector files cannot share one stream
                with_unit!(name.as_str(), U => Ok::<_, String>(print!("{}", synth::export::<U>().text)))?;
                return Ok(());
            }
            let text = vectors::csv::golden(u.name)
                .ok_or_else(|| format!("{name} has no golden vector file in this build"))?;
            let file = vectors::csv::parse(u, text).map_err(|e| format!("vectors/data/{name}.csv: {e}"))?;
            let n_in = u.inputs.len();
            let ins: Vec<Vec<u64>> =
                file.rows.iter().map(|r| vectors::unit::to_patterns(&r[..n_in], u.inputs)).collect();
            let outs: Vec<Vec<u64>> =
                file.rows.iter().map(|r| vectors::unit::to_patterns(&r[n_in..], u.outputs)).collect();
            let source = format!("vectors/data/{name}.csv");
            let paths = with_unit!(name.as_str(), U => {
                let v = synth::export::<U>().write(&out)?;
                let mut p = vec![v];
                p.extend(synth::selfcheck::write::<U>(&out, &ins, &outs, &source)?);
                Ok::<_, String>(p)
            })?;
            for p in paths {
                println!("{}", p.display());
            }
        }
        Cmd::Wave { unit: name, out, count } => {
            let u = unit(&name)?;
            let inputs = vectors::unit::generate(u, false, count, 1)?;
            if out.as_os_str() == "-" {
                let w = Box::new(std::io::BufWriter::new(std::io::stdout()));
                with_unit!(name.as_str(), U => sim::wave::trace::<U>(u, &inputs, w).map_err(|e| format!("cannot write the VCD to standard output: {e}")))?;
            } else {
                with_unit!(name.as_str(), U => sim::wave::write_vcd::<U>(u, &inputs, &out))?;
                println!("{} ({} vectors)", out.display(), inputs.len());
            }
        }
        Cmd::Widths { unit: name, budget: Some(b), target, dir, .. } => {
            unit(&name)?;
            let part = synth::fpga::part(&target)?;
            writable_folder(&dir)?; // before the first synthesis
            crate::widths::budget(&name, b, part, &dir)?
        }
        Cmd::Widths { unit: name, count, seed, csv, .. } => {
            let m = unit(&name)?;
            if let Some(c) = &csv {
                writable_file(c)?; // before the minutes of simulation
            }
            with_unit!(name.as_str(), U => crate::widths::run::<U>(m, count, seed, csv.as_deref()))?;
        }
        Cmd::Synth { unit: name, scene, target, dir, freq } => {
            let name = match (name, scene) {
                (Some(n), _) => n,
                (None, Some(scene)) => {
                    let spec = sim::scene_file::load(&scene)?;
                    let row = spec.pipeline;
                    println!("{}: {} ({})", spec.name, row.name, row.units.join(" → "));
                    row.name.to_string()
                }
                (None, None) => return Err("synth: name a unit or --scene FILE".into()),
            };
            unit(&name)?;
            let part = target.as_deref().map(synth::fpga::part).transpose()?;
            if let Some(f) = freq {
                if !(1.0..=500.0).contains(&f) {
                    return Err(format!("--freq {f}: the clock target must be between 1 and 500 MHz"));
                }
            }
            let d = dir.join(&name);
            let r = with_unit!(name.as_str(), U => {
                let (part, choice) = match part {
                    Some(p) => (p, String::new()),
                    None => {
                        let (p, _, why) = synth::fpga::choose::<U>(&d)?;
                        (p, why)
                    }
                };
                let freq = freq.unwrap_or(part.default_freq());
                synth::fpga::synth_and_place::<U>(&d, part, freq, &choice)
            })?;
            crate::report::synth_row(&r);
            let family = r.part().family;
            let tied = |tag: &str, ties: &[(&str, u64)], keep: &[&str]| with_unit!(name.as_str(), U => synth::fpga::synth_tied::<U>(&d, family, tag, ties, keep));
            crate::hardware::mode_views(&name, family, &tied)?;
        }
        Cmd::Report { scenes, out, budgets, no_place, only, plan, point, merge } => {
            let scenes =
                if scenes.is_empty() { crate::sweep::DEFAULT_SCENES.map(String::from).to_vec() } else { scenes };
            let place = !no_place;
            match (plan, point, merge) {
                (Some(file), _, _) => {
                    writable_file(&file)?;
                    crate::sweep::plan(&scenes, &file, &out, &budgets, place, only.as_deref())?
                }
                (None, Some(id), _) => crate::sweep::one(&scenes, &id, &out, place)?,
                (None, None, true) => crate::sweep::merge(&scenes, &out, &budgets, only.as_deref())?,
                (None, None, false) => crate::sweep::run(&scenes, &out, &budgets, place, only.as_deref())?,
            }
        }
        Cmd::Accuracy { directions, samples, lut_cost, dir } => {
            crate::report::accuracy(directions, samples);
            crate::report::lut_sizes(lut_cost, &dir)?;
        }
        Cmd::Quantize { out, .. } if out.as_os_str() == "-" => {
            return Err("--out -: quantize writes a folder of files (palette, index map, mips); name a folder".into())
        }
        Cmd::Quantize { map, size, dither, green_down, relief, q, out } => {
            let args =
                crate::quantize::Args { map: &map, size: size as usize, dither, green_down, relief, q, out: &out };
            crate::quantize::run(&args)?
        }
        Cmd::PaletteTable { no_synth, dir, out } => {
            writable_folder(&out)?; // before the minutes of work, synthesis included
            let tools =
                synth::tools::missing(&["yosys", "nextpnr-ice40"]).is_empty() && synth::tools::nextpnr_ecp5().is_some();
            let fmax =
                if no_synth || !tools {
                    if !no_synth {
                        println!(
                            "the rtl columns need yosys, nextpnr-ice40 and nextpnr-ecp5 (`bash .ci/run` installs them)"
                        );
                    }
                    crate::palette_table::Fmax::default()
                } else {
                    let (ecp5, up5k) = (synth::fpga::ECP5_25F, synth::fpga::UP5K);
                    let d = dir.join("table_builder").join(ecp5.name);
                    let one = synth::fpga::synth_and_place_cached::<rtl::table_builder::TableBuilder>(
                        &d,
                        ecp5,
                        ecp5.default_freq(),
                    )?;
                    let d = dir.join("palette_pipeline_shared").join(up5k.name);
                    let shared = synth::fpga::synth_and_place_cached::<
                        rtl::palette_pipeline_shared::PalettePipelineShared,
                    >(&d, up5k, up5k.default_freq())?;
                    crate::palette_table::Fmax { builder_mhz: one.fmax_mhz, shared_mhz: shared.fmax_mhz }
                };
            crate::palette_table::run(fmax, &out)?
        }
        Cmd::Render { out, .. } if out.as_os_str() == "-" => {
            return Err("--out -: render writes pictures and a waveform; name a folder".into())
        }
        Cmd::Render { scene, out, window, no_verilator } => crate::render::run(&scene, &out, window, !no_verilator)?,
        Cmd::Hardcases => crate::hardcases::run(&|name, inputs| {
            let m = unit(name)?;
            with_unit!(name, U => Ok(crate::hardcases::rtl_outputs::<U>(m, inputs)))
        })?,
        Cmd::Demo { out, .. } if out.as_os_str() == "-" => {
            return Err("--out -: the demo writes a folder of pictures, waveforms and Verilog; name a folder".into())
        }
        Cmd::Demo { out, size, polar_scale, no_synth, height_map, relief } => {
            crate::demo::run(&out, size as usize, polar_scale.into(), !no_synth, height_map.as_deref(), relief)?
        }
    }
    Ok(())
}

/// A unit's iCE40 cells from yosys (cached), by name.
pub fn synth_cells(name: &str, dir: &std::path::Path) -> Result<synth::fpga::Cells, String> {
    with_unit!(name, U => synth::fpga::synth_unit::<U>(dir, synth::fpga::Family::Ice40))
}

/// A unit placed on the smallest part it fits at that part's default clock target (cached); None where that part
/// is an ECP5 and nextpnr-ecp5 is not installed.
pub fn place_cached(name: &str, dir: &std::path::Path) -> Result<Option<synth::fpga::SynthReport>, String> {
    with_unit!(name, U => {
        let (part, _, _) = synth::fpga::choose::<U>(dir)?;
        if part.family == synth::fpga::Family::Ecp5 && synth::tools::nextpnr_ecp5().is_none() {
            Ok(None)
        } else {
            synth::fpga::synth_and_place_cached::<U>(dir, part, part.default_freq()).map(Some)
        }
    })
}
