//! The AXI4-Stream wrapper's rules (`rtl::axis`), proved on its exported Verilog: by yosys on the netlist for the one
//! that is structural, by `yosys-smtbmc` with z3 for the rest, against the bare unit as the reference.
//!
//! The harness instantiates `<unit>_axis` with every input free (the source's tvalid and tdata, the sink's tready,
//! aresetn; the first clock in reset) and a second, bare copy of the unit, fed one beat: the k-th taken since the
//! last reset, k chosen by the solver (`anyconst`), so every claim about "the beat followed" holds for every beat.
//! The rules:
//! - **no valid waits on a ready**: no combinational path from `m_axis_tready` to `m_axis_tvalid` (nor to
//!   `s_axis_tready`); yosys's `select` over the flattened netlist, its memories mapped to registers. Beside it,
//!   the same search through registers must find the path (tready does steer tvalid, a clock later), so the
//!   check looks where the logic is;
//! - **tdata stable until taken**: a word offered and not taken is offered again, unchanged, on the next clock
//!   (out of reset);
//! - **in reset, nothing offered or taken**: while aresetn is low both m_axis_tvalid and s_axis_tready are low;
//! - **no beat invented or duplicated**: each beat given out is one taken since the reset (counts);
//! - **none reordered or changed**: the k-th beat given out is the unit's output for the k-th taken;
//! - **none lost**: after `drain` clocks with the sink ready and no beat taken, every beat taken has left.
//!
//! A unit with a map write port (the texture unit's, `height_fetch`'s) has its structural rule proven and the others
//! not tried: its reference would need the same writes clock for clock, which this harness does not give it; and so
//! neither is the one k-clock variant (a map unit), whose pace the wrapper's own tests hold.
//!
//! Each rule is checked alone by yosys's own SAT solver (`sat -prove-asserts -seq N`), over every trace of `depth`
//! clocks from reset: a bounded proof, and the verdict says so. (z3 through `yosys-smtbmc` did not finish the first
//! clock of this harness in minutes; the SAT solver on each rule's own cone does.)

use crate::prove::{ports, Status};
use crate::units::Unit;
use std::path::Path;
use std::time::{Duration, Instant};

/// One rule's verdict.
pub struct Rule {
    pub name: &'static str,
    pub status: Status,
    pub seconds: f64,
}

/// The rule yosys checks on the netlist's structure.
pub const STRUCTURAL: &str = "no valid waits on a ready";

impl Rule {
    /// Whether a proof of this rule holds for every trace (the structural one), not only those of the bounded depth.
    pub fn unbounded(&self) -> bool {
        self.name == STRUCTURAL
    }
}

/// The wrapper's proof.
pub struct AxisProof {
    pub unit: &'static str,
    pub rules: Vec<Rule>,
    /// the bounded check's depth, in clocks from reset
    pub depth: usize,
    pub seconds: f64,
}

/// The rules the solver checks, in the harness's order (the structural one is checked by yosys beside them).
pub const RULES: &[&str] = &[
    "tdata stable until taken",
    "in reset, nothing offered or taken",
    "no beat invented or duplicated",
    "none reordered or changed",
    "none lost",
];

/// The harness text: the wrapper, the bare unit and the `axis_rules` top with the rules as assertions, each marked
/// `// rule N`.
fn harness(unit: &Unit, drain: usize) -> Result<(String, Vec<usize>), String> {
    let name = unit.rtl.name();
    let module = unit.axis.module();
    let (bare, wrapped) = (unit.rtl.verilog(), unit.axis.verilog());
    let wp = ports(&wrapped, &module)?;
    let bits = |n: &str| wp.iter().find(|p| p.0 == n).map(|p| p.1).ok_or(format!("{module}: no port {n}"));
    let (iw, ow) = (bits("s_axis_tdata")?, bits("m_axis_tdata")?);
    let up = ports(&bare, name)?;
    let cw = 8; // counts up to 255: more beats than a bounded trace can take
    let mut v = vec![];
    v.push("module axis_rules(clock, aresetn, s_tdata, s_tvalid, m_tready);".to_string());
    v.push("    input wire clock;\n    input wire aresetn;".into());
    v.push(format!("    input wire [{}:0] s_tdata;\n    input wire s_tvalid;\n    input wire m_tready;", iw - 1));
    v.push(format!("    wire s_tready, m_tvalid;\n    wire [{}:0] m_tdata;", ow - 1));
    v.push(format!(
        "    {module} dut(.aclk(clock), .aresetn(aresetn), .s_axis_tdata(s_tdata), .s_axis_tvalid(s_tvalid), \
         .s_axis_tready(s_tready), .m_axis_tdata(m_tdata), .m_axis_tvalid(m_tvalid), .m_axis_tready(m_tready));"
    ));
    // the beat followed, and the counts since the last reset
    v.push(format!("    (* anyconst *) reg [{}:0] f_k;", cw - 1));
    v.push(format!("    reg [{}:0] n_in = 0, n_out = 0;", cw - 1));
    v.push(format!("    reg f_init = 1, f_taken = 0, f_ok = 0;\n    reg [{}:0] f_want = 0;", ow - 1));
    v.push("    wire take = aresetn && s_tvalid && s_tready;\n    wire give = aresetn && m_tvalid && m_tready;".into());
    v.push("    wire pick = take && n_in == f_k && !f_taken;".into());
    // the bare unit: its inputs unpacked from the beat as the wrapper packs them (the first port in the low bits)
    let mut conns = vec![".clock(clock)".to_string(), ".valid_in(pick)".into(), ".valid_out(r_valid)".into()];
    let (mut at_in, mut at_out) = (0, 0);
    let mut outs = vec![];
    for (p, b, input) in &up {
        if p == "clock" || p == "valid_in" || p == "valid_out" {
            continue;
        }
        if *input {
            conns.push(format!(".{p}(s_tdata[{}:{at_in}])", at_in + b - 1));
            at_in += b;
        } else {
            v.push(format!("    wire [{}:0] r_{p};", b - 1));
            conns.push(format!(".{p}(r_{p})"));
            outs.push(format!("r_{p}"));
            at_out += b;
        }
    }
    v.push("    wire r_valid;".into());
    v.push(format!("    {name} reference({});", conns.join(", ")));
    outs.reverse();
    let pad = ow as usize - at_out as usize;
    let word = if pad > 0 { format!("{{{pad}'d0, {}}}", outs.join(", ")) } else { format!("{{{}}}", outs.join(", ")) };
    v.push(format!("    wire [{}:0] r_word = {word};", ow - 1));
    // the clock before
    v.push(format!("    reg p_run = 0, p_mv = 0, p_mr = 0;\n    reg [{}:0] p_md = 0;", ow - 1));
    v.push(format!("    reg [{}:0] f_quiet = 0;", cw - 1));
    v.push("    always @(posedge clock) begin".into());
    v.push("        f_init <= 0;".into());
    v.push("        p_run <= aresetn; p_mv <= m_tvalid; p_mr <= m_tready; p_md <= m_tdata;".into());
    v.push("        if (!aresetn) begin".into());
    v.push("            n_in <= 0; n_out <= 0; f_taken <= 0; f_ok <= 0; f_quiet <= 0;".into());
    v.push("        end else begin".into());
    v.push("            n_in <= n_in + take; n_out <= n_out + give;".into());
    v.push("            if (pick) f_taken <= 1;".into());
    v.push("            if (r_valid && f_taken && !f_ok) begin f_want <= r_word; f_ok <= 1; end".into());
    v.push("            f_quiet <= (m_tready && !take) ? f_quiet + 1 : 0;".into());
    v.push("        end".into());
    v.push("    end".into());
    v.push("    always @(*) begin".into());
    v.push("        if (f_init) assume(!aresetn);".into());
    let rules = [
        "if (!f_init && p_run && aresetn && p_mv && !p_mr) assert(m_tvalid && m_tdata == p_md);".to_string(),
        "if (!aresetn) assert(!m_tvalid && !s_tready);".into(),
        "if (give) assert(n_out < n_in);".into(),
        "if (give && n_out == f_k) assert(f_ok && m_tdata == f_want);".into(),
        format!("if (aresetn && f_quiet >= {drain}) assert(n_out == n_in);"),
    ];
    let mut lines = vec![];
    for (i, r) in rules.iter().enumerate() {
        v.push(format!("        {r} // rule {}", i + 1));
        lines.push(0);
    }
    v.push("    end".into());
    v.push("endmodule".into());
    let text = format!("{wrapped}\n{bare}\n{}\n", v.join("\n"));
    for (i, l) in text.lines().enumerate() {
        if let Some((_, n)) = l.rsplit_once("// rule ") {
            if let Ok(n) = n.trim().parse::<usize>() {
                lines[n - 1] = i + 1;
            }
        }
    }
    Ok((text, lines))
}

/// The structural rule: yosys finds no combinational path from `m_axis_tready` to either valid or ready output, and
/// does find the path through registers (so the search reads the logic it should). The reason where it fails.
fn no_valid_waits_on_ready(unit: &Unit, dir: &Path) -> Result<Status, String> {
    let module = unit.axis.module();
    let v = format!("{module}.v");
    std::fs::write(dir.join(&v), unit.axis.verilog()).map_err(|e| format!("{}: {e}", dir.display()))?;
    let script = format!(
        "read_verilog {v}\nprep -top {module}\nflatten\nmemory\nopt_clean\n\
         select -assert-none w:m_axis_tready %coe* w:m_axis_tvalid w:s_axis_tready %u %i\n\
         select -assert-any w:m_axis_tready %co* w:m_axis_tvalid %i\n"
    );
    let ys = dir.join("axis_paths.ys");
    std::fs::write(&ys, script).map_err(|e| format!("{}: {e}", ys.display()))?;
    Ok(match synth::tools::run(dir, "yosys", &["-q", "-s", "axis_paths.ys"]) {
        Ok(_) => Status::Proven,
        Err(e) => Status::Refuted(format!("yosys: {}", e.lines().last().unwrap_or(""))),
    })
}

/// Prove `unit`'s wrapper's rules in `dir` over traces of `depth` clocks from reset (0: twice the unit's latency, its
/// FIFO and six more: the flush after reset, then a beat taken, through the unit, behind a full FIFO and given out,
/// and the quiet clocks "none lost" waits), "none lost" after `drain`
/// quiet clocks (None: the latency, the FIFO's places and two: a beat's longest way out); each rule's solver run up to
/// `limit`.
pub fn prove(
    unit: &'static Unit,
    dir: &Path,
    depth: usize,
    drain: Option<usize>,
    limit: Duration,
) -> Result<AxisProof, String> {
    prove_rules(unit, dir, depth, drain, limit, RULES)
}

/// `prove`, for the rules named in `only` (of `RULES`; the structural one always).
pub fn prove_rules(
    unit: &'static Unit,
    dir: &Path,
    depth: usize,
    drain: Option<usize>,
    limit: Duration,
    only: &[&str],
) -> Result<AxisProof, String> {
    if !synth::tools::missing(&["yosys"]).is_empty() {
        return Err("prove --axis: yosys not on the PATH (the test command installs it)".into());
    }
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let start = Instant::now();
    let (places, _, _) = unit.axis.fifo();
    let latency = unit.rtl.latency();
    let drain = drain.unwrap_or(latency + places + 2);
    let depth = if depth == 0 { 2 * latency + places + 6 } else { depth };
    let t = Instant::now();
    let paths = no_valid_waits_on_ready(unit, dir)?;
    let mut rules = vec![Rule { name: STRUCTURAL, status: paths, seconds: t.elapsed().as_secs_f64() }];
    if ports(&unit.axis.verilog(), &unit.axis.module())?.iter().any(|p| p.0 == "s_axis_map_tvalid") {
        let why = "a unit with a map write port: its reference would need the same writes, clock for clock";
        for name in RULES.iter().filter(|r| only.contains(r)) {
            rules.push(Rule { name, status: Status::NotTried(why.into()), seconds: 0.0 });
        }
        return Ok(AxisProof { unit: unit.rtl.name(), rules, depth, seconds: start.elapsed().as_secs_f64() });
    }
    let (text, lines) = harness(unit, drain)?;
    let all: Vec<&str> = text.lines().collect();
    for (i, name) in RULES.iter().enumerate().filter(|(_, r)| only.contains(r)) {
        // this rule's assertion alone: the solver reads its cone only
        let own: Vec<&str> = all
            .iter()
            .enumerate()
            .filter(|(n, l)| !l.contains("// rule ") || *n + 1 == lines[i])
            .map(|(_, l)| *l)
            .collect();
        let v = format!("axis_rule_{}.v", i + 1);
        std::fs::write(dir.join(&v), own.join("\n") + "\n").map_err(|e| format!("{}: {e}", dir.display()))?;
        let vcd = format!("axis_rule_{}.vcd", i + 1);
        let script = format!(
            "read_verilog -formal {v}\nprep -top axis_rules\nflatten\nmemory\nopt_clean\n\
             sat -prove-asserts -set-assumes -set-init-zero -seq {depth} -dump_vcd {vcd} -show-inputs\n"
        );
        let ys = dir.join(format!("axis_rule_{}.ys", i + 1));
        std::fs::write(&ys, script).map_err(|e| format!("{}: {e}", ys.display()))?;
        let t = Instant::now();
        let ys_name = format!("axis_rule_{}.ys", i + 1);
        let (out, finished) = synth::tools::run_limited_any(dir, "yosys", &["-s", &ys_name], limit)?;
        let log = String::from_utf8_lossy(&out.stdout);
        let status = if !finished {
            Status::NotTried(format!("the solver ran past {} s", limit.as_secs()))
        } else if log.contains("no model found: SUCCESS") {
            Status::Proven
        } else if log.contains("model found: FAIL") {
            Status::Refuted(format!("a trace of {depth} clocks: {}", dir.join(&vcd).display()))
        } else {
            let tail: Vec<&str> = log.lines().rev().take(3).collect();
            return Err(format!("yosys sat in {}: no verdict ({})", dir.display(), tail.join(" / ")));
        };
        rules.push(Rule { name, status, seconds: t.elapsed().as_secs_f64() });
    }
    Ok(AxisProof { unit: unit.rtl.name(), rules, depth, seconds: start.elapsed().as_secs_f64() })
}
