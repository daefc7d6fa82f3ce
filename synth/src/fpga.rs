//! Synthesis and placement for the open flow's two families: iCE40 UP5K (yosys `synth_ice40 -dsp -spram`,
//! nextpnr-ice40) and Lattice ECP5 25F / 45F / 85F (yosys `synth_ecp5`, nextpnr-ecp5).
//!
//! A unit is first synthesised alone, for its own cell counts; those decide whether it fits a part. It is then
//! placed inside a serial I/O wrapper (a unit has hundreds of port bits, a package a few dozen to a few hundred
//! pins): the wrapper's `hold` register sits between the input shift chain and the unit, so that yosys cannot
//! merge pipeline flops into the chain. nextpnr gives the logic cells used and the fmax of the real clock.

use crate::cache;
use crate::export::write_atomic;
use crate::tools;
use crate::unit::Unit;
use std::fmt::Write as _;
use std::path::Path;

/// A device family: which yosys script, which place-and-route tool, and what yosys calls its cells.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    Ice40,
    Ecp5,
}

impl Family {
    /// yosys cell names: LUT, flip-flop (a prefix), multiplier, block RAM, carry.
    pub fn cells(self) -> [&'static str; 5] {
        match self {
            Family::Ice40 => ["SB_LUT4", "SB_DFF", "SB_MAC16", "SB_RAM40_4K", "SB_CARRY"],
            Family::Ecp5 => ["LUT4", "TRELLIS_FF", "MULT18X18D", "DP16KD", "CCU2C"],
        }
    }

    /// The single-port RAM block the family has beside its block RAM: the UP5K's SPRAM (16,384 × 16 bits).
    pub fn spram_cell(self) -> Option<&'static str> {
        match self {
            Family::Ice40 => Some("SB_SPRAM256KA"),
            Family::Ecp5 => None,
        }
    }

    /// yosys's synthesis command; `-spram` puts a single-port memory (`rtl::prim::sp_ram`) in SPRAM.
    pub fn synth_command(self) -> &'static str {
        match self {
            Family::Ice40 => "synth_ice40 -dsp -spram",
            Family::Ecp5 => "synth_ecp5",
        }
    }
}

/// One part the flow can place on, with the resources a fit is judged by.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Part {
    /// the name `--target` takes
    pub name: &'static str,
    pub title: &'static str,
    pub family: Family,
    pub lut4: u64,
    pub ff: u64,
    pub dsp: u64,
    pub bram: u64,
    /// single-port RAM blocks (the UP5K's SPRAM; none on the ECP5)
    pub spram: u64,
    pub pnr: &'static [&'static str],
}

pub const UP5K: Part = Part {
    name: "up5k",
    title: "iCE40 UP5K (SG48)",
    family: Family::Ice40,
    lut4: 5280,
    ff: 5280,
    dsp: 8,
    bram: 30,
    spram: 4,
    pnr: &["--up5k", "--package", "sg48", "--pcf-allow-unconstrained"],
};
pub const ECP5_25F: Part = Part {
    name: "ecp5-25f",
    title: "ECP5 LFE5U-25F-6 (CABGA381)",
    family: Family::Ecp5,
    lut4: 24288,
    ff: 24288,
    dsp: 28,
    bram: 56,
    spram: 0,
    pnr: &["--25k", "--package", "CABGA381", "--speed", "6", "--lpf-allow-unconstrained"],
};
pub const ECP5_45F: Part = Part {
    name: "ecp5-45f",
    title: "ECP5 LFE5U-45F-6 (CABGA381)",
    family: Family::Ecp5,
    lut4: 43848,
    ff: 43848,
    dsp: 72,
    bram: 108,
    spram: 0,
    pnr: &["--45k", "--package", "CABGA381", "--speed", "6", "--lpf-allow-unconstrained"],
};
pub const ECP5_85F: Part = Part {
    name: "ecp5-85f",
    title: "ECP5 LFE5U-85F-6 (CABGA381)",
    family: Family::Ecp5,
    lut4: 83640,
    ff: 83640,
    dsp: 156,
    bram: 208,
    spram: 0,
    pnr: &["--85k", "--package", "CABGA381", "--speed", "6", "--lpf-allow-unconstrained"],
};

/// Smallest first within a family, the UP5K first of all: the order the default target is chosen in.
pub const PARTS: &[Part] = &[UP5K, ECP5_25F, ECP5_45F, ECP5_85F];

pub fn part(name: &str) -> Result<Part, String> {
    PARTS.iter().copied().find(|p| p.name == name).ok_or_else(|| {
        let names: Vec<&str> = PARTS.iter().map(|p| p.name).collect();
        format!("unknown target `{name}`; the targets are: {}", names.join(", "))
    })
}

impl Part {
    /// What nextpnr calls the logic cells it reports as used.
    pub fn logic_cell_name(&self) -> &'static str {
        match self.family {
            Family::Ice40 => "ICESTORM_LC",
            Family::Ecp5 => "TRELLIS_COMB",
        }
    }

    /// The clock target asked of nextpnr when the user names none, MHz.
    pub fn default_freq(&self) -> f64 {
        match self.family {
            Family::Ice40 => 50.0,
            Family::Ecp5 => 125.0,
        }
    }

    /// The first resource the unit's cell counts overflow on this part, as a phrase; None when it fits.
    pub fn overflow(&self, r: &Cells) -> Option<String> {
        let [lut, ff, dsp, bram, _] = self.family.cells();
        // an ECP5 carry cell (CCU2C) holds two LUT4s of a slice; an iCE40 carry sits beside its LUT
        let luts = match self.family {
            Family::Ice40 => r.lut4,
            Family::Ecp5 => r.lut4 + 2 * r.carry,
        };
        let lut_name = match self.family {
            Family::Ice40 => lut.to_string(),
            Family::Ecp5 => "LUT4 (CCU2C counted as two)".to_string(),
        };
        [
            (dsp.to_string(), r.dsp, self.dsp),
            (bram.to_string(), r.bram, self.bram),
            (self.family.spram_cell().unwrap_or("SPRAM").to_string(), r.spram, self.spram),
            (lut_name, luts, self.lut4),
            (ff.to_string(), r.ff, self.ff),
        ]
        .into_iter()
        .find(|(_, need, have)| need > have)
        .map(|(name, need, have)| format!("it needs {need} {name}, the {} has {have}", self.title))
        .map(|o| match r.soft {
            0 => o,
            n => format!("{o} (with {n} of its products built in logic to leave {} for the DSP blocks)", r.dsp),
        })
    }
}

/// What yosys made of a unit alone, in the family's own cells.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Cells {
    pub lut4: u64,
    pub ff: u64,
    pub dsp: u64,
    pub bram: u64,
    pub carry: u64,
    /// products built in logic rather than DSP blocks (`FABRIC_PRODUCTS`)
    pub soft: u64,
    /// single-port RAM blocks (`Family::spram_cell`)
    pub spram: u64,
}

/// The hard blocks (DSP, block RAM) synthesis kept inside each of a design's top-level instances, read from the
/// cells' names (yosys keeps a flattened cell's instance path in its name: `unit$0.mul1.s3_p.d_MULT18X18D_P0`,
/// `lookup.tables.mem.0.0`); yosys lists each type apart, so the type never rests on the name.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Blocks {
    /// (instance, DSP, BRAM), in name order; `-` for cells at the top level
    pub by_instance: Vec<(String, u64, u64)>,
}

impl Blocks {
    /// From yosys's `select -list` of the DSP cells and of the block RAM cells (`module/cell` lines); the cells'
    /// names begin with `prefix` when the unit sits in a wrapper (its instance and a dot).
    fn parse(dsp: &str, bram: &str, prefix: &str) -> Blocks {
        let mut m: std::collections::BTreeMap<String, (u64, u64)> = Default::default();
        for (k, text) in [(0, dsp), (1, bram)] {
            for line in text.lines() {
                let Some((_, cell)) = line.trim().split_once('/') else { continue };
                let cell = cell.trim_start_matches('\\');
                let cell = cell.strip_prefix(prefix).unwrap_or(cell);
                let inst = cell.split_once('.').map(|(i, _)| i).unwrap_or("-").to_string();
                let e = m.entry(inst).or_default();
                if k == 0 {
                    e.0 += 1;
                } else {
                    e.1 += 1;
                }
            }
        }
        Blocks { by_instance: m.into_iter().map(|(k, (d, b))| (k, d, b)).collect() }
    }

    fn read_under(dir: &Path, top: &str, family: Family, prefix: &str) -> Blocks {
        let list =
            |kind: &str| std::fs::read_to_string(dir.join(format!("{top}.{family:?}.{kind}"))).unwrap_or_default();
        Blocks::parse(&list("dsp"), &list("bram"), prefix)
    }

    fn read(dir: &Path, top: &str, family: Family) -> Blocks {
        Blocks::read_under(dir, top, family, "")
    }

    /// `name:dsp:bram,...`, for the saved report.
    fn to_text(&self) -> String {
        self.by_instance.iter().map(|(n, d, b)| format!("{n}:{d}:{b}")).collect::<Vec<_>>().join(",")
    }

    fn from_text(text: &str) -> Blocks {
        let by_instance = text
            .split(',')
            .filter_map(|e| {
                let mut f = e.rsplitn(3, ':');
                let (b, d, n) = (f.next()?.parse().ok()?, f.next()?.parse().ok()?, f.next()?);
                Some((n.to_string(), d, b))
            })
            .collect();
        Blocks { by_instance }
    }
}

/// A unit's figures on one part.
#[derive(Clone, Debug, Default)]
pub struct SynthReport {
    pub unit: String,
    /// the part's `--target` name
    pub part: String,
    pub cells: Cells,
    pub latency: usize,
    /// clocks a pixel (`StreamUnit::INTERVAL`: 1 but for a k-clock variant), so the pixel rate is fmax / interval
    pub interval: usize,
    /// why this part: the resource that ruled out each smaller one (empty when the user named the part)
    pub choice: String,
    /// from nextpnr, with the I/O wrapper: logic cells used (ICESTORM_LC, TRELLIS_COMB), fmax of the real clock,
    /// and the critical path as nextpnr reports it (its end points and delay)
    /// (all of them the median placement's, see `median`)
    pub lc: Option<u64>,
    pub fmax_mhz: Option<f64>,
    pub critical: Option<String>,
    /// why place-and-route failed, when it did (at every seed: see `unplaced` for a design that places at some)
    pub place_error: Option<String>,
    /// the seeds at which the design did not place (nextpnr's error, or stopped at the time limit), each "seed N:
    /// why", in seed order
    pub unplaced: Vec<String>,
    /// how many placements (nextpnr seeds) the figures are the median of, the seed of the median one, and the
    /// slowest and the fastest placement's fmax
    pub placements: u32,
    pub seed: u32,
    pub fmax_range: Option<(f64, f64)>,
    /// the hard blocks of each top-level instance (the unit alone, before the wrapper)
    pub blocks: Blocks,
    /// what `regpack` moved into the ECP5's blocks before placement (empty: nothing packed, or an iCE40)
    pub packed: String,
}

impl SynthReport {
    pub fn part(&self) -> Part {
        part(&self.part).expect("a report names a known part")
    }

    /// The time limit a placement was stopped at, in seconds (None: it was not stopped).
    pub fn stopped_after(&self) -> Option<u64> {
        let rest = self.place_error.as_deref()?.strip_prefix(STOPPED)?;
        rest.split_whitespace().next()?.parse().ok()
    }

    /// What a design that did not place shows where its fmax would be: "not placed within 900 s" where nextpnr was
    /// stopped at the time limit, else "does not place".
    pub fn unplaced_text(&self) -> String {
        match self.stopped_after() {
            Some(s) => format!("not placed within {s} s"),
            None => "does not place".into(),
        }
    }

    /// How many placements the figures are the median of: "5", or "4 of 5" where one did not place.
    pub fn placed_of(&self) -> String {
        match self.unplaced.len() {
            0 => self.placements.to_string(),
            k => format!("{} of {}", self.placements, self.placements + k as u32),
        }
    }
}

/// The serial I/O wrapper `<unit>_io` a unit is placed in: a shift chain in, a `hold` register, the unit, a shift
/// chain out (three pins and a clock).
pub fn io_wrapper(u: &Unit) -> String {
    let ni: usize = 1 + u.inputs.iter().map(|p| p.1).sum::<usize>();
    let no: usize = 1 + u.outputs.iter().map(|p| p.1).sum::<usize>();
    let mut s = String::new();
    let _ = writeln!(s, "// generated by bumprtl: serial I/O wrapper for place-and-route of {}", u.name);
    let _ = writeln!(s, "module {}_io(input clk, input sin, input load, output sout);", u.name);
    let _ = writeln!(
        s,
        "  reg [{}:0] shin = 0; reg [{}:0] hold = 0; reg [{}:0] shout = 0; wire [{}:0] res;",
        ni - 1,
        ni - 1,
        no - 1,
        no - 1
    );
    let _ = writeln!(s, "  always @(posedge clk) begin\n    shin <= {{shin[{}:0], sin}};", ni.saturating_sub(2));
    let _ = writeln!(s, "    if (load) begin hold <= shin; shout <= res; end");
    let _ = writeln!(s, "    else shout <= {{shout[{}:0], 1'b0}};\n  end", no.saturating_sub(2));
    let _ = writeln!(s, "  assign sout = shout[{}];", no - 1);
    let mut conns = vec![".clock(clk)".to_string(), ".valid_in(hold[0])".into(), ".valid_out(res[0])".into()];
    conns.extend(crate::export::bus_slices(u.inputs, "hold", 1));
    conns.extend(crate::export::bus_slices(u.outputs, "res", 1));
    let _ = writeln!(s, "  {} dut({});\nendmodule", u.name, conns.join(", "));
    s
}

fn stat_count(text: &str, cell: &str, prefix: bool) -> u64 {
    // the last `stat` table in the log is the final netlist; yosys 0.23 writes a cell's row as `NAME COUNT`, current
    // versions as `COUNT NAME`
    let start = text.rfind("Printing statistics").unwrap_or(0);
    text[start..]
        .lines()
        .filter_map(|l| {
            let mut f = l.split_whitespace();
            let (a, b) = (f.next()?, f.next()?);
            let (name, n) = match (a.parse::<u64>(), b.parse::<u64>()) {
                (Err(_), Ok(n)) => (a, n),
                (Ok(n), Err(_)) => (b, n),
                _ => return None,
            };
            let hit = if prefix { name.starts_with(cell) } else { name == cell };
            hit.then_some(n)
        })
        .sum()
}

fn cells(family: Family, log: &str) -> Cells {
    let [lut, ff, dsp, bram, carry] = family.cells();
    Cells {
        lut4: stat_count(log, lut, false),
        ff: stat_count(log, ff, true),
        dsp: stat_count(log, dsp, false),
        bram: stat_count(log, bram, false),
        carry: stat_count(log, carry, false),
        soft: 0,
        spram: family.spram_cell().map_or(0, |c| stat_count(log, c, false)),
    }
}

/// Run before synthesis, after reading the Verilog: registers yosys would merge because they hold the same word,
/// kept apart (`keep`: `opt_merge` never merges two cells that both have it) so that each copy can be placed by
/// what it drives. Registers named `mop_*` are a multiplier's operand copied once per multiplier, to sit beside its
/// DSP. Every register of a fetch (`tex_fetch`, `height_fetch`): a colour pipeline's colour map and bump map are
/// read at the same texels, so their fetches' address stages are the same words, and merged they drove both maps'
/// block RAMs (cart_tex_bilinear_colour's critical path ran from the colour fetch's stage 2 to the bump fetch's bank
/// registers: 2.03 ns of logic, 3.85 ns of routing). rust-hdl writes every DFF as its own module, which is what the
/// selection names.
pub const KEEP_COPIES: &str = "proc; setattr -set keep 1 *$mop_*/t:$dff *fetch$*/t:$dff";

/// The iCE40 flow's rule for a design that needs more SB_MAC16 blocks than the UP5K's 8: it is synthesised as
/// always first, and only when its DSP count is over 8 are some of its products built in logic instead. The design
/// is flattened and its widths reduced (`opt -full` strips the constant-zero tops of the 16-bit operands rust-hdl
/// multiplies), its `$mul` cells listed, and the smallest (A × B operand bits, then name) retyped `$__soft_mul`,
/// the cell yosys's own DSP mapping leaves to logic: first as many as the blocks over 8, then more while the count
/// is still over (two products can share a block, so moving one does not always free one). Each product in logic is
/// then split across the register that takes it (`crate::softsplit`), half its adder tree a clock.
pub const FABRIC_PRODUCTS: &str = "iCE40: over 8 SB_MAC16, the fewest smallest products in logic that bring it to 8, \
    each split across the register that takes it (bumprtl softsplit 2)";
pub(crate) const PREPARE: &str = "flatten; opt -full; wreduce; opt_clean; share; opt_clean";

/// A multiplier cell of a prepared design: its name and operand widths.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Product {
    pub name: String,
    pub a: u64,
    pub b: u64,
}

/// The `$mul` cells of yosys's `dump` output.
fn products(dump: &str) -> Vec<Product> {
    let mut out: Vec<Product> = vec![];
    for l in dump.lines().map(str::trim) {
        if let Some(name) = l.strip_prefix("cell $mul ") {
            out.push(Product { name: name.trim().to_string(), a: 0, b: 0 });
        } else if let (Some(p), Some(w)) = (out.last_mut(), l.strip_prefix("parameter \\")) {
            let mut f = w.split_whitespace();
            match (f.next(), f.next().and_then(|x| x.parse().ok())) {
                (Some("A_WIDTH"), Some(n)) => p.a = n,
                (Some("B_WIDTH"), Some(n)) => p.b = n,
                _ => {}
            }
        }
    }
    out
}

/// The `n` smallest products (A × B operand bits, then name): the first to build in logic.
fn to_fabric(mut all: Vec<Product>, n: usize) -> Vec<Product> {
    all.sort_by(|x, y| (x.a * x.b, &x.name).cmp(&(y.a * y.b, &y.name)));
    all.truncate(n);
    all
}

/// yosys on a design, returning its log and how many of its products were built in logic (`FABRIC_PRODUCTS`).
fn yosys(dir: &Path, family: Family, top: &str, files: &[&str], json: Option<&str>) -> Result<(String, u64), String> {
    let log = yosys_with(dir, family, top, files, json, KEEP_COPIES, None)?;
    let limit = UP5K.dsp;
    let mut over = cells(family, &log).dsp.saturating_sub(limit);
    if family != Family::Ice40 || over == 0 {
        return Ok((log, 0));
    }
    let mut script = String::new();
    for f in files {
        let _ = write!(script, "read_verilog {f}; ");
    }
    let _ = write!(script, "hierarchy -top {top}; {KEEP_COPIES}; {PREPARE}; tee -q -o {top}.products dump t:$mul; memory_collect; write_rtlil {top}.prepared.il; write_json {top}.prepared.json");
    tools::run(dir, tools::toolchain().yosys(), &["-q", "-p", &script])?;
    let dump = std::fs::read_to_string(dir.join(format!("{top}.products")))
        .map_err(|e| format!("no yosys product list: {e}"))?;
    let all = products(&dump);
    let prepared = std::fs::read_to_string(dir.join(format!("{top}.prepared.json")))
        .map_err(|e| format!("no prepared yosys design: {e}"))?;
    // the names yosys made so far end in numbers up to RTLIL's `autoidx`, which JSON does not carry: read back
    // without it, yosys numbers its new cells from 1 again and stops when one is named twice ("Assert
    // `count_id(cell->name) == 0'", `cart_tex_nearest_surface_matte` in `synth_ice40`'s arithmetic mapping)
    let il = std::fs::read_to_string(dir.join(format!("{top}.prepared.il")))
        .map_err(|e| format!("no prepared yosys design: {e}"))?;
    let autoidx = il.lines().find(|l| l.starts_with("autoidx ")).ok_or("the prepared yosys design has no autoidx")?;
    write_atomic(&dir.join(format!("{top}.autoidx.il")), format!("{autoidx}\n").as_bytes())?;
    let mut n = 0usize;
    loop {
        n = (n + over as usize).min(all.len());
        let soft: Vec<String> = to_fabric(all.clone(), n).into_iter().map(|p| p.name).collect();
        let (split, pieces, _) = crate::softsplit::split(&prepared, top, &soft)?;
        write_atomic(&dir.join(format!("{top}.split.json")), split.as_bytes())?;
        let retype = |cells: &[String]| {
            let list: Vec<String> = cells.iter().map(|p| format!("{top}/{p}")).collect();
            format!("chtype -set $__soft_mul {}", list.join(" "))
        };
        let log = yosys_with(dir, family, top, &[], json, &retype(&pieces), Some(&format!("{top}.split.json")))?;
        over = cells(family, &log).dsp.saturating_sub(limit);
        if over == 0 || n == all.len() {
            return Ok((log, n as u64));
        }
    }
}

fn yosys_with(
    dir: &Path,
    family: Family,
    top: &str,
    files: &[&str],
    json: Option<&str>,
    before: &str,
    design: Option<&str>,
) -> Result<String, String> {
    let mut script = String::new();
    for f in files {
        let _ = write!(script, "read_verilog {f}; ");
    }
    if let Some(d) = design {
        let _ = write!(script, "read_rtlil {top}.autoidx.il; read_json {d}; ");
    }
    let synth = format!("{} -top {top}", family.synth_command());
    if design.is_some() {
        // products marked for logic (`$__soft_mul`) after `synth_ice40`'s `begin` has checked the hierarchy: current
        // yosys refuses such a cell there, though `synth_ice40` makes them itself later on (`synth_ecp5` has no
        // `flatten` label: the iCE40 is the only family whose products go to logic)
        assert_eq!(family, Family::Ice40, "products are built in logic on the iCE40 only");
        let _ = write!(script, "hierarchy -top {top}; {synth} -run :flatten; {before}; {synth} -run flatten:");
    } else {
        let _ = write!(script, "hierarchy -top {top}; {before}; {synth}");
    }
    if let Some(j) = json {
        let _ = write!(script, " -json {j}");
    }
    let [_, _, dsp, bram, _] = family.cells();
    let _ = write!(script, "; tee -q -o {top}.{family:?}.dsp select -list t:{dsp}; tee -q -o {top}.{family:?}.bram select -list t:{bram}; stat");
    let log = format!("{top}.{}.yosys.log", family.synth_command().split_whitespace().next().unwrap_or("synth"));
    tools::run(dir, tools::toolchain().yosys(), &["-q", "-p", &script, "-l", &log])?;
    std::fs::read_to_string(dir.join(&log)).map_err(|e| format!("no yosys log: {e}"))
}

/// yosys figures of the unit alone in one family's cells (no place-and-route), written into `dir` and kept in the
/// synthesis cache (`crate::cache`) under the hash of the unit's Verilog, the flow and yosys's version.
pub fn synth_unit(u: &Unit, dir: &Path, family: Family) -> Result<Cells, String> {
    cached_cells(dir, family, &u.export(), FABRIC_PRODUCTS, &|top, file| yosys(dir, family, top, &[file], None))
}

/// yosys figures of the unit alone with every product in a DSP block, however many the part has: one synthesis
/// pass (`synth_unit` adds passes that move products into logic when an iCE40 has too few blocks). This is what a
/// plain `synth_ice40 -dsp -spram` / `synth_ecp5` flow, such as a FuseSoC target, makes of the unit.
pub fn synth_unit_hard(u: &Unit, dir: &Path, family: Family) -> Result<Cells, String> {
    if family == Family::Ecp5 {
        // the project's flow moves no product into logic on the ECP5, so the two are one synthesis (and one cache entry)
        return synth_unit(u, dir, family);
    }
    cached_cells(dir, family, &u.export(), "every product in a DSP block", &|top, file| {
        one_pass(dir, family, top, file)
    })
}

/// yosys figures of what the AXI4-Stream wrapper adds to its unit (`export_axis_ctl`: its control and output FIFO,
/// which hold no product), synthesised alone in one pass.
pub fn synth_axis_ctl<W: rtl::axis::AxisBlock>(dir: &Path, family: Family) -> Result<Cells, String> {
    let v = crate::export::export_axis_ctl::<W>();
    cached_cells(dir, family, &v, "the AXI4-Stream wrapper's control alone", &|top, file| {
        one_pass(dir, family, top, file)
    })
}

fn one_pass(dir: &Path, family: Family, top: &str, file: &str) -> Result<(String, u64), String> {
    Ok((yosys_with(dir, family, top, &[file], None, KEEP_COPIES, None)?, 0))
}

/// The cells of the exported module `v` under `run` (yosys's log and its count of products built in logic, given
/// the top module and its file), cached under the synthesis command, the flow's `how`, and the Verilog; the figures
/// are also written to `<family>.cells` in `dir`.
fn cached_cells(
    dir: &Path,
    family: Family,
    v: &crate::export::Exported,
    how: &str,
    run: &dyn Fn(&str, &str) -> Result<(String, u64), String>,
) -> Result<Cells, String> {
    v.write(dir)?;
    let key = cache::key(
        &format!("cells\n{}\n{KEEP_COPIES}\n{how}\nblocks by type\n{}", family.synth_command(), v.text),
        &[&tools::toolchain().yosys()],
    );
    let saved = dir.join(format!("{family:?}.cells"));
    let read = |t: &str| match t.split_whitespace().filter_map(|x| x.parse().ok()).collect::<Vec<u64>>()[..] {
        [lut4, ff, dsp, bram, carry, soft, spram] => Some(Cells { lut4, ff, dsp, bram, carry, soft, spram }),
        // an entry from before SPRAM was counted (its key holds the synthesis command, which then had no -spram)
        [lut4, ff, dsp, bram, carry, soft] => Some(Cells { lut4, ff, dsp, bram, carry, soft, spram: 0 }),
        _ => None,
    };
    let text = |c: &Cells| format!("{} {} {} {} {} {} {}", c.lut4, c.ff, c.dsp, c.bram, c.carry, c.soft, c.spram);
    let cached = || cache::get(&key, "cells").as_deref().and_then(read);
    if let Some(c) = cached() {
        write_atomic(&saved, text(&c).as_bytes())?;
        return Ok(c);
    }
    let _making = cache::making(&key, "cells")?;
    if let Some(c) = cached() {
        write_atomic(&saved, text(&c).as_bytes())?;
        return Ok(c);
    }
    let (log, soft) = run(&v.module, &format!("{}.v", v.module))?;
    let c = Cells { soft, ..cells(family, &log) };
    let text = text(&c);
    write_atomic(&saved, text.as_bytes())?;
    cache::put(&key, "cells", &text)?;
    Ok(c)
}

/// yosys figures of the unit with some inputs tied to constants and only some outputs used (the rest left open), as
/// a design that needs one mode of a unit would hold it: synthesis removes what the constants and the open outputs
/// make dead. `tag` names the wrapper module and its files. The multipliers' operand copies are not marked `keep`
/// here (a kept copy would hold its dead multiplier alive), so compare these figures with each other, not with
/// `synth_unit`'s.
pub fn synth_tied(
    u: &Unit,
    dir: &Path,
    family: Family,
    tag: &str,
    ties: &[(&str, u64)],
    keep: &[&str],
) -> Result<(Cells, Blocks), String> {
    let v = u.export();
    v.write(dir)?;
    let top = format!("{}_{tag}", u.name);
    let ins: Vec<(&str, usize)> = u.inputs.iter().filter(|(n, _)| !ties.iter().any(|t| t.0 == *n)).copied().collect();
    let outs: Vec<(&str, usize)> = u.outputs.iter().filter(|(n, _)| keep.contains(n)).copied().collect();
    let port = |dir: &str, (n, w): &(&str, usize)| format!("{dir} [{}:0] {n}", w - 1);
    let mut decl = vec!["input clock".to_string(), "input valid_in".into(), "output valid_out".into()];
    decl.extend(ins.iter().map(|p| port("input", p)));
    decl.extend(outs.iter().map(|p| port("output", p)));
    let mut conns = vec![".clock(clock)".to_string(), ".valid_in(valid_in)".into(), ".valid_out(valid_out)".into()];
    for (n, w) in u.inputs {
        match ties.iter().find(|t| t.0 == *n) {
            Some((_, value)) => conns.push(format!(".{n}({w}'d{value})")),
            None => conns.push(format!(".{n}({n})")),
        }
    }
    conns.extend(outs.iter().map(|(n, _)| format!(".{n}({n})")));
    let text = format!(
        "// generated by bumprtl: {} with {} tied\nmodule {top}({});\n  {} dut({});\nendmodule\n",
        u.name,
        ties.iter().map(|(n, v)| format!("{n} = {v}")).collect::<Vec<_>>().join(", "),
        decl.join(", "),
        u.name,
        conns.join(", ")
    );
    let w = format!("{top}.v");
    write_atomic(&dir.join(&w), text.as_bytes())?;
    let log = yosys_with(dir, family, &top, &[&format!("{}.v", u.name), &w], None, "proc", None)?;
    Ok((cells(family, &log), Blocks::read_under(dir, &top, family, "dut.")))
}

/// The hard blocks of each top-level instance of the unit, as its last `synth_unit` in `dir` left them.
pub fn blocks_of(u: &Unit, dir: &Path, family: Family) -> Blocks {
    Blocks::read(dir, u.name, family)
}

/// The part a unit is placed on when the user names none: the UP5K when the unit fits it, else the smallest ECP5
/// it fits. Returns the part, the unit's cells in that part's family, and why each smaller part was passed over.
pub fn choose(u: &Unit, dir: &Path) -> Result<(Part, Cells, String), String> {
    let mut why = Vec::new();
    let mut by_family: Vec<(Family, Cells)> = Vec::new();
    for p in PARTS {
        let c = match by_family.iter().find(|(f, _)| *f == p.family) {
            Some((_, c)) => *c,
            None => {
                let c = synth_unit(u, dir, p.family)?;
                by_family.push((p.family, c));
                c
            }
        };
        match p.overflow(&c) {
            None => {
                let why = if why.is_empty() { format!("it fits the {}", p.title) } else { why.join("; ") };
                return Ok((*p, c, why));
            }
            Some(o) => why.push(format!("not {}: {o}", p.name)),
        }
    }
    Err(format!("{} fits none of the parts: {}", u.name, why.join("; ")))
}

/// The first of nextpnr's critical path reports, cut to its end points and total delay.
fn critical_path(log: &str) -> Option<String> {
    let start = log.find("Critical path report for clock")?;
    // the report ends at its "N ns logic, M ns routing" line
    let lines: Vec<&str> = log[start..].lines().skip(1).collect();
    let end = lines.iter().position(|l| l.contains("ns logic,"))?;
    let block = &lines[..=end];
    let cell = |l: &str| l.split("Source ").nth(1).or_else(|| l.split("Sink ").nth(1)).map(|x| x.trim().to_string());
    let first = block.iter().find_map(|l| l.contains("Source ").then(|| cell(l)).flatten())?;
    let last = block.iter().rev().find_map(|l| l.contains("Sink ").then(|| cell(l)).flatten())?;
    // "Info: 13.5 ns logic, 2.1 ns routing" closes each report
    let total = block[end].trim_start_matches("Info:").trim();
    Some(format!("{first} → {last} ({total})"))
}

/// How many placements an fmax is the median of: nextpnr at seeds 1 ..= `n` (those that place: `median`), each
/// placement cached under its seed;
/// at least `least` of them in hand (placed now where the cache does not hold them), and any other of the `n` the
/// cache holds reused. `synth` and `report` place all five; the demo places one and reuses what the cache holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Seeds {
    pub n: u32,
    pub least: u32,
}

impl Seeds {
    /// five placements, `synth`'s and `report`'s default
    pub const FIVE: Seeds = Seeds::all(5);

    /// every seed of 1 ..= n placed, or read from the cache
    pub const fn all(n: u32) -> Seeds {
        Seeds { n, least: n }
    }
}

/// The unit's own cells (with the fit check that names the resource that overflows), its hard blocks, and the unit
/// in its I/O wrapper through yosys to `wrapped.json`: what every placement starts from.
fn wrapped(u: &Unit, dir: &Path, part: Part, choice: &str) -> Result<SynthReport, String> {
    let c = synth_unit(u, dir, part.family)?;
    if let Some(o) = part.overflow(&c) {
        return Err(format!("{} does not fit the {}: {o}", u.name, part.title));
    }
    let blocks = Blocks::read(dir, u.name, part.family);
    let w = format!("{}_io.v", u.name);
    write_atomic(&dir.join(&w), io_wrapper(u).as_bytes())?;
    let top = format!("{}_io", u.name);
    yosys(dir, part.family, &top, &[&format!("{}.v", u.name), &w], Some("wrapped.json"))?;
    let mut packed = String::new();
    if part.family == Family::Ecp5 && crate::regpack::packs() {
        // yosys's netlist kept beside the one placed, for a user to compare
        let read = |f: &str| std::fs::read_to_string(dir.join(f)).map_err(|e| format!("no yosys netlist {f}: {e}"));
        let text = read("wrapped.json")?;
        write_atomic(&dir.join("wrapped.yosys.json"), text.as_bytes())?;
        let (out, p) = crate::regpack::pack_ecp5(&text, &top)?;
        write_atomic(&dir.join("wrapped.json"), out.as_bytes())?;
        packed = p.to_string();
    }
    Ok(SynthReport {
        unit: u.name.into(),
        part: part.name.into(),
        cells: c,
        latency: u.latency,
        interval: u.interval,
        choice: choice.into(),
        blocks,
        packed,
        ..Default::default()
    })
}

/// How a placement stopped at the time limit begins its error, followed by the limit ("… after 900 s"). It is cached
/// with its limit and placed again only under a longer one.
const STOPPED: &str = "nextpnr had not finished after";

/// How long one placement may take: `$BUMPRTL_PLACE_LIMIT` seconds, else 15 minutes. nextpnr-ice40 0.4's router can
/// go round without end on a nearly full part: `cart_tex_nearest_surface_matte` on the UP5K (82 % of its logic
/// cells) routes in minutes at seeds 1, 3, 4 and 5, and at seed 2 still had the same 5,591 arcs to route after
/// 170,000 iterations.
pub fn place_limit() -> Result<std::time::Duration, String> {
    let secs = match std::env::var("BUMPRTL_PLACE_LIMIT") {
        Ok(v) => v.trim().parse().map_err(|_| format!("BUMPRTL_PLACE_LIMIT={v}: not a whole number of seconds"))?,
        Err(_) => 900,
    };
    Ok(std::time::Duration::from_secs(secs))
}

/// One nextpnr placement of `wrapped.json` in `dir` at `seed` and a `freq_mhz` target: `base` with this placement's
/// logic cells, fmax and critical path (its log `nextpnr.seed<N>.log`). A placement that fails (a design too big
/// for the part in a way the cell counts did not show) or that has not finished within `place_limit()` is a
/// figure, not an error; a tool that cannot run is an error.
fn place(dir: &Path, part: Part, freq_mhz: f64, seed: u32, base: &SynthReport) -> Result<SynthReport, String> {
    let mut r = SynthReport { seed, placements: 1, ..base.clone() };
    let (freq, seed_arg, asc) = (format!("{freq_mhz}"), seed.to_string(), format!("wrapped.seed{seed}.asc"));
    let mut args: Vec<&str> = part.pnr.to_vec();
    args.extend(["--json", "wrapped.json", "--freq", &freq, "--timing-allow-fail", "--seed", &seed_arg]);
    let prog = match part.family {
        Family::Ice40 => {
            args.extend(["--asc", &asc]);
            tools::toolchain().nextpnr_ice40()
        }
        Family::Ecp5 => tools::nextpnr_ecp5().ok_or_else(tools::nextpnr_ecp5_missing)?,
    };
    let lc_name = format!("{}:", part.logic_cell_name());
    let limit = place_limit()?;
    let out = match tools::run_limited(dir, &prog, &args, limit) {
        Ok((o, true)) => o,
        Ok((o, false)) => {
            write_atomic(&dir.join(format!("nextpnr.seed{seed}.log")), &o.stderr)?;
            r.place_error = Some(format!("{STOPPED} {} s", limit.as_secs()));
            return Ok(r);
        }
        // nextpnr said why the design does not place: a figure of the report; anything else (the tool missing or
        // crashing) is an error
        Err(e) => match e.lines().find(|l| l.contains("ERROR")) {
            Some(why) => {
                r.place_error = Some(why.trim().to_string());
                return Ok(r);
            }
            None => {
                // one line: which tool failed where, and its last word
                let mut lines = e.lines().map(str::trim).filter(|l| !l.is_empty());
                let first = lines.next().unwrap_or("place-and-route failed").to_string();
                return Err(match lines.next_back() {
                    Some(last) => format!("{first} {last}"),
                    None => first,
                });
            }
        },
    };
    let text = String::from_utf8_lossy(&out.stderr).to_string();
    write_atomic(&dir.join(format!("nextpnr.seed{seed}.log")), text.as_bytes())?;
    for l in text.lines() {
        if let Some(rest) = l.split(lc_name.as_str()).nth(1) {
            // the utilisation table ("  224/ 5280  4%"), not the placer's progress lines
            if let Some(n) = rest.trim().split('/').next().and_then(|x| x.trim().parse().ok()) {
                r.lc = Some(n);
            }
        }
        if l.contains("Max frequency for clock") && l.contains("clk") && !l.contains("PACKER") {
            r.fmax_mhz = l.split(':').nth(2).and_then(|x| x.split_whitespace().next()).and_then(|x| x.parse().ok());
        }
    }
    // the last report is the routed design's
    r.critical = text.rfind("Critical path report for clock").and_then(|k| critical_path(&text[k..]));
    r.fmax_range = r.fmax_mhz.map(|f| (f, f));
    Ok(r)
}

/// The placements of `base` at `seeds`, in seed order, on as many threads as the machine has cores (nextpnr places
/// on one): a cold `synth` of five seeds takes two and a half placements' time on two cores, not five.
fn place_all(
    dir: &Path,
    part: Part,
    freq_mhz: f64,
    seeds: &[u32],
    base: &SynthReport,
) -> Result<Vec<SynthReport>, String> {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()).min(seeds.len()).max(1);
    let next = std::sync::atomic::AtomicUsize::new(0);
    let done: std::sync::Mutex<Vec<(usize, Result<SynthReport, String>)>> = Default::default();
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| loop {
                let k = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(&seed) = seeds.get(k) else { break };
                let r = place(dir, part, freq_mhz, seed, base);
                done.lock().unwrap_or_else(|e| e.into_inner()).push((k, r));
            });
        }
    });
    let mut done = done.into_inner().unwrap_or_else(|e| e.into_inner());
    done.sort_by_key(|(k, _)| *k);
    done.into_iter().map(|(_, r)| r).collect()
}

/// The median of placements of one design (one report a seed): that placement's logic cells, fmax and critical
/// path, with how many placements it is the median of and their slowest and fastest fmax. With an even count it is
/// the slower of the two middle placements, so that the critical path shown is one nextpnr reported. Placements
/// that failed are not ranked: the median is of those that placed, and the failed ones are named with their seeds
/// (`unplaced`); a design that places at no seed is one that does not place, its error naming the first seed.
pub fn median(all: Vec<SynthReport>) -> Option<SynthReport> {
    let (mut failed, mut all): (Vec<_>, Vec<_>) = all.into_iter().partition(|r| r.place_error.is_some());
    failed.sort_by_key(|r| r.seed);
    let unplaced =
        failed.iter().map(|r| format!("seed {}: {}", r.seed, r.place_error.as_deref().unwrap_or(""))).collect();
    if all.is_empty() {
        // nextpnr's own error before a placement stopped at the time limit
        let k = failed.iter().position(|r| r.stopped_after().is_none()).unwrap_or(0);
        let mut r = failed.into_iter().nth(k)?;
        r.place_error = r.place_error.map(|e| format!("{e} (at nextpnr seed {})", r.seed));
        (r.placements, r.fmax_mhz, r.fmax_range, r.lc, r.critical) = (0, None, None, None, None);
        r.unplaced = unplaced;
        return Some(r);
    }
    let n = all.len() as u32;
    // a placement without an fmax figure (nextpnr printed none) ranks below every one with a figure
    let rank = |r: &SynthReport| r.fmax_mhz.unwrap_or(f64::NEG_INFINITY);
    all.sort_by(|a, b| rank(a).total_cmp(&rank(b)).then(a.seed.cmp(&b.seed)));
    let range = match (all.first()?.fmax_mhz, all.last()?.fmax_mhz) {
        (Some(lo), Some(hi)) => Some((lo, hi)),
        _ => None,
    };
    let mut r = all.swap_remove((all.len() - 1) / 2);
    (r.placements, r.fmax_range, r.unplaced) = (n, range, unplaced);
    Some(r)
}

/// The unit on a part: its own cells (and the fit check), then the wrapped unit through yosys and nextpnr at a
/// `freq_mhz` target at each seed `seeds` asks for, each placement reused from the synthesis cache
/// (`crate::cache`) when the unit's Verilog, the wrapper, the part, the target frequency, the seed and the tools'
/// versions are all unchanged (a placement takes minutes). The report (`report.txt` in `dir`) is the median
/// placement's.
pub fn synth_and_place(
    u: &Unit,
    dir: &Path,
    part: Part,
    freq_mhz: f64,
    choice: &str,
    seeds: Seeds,
) -> Result<SynthReport, String> {
    if seeds.n == 0 || seeds.least > seeds.n {
        return Err(format!("{} placements of seeds 1 ..= {}: nothing to place", seeds.least, seeds.n));
    }
    let packing = match part.family {
        Family::Ecp5 if crate::regpack::packs() => format!("\n{}", crate::regpack::VERSION),
        Family::Ecp5 => "\nevery register in the fabric".to_string(),
        Family::Ice40 => String::new(),
    };
    let inputs = format!(
        "place\n{}\n{}\n{}\n{KEEP_COPIES}\n{FABRIC_PRODUCTS}\n{freq_mhz}\nblocks by type{packing}",
        u.export().text,
        io_wrapper(u),
        part.name
    );
    let pnr = match part.family {
        Family::Ice40 => tools::toolchain().nextpnr_ice40(),
        Family::Ecp5 => tools::nextpnr_ecp5().unwrap_or_else(|| "nextpnr-ecp5".into()),
    };
    let yosys = tools::toolchain().yosys();
    // a placement stopped at a shorter time limit than this run's is placed again
    let limit = place_limit()?;
    let key = |seed: u32| cache::key(&format!("{inputs}\nseed {seed}"), &[&yosys, &pnr]);
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let cached = || -> Vec<SynthReport> {
        (1..=seeds.n)
            .filter_map(|s| cache::get(&key(s), "placement").as_deref().and_then(SynthReport::from_text))
            .filter(|r| r.placements == 1 && r.stopped_after().is_none_or(|s| s >= limit.as_secs()))
            .collect()
    };
    let mut have = cached();
    let mut _making = None;
    if have.len() < seeds.least as usize {
        // another process placing the same design waits for these placements, and this one for its
        _making = Some(cache::making(&key(0), "placement")?);
        have = cached();
    }
    let want = (seeds.least as usize).saturating_sub(have.len());
    let missing: Vec<u32> = (1..=seeds.n).filter(|s| !have.iter().any(|r| r.seed == *s)).take(want).collect();
    if !missing.is_empty() {
        let base = wrapped(u, dir, part, choice)?;
        for r in place_all(dir, part, freq_mhz, &missing, &base)? {
            cache::put(&key(r.seed), "placement", &r.to_text())?;
            have.push(r);
        }
    }
    let mut r = median(have).ok_or("no placement in hand")?;
    r.choice = choice.into();
    r.interval = u.interval; // the unit's, whatever a placement cached before the field said
    write_atomic(&dir.join("report.txt"), r.to_text().as_bytes())?;
    Ok(r)
}

impl SynthReport {
    fn to_text(&self) -> String {
        let o = |x: Option<String>| x.unwrap_or_default();
        let c = &self.cells;
        let (lo, hi) = (self.fmax_range.map(|r| r.0.to_string()), self.fmax_range.map(|r| r.1.to_string()));
        format!(
            "unit={}\npart={}\nlut4={}\nff={}\ndsp={}\nbram={}\ncarry={}\nsoft={}\nspram={}\nlatency={}\nchoice={}\nlc={}\nfmax_mhz={}\ncritical={}\nplace_error={}\nplacements={}\nseed={}\nfmax_min={}\nfmax_max={}\nblocks={}\npacked={}\ninterval={}\nunplaced={}\n",
            self.unit, self.part, c.lut4, c.ff, c.dsp, c.bram, c.carry, c.soft, c.spram, self.latency, self.choice.replace('\n', " "),
            o(self.lc.map(|x| x.to_string())), o(self.fmax_mhz.map(|x| x.to_string())),
            o(self.critical.clone()), o(self.place_error.clone()), self.placements, self.seed, o(lo), o(hi),
            self.blocks.to_text(),
            self.packed,
            self.interval,
            self.unplaced.join(" | ")
        )
    }

    fn from_text(text: &str) -> Option<SynthReport> {
        let get = |k: &str| text.lines().find_map(|l| l.strip_prefix(k).and_then(|r| r.strip_prefix('=')));
        let opt = |k: &str| get(k).filter(|v| !v.is_empty());
        let part = get("part")?;
        self::part(part).ok()?;
        Some(SynthReport {
            unit: get("unit")?.to_string(),
            part: part.to_string(),
            cells: Cells {
                lut4: get("lut4")?.parse().ok()?,
                ff: get("ff")?.parse().ok()?,
                dsp: get("dsp")?.parse().ok()?,
                bram: get("bram")?.parse().ok()?,
                carry: get("carry")?.parse().ok()?,
                soft: get("soft")?.parse().ok()?,
                spram: get("spram").and_then(|v| v.parse().ok()).unwrap_or(0),
            },
            latency: get("latency")?.parse().ok()?,
            // a report saved before the field: every unit then took a pixel a clock
            interval: get("interval").and_then(|v| v.parse().ok()).unwrap_or(1),
            choice: get("choice")?.to_string(),
            lc: opt("lc").and_then(|v| v.parse().ok()),
            fmax_mhz: opt("fmax_mhz").and_then(|v| v.parse().ok()),
            critical: opt("critical").map(str::to_string),
            place_error: opt("place_error").map(str::to_string),
            placements: get("placements")?.parse().ok()?,
            seed: get("seed")?.parse().ok()?,
            fmax_range: opt("fmax_min").and_then(|v| v.parse().ok()).zip(opt("fmax_max").and_then(|v| v.parse().ok())),
            blocks: Blocks::from_text(get("blocks")?),
            packed: get("packed").unwrap_or_default().to_string(),
            unplaced: opt("unplaced").map(|v| v.split(" | ").map(str::to_string).collect()).unwrap_or_default(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The final `stat` table as yosys 0.23 and 0.70 write it (the same netlist's rows, taken from their logs):
    /// each read whole, the FFs summed over their kinds, and an earlier table of the log left out.
    #[test]
    fn the_cells_are_read_off_the_last_stat_table_of_either_yosys() {
        let old = "2. Printing statistics.\n\n=== top ===\n   Number of cells:  9\n     SB_LUT4   900\n\n5. Printing statistics.\n\n=== polar_pipeline ===\n\n   Number of wires:               1281\n   Number of cells:               1045\n     SB_CARRY                      165\n     SB_DFF                        558\n     SB_DFFSR                       29\n     SB_DFFSS                        2\n     SB_LUT4                       277\n     SB_MAC16                        7\n     SB_RAM40_4K                     7\n\nWarnings: 3 unique messages, 3 total\n";
        let new = "4.59. Printing statistics.\n      1009 submodules\n       542   SB_DFF\n       273   SB_LUT4\n\n5. Printing statistics.\n\n=== polar_pipeline ===\n\n        +----------Local Count, excluding submodules.\n        | \n      711 wires\n     1207 cells\n      184   $scopeinfo\n      163   SB_CARRY\n      542   SB_DFF\n       29   SB_DFFSR\n        2   SB_DFFSS\n      273   SB_LUT4\n        7   SB_MAC16\n        7   SB_RAM40_4K\n\nWarnings: 3 unique messages, 3 total\n";
        let c = cells(Family::Ice40, old);
        assert_eq!((c.lut4, c.ff, c.dsp, c.bram, c.carry, c.spram), (277, 589, 7, 7, 165, 0));
        let c = cells(Family::Ice40, new);
        assert_eq!((c.lut4, c.ff, c.dsp, c.bram, c.carry, c.spram), (273, 573, 7, 7, 163, 0));
    }

    #[test]
    fn a_saved_report_reads_back_whole() {
        let r = SynthReport {
            unit: "u".into(),
            part: "ecp5-45f".into(),
            cells: Cells { lut4: 1, ff: 3, dsp: 4, bram: 5, carry: 2, soft: 9, spram: 10 },
            latency: 8,
            interval: 2,
            choice: "not up5k: it needs 9 SB_MAC16".into(),
            lc: Some(6),
            fmax_mhz: Some(7.5),
            critical: Some("a → b (1 ns logic, 2 ns routing)".into()),
            place_error: Some("ERROR: no BELs".into()),
            placements: 5,
            seed: 3,
            fmax_range: Some((6.25, 8.5)),
            blocks: Blocks { by_instance: vec![("unit$0".into(), 3, 0), ("norm".into(), 6, 1)] },
            packed: "2 multiplier operands and 1 products through the MULT18X18D registers".into(),
            unplaced: vec!["seed 1: ERROR: no route".into(), "seed 4: nextpnr had not finished after 900 s".into()],
        };
        let back = SynthReport::from_text(&r.to_text()).unwrap();
        assert_eq!(back.to_text(), r.to_text());
        let none = SynthReport {
            lc: None,
            fmax_mhz: None,
            critical: None,
            place_error: None,
            fmax_range: None,
            unplaced: vec![],
            ..r
        };
        assert_eq!(SynthReport::from_text(&none.to_text()).unwrap().to_text(), none.to_text());
        assert!(SynthReport::from_text("unit=u\nlut4=x\n").is_none());
        assert!(SynthReport::from_text(&none.to_text().replace("ecp5-45f", "ecp5-12f")).is_none());
    }

    #[test]
    fn the_median_placement_is_the_middle_fmax_and_the_slower_middle_of_an_even_count() {
        let at = |seed: u32, f: f64| SynthReport {
            seed,
            placements: 1,
            fmax_mhz: Some(f),
            fmax_range: Some((f, f)),
            lc: Some(100 + seed as u64),
            critical: Some(format!("path {seed}")),
            ..Default::default()
        };
        let m = median(vec![at(1, 120.0), at(2, 101.5), at(3, 110.25)]).unwrap();
        assert_eq!((m.seed, m.fmax_mhz, m.lc, m.critical.as_deref()), (3, Some(110.25), Some(103), Some("path 3")));
        assert_eq!((m.placements, m.fmax_range), (3, Some((101.5, 120.0))));
        let m = median(vec![at(1, 90.0), at(2, 80.0), at(3, 95.0), at(4, 85.0)]).unwrap();
        assert_eq!((m.seed, m.fmax_mhz, m.placements, m.fmax_range), (4, Some(85.0), 4, Some((80.0, 95.0))));
        let one = median(vec![at(7, 50.0)]).unwrap();
        assert_eq!((one.seed, one.placements, one.fmax_range), (7, 1, Some((50.0, 50.0))));
        // a placement with no fmax figure is the slowest
        let m = median(vec![at(1, 60.0), SynthReport { fmax_mhz: None, ..at(2, 0.0) }, at(3, 70.0)]).unwrap();
        assert_eq!((m.seed, m.fmax_range), (1, None));
        // one that failed is named, and the median is of the others: of two, the slower
        let failed = |seed| SynthReport { place_error: Some("ERROR: no route".into()), ..at(seed, 0.0) };
        let m = median(vec![at(1, 60.0), failed(2), at(3, 70.0)]).unwrap();
        assert_eq!((m.place_error, m.seed, m.fmax_mhz, m.placements), (None, 1, Some(60.0), 2));
        assert_eq!((m.fmax_range, m.unplaced), (Some((60.0, 70.0)), vec!["seed 2: ERROR: no route".to_string()]));
        // failed at every seed: a design that does not place, the first seed named, nextpnr's own error before a
        // placement stopped at the time limit
        let m = median(vec![failed(5), failed(3)]).unwrap();
        assert_eq!(m.place_error.as_deref(), Some("ERROR: no route (at nextpnr seed 3)"));
        assert_eq!(m.unplaced_text(), "does not place");
        assert_eq!((m.fmax_mhz, m.placements, m.critical, m.unplaced.len()), (None, 0, None, 2));
        let stopped = |seed| SynthReport { place_error: Some(format!("{STOPPED} 900 s")), ..at(seed, 0.0) };
        assert_eq!((stopped(1).stopped_after(), failed(1).stopped_after()), (Some(900), None));
        let m = median(vec![stopped(1), failed(4), stopped(2)]).unwrap();
        assert_eq!(m.place_error.as_deref(), Some("ERROR: no route (at nextpnr seed 4)"));
        assert_eq!(m.unplaced[0], "seed 1: nextpnr had not finished after 900 s");
        let m = median(vec![stopped(2)]).unwrap();
        assert_eq!(m.unplaced_text(), "not placed within 900 s");
        assert!(median(vec![]).is_none());
    }

    #[test]
    fn hard_blocks_are_counted_by_the_instance_their_names_begin_with() {
        let dsp = "texture_filter/unit$0.mul0.s3_p.d_MULT18X18D_P0\ntexture_filter/unit$0.mul1.s3_p.d_MULT18X18D_P0\n\
                   texture_filter/norm.s2_sq$0$d_MULT18X18D_P0\n";
        let bram = "texture_filter/norm.s6_r.q_DP16KD_DOA0\ntexture_filter/lookup.tables.mem.0.0\ntexture_filter/x\n";
        let b = Blocks::parse(dsp, bram, "");
        assert_eq!(
            b.by_instance,
            vec![("-".into(), 0, 1), ("lookup".into(), 0, 1), ("norm".into(), 1, 1), ("unit$0".into(), 2, 0)]
        );
        let wrapped = Blocks::parse("w/dut.unit$0.mul0.x\n", "", "dut.");
        assert_eq!(wrapped.by_instance, vec![("unit$0".into(), 1, 0)]);
        assert_eq!(Blocks::from_text(&b.to_text()), b);
    }

    #[test]
    fn overflow_names_the_first_resource_past_the_part() {
        let c = Cells { lut4: 2269, ff: 3341, dsp: 36, bram: 4, carry: 300, soft: 0, spram: 0 };
        let o = ECP5_25F.overflow(&c).unwrap();
        assert!(o.contains("36 MULT18X18D") && o.contains("has 28"), "{o}");
        assert_eq!(ECP5_45F.overflow(&c), None);
        let o = UP5K.overflow(&Cells { lut4: 5281, ..Default::default() }).unwrap();
        assert!(o.contains("5281 SB_LUT4") && o.contains("has 5280"), "{o}");
        let o = UP5K.overflow(&Cells { ff: 6000, ..Default::default() }).unwrap();
        assert!(o.contains("6000 SB_DFF,"), "{o}");
        // the UP5K's four SPRAMs, and none on the ECP5
        assert_eq!(UP5K.overflow(&Cells { spram: 4, ..Default::default() }), None);
        let o = UP5K.overflow(&Cells { spram: 5, ..Default::default() }).unwrap();
        assert!(o.contains("5 SB_SPRAM256KA") && o.contains("has 4"), "{o}");
        assert!(ECP5_85F.overflow(&Cells { spram: 1, ..Default::default() }).is_some());
        // two CCU2C are four LUT4s of the part
        assert!(ECP5_25F.overflow(&Cells { lut4: 24285, carry: 2, ..Default::default() }).is_some());
        assert_eq!(ECP5_25F.overflow(&Cells { lut4: 24284, carry: 2, ..Default::default() }), None);
    }

    #[test]
    fn the_smallest_products_go_into_logic_first() {
        // yosys's dump of three $mul cells (the shape `dump t:$mul` writes), one of them 8 × 8
        let dump = "  cell $mul $flatten\\dot.$mul$u.v:7$3\n    parameter \\A_SIGNED 0\n    parameter \\A_WIDTH 12\n    parameter \\B_WIDTH 12\n    connect \\A x\n  end\n\
                    cell $mul $flatten\\blend.$mul$u.v:9$5\n    parameter \\A_WIDTH 8\n    parameter \\B_WIDTH 8\n  end\n\
                    cell $mul $flatten\\norm.$mul$u.v:4$1\n    parameter \\A_WIDTH 10\n    parameter \\B_WIDTH 13\n  end\n";
        let all = products(dump);
        assert_eq!(all.iter().map(|p| (p.a, p.b)).collect::<Vec<_>>(), [(12, 12), (8, 8), (10, 13)]);
        assert_eq!(all[1].name, "$flatten\\blend.$mul$u.v:9$5");
        assert!(to_fabric(all.clone(), 0).is_empty());
        let soft = to_fabric(all.clone(), 2);
        assert_eq!(soft.iter().map(|p| p.a * p.b).collect::<Vec<_>>(), [64, 130]);
        assert_eq!(to_fabric(all, 5).len(), 3);
        let o = UP5K.overflow(&Cells { lut4: 6000, dsp: 8, soft: 25, ..Default::default() }).unwrap();
        assert!(o.contains("6000 SB_LUT4") && o.contains("25 of its products built in logic"), "{o}");
    }

    #[test]
    fn targets_are_named_and_unknown_ones_refused() {
        assert_eq!(part("ecp5-45f").unwrap(), ECP5_45F);
        let e = part("ecp5-12f").unwrap_err();
        assert!(e.contains("up5k, ecp5-25f, ecp5-45f, ecp5-85f"), "{e}");
    }
}

/// A unit on one part: placed, or the resource that keeps it off the part.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)] // a handful a command, each read whole: boxing the report buys nothing
pub enum Fit {
    Placed(SynthReport),
    DoesNotFit(String),
}

/// A unit's figures on `parts` (synthesised for each; placed where it fits at the `seeds` asked for, each placement
/// cached); `say` tells a progress line what runs now.
pub fn measure(
    u: &Unit,
    dir: &Path,
    parts: &[Part],
    seeds: Seeds,
    say: &dyn Fn(String),
) -> Result<Vec<(Part, Fit)>, String> {
    let mut v = Vec::new();
    for p in parts {
        let d = dir.join(u.name).join(p.name);
        say(format!("{}: yosys for the {}", u.name, p.title));
        let c = synth_unit(u, &d, p.family)?;
        let fit = match p.overflow(&c) {
            Some(o) => Fit::DoesNotFit(o),
            None => {
                say(format!("{}: nextpnr for the {} (each placement cached after its first run)", u.name, p.title));
                Fit::Placed(synth_and_place(u, &d, *p, p.default_freq(), "", seeds)?)
            }
        };
        v.push((*p, fit));
    }
    Ok(v)
}
