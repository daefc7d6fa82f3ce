//! The commands on one unit of the table of units (`sim::units`), or the pipeline a scene names: its vectors,
//! Verilog, waveform, widths, synthesis, and the hard cases of every unit; each checks its arguments before any work.

use std::path::PathBuf;

/// Write a unit's test vectors as CSV.
pub fn vectors(name: String, exhaustive: bool, count: usize, seed: u64, out: Option<PathBuf>) -> Result<(), String> {
    let u = sim::units::unit(&name)?.model;
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
    Ok(())
}

/// The pipeline a scene file is rendered by, exported as `verilog <unit>` exports a unit (to `-`: its module alone).
pub fn verilog_scene(scene: PathBuf, out: PathBuf) -> Result<(), String> {
    let spec = sim::scene_file::load(&scene)?;
    let row = spec.pipeline;
    if out.as_os_str() == "-" {
        print!("{}", row.rtl().verilog());
        return Ok(());
    }
    crate::output::writable_folder(&out)?;
    println!("{}: {} ({})", spec.name, row.name, row.units.join(" → "));
    // the pipeline is a unit of the table, exported whole: its bench, its wrapper and the package
    verilog(row.name.to_string(), out)
}

/// A unit's Verilog with a self-checking testbench of its golden vectors, the same unit behind its AXI4-Stream
/// wrapper with a testbench of its own on the same vectors, Verilator's waivers for both, and the package around
/// them: a FuseSoC core, a cocotb test and its Makefile, and the serial I/O wrapper the core's `synth` target places.
pub fn verilog(name: String, out: PathBuf) -> Result<(), String> {
    let unit = sim::units::unit(&name)?;
    let u = unit.model;
    if out.as_os_str() == "-" {
        // the module alone: a testbench and its vector files cannot share one stream
        print!("{}", unit.rtl.verilog());
        return Ok(());
    }
    let text = vectors::csv::golden(u.name).ok_or_else(|| format!("{name} has no golden vector file in this build"))?;
    let file = vectors::csv::parse(u, text).map_err(|e| format!("vectors/data/{name}.csv: {e}"))?;
    let n_in = u.inputs.len();
    let ins: Vec<Vec<u64>> = file.rows.iter().map(|r| vectors::unit::to_patterns(&r[..n_in], u.inputs)).collect();
    let outs: Vec<Vec<u64>> = file.rows.iter().map(|r| vectors::unit::to_patterns(&r[n_in..], u.outputs)).collect();
    let source = format!("vectors/data/{name}.csv");
    for p in unit.rtl.selfcheck(&out, &ins, &outs, &source)? {
        println!("{}", p.display());
    }
    for p in unit.axis.selfcheck(&out, ins.len(), &source)? {
        println!("{}", p.display());
    }
    // the Verilator waivers are read off Verilator's own warnings on the files as written
    let module = unit.axis.module();
    let waivers = synth::tools::missing(&["verilator"]).is_empty();
    if waivers {
        let files = [(format!("{name}.v"), name.clone()), (format!("{module}.v"), module.clone())];
        let files: Vec<(&str, &str)> = files.iter().map(|(f, m)| (f.as_str(), m.as_str())).collect();
        let (p, design) = crate::progress::step(
            &format!("{name}: Verilator's warnings read, the waivers checked"),
            |r: &Result<_, String>| r.is_ok().then(|| String::from("2 modules")),
            || synth::lint::write_waivers(&out, &name, &files, &unit.waivers()),
        )?;
        println!("{}", p.display());
        for d in design {
            println!("  not waived (the design's): {d}");
        }
    } else {
        println!("{name}.vlt not written: Verilator is not installed (its waivers are read off Verilator's warnings)");
    }
    // which part the unit fits is synthesised in a scratch folder beside the output, removed after
    let scratch = out.join(format!(".{name}-fit"));
    let packaged = crate::progress::step(
        &format!("{name}: the package, yosys on each part for the core's synth target"),
        |r: &Result<_, String>| r.is_ok().then(|| String::from("a FuseSoC core and a cocotb test")),
        || unit.axis.package(&out, waivers, &scratch),
    );
    let _ = std::fs::remove_dir_all(&scratch);
    let (written, no_synth) = packaged?;
    for p in written {
        println!("{}", p.display());
    }
    if let Some(why) = no_synth {
        println!("{name}.core has no synth target: {why}");
    }
    Ok(())
}

/// A unit traced in rust-hdl to a VCD.
pub fn wave(name: String, out: PathBuf, count: usize, fst: bool) -> Result<(), String> {
    let unit = sim::units::unit(&name)?;
    let u = unit.model;
    if fst && out.as_os_str() == "-" {
        return Err("wave --fst: an FST is written to a file (it is seeked), so --out must name the VCD file".into());
    }
    if fst && out.extension().is_some_and(|e| e == "fst") {
        return Err(format!("wave --fst: --out {} is the VCD's name; the FST goes beside it as .fst", out.display()));
    }
    let inputs = vectors::unit::generate(u, false, count, 1)?;
    if out.as_os_str() == "-" {
        let w = Box::new(std::io::BufWriter::new(std::io::stdout()));
        unit.rtl.trace(u, &inputs, w).map_err(|e| format!("cannot write the VCD to standard output: {e}"))?;
    } else {
        crate::progress::step(
            &format!("{name}: rust-hdl, every signal traced"),
            |r: &Result<_, String>| r.is_ok().then(|| format!("{} vectors", inputs.len())),
            || unit.rtl.write_vcd(u, &inputs, &out),
        )?;
        println!("{} ({} vectors)", out.display(), inputs.len());
        if fst {
            let f = out.with_extension("fst");
            let changes = sim::fst::vcd_to_fst(&out, &f)?;
            println!("{} ({changes} value changes)", f.display());
        }
    }
    Ok(())
}

/// `widths --budget`: the unit's width parameters swept against cost.
pub fn widths_budget(name: String, b: f64, target: String, dir: PathBuf) -> Result<(), String> {
    sim::units::unit(&name)?;
    let part = synth::fpga::part(&target)?;
    crate::output::writable_folder(&dir)?; // before the first synthesis
    crate::widths::budget(&name, b, part, &dir)?;
    Ok(())
}

/// Every signal of a unit's rtl block: its format and the range it takes.
pub fn widths(
    name: String,
    count: usize,
    seed: u64,
    csv: Option<PathBuf>,
    solver: Option<sim::prove::Options>,
) -> Result<(), String> {
    let unit = sim::units::unit(&name)?;
    if let Some(c) = &csv {
        crate::output::writable_file(c)?; // before the minutes of simulation
    }
    crate::widths::run(unit, count, seed, csv.as_deref(), solver.as_ref())?;
    Ok(())
}

/// A unit (or a scene's pipeline) synthesised and placed, its figures printed.
pub fn synth(
    name: Option<String>,
    scene: Option<PathBuf>,
    target: Option<String>,
    dir: PathBuf,
    freq: Option<f64>,
    seeds: u32,
) -> Result<(), String> {
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
    let rtl = sim::units::unit(&name)?.rtl;
    let part = target.as_deref().map(synth::fpga::part).transpose()?;
    if let Some(f) = freq {
        if !(1.0..=500.0).contains(&f) {
            return Err(format!("--freq {f}: the clock target must be between 1 and 500 MHz"));
        }
    }
    let d = dir.join(&name);
    let (part, choice) = match part {
        Some(p) => (p, String::new()),
        None => {
            let (p, _, why) = crate::progress::step(
                &format!("{name}: yosys on each part, smallest first, to the first it fits"),
                |r: &Result<(synth::fpga::Part, _, _), String>| r.as_ref().ok().map(|r| r.0.name.to_string()),
                || rtl.choose(&d),
            )?;
            (p, why)
        }
    };
    let r = crate::progress::step(
        &format!("{name} on the {}: yosys, then nextpnr at {seeds} seeds", part.name),
        |r: &Result<_, String>| r.is_ok().then(|| format!("{seeds} placements")),
        || rtl.synth_and_place(&d, part, freq.unwrap_or(part.default_freq()), &choice, synth::fpga::Seeds::all(seeds)),
    )?;
    crate::synth_figures::synth_row(&r);
    let family = r.part().family;
    let tied = |tag: &str, ties: &[(&str, u64)], keep: &[&str]| rtl.synth_tied(&d, family, tag, ties, keep);
    crate::hardware::mode_views(&name, family, &tied)?;
    Ok(())
}

/// Every unit's hard cases through its model and its rtl block.
pub fn hardcases() -> Result<(), String> {
    crate::hardcases::run()
}
