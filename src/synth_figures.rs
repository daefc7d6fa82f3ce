//! A unit's synthesis figures as `synth` (and the demo's hardware table) print them: each resource as a share of
//! the part, the hard blocks by instance.

/// One unit's figures on its part, each resource as a share of the part.
pub fn synth_row(r: &synth::fpga::SynthReport) {
    let p = r.part();
    let [lut, ff, dsp, bram, carry] = p.family.cells();
    println!("{} on the {}", r.unit, p.title);
    if !r.choice.is_empty() {
        println!("  chosen because {}", r.choice);
    }
    let share = |n: u64, of: u64| format!("{n:>6} of {of:>6}  {:>5.1} %", 100.0 * n as f64 / of as f64);
    println!("  {lut:<12} {}", share(r.cells.lut4, p.lut4));
    println!("  {ff:<12} {}", share(r.cells.ff, p.ff));
    println!("  {dsp:<12} {}", share(r.cells.dsp, p.dsp));
    println!("  {bram:<12} {}", share(r.cells.bram, p.bram));
    if let Some(sp) = p.family.spram_cell() {
        println!("  {sp:<12} {}", share(r.cells.spram, p.spram));
    }
    println!("  {carry:<12} {:>6}", r.cells.carry);
    if r.cells.soft > 0 {
        println!("  {} of its products built in logic, the smallest first, to fit the {} {dsp}", r.cells.soft, p.dsp);
    }
    match (&r.place_error, r.lc, r.fmax_mhz) {
        (Some(e), _, _) => println!("  {}: {e}", r.unplaced_text()),
        (None, lc, f) => {
            if let Some(lc) = lc {
                println!("  {:<12} {}  (placed, with the serial I/O wrapper)", p.logic_cell_name(), share(lc, p.lut4));
            }
            println!(
                "  fmax         {:>6} MHz  latency {} clocks, {}",
                f.map(|x| format!("{x:.1}")).unwrap_or("-".into()),
                r.latency,
                rate(r.interval, f)
            );
            println!("               {}", placements(r));
        }
    }
    if let Some(c) = &r.critical {
        println!("  critical path at seed {}: {c}", r.seed);
    }
    blocks_line(&r.blocks, p.family, 2);
    if !r.packed.is_empty() {
        println!("  registers    {}", r.packed);
    } else if p.family == synth::fpga::Family::Ecp5 && !synth::regpack::packs() {
        println!("  registers    every one in the fabric, as yosys placed them (--fabric-registers)");
    }
    println!("  tools        {}", synth::tools::toolchain().versions(p.family));
}

/// The pixel rate a unit keeps: "one pixel per clock", or for a k-clock variant "a pixel every 2 clocks
/// (60.0 M pixels/s at fmax)".
pub fn rate(interval: usize, fmax_mhz: Option<f64>) -> String {
    match (interval, fmax_mhz) {
        (0 | 1, _) => "one pixel per clock".into(),
        (k, Some(f)) => format!("a pixel every {k} clocks ({:.1} M pixels/s at fmax)", f / k as f64),
        (k, None) => format!("a pixel every {k} clocks"),
    }
}

/// What an fmax is the median of: "the median of 5 placements (nextpnr seeds), slowest 120.3, fastest 131.0 MHz",
/// and the seeds at which the design did not place, if any.
pub fn placements(r: &synth::fpga::SynthReport) -> String {
    let n = r.placements;
    let range = match r.fmax_range {
        Some((lo, hi)) if n > 1 => format!(", slowest {lo:.1}, fastest {hi:.1} MHz"),
        _ => String::new(),
    };
    let median = match n {
        1 => format!("one placement (nextpnr seed {})", r.seed),
        _ => format!("the median of {n} placements (nextpnr seeds){range}"),
    };
    match r.unplaced.as_slice() {
        [] => median,
        u => format!("{median}; it did not place at {}", u.join("; ")),
    }
}

/// The hard blocks by top-level instance: "unit$0 3, unit$1 3, …" DSP, then BRAM.
pub fn blocks_line(b: &synth::fpga::Blocks, family: synth::fpga::Family, indent: usize) {
    let [.., dsp, bram, _] = family.cells();
    for (k, name) in [(0, dsp), (1, bram)] {
        let list: Vec<String> = b
            .by_instance
            .iter()
            .map(|(i, d, m)| (i, [*d, *m][k]))
            .filter(|x| x.1 > 0)
            .map(|(i, n)| format!("{i} {n}"))
            .collect();
        if !list.is_empty() {
            println!("{:indent$}{name:<12} by instance: {}", "", list.join(", "));
        }
    }
}
