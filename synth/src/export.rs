//! Verilog export: rust-hdl's `generate_verilog`, with the top module (and its DFF submodules' prefix) renamed
//! from rust-hdl's `top` to the unit's name, so that several units can be read into one tool run; each child's clock
//! a wire (`clocks_as_wires`) and the delay lines' memories marked (`mark_rings`).

use rtl::axis::AxisBlock;
use rtl::StreamUnit;
use rust_hdl::prelude::*;
use std::path::{Path, PathBuf};

pub struct Exported {
    pub module: String,
    pub text: String,
}

pub fn export<U: StreamUnit>() -> Exported {
    named(U::build(), U::NAME)
}

/// A unit behind its AXI4-Stream wrapper, as the module `<unit>_axis` (its unit inside, under that prefix, so the
/// file stands alone and can be read beside `<unit>.v`).
pub fn export_axis<W: AxisBlock>() -> Exported {
    named(W::build(), &W::name())
}

/// The wrapper's own logic around its unit, its control and output FIFO (`rtl::axis::AxisCtl`, and a map unit's
/// `AxisMapCtl` around it) at the depth the wrapper builds, as the module `<unit>_axis_ctl`: what the wrapper adds to
/// the unit, synthesised alone.
pub fn export_axis_ctl<W: AxisBlock>() -> Exported {
    named(W::ctl(), &format!("{}_ctl", W::name()))
}

/// Any block's Verilog with rust-hdl's `top` renamed `module`.
pub fn named<B: Block>(mut uut: B, module: &str) -> Exported {
    uut.connect_all();
    renamed(&generate_verilog(&uut), module)
}

/// rust-hdl's Verilog `text` with its `top` renamed `module` (apart from `named`, which is compiled once a block),
/// its children's clocks made wires (`clocks_as_wires`) and its delay lines' memories marked (`mark_rings`).
fn renamed(text: &str, module: &str) -> Exported {
    let text = text.replace("module top(", &format!("module {module}("));
    let text = prefix_renamed(&text, "top$", &format!("{module}$"));
    Exported { module: module.to_string(), text: mark_rings(&clocks_as_wires(&text)) }
}

/// Whether `c` can be part of a Verilog identifier as rust-hdl writes them (`$` joins a child to its parent).
fn ident_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_' || c == '$'
}

/// `text` with every identifier that starts with `from` starting with `to` instead: rust-hdl's module names
/// `top$child$…`, but not a signal whose name only ends in `top` (`s2_top$d`, which a plain replace made
/// `s2_<unit>$d` in the exported file and its waveforms).
fn prefix_renamed(text: &str, from: &str, to: &str) -> String {
    let mut out = String::with_capacity(text.len() + 4096);
    let mut rest = text;
    while let Some(i) = rest.find(from) {
        let starts = !rest[..i].chars().next_back().is_some_and(ident_char);
        out.push_str(&rest[..i]);
        out.push_str(if starts { to } else { from });
        rest = &rest[i + from.len()..];
    }
    out.push_str(rest);
    out
}

/// rust-hdl hands each child its clock inside the parent's combinational block (`always @(*) begin … x$clock =
/// clock; …`), so every clock edge, rising and falling, wakes every such block in the design to pass the edge on,
/// and an event-driven simulator evaluates all the logic twice a clock more than the design needs (Icarus ran the
/// trilinear colour pipeline at 10 ms a clock, 5 ms with this pass). A child's clock assigned once in its module, at
/// the top level of a combinational block, from one of the module's inputs, is the same signal as a continuous
/// assignment of that input: it becomes `wire x$clock; assign x$clock = clock;` and leaves the block. Any other
/// use (assigned twice, under a condition, from an expression) stays as rust-hdl wrote it.
fn clocks_as_wires(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 4096);
    let mut module = String::new();
    for line in text.split_inclusive('\n') {
        if line.starts_with("module ") && !module.is_empty() {
            out.push_str(&module_clocks_as_wires(&module));
            module.clear();
        }
        module.push_str(line);
    }
    out.push_str(&module_clocks_as_wires(&module));
    out
}

/// `clocks_as_wires` on one module's text.
fn module_clocks_as_wires(module: &str) -> String {
    use std::collections::{HashMap, HashSet};
    let lines: Vec<&str> = module.split_inclusive('\n').collect();
    let indent = |l: &str| l.len() - l.trim_start().len();
    let mut inputs = HashSet::new();
    let mut clock_regs = HashSet::new();
    // every line that assigns each name (`name = …` or `name <= …`)
    let mut assigned: HashMap<&str, usize> = HashMap::new();
    for l in &lines {
        let t = l.trim();
        if let Some(rest) = t.strip_prefix("input wire") {
            if let Some(name) = rest.trim().strip_suffix(';').filter(|n| !n.contains(['[', ' '])) {
                inputs.insert(name);
            }
        } else if let Some(name) = t.strip_prefix("reg").and_then(|r| r.trim().strip_suffix(';')) {
            if name.ends_with("$clock") && !name.contains(['[', ' ']) {
                clock_regs.insert(name);
            }
        }
        if let Some((lhs, _)) = t.split_once(" = ").or_else(|| t.split_once(" <= ")) {
            *assigned.entry(lhs.trim()).or_default() += 1;
        }
    }
    // the assignments that move: at the statement level of an `always @(*) begin` block
    let mut moved: Vec<(&str, &str)> = Vec::new();
    let mut moved_lines = HashSet::new();
    let mut block: Option<(usize, Option<usize>)> = None; // (the always line's indent, its statements' indent)
    for (i, l) in lines.iter().enumerate() {
        let t = l.trim();
        match &mut block {
            None if t == "always @(*) begin" => block = Some((indent(l), None)),
            None => {}
            Some((at, _)) if t == "end" && indent(l) == *at => block = None,
            Some((_, level)) if !t.is_empty() => {
                let level = *level.get_or_insert(indent(l));
                let pair = t.strip_suffix(';').and_then(|a| a.split_once(" = "));
                if let Some((lhs, rhs)) = pair.filter(|_| indent(l) == level) {
                    if clock_regs.contains(lhs) && inputs.contains(rhs) && assigned.get(lhs) == Some(&1) {
                        moved.push((lhs, rhs));
                        moved_lines.insert(i);
                    }
                }
            }
            Some(_) => {}
        }
    }
    if moved.is_empty() {
        return module.to_string();
    }
    let source: HashMap<&str, &str> = moved.iter().copied().collect();
    let mut out = String::with_capacity(module.len() + 32 * moved.len());
    for (i, l) in lines.iter().enumerate() {
        if moved_lines.contains(&i) {
            continue;
        }
        let t = l.trim();
        let declared = t.strip_prefix("reg").and_then(|r| r.trim().strip_suffix(';'));
        match declared.and_then(|name| source.get(name).map(|rhs| (name, rhs))) {
            Some((name, rhs)) => {
                let pad = &l[..indent(l)];
                out.push_str(&format!("{pad}wire {name};\n{pad}assign {name} = {rhs};\n"));
            }
            None => out.push_str(l),
        }
    }
    out
}

/// The memory of every module `…$ring` (`rtl::prim::ram_delay::RamDelay`'s RAM) and `…$tables`
/// (`rtl::palette_lookup`'s two colour tables) marked `(* no_rw_check *)`: a delay line never reads the word it
/// writes on the same edge, nor a pixel the table being written, and so a synthesis tool need not keep the old word
/// on such a collision (yosys otherwise adds a comparator and a bypass behind the block RAM's read, which also keeps
/// the read out of the block's output register). Simulators ignore the attribute.
fn mark_rings(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 256);
    let mut ring = false;
    for line in text.split_inclusive('\n') {
        let t = line.trim_start();
        if let Some(rest) = t.strip_prefix("module ") {
            ring = rest.split('(').next().is_some_and(|name| name.ends_with("$ring") || name.ends_with("$tables"));
        } else if ring && t.starts_with("reg[") && t.contains("] mem[") {
            out.push_str(&line[..line.len() - t.len()]);
            out.push_str("(* no_rw_check *) ");
            out.push_str(t);
            continue;
        }
        out.push_str(line);
    }
    out
}

impl Exported {
    /// Write `<dir>/<module>.v`, through a temporary file so that a failed write leaves no partial file behind.
    pub fn write(&self, dir: &Path) -> Result<PathBuf, String> {
        std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
        let path = dir.join(format!("{}.v", self.module));
        write_atomic(&path, self.text.as_bytes())?;
        Ok(path)
    }
}

/// Write a file whole or not at all. The temporary file's name is the process's and the call's own, so that two
/// processes writing the same file (test processes sharing a build folder) never write into one temporary file.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), String> {
    static CALL: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let n = CALL.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let name = path.file_name().map(|f| f.to_string_lossy().into_owned()).unwrap_or_default();
    let tmp = path.with_file_name(format!(".{name}.{}.{n}.partial", std::process::id()));
    std::fs::write(&tmp, bytes).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        format!("cannot write {}: {e}", path.display())
    })
}

/// Port connections that take each port from a slice of one bus, the first port at bit `from`:
/// `.a(bus[2:0])`, `.b(bus[10:3])`, ... (the wrappers and benches that pack a unit's ports into one word).
pub fn bus_slices(ports: &[(&str, usize)], bus: &str, from: usize) -> Vec<String> {
    let mut at = from;
    ports
        .iter()
        .map(|(n, w)| {
            let c = format!(".{n}({bus}[{}:{at}])", at + w - 1);
            at += w;
            c
        })
        .collect()
}

/// An exclusive lock on a folder, held by this process until it is dropped: `flock` on `<dir>/.lock`, so that
/// builds in one folder by several processes (the test runner runs each test in a process of its own) take turns.
/// The operating system releases it if the process dies.
pub struct FolderLock {
    _file: std::fs::File,
}

impl FolderLock {
    pub fn take(dir: &Path) -> Result<FolderLock, String> {
        std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
        FolderLock::take_file(&dir.join(".lock"))
    }

    /// The lock on the file `path` itself (created if need be; its folder must exist).
    pub fn take_file(path: &Path) -> Result<FolderLock, String> {
        let file = std::fs::OpenOptions::new()
            .create(true)
            .truncate(false)
            .write(true)
            .open(path)
            .map_err(|e| format!("cannot open {}: {e}", path.display()))?;
        file.lock().map_err(|e| format!("cannot lock {}: {e}", path.display()))?;
        Ok(FolderLock { _file: file })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_top_prefix_is_renamed_only_where_an_identifier_starts() {
        let text = "module top$a$s2_top(d,q,clock);\n    top$a$s2_top s2_top(.d(s2_top$d), .q(stop$q));\n";
        let got = prefix_renamed(text, "top$", "unit$");
        assert_eq!(got, "module unit$a$s2_top(d,q,clock);\n    unit$a$s2_top s2_top(.d(s2_top$d), .q(stop$q));\n");
    }

    /// A child's clock handed on at the top level of the block from an input leaves the block as a wire; one
    /// under a condition, one assigned twice and one from an expression stay where they are.
    #[test]
    fn only_a_clock_passed_on_unconditionally_from_an_input_becomes_a_wire() {
        let text = "\
module m(clock,other,en);
    input wire  clock;
    input wire  other;
    input wire  en;
    reg  a$clock;
    reg  b$clock;
    reg  c$clock;
    reg  d$clock;
    reg  e$clock;
    always @(*) begin
        a$clock = clock;
        if (en) begin
            b$clock = clock;
        end
        c$clock = clock;
        c$clock = other;
        d$clock = ~clock;
        e$clock = other;
    end
endmodule // m
";
        let got = clocks_as_wires(text);
        let want = text
            .replace("    reg  a$clock;\n", "    wire a$clock;\n    assign a$clock = clock;\n")
            .replace("    reg  e$clock;\n", "    wire e$clock;\n    assign e$clock = other;\n")
            .replace("        a$clock = clock;\n", "")
            .replace("        e$clock = other;\n", "");
        assert_eq!(got, want);
    }

    /// Whether another process (util-linux's `flock -n`) can take the folder's lock now.
    fn free_to_another_process(dir: &Path) -> bool {
        let status = std::process::Command::new("flock")
            .args(["-n", "-E", "3"])
            .arg(dir.join(".lock"))
            .arg("true")
            .status()
            .expect("util-linux's flock");
        match status.code() {
            Some(0) => true,
            Some(3) => false,
            c => panic!("flock exited with {c:?}"),
        }
    }

    #[test]
    fn a_folder_lock_keeps_other_processes_out_until_it_is_dropped() {
        let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/test-files/folder-lock");
        let lock = FolderLock::take(&dir).unwrap();
        assert!(!free_to_another_process(&dir), "another process took the lock while it was held");
        drop(lock);
        assert!(free_to_another_process(&dir), "the lock was not released when dropped");
    }

    #[test]
    fn only_the_memories_that_never_read_the_word_being_written_are_marked() {
        // the palette lookup's two tables (a pixel reads one, the builder writes the other) and a delay line
        let lookup = export::<rtl::palette_lookup::PaletteLookup<8, 9>>().text;
        assert!(lookup.contains("(* no_rw_check *) reg[31:0] mem[511:0];"), "{lookup}");
        let ring = named(rtl::prim::ram_delay::RamDelay::<48, 7, 100>::default(), "ring").text;
        assert_eq!(ring.matches("(* no_rw_check *)").count(), 1, "{ring}");
        // a memory of any other name is left as rust-hdl writes it (the AXI wrapper's FIFO may read the slot it
        // writes: an empty FIFO)
        let fetch = export::<rtl::height_fetch::HeightFetch>().text;
        assert!(fetch.contains("] mem[") && !fetch.contains("no_rw_check"), "{fetch}");
    }

    #[test]
    fn an_atomic_write_leaves_no_temporary_file() {
        let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/test-files/write-atomic");
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        write_atomic(&dir.join("a.v"), b"one").unwrap();
        write_atomic(&dir.join("a.v"), b"two").unwrap();
        assert_eq!(std::fs::read(dir.join("a.v")).unwrap(), b"two");
        let names: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, ["a.v"]);
    }
}
