//! The ECP5's own registers, used where the pipeline already has the stage: a synthesis-only rewrite of the
//! netlist `synth_ecp5` writes, between yosys and nextpnr.
//!
//! yosys (0.23 and 0.70 alike) maps every product to a MULT18X18D with its input, pipeline and output registers
//! off, and every block RAM to a DP16KD with its output register off (`REGMODE NOREG`); the pipeline's own
//! registers on either side stay in the fabric. Without them a MULT18X18D is 3.93 ns from A to P and a DP16KD read
//! 5.6 ns from clock to DO (speed 6); with them, 0.74 and 0.97 ns from clock to out. This pass moves those
//! flip-flops into the blocks:
//! - a fabric flip-flop between a DP16KD's DO and its one load becomes the port's output register (`REGMODE_x
//!   OUTREG`); in the 36-bit mode, where one read comes out on both ports' pins, the flip-flops behind all 36 become
//!   both ports' output registers;
//! - the flip-flops that take a MULT18X18D's P become its output register (`REG_OUTPUT_CLK CLK0`);
//! - the flip-flops that give a MULT18X18D's A (or B) become its input register (`REG_INPUTA_CLK CLK0`); a
//!   flip-flop that also feeds other logic stays, and the block's register is its copy. One straight behind a
//!   product, or behind a DP16KD read without its output register, stays in the fabric beside that block.
//!
//! Only a plain flip-flop moves: the one clock, always enabled, no set or reset, initial value 0 (the value a
//! block's register starts from), so every clock after the first one the design computes what it did before, word
//! for word. The rust-hdl blocks, their simulation, their golden vectors and their exported Verilog are not touched:
//! this is the netlist that is placed. `models` gives the two blocks' behaviour, and `tests/exported.rs` simulates
//! the netlist before and after this pass against a unit's golden vectors.

use serde_json::{Map, Value};
use std::collections::{HashMap, HashSet};
use std::fmt::Write as _;

/// The pass's version, part of every ECP5 placement's cache key: a change to what it packs makes new placements.
pub const VERSION: &str = "ecp5 block registers packed (bumprtl regpack 5)";

static FABRIC: std::sync::OnceLock<bool> = std::sync::OnceLock::new();

/// Place the ECP5 netlist as yosys wrote it, every register in the fabric, for the rest of this process (a
/// command's `--fabric-registers`, to compare); chosen before any placement.
pub fn keep_fabric_registers(fabric: bool) -> Result<(), String> {
    match *FABRIC.get_or_init(|| fabric) {
        f if f == fabric => Ok(()),
        _ => Err("the register packing is chosen already".into()),
    }
}

/// Whether ECP5 netlists are packed before they are placed (the default).
pub fn packs() -> bool {
    !FABRIC.get().copied().unwrap_or(false)
}

/// What the pass moved into the blocks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Packing {
    /// MULT18X18D operands (A or B) taken through the block's input register
    pub mult_inputs: usize,
    /// MULT18X18D products taken through the block's output register
    pub mult_outputs: usize,
    /// DP16KD read ports taken through the block's output register
    pub bram_outputs: usize,
    /// fabric flip-flops left out of the netlist
    pub ffs_removed: usize,
}

impl std::fmt::Display for Packing {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} multiplier operands and {} products through the MULT18X18D registers, {} block RAM reads through the \
             DP16KD output register ({} fabric flip-flops fewer)",
            self.mult_inputs, self.mult_outputs, self.bram_outputs, self.ffs_removed
        )
    }
}

/// A cell's port: (cell name, port name).
type Pin = (String, String);

/// Who drives and who reads each net bit of a module.
struct Nets {
    driver: HashMap<u64, Pin>,
    loads: HashMap<u64, Vec<Pin>>,
    /// bits on the module's own ports: never a flip-flop's to remove
    ports: HashSet<u64>,
}

fn bit(v: &Value) -> Option<u64> {
    v.as_u64()
}

/// A string parameter as yosys writes it (a string of 0/1/x/z characters gets a trailing space).
fn param<'a>(cell: &'a Value, name: &str) -> Option<&'a str> {
    cell["parameters"].get(name).and_then(Value::as_str).map(str::trim_end)
}

/// A parameter yosys wrote as a bit string ("00…010010"), as a number.
fn param_num(cell: &Value, name: &str) -> Option<u64> {
    param(cell, name).and_then(|s| u64::from_str_radix(s, 2).ok())
}

fn conn<'a>(cell: &'a Value, port: &str) -> Option<&'a Value> {
    cell["connections"].get(port).and_then(|v| v.get(0))
}

fn is_const(v: Option<&Value>, c: &str) -> bool {
    v.and_then(Value::as_str) == Some(c)
}

impl Nets {
    fn of(module: &Value) -> Nets {
        let mut n = Nets { driver: HashMap::new(), loads: HashMap::new(), ports: HashSet::new() };
        if let Some(cells) = module["cells"].as_object() {
            for (name, c) in cells {
                let Some(conns) = c["connections"].as_object() else { continue };
                for (port, bits) in conns {
                    let output = c["port_directions"].get(port).and_then(Value::as_str) == Some("output");
                    for b in bits.as_array().into_iter().flatten().filter_map(bit) {
                        if output {
                            n.driver.insert(b, (name.clone(), port.clone()));
                        } else {
                            n.loads.entry(b).or_default().push((name.clone(), port.clone()));
                        }
                    }
                }
            }
        }
        if let Some(ports) = module["ports"].as_object() {
            for p in ports.values() {
                n.ports.extend(p["bits"].as_array().into_iter().flatten().filter_map(bit));
            }
        }
        n
    }

    fn loads(&self, b: u64) -> &[Pin] {
        self.loads.get(&b).map(Vec::as_slice).unwrap_or(&[])
    }
}

/// A flip-flop a block's register can stand for: `TRELLIS_FF` on a clock, always enabled, never set or reset,
/// starting at 0. Its (clock, D, Q).
fn plain_ff(cell: &Value) -> Option<(u64, Value, u64)> {
    if cell["type"].as_str() != Some("TRELLIS_FF") {
        return None;
    }
    let default = |name: &str, want: &str| param(cell, name).is_none_or(|v| v == want);
    let enabled = match param(cell, "CEMUX") {
        Some("1") => true,
        None | Some("CE") => is_const(conn(cell, "CE"), "1"),
        _ => false,
    };
    let no_reset = conn(cell, "LSR").is_none() || is_const(conn(cell, "LSR"), "0");
    let plain = enabled
        && no_reset
        && default("REGSET", "RESET")
        && default("CLKMUX", "CLK")
        && default("LSRMUX", "LSR")
        && default("LSRMODE", "LSR");
    if !plain {
        return None;
    }
    Some((bit(conn(cell, "CLK")?)?, conn(cell, "DI")?.clone(), bit(conn(cell, "Q")?)?))
}

/// Whether net bit `d` comes straight out of a hard block through no register of the block's own: a product (this
/// pass puts a product's output register on only as it reaches that multiplier), or a DP16KD read with its output
/// register off (the block RAM pass runs first, so a read it packed is registered by now).
fn from_unregistered_block(cells: &Map<String, Value>, nets: &Nets, d: &Value) -> bool {
    let Some((c, pin)) = d.as_u64().and_then(|b| nets.driver.get(&b)) else { return false };
    let cell = &cells[c];
    match cell["type"].as_str() {
        Some("DP16KD") => {
            let port = if pin.starts_with("DOA") { "A" } else { "B" };
            param(cell, &format!("REGMODE_{port}")).is_none_or(|m| m == "NOREG")
        }
        Some("MULT18X18D") => true,
        _ => false,
    }
}

fn set_conn(cells: &mut Map<String, Value>, cell: &str, port: &str, v: Value, input: bool) {
    let c = &mut cells[cell];
    c["connections"][port] = Value::Array(vec![v]);
    c["port_directions"][port] = Value::String(if input { "input" } else { "output" }.into());
}

fn set_param(cells: &mut Map<String, Value>, cell: &str, name: &str, v: &str) {
    cells[cell]["parameters"][name] = Value::String(v.into());
}

/// The flip-flops that take every used bit of `outs` (cell `name`'s output pins), each bit's one load, all on one
/// clock: (clock, [(pin, flip-flop)]), or None when any used bit goes elsewhere or no bit is used.
fn output_flops(
    cells: &Map<String, Value>,
    nets: &Nets,
    name: &str,
    outs: &[String],
) -> Option<(u64, Vec<(String, String)>)> {
    let cell = &cells[name];
    let mut clock = None;
    let mut flops = Vec::new();
    for pin in outs {
        let Some(b) = conn(cell, pin).and_then(bit) else { continue };
        match nets.loads(b) {
            [] => {}
            [(ff, port)] if port == "DI" && !nets.ports.contains(&b) => {
                let (clk, _, _) = plain_ff(&cells[ff])?;
                if clock.is_some_and(|c| c != clk) {
                    return None;
                }
                clock = Some(clk);
                flops.push((pin.clone(), ff.clone()));
            }
            _ => return None,
        }
    }
    Some((clock?, flops))
}

/// Move each flip-flop of `flops` behind its output pin into the block: the pin drives the flip-flop's Q net,
/// and the flip-flop goes.
fn absorb_outputs(cells: &mut Map<String, Value>, name: &str, flops: &[(String, String)]) -> usize {
    for (pin, ff) in flops {
        let q = conn(&cells[ff], "Q").cloned().expect("a flip-flop has a Q");
        set_conn(cells, name, pin, q, false);
        cells.remove(ff);
    }
    flops.len()
}

fn pins(prefix: &str, n: usize) -> Vec<String> {
    (0..n).map(|i| format!("{prefix}{i}")).collect()
}

/// Pack `top`'s block registers in a yosys JSON netlist (`synth_ecp5 -json`): the netlist again, and what moved.
pub fn pack_ecp5(json: &str, top: &str) -> Result<(String, Packing), String> {
    let mut design: Value = serde_json::from_str(json).map_err(|e| format!("the yosys netlist does not read: {e}"))?;
    let module = design["modules"].get_mut(top).ok_or_else(|| format!("the yosys netlist has no module {top}"))?;
    let mut p = Packing::default();
    let names = |module: &Value, ty: &str| -> Vec<String> {
        module["cells"]
            .as_object()
            .map(|c| c.iter().filter(|(_, v)| v["type"].as_str() == Some(ty)).map(|(k, _)| k.clone()).collect())
            .unwrap_or_default()
    };

    // block RAM read ports first: a flip-flop behind DO is the DP16KD's output register rather than the input
    // register of a product it feeds (0.97 ns from the clock against 5.6)
    for name in names(module, "DP16KD") {
        // the 36-bit (pseudo dual-port) mode: port A writes, port B reads, and the word comes out on DOA (bits
        // 0..17) and DOB (18..35) on port B's clock. Packed as one read, all 36 pins or none, with both ports'
        // REGMODE and OCE set alike (as Lattice's own tools set a PDPW16KD's single REGMODE on the DP16KD), so that
        // whichever port's settings govern the DOA half, it is registered on the same edge; only where the two
        // ports share one clock.
        {
            let nets = Nets::of(module);
            let cells = module["cells"].as_object_mut().expect("a module with cells");
            let c = &cells[&name];
            let wide = param_num(c, "DATA_WIDTH_A") == Some(36) && param_num(c, "DATA_WIDTH_B") == Some(36);
            let clock = conn(c, "CLKB").and_then(bit);
            let ready =
                wide && ['A', 'B'].iter().all(|port| {
                    param(c, &format!("REGMODE_{port}")).is_none_or(|m| m == "NOREG")
                        && param(c, &format!("CLK{port}MUX")).is_none_or(|m| m == format!("CLK{port}"))
                        && is_const(conn(c, &format!("RST{port}")), "0")
                }) && is_const(conn(c, "OCEB"), "1")
                    && clock.is_some()
                    && conn(c, "CLKA").and_then(bit) == clock;
            if ready {
                let outs: Vec<String> = pins("DOA", 18).into_iter().chain(pins("DOB", 18)).collect();
                if let Some((clk, flops)) = output_flops(cells, &nets, &name, &outs) {
                    if Some(clk) == clock && !flops.is_empty() {
                        p.ffs_removed += absorb_outputs(cells, &name, &flops);
                        set_param(cells, &name, "REGMODE_A", "OUTREG");
                        set_param(cells, &name, "REGMODE_B", "OUTREG");
                        set_conn(cells, &name, "OCEA", Value::String("1".into()), true);
                        p.bram_outputs += 1;
                    }
                }
            }
        }
        for port in ['A', 'B'] {
            let nets = Nets::of(module);
            let cells = module["cells"].as_object_mut().expect("a module with cells");
            let c = &cells[&name];
            // the 36-bit mode is packed above, as one read
            let narrow =
                param_num(c, "DATA_WIDTH_A").unwrap_or(18) <= 18 && param_num(c, "DATA_WIDTH_B").unwrap_or(18) <= 18;
            let ready = narrow
                && param(c, &format!("REGMODE_{port}")).is_none_or(|m| m == "NOREG")
                && param(c, &format!("CLK{port}MUX")).is_none_or(|m| m == format!("CLK{port}"))
                && is_const(conn(c, &format!("OCE{port}")), "1")
                && is_const(conn(c, &format!("RST{port}")), "0");
            let clock = conn(c, &format!("CLK{port}")).and_then(bit);
            if !ready {
                continue;
            }
            let Some((clk, flops)) = output_flops(cells, &nets, &name, &pins(&format!("DO{port}"), 18)) else {
                continue;
            };
            if Some(clk) != clock || flops.is_empty() {
                continue;
            }
            p.ffs_removed += absorb_outputs(cells, &name, &flops);
            set_param(cells, &name, &format!("REGMODE_{port}"), "OUTREG");
            p.bram_outputs += 1;
        }
    }

    for name in names(module, "MULT18X18D") {
        let unset = |c: &Value, r: &str| param(c, &format!("REG_{r}_CLK")).is_none_or(|m| m == "NONE");
        let mut clock: Option<u64> = None;

        // the product
        let nets = Nets::of(module);
        let cells = module["cells"].as_object_mut().expect("a module with cells");
        if unset(&cells[&name], "OUTPUT") && unset(&cells[&name], "PIPELINE") {
            if let Some((clk, flops)) = output_flops(cells, &nets, &name, &pins("P", 36)) {
                if !flops.is_empty() {
                    p.ffs_removed += absorb_outputs(cells, &name, &flops);
                    set_param(cells, &name, "REG_OUTPUT_CLK", "CLK0");
                    p.mult_outputs += 1;
                    clock = Some(clk);
                }
            }
        }

        // each operand: every bit a constant 0 or a plain flip-flop's Q, one clock; its sign a constant
        for side in ['A', 'B'] {
            let nets = Nets::of(module);
            let cells = module["cells"].as_object_mut().expect("a module with cells");
            let c = &cells[&name];
            if !unset(c, &format!("INPUT{side}")) || !conn(c, &format!("SIGNED{side}")).is_some_and(Value::is_string) {
                continue;
            }
            let mut feeds: Vec<(String, Value, String)> = Vec::new();
            let mut ok = true;
            // the operand's clock, the block's once the operand is packed
            let mut side_clock = clock;
            for pin in pins(&side.to_string(), 18) {
                match conn(c, &pin) {
                    None => {}
                    Some(v) if is_const(Some(v), "0") => {}
                    Some(v) => {
                        let ff = v.as_u64().and_then(|b| nets.driver.get(&b)).filter(|(_, port)| port == "Q");
                        match ff.and_then(|(ff, _)| plain_ff(&cells[ff]).map(|f| (ff.clone(), f))) {
                            // a flip-flop straight behind a block's unregistered output (a DP16KD read without
                            // its output register, a product without its own) stays in the fabric beside it: in the
                            // multiplier's input register it would add the route to the DSP to the block's slow
                            // clock-to-out (cart_pipeline's normaliser: 123.5 → 114.4 MHz). Behind a DP16KD read
                            // through its output register (0.97 ns from the clock) it moves.
                            Some((_, (_, d, _))) if from_unregistered_block(cells, &nets, &d) => ok = false,
                            Some((ff, (clk, d, _))) if side_clock.is_none_or(|c| c == clk) => {
                                side_clock = Some(clk);
                                feeds.push((pin, d, ff));
                            }
                            _ => ok = false,
                        }
                    }
                }
            }
            if !ok || feeds.is_empty() {
                continue;
            }
            for (pin, d, _) in &feeds {
                set_conn(cells, &name, pin, d.clone(), true);
            }
            set_param(cells, &name, &format!("REG_INPUT{side}_CLK"), "CLK0");
            p.mult_inputs += 1;
            clock = side_clock;
            // a flip-flop that fed nothing but this operand goes
            let gone: HashSet<&String> = feeds.iter().map(|f| &f.2).collect();
            let nets = Nets::of(module);
            let cells = module["cells"].as_object_mut().expect("a module with cells");
            for ff in gone {
                let q = conn(&cells[ff], "Q").and_then(bit).expect("a flip-flop has a Q");
                if nets.loads(q).is_empty() && !nets.ports.contains(&q) {
                    cells.remove(ff);
                    p.ffs_removed += 1;
                }
            }
        }

        if let Some(clk) = clock {
            let cells = module["cells"].as_object_mut().expect("a module with cells");
            set_conn(cells, &name, "CLK0", Value::from(clk), true);
            set_conn(cells, &name, "CE0", Value::String("1".into()), true);
            set_conn(cells, &name, "RST0", Value::String("0".into()), true);
        }
    }
    let text = serde_json::to_string(&design).map_err(|e| format!("the packed netlist does not write: {e}"))?;
    Ok((text, p))
}

/// Behavioural models of the two blocks, for simulating a netlist `synth_ecp5` wrote (yosys ships none: both are
/// black boxes in its ECP5 library): MULT18X18D as a product of A and B (each signed by SIGNEDA / SIGNEDB) with its
/// input and output registers on CLK0 / CE0 / RST0; DP16KD with its data widths 1, 2, 4, 9 and 18 per port (or 36
/// on both, the pseudo dual-port mode), its initial contents, its three write modes and its output register. A
/// setting outside that stops the simulation with `$fatal` rather than being guessed; in the 36-bit mode, where the
/// sources leave open which port's settings govern the DOA half, both ports' REGMODE must agree and the register
/// loads only while both OCE are high.
pub fn models() -> String {
    let mut s = String::new();
    let list = |p: &str, n: usize| (0..n).rev().map(|i| format!("{p}{i}")).collect::<Vec<_>>().join(", ");
    let _ = writeln!(
        s,
        "// generated by bumprtl: behavioural models of the ECP5 MULT18X18D and DP16KD, as regpack uses them"
    );
    let _ = writeln!(s, "`timescale 1ns/1ps");
    let _ = writeln!(
        s,
        "module MULT18X18D(\n  input {}, {}, {},\n  input SIGNEDA, SIGNEDB, SOURCEA, SOURCEB, CLK0, CLK1, CLK2, CLK3, CE0, CE1, CE2, CE3, RST0, RST1, RST2, RST3,\n  output {}, SIGNEDP);",
        list("A", 18),
        list("B", 18),
        list("C", 18),
        list("P", 36)
    );
    s.push_str(MULT_BODY);
    let _ = writeln!(
        s,
        "module DP16KD(\n  input {}, {}, CEA, OCEA, CLKA, WEA, RSTA, CSA2, CSA1, CSA0,\n  input {}, {}, CEB, OCEB, CLKB, WEB, RSTB, CSB2, CSB1, CSB0,\n  output {},\n  output {});",
        list("DIA", 18),
        list("ADA", 14),
        list("DIB", 18),
        list("ADB", 14),
        list("DOA", 18),
        list("DOB", 18)
    );
    for k in 0..64 {
        let _ = writeln!(s, "  parameter [319:0] INITVAL_{k:02X} = 320'h0;");
    }
    let inits: Vec<String> = (0..64).rev().map(|k| format!("INITVAL_{k:02X}")).collect();
    let _ = writeln!(s, "  wire [20479:0] init = {{{}}};", inits.join(", "));
    let _ = writeln!(
        s,
        "  wire [17:0] dia = {{{}}}, dib = {{{}}};\n  wire [13:0] ada = {{{}}}, adb = {{{}}};\n  assign {{{}}} = doa;\n  assign {{{}}} = dob;",
        list("DIA", 18),
        list("DIB", 18),
        list("ADA", 14),
        list("ADB", 14),
        list("DOA", 18),
        list("DOB", 18)
    );
    s.push_str(BRAM_BODY);
    s
}

const MULT_BODY: &str = r#"  parameter REG_INPUTA_CLK = "NONE";
  parameter REG_INPUTA_CE = "CE0";
  parameter REG_INPUTA_RST = "RST0";
  parameter REG_INPUTB_CLK = "NONE";
  parameter REG_INPUTB_CE = "CE0";
  parameter REG_INPUTB_RST = "RST0";
  parameter REG_INPUTC_CLK = "NONE";
  parameter REG_PIPELINE_CLK = "NONE";
  parameter REG_OUTPUT_CLK = "NONE";
  parameter REG_OUTPUT_CE = "CE0";
  parameter REG_OUTPUT_RST = "RST0";
  parameter GSR = "ENABLED";
  parameter RESETMODE = "SYNC";
  parameter MULT_BYPASS = "DISABLED";
  parameter SOURCEB_MODE = "B_SHIFT";
  parameter CAS_MATCH_REG = "FALSE";
  parameter HIGHSPEED_CLK = "NONE";
  wire [17:0] a = {A17, A16, A15, A14, A13, A12, A11, A10, A9, A8, A7, A6, A5, A4, A3, A2, A1, A0};
  wire [17:0] b = {B17, B16, B15, B14, B13, B12, B11, B10, B9, B8, B7, B6, B5, B4, B3, B2, B1, B0};
  reg [17:0] ra = 0, rb = 0;
  reg [35:0] rp = 0;
  // SIGNEDA / SIGNEDB are constants in every netlist the packing accepts: taken as they come
  wire [17:0] ua = REG_INPUTA_CLK == "NONE" ? a : ra;
  wire [17:0] ub = REG_INPUTB_CLK == "NONE" ? b : rb;
  wire signed [18:0] sa = {SIGNEDA & ua[17], ua};
  wire signed [18:0] sb = {SIGNEDB & ub[17], ub};
  wire signed [37:0] prod = sa * sb;
  wire [35:0] p = prod[35:0];
  wire [35:0] po = REG_OUTPUT_CLK == "NONE" ? p : rp;
  assign {P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24, P23, P22, P21, P20, P19, P18, P17, P16, P15,
    P14, P13, P12, P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1, P0} = po;
  assign SIGNEDP = SIGNEDA ^ SIGNEDB;
  initial begin
    if ((REG_INPUTA_CLK != "NONE" && REG_INPUTA_CLK != "CLK0") || (REG_INPUTB_CLK != "NONE" && REG_INPUTB_CLK != "CLK0")
        || (REG_OUTPUT_CLK != "NONE" && REG_OUTPUT_CLK != "CLK0") || REG_PIPELINE_CLK != "NONE" || REG_INPUTC_CLK != "NONE"
        || REG_INPUTA_CE != "CE0" || REG_INPUTB_CE != "CE0" || REG_OUTPUT_CE != "CE0"
        || REG_INPUTA_RST != "RST0" || REG_INPUTB_RST != "RST0" || REG_OUTPUT_RST != "RST0")
      $fatal(1, "MULT18X18D %m: a register setting this model does not cover");
  end
  always @(posedge CLK0)
    if (RST0) begin
      ra <= 0; rb <= 0; rp <= 0;
    end else if (CE0) begin
      ra <= a; rb <= b; rp <= p;
    end
endmodule

"#;

const BRAM_BODY: &str = r#"  parameter DATA_WIDTH_A = 18;
  parameter DATA_WIDTH_B = 18;
  parameter REGMODE_A = "NOREG";
  parameter REGMODE_B = "NOREG";
  parameter RESETMODE = "SYNC";
  parameter ASYNC_RESET_RELEASE = "SYNC";
  parameter CSDECODE_A = "0b000";
  parameter CSDECODE_B = "0b000";
  parameter WRITEMODE_A = "NORMAL";
  parameter WRITEMODE_B = "NORMAL";
  parameter CLKAMUX = "CLKA";
  parameter CLKBMUX = "CLKB";
  parameter GSR = "ENABLED";
  // 1024 rows of 18 bits; a narrower word is a slice of a row: 9 bits at [9j +: 9], 4, 2 and 1 bits at [wj +: w]
  // of the row's two 8-bit halves (bits 0..7, 9..16; bits 8 and 17 are the 9-bit words' ninth bits)
  reg [17:0] mem [0:1023];
  reg [35:0] wide [0:511];
  reg [17:0] la = 0, lb = 0, ra = 0, rb = 0;
  reg [35:0] lw = 0, rw = 0;
  integer k;
  wire w36 = DATA_WIDTH_A == 36 || DATA_WIDTH_B == 36;
  initial begin
    for (k = 0; k < 1024; k = k + 1) mem[k] = init[k * 20 +: 18];
    for (k = 0; k < 512; k = k + 1) wide[k] = 36'd0;
    if (CSDECODE_A != "0b000" || CSDECODE_B != "0b000" || CLKAMUX != "CLKA" || CLKBMUX != "CLKB")
      $fatal(1, "DP16KD %m: a setting this model does not cover");
    if (w36 && (DATA_WIDTH_A != 36 || DATA_WIDTH_B != 36 || init != 0))
      $fatal(1, "DP16KD %m: the 36-bit mode is modelled with 36 bits on both ports and no initial contents only");
    // which port's REGMODE and OCE govern the DOA half of a 36-bit read is not modelled: both ports alike only
    if (w36 && REGMODE_A != REGMODE_B)
      $fatal(1, "DP16KD %m: the 36-bit mode is modelled with both ports' REGMODE alike only");
  end
  function integer shift(input integer w);
    shift = w == 18 ? 4 : w == 9 ? 3 : w == 4 ? 2 : w == 2 ? 1 : 0;
  endfunction
  // the bit of a row that bit `i` of word `j` of width `w` is (w < 9)
  function integer at(input integer w, input integer j, input integer i);
    integer p;
    begin
      p = w * j + i;
      at = p < 8 ? p : p + 1;
    end
  endfunction
  function [17:0] read(input integer w, input [13:0] ad);
    integer row, j, i;
    reg [17:0] r;
    begin
      row = ad[13:4];
      j = (ad & 14'hf) >> shift(w);
      r = mem[row];
      read = 18'd0;
      if (w == 18) read = r;
      else if (w == 9) read = j[0] ? r[17:9] : r[8:0];
      else for (i = 0; i < w; i = i + 1) read[i] = r[at(w, j, i)];
    end
  endfunction
  task write(input integer w, input [13:0] ad, input [17:0] d);
    integer row, j, i;
    begin
      row = ad[13:4];
      j = (ad & 14'hf) >> shift(w);
      if (w == 18) begin
        if (ad[0]) mem[row][8:0] <= d[8:0];
        if (ad[1]) mem[row][17:9] <= d[17:9];
      end else if (w == 9) begin
        if (j[0]) mem[row][17:9] <= d[8:0]; else mem[row][8:0] <= d[8:0];
      end else for (i = 0; i < w; i = i + 1) mem[row][at(w, j, i)] <= d[i];
    end
  endtask
  // port A, and in the 36-bit mode the write port
  always @(posedge CLKA) begin
    if (w36) begin
      if (CEA && WEA) begin
        if (ada[0]) wide[ada[13:5]][8:0] <= dia[8:0];
        if (ada[1]) wide[ada[13:5]][17:9] <= dia[17:9];
        if (ada[2]) wide[ada[13:5]][26:18] <= dib[8:0];
        if (ada[3]) wide[ada[13:5]][35:27] <= dib[17:9];
      end
    end else begin
      if (RSTA) la <= 0;
      else if (CEA) begin
        if (!WEA) la <= read(DATA_WIDTH_A, ada);
        else if (WRITEMODE_A == "READBEFOREWRITE") la <= read(DATA_WIDTH_A, ada);
        else if (WRITEMODE_A == "WRITETHROUGH") la <= dia;
      end
      if (RSTA) ra <= 0; else if (OCEA) ra <= la;
      if (CEA && WEA) write(DATA_WIDTH_A, ada, dia);
    end
  end
  // port B, and in the 36-bit mode the read port
  always @(posedge CLKB) begin
    if (w36) begin
      if (RSTB) lw <= 0; else if (CEB) lw <= wide[adb[13:5]];
      if (RSTB) rw <= 0; else if (OCEA && OCEB) rw <= lw; // either port's OCE low holds the word
    end else begin
      if (RSTB) lb <= 0;
      else if (CEB) begin
        if (!WEB) lb <= read(DATA_WIDTH_B, adb);
        else if (WRITEMODE_B == "READBEFOREWRITE") lb <= read(DATA_WIDTH_B, adb);
        else if (WRITEMODE_B == "WRITETHROUGH") lb <= dib;
      end
      if (RSTB) rb <= 0; else if (OCEB) rb <= lb;
      if (CEB && WEB) write(DATA_WIDTH_B, adb, dib);
    end
  end
  wire [35:0] ow = REGMODE_B == "OUTREG" ? rw : lw;
  wire [17:0] doa = w36 ? ow[17:0] : REGMODE_A == "OUTREG" ? ra : la;
  wire [17:0] dob = w36 ? ow[35:18] : REGMODE_B == "OUTREG" ? rb : lb;
endmodule
"#;

/// yosys's ECP5 cell library for simulation (its `cells_sim.v`, beside the yosys binary on the PATH, with its
/// DP16KD black box left out) and `models()`, as one file.
fn sim_library() -> Result<String, String> {
    let yosys = crate::tools::toolchain().yosys();
    let bin = std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default())
        .map(|d| d.join(&yosys))
        .find(|p| p.is_file())
        .ok_or_else(|| format!("cannot find {yosys} on the PATH"))?;
    let share = bin.parent().and_then(|b| b.parent()).map(|p| p.join("share/yosys/ecp5")).unwrap_or_default();
    let read = |f: &str| {
        std::fs::read_to_string(share.join(f)).map_err(|e| {
            format!(
                "cannot read {f} of yosys's ECP5 library at {} ({e}): the netlist simulation needs Debian's yosys",
                share.display()
            )
        })
    };
    let mut out = String::new();
    let mut skip = false;
    let mut held: Option<&str> = None;
    let text = read("cells_sim.v")?;
    for l in text.lines() {
        if l.trim() == "(* blackbox *)" {
            held = Some(l);
            continue;
        }
        if l.starts_with("module DP16KD(") {
            skip = true;
        }
        if let Some(h) = held.take() {
            if !skip {
                out.push_str(h);
                out.push('\n');
            }
        }
        if l.starts_with("`include \"") {
            // the library's two include files, in place, so that the one file is the whole library
            let f = l.trim_start_matches("`include \"").trim_end_matches('"');
            out.push_str(&read(f)?);
        } else if !skip {
            out.push_str(l);
            out.push('\n');
        }
        if skip && l.starts_with("endmodule") {
            skip = false;
        }
    }
    Ok(models() + &out)
}

/// The unit `top` (its Verilog `verilog` in `dir`) through `synth_ecp5`, as yosys writes it (`<top>.ecp5.json`,
/// `<top>.ecp5.v`) and packed by this pass (`<top>.packed.json`, `<top>.packed.v`), with the library a simulator
/// runs them on (`ecp5_cells.v`: yosys's cells and `models()`): each netlist module is `top`, ports and latency
/// unchanged, so the unit's exported testbench runs on either.
pub fn netlists(dir: &std::path::Path, top: &str, verilog: &str) -> Result<Packing, String> {
    let script = format!("read_verilog {verilog}; synth_ecp5 -top {top} -json {top}.ecp5.json");
    crate::tools::run(dir, crate::tools::toolchain().yosys(), &["-q", "-p", &script])?;
    let text = std::fs::read_to_string(dir.join(format!("{top}.ecp5.json"))).map_err(|e| format!("no netlist: {e}"))?;
    let (packed, p) = pack_ecp5(&text, top)?;
    crate::export::write_atomic(&dir.join(format!("{top}.packed.json")), packed.as_bytes())?;
    for n in ["ecp5", "packed"] {
        crate::tools::netlist_verilog(dir, &format!("{top}.{n}.json"), &format!("{top}.{n}.v"))?;
    }
    crate::export::write_atomic(&dir.join("ecp5_cells.v"), sim_library()?.as_bytes())?;
    Ok(p)
}
