//! The iCE40's products in logic, each cut into pieces across the registers that take it: a synthesis-only
//! rewrite of the flattened design, between the choice of which products go into logic (`fpga::FABRIC_PRODUCTS`)
//! and `synth_ice40`.
//!
//! A pipeline that needs more products than the UP5K's 8 SB_MAC16 has its smallest built in logic, where yosys
//! makes each one an adder tree in a single clock: 22 to 28 ns for an 8 × 8 or 10 × 10 product on the UP5K, the
//! critical path of every Cartesian pipeline on that part. Every product of the rtl is taken by a register of its
//! own (the DSP's output register on the parts with one), and most by a copy of that register too (the route out of
//! a DSP on a clock of its own). This pass moves those registers into the product. With b = Σ b_j·2^(o_j), the
//! rows of b in slices at offsets o_j:
//! - register and copy: `r ← a·b; c ← r` becomes `p_j ← a·b_j` (four slices) and `c ← Σ p_j·2^(o_j)`;
//! - a register alone: `r ← a·b` becomes `p_j ← a·b_j` (two slices) and `r = Σ p_j·2^(o_j)`, the sum joining
//!   whatever reads r in the next clock.
//!
//! Σ (a·b_j mod 2^(w − o_j))·2^(o_j) mod 2^w = a·b mod 2^w for the w bits kept, so the registers that stay hold the
//! same word on every clock as before, and the new ones start at 0, as the old ones did.
//!
//! Only a product all of whose used bits go to one plain register is split: a `$dff` on the rising edge, with no
//! enable and no reset, whose D is the product's low bits in order (above them constant zeros, where the whole
//! product fits below them) and whose initial value is 0 or unset, and an unsigned product; a copy likewise, reading
//! nothing but that register and the only reader of it. Any other product stays whole. The rust-hdl blocks, their
//! simulation, their golden vectors and their exported Verilog are not touched; `tests/exported.rs` simulates units
//! split here against their golden vectors, and a wrong split against them.

use serde_json::{json, Map, Value};
use std::collections::HashMap;

/// A number parameter as yosys writes it: a string of binary digits, or a number.
fn num(cell: &Value, name: &str) -> Option<u64> {
    match cell["parameters"].get(name)? {
        Value::String(s) => u64::from_str_radix(s.trim_end(), 2).ok(),
        v => v.as_u64(),
    }
}

fn bits<'a>(cell: &'a Value, port: &str) -> &'a [Value] {
    cell["connections"].get(port).and_then(Value::as_array).map(Vec::as_slice).unwrap_or(&[])
}

/// A 32-bit parameter, as yosys's `write_json` writes one.
fn p32(v: usize) -> Value {
    Value::String(format!("{v:032b}"))
}

/// The yosys JSON `json` with every product of `soft` (cell names in module `top`) split where it can be: the design
/// again, the cells to build in logic (the pieces of a split product, a product that could not be split as itself),
/// and how many were split.
pub fn split(json: &str, top: &str, soft: &[String]) -> Result<(String, Vec<String>, usize), String> {
    let mut design: Value = serde_json::from_str(json).map_err(|e| format!("the yosys design does not read: {e}"))?;
    let module = design["modules"].get_mut(top).ok_or_else(|| format!("the yosys design has no module {top}"))?;
    let mut next_bit = max_bit(module) + 1;
    let mut cells_out = Vec::new();
    let mut count = 0;
    for (i, name) in soft.iter().enumerate() {
        let Some(mut plan) = plan(module, name) else {
            cells_out.push(name.clone());
            continue;
        };
        let mut fresh = |n: usize| -> Vec<Value> {
            let v = (next_bit..next_bit + n as u64).map(Value::from).collect();
            next_bit += n as u64;
            v
        };
        for b in plan.out.iter_mut().filter(|b| b.is_null()) {
            *b = fresh(1).remove(0);
        }
        let w = plan.out.len();
        let tag = format!("$bumprtl$softsplit${i}");
        let mut new_cells: Vec<(String, Value)> = Vec::new();
        let mut new_nets: Vec<(String, Vec<Value>, bool)> = Vec::new();
        let mut reg = |n: String, d: Vec<Value>, fresh: &mut dyn FnMut(usize) -> Vec<Value>| {
            let q = fresh(d.len());
            new_nets.push((format!("{n}$d"), d.clone(), false));
            new_nets.push((format!("{n}$q"), q.clone(), true));
            new_cells.push((n, dff(&plan.clock, &d, &q)));
            q
        };
        // the pieces: 2^levels slices of the rows' operand, each product registered, at its row offset
        let pieces = 1usize << plan.levels;
        let g = plan.rows.len();
        let mut values: Vec<(usize, Vec<Value>)> = Vec::new();
        let mut arith: Vec<(String, Value)> = Vec::new();
        for j in 0..pieces {
            let (lo, hi) = (j * g / pieces, (j + 1) * g / pieces);
            let y = fresh(w - lo);
            let m = format!("{tag}$p{j}");
            arith.push((m.clone(), arith_cell("$mul", &plan.cols, &plan.rows[lo..hi], &y)));
            cells_out.push(m);
            let q = reg(format!("{tag}$p{j}_q"), y, &mut fresh);
            values.push((lo, q));
        }
        // the pieces summed, each shifted to its rows' place: straight into the old register's output (one level), or
        // into a register of their own whose output that is (two levels: the sum has the copy's clock to itself)
        let mut acc = values[0].1.clone();
        for (m, (o, v)) in values.iter().enumerate().skip(1) {
            let mut shifted = vec![Value::String("0".into()); *o];
            shifted.extend(v.iter().cloned());
            let last = m + 1 == values.len();
            let y = if last && plan.levels == 1 { plan.out.clone() } else { fresh(w) };
            arith.push((format!("{tag}$s{m}"), arith_cell("$add", &acc, &shifted, &y)));
            acc = y;
        }
        let out_init = plan.levels == 2;
        if out_init {
            new_nets.push((format!("{tag}$sum"), acc.clone(), false));
            new_cells.push((format!("{tag}$sum_q"), dff(&plan.clock, &acc, &plan.out)));
        }
        let cells = module["cells"].as_object_mut().expect("a module with cells");
        cells.remove(name);
        for ff in &plan.ffs {
            cells.remove(ff);
        }
        cells.extend(new_cells);
        cells.extend(arith);
        // the old registers' outputs are sums now: their initial value moves to the new registers
        let netnames = module["netnames"].as_object_mut().expect("a module with net names");
        drop_init(netnames, &plan.out);
        if out_init {
            new_nets.push((format!("{tag}$sum_q$q"), plan.out.clone(), true));
        }
        for (n, v, init) in new_nets {
            let mut attributes = Map::new();
            if init {
                attributes.insert("init".into(), Value::String("0".repeat(v.len())));
            }
            netnames.insert(n, json!({ "hide_name": 1, "bits": v, "attributes": attributes }));
        }
        count += 1;
    }
    let text = serde_json::to_string(&design).map_err(|e| format!("the split design does not write: {e}"))?;
    Ok((text, cells_out, count))
}

/// An unsigned `$mul` or `$add` cell `y` = a × b or a + b, y's width.
fn arith_cell(kind: &str, a: &[Value], b: &[Value], y: &[Value]) -> Value {
    json!({
        "hide_name": 1, "type": kind,
        "parameters": { "A_SIGNED": p32(0), "A_WIDTH": p32(a.len()), "B_SIGNED": p32(0), "B_WIDTH": p32(b.len()),
            "Y_WIDTH": p32(y.len()) },
        "attributes": {},
        "port_directions": { "A": "input", "B": "input", "Y": "output" },
        "connections": { "A": a, "B": b, "Y": y },
    })
}

/// A plain register on the rising edge of `clock`.
fn dff(clock: &[Value], d: &[Value], q: &[Value]) -> Value {
    json!({
        "hide_name": 1, "type": "$dff",
        "parameters": { "CLK_POLARITY": p32(1), "WIDTH": p32(d.len()) },
        "attributes": {},
        "port_directions": { "CLK": "input", "D": "input", "Q": "output" },
        "connections": { "CLK": clock, "D": d, "Q": q },
    })
}

/// The unit `top` (its Verilog `verilog` in `dir`) prepared as the iCE40 flow prepares a design before it chooses
/// products for logic (`<top>.prepared.json`, `<top>.prepared.v`), and with every product split by this pass
/// (`<top>.split.json`, `<top>.split.v`): coarse cells, which a simulator runs as they are, each module `top` with
/// its ports and latency, so the unit's exported testbench runs on either. How many products were split.
pub fn netlists(dir: &std::path::Path, top: &str, verilog: &str) -> Result<usize, String> {
    use crate::fpga::{KEEP_COPIES, PREPARE};
    let yosys = |script: &str| crate::tools::run(dir, crate::tools::toolchain().yosys(), &["-q", "-p", script]);
    yosys(&format!(
        "read_verilog {verilog}; hierarchy -top {top}; {KEEP_COPIES}; {PREPARE}; memory_collect; \
         write_json {top}.prepared.json"
    ))?;
    let text =
        std::fs::read_to_string(dir.join(format!("{top}.prepared.json"))).map_err(|e| format!("no design: {e}"))?;
    let design: Value = serde_json::from_str(&text).map_err(|e| format!("the yosys design does not read: {e}"))?;
    let products: Vec<String> = design["modules"][top]["cells"]
        .as_object()
        .into_iter()
        .flatten()
        .filter(|(_, c)| c["type"].as_str() == Some("$mul"))
        .map(|(n, _)| n.clone())
        .collect();
    let (out, _, n) = split(&text, top, &products)?;
    crate::export::write_atomic(&dir.join(format!("{top}.split.json")), out.as_bytes())?;
    for n in ["prepared", "split"] {
        crate::tools::netlist_verilog(dir, &format!("{top}.{n}.json"), &format!("{top}.{n}.v"))?;
    }
    Ok(n)
}

/// How to split one product: its unsplit operand's bits (`cols`), the operand split into rows (the narrower: fewer
/// rows to a piece), the registers it
/// replaces (the one that takes the product, and the plain copies of that one, if every bit it gives goes to one),
/// their clock, how many registers deep the pieces are summed (1, or 2 through the copies), and the bits the last
/// sum drives (the last replaced registers' outputs; `Null` where a bit is read by none).
struct Plan {
    cols: Vec<Value>,
    rows: Vec<Value>,
    ffs: Vec<String>,
    clock: Vec<Value>,
    levels: usize,
    out: Vec<Value>,
}

/// A cell's input pins reading each net bit: (cell, port, index).
type Loads<'a> = HashMap<u64, Vec<(&'a str, &'a str, usize)>>;

/// A plain register: `$dff` on the rising edge of `clock` (any clock when None), its initial value 0 or unset.
fn plain<'a>(module: &Value, cells: &'a Map<String, Value>, name: &str, clock: Option<&[Value]>) -> Option<&'a Value> {
    let f = cells.get(name)?;
    let ok = f["type"].as_str() == Some("$dff")
        && num(f, "CLK_POLARITY")? == 1
        && clock.is_none_or(|c| bits(f, "CLK") == c)
        && !has_init_one(module, bits(f, "Q"));
    ok.then_some(f)
}

fn plan(module: &Value, name: &str) -> Option<Plan> {
    let cells = module["cells"].as_object()?;
    let m = cells.get(name)?;
    if m["type"].as_str() != Some("$mul") || num(m, "A_SIGNED")? != 0 || num(m, "B_SIGNED")? != 0 {
        return None;
    }
    let y = bits(m, "Y");
    let mut loads: Loads = HashMap::new();
    for (cn, c) in cells {
        for (port, v) in c["connections"].as_object()? {
            if c["port_directions"].get(port).and_then(Value::as_str) == Some("output") {
                continue;
            }
            for (i, b) in v.as_array()?.iter().enumerate() {
                if let Some(b) = b.as_u64() {
                    loads.entry(b).or_default().push((cn, port, i));
                }
            }
        }
    }
    let port_bits: Vec<u64> = module["ports"]
        .as_object()?
        .values()
        .flat_map(|p| p["bits"].as_array().into_iter().flatten().filter_map(Value::as_u64))
        .collect();
    let mut ff: Option<&str> = None;
    let mut used = 0;
    for (i, reader) in d_readers(&loads, &port_bits, y)?.into_iter().enumerate() {
        if let Some((cn, j)) = reader {
            if j != i || ff.is_some_and(|f| f != cn) {
                return None;
            }
            ff = Some(cn);
            used = i + 1;
        }
    }
    let ff = ff?;
    let f = plain(module, cells, ff, None)?;
    let d = bits(f, "D");
    if d.len() < used || d[..used] != y[..used] {
        return None;
    }
    // a register wider than the product: its top bits are constant zeros, right only if the whole product fits below
    let (a, b) = (bits(m, "A").to_vec(), bits(m, "B").to_vec());
    if d.len() > used && (d[used..].iter().any(|b| b.as_str() != Some("0")) || used < a.len() + b.len()) {
        return None;
    }
    let (clock, q) = (bits(f, "CLK").to_vec(), bits(f, "Q").to_vec());
    let (cols, rows) = if b.len() <= a.len() { (a, b) } else { (b, a) };
    if rows.len() < 2 || q.len() <= rows.len() {
        return None;
    }
    let mut p = Plan { cols, rows, ffs: vec![ff.to_string()], clock, levels: 1, out: q.clone() };
    if p.rows.len() >= 4 {
        if let Some((copies, out)) = copies(module, cells, &loads, &port_bits, &p.clock, &q) {
            p.ffs.extend(copies);
            p.levels = 2;
            p.out = out;
        }
    }
    Some(p)
}

/// The plain registers on `clock` that take every bit of `q` that is read, each such bit's one reader, and read
/// nothing else: their names, and for each bit of `q` the copy's output (`Null` where none reads it).
fn copies(
    module: &Value,
    cells: &Map<String, Value>,
    loads: &Loads,
    port_bits: &[u64],
    clock: &[Value],
    q: &[Value],
) -> Option<(Vec<String>, Vec<Value>)> {
    let mut names: Vec<String> = Vec::new();
    let mut out = vec![Value::Null; q.len()];
    for (i, reader) in d_readers(loads, port_bits, q)?.into_iter().enumerate() {
        if let Some((cn, j)) = reader {
            let c = plain(module, cells, cn, Some(clock))?;
            out[i] = bits(c, "Q").get(j)?.clone();
            if !names.iter().any(|n| n == cn) {
                names.push(cn.to_string());
            }
        }
    }
    // every bit a copy takes is one of q's
    let all = names.iter().all(|n| bits(&cells[n], "D").iter().all(|d| q.contains(d)));
    (all && !names.is_empty()).then_some((names, out))
}

/// Each bit of `v`'s one reader, a register's D input: for each bit, the register and the bit's place in its D, or
/// None where nothing reads the bit; None for the whole when a bit is a port's or is read by anything else or twice.
fn d_readers<'a>(loads: &Loads<'a>, port_bits: &[u64], v: &[Value]) -> Option<Vec<Option<(&'a str, usize)>>> {
    v.iter()
        .map(|b| {
            let b = b.as_u64()?;
            if port_bits.contains(&b) {
                return None;
            }
            match loads.get(&b).map(Vec::as_slice).unwrap_or(&[]) {
                [] => Some(None),
                [(cn, "D", j)] => Some(Some((*cn, *j))),
                _ => None,
            }
        })
        .collect()
}

fn max_bit(module: &Value) -> u64 {
    let mut m = 1;
    let mut see = |v: &Value| {
        for b in v.as_array().into_iter().flatten().filter_map(Value::as_u64) {
            m = m.max(b);
        }
    };
    for c in module["cells"].as_object().into_iter().flat_map(|c| c.values()) {
        for v in c["connections"].as_object().into_iter().flat_map(|c| c.values()) {
            see(v);
        }
    }
    for n in module["netnames"].as_object().into_iter().flat_map(|n| n.values()) {
        see(&n["bits"]);
    }
    for p in module["ports"].as_object().into_iter().flat_map(|p| p.values()) {
        see(&p["bits"]);
    }
    m
}

/// A net name's initial value bit by bit, least significant first ('0', '1', 'x'); yosys writes it most significant
/// first.
fn init_of(n: &Value) -> Option<Vec<char>> {
    n["attributes"].get("init").and_then(Value::as_str).map(|s| s.trim_end().chars().rev().collect())
}

fn has_init_one(module: &Value, q: &[Value]) -> bool {
    module["netnames"].as_object().into_iter().flat_map(|n| n.values()).any(|n| {
        let Some(init) = init_of(n) else { return false };
        n["bits"].as_array().into_iter().flatten().zip(init).any(|(b, c)| c == '1' && q.contains(b))
    })
}

/// Set the initial value of the bits `q` to x in every net name that holds them, and drop an initial value that is
/// then all x.
fn drop_init(netnames: &mut Map<String, Value>, q: &[Value]) {
    for n in netnames.values_mut() {
        let Some(mut init) = init_of(n) else { continue };
        let mut changed = false;
        for (b, c) in n["bits"].as_array().into_iter().flatten().zip(init.iter_mut()) {
            if q.contains(b) && *c != 'x' {
                *c = 'x';
                changed = true;
            }
        }
        if !changed {
            continue;
        }
        let attributes = n["attributes"].as_object_mut().expect("a net name with an initial value has attributes");
        if init.iter().all(|c| *c == 'x') {
            attributes.remove("init");
        } else {
            attributes.insert("init".into(), Value::String(init.iter().rev().collect()));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A module where `m` = a × b (8 × 6 bits) goes to a plain register `r` of 8 bits, its Q bits 30..37; with
    /// `copy`, r's Q goes to a plain register `c` (Q bits 50..57) and nothing else; with `extra_load`, a bit of the
    /// product is read by another cell too.
    fn design(copy: bool, extra_load: bool) -> String {
        let a: Vec<u64> = (100..108).collect();
        let b: Vec<u64> = (6..12).collect();
        let y: Vec<u64> = (12..22).collect();
        let q: Vec<u64> = (30..38).collect();
        let dff = |d: &[u64], q: &[u64]| {
            json!({ "type": "$dff", "parameters": { "CLK_POLARITY": p32(1), "WIDTH": p32(d.len()) },
                "port_directions": { "CLK": "input", "D": "input", "Q": "output" },
                "connections": { "CLK": [1], "D": d, "Q": q } })
        };
        let mut cells = json!({
            "m": { "type": "$mul", "parameters": { "A_SIGNED": p32(0), "B_SIGNED": p32(0), "A_WIDTH": p32(8),
                "B_WIDTH": p32(6), "Y_WIDTH": p32(10) },
                "port_directions": { "A": "input", "B": "input", "Y": "output" },
                "connections": { "A": a, "B": b, "Y": y } },
            "r": dff(&y[..8], &q),
        });
        if copy {
            cells["c"] = dff(&q, &(50..58).collect::<Vec<u64>>());
        }
        if extra_load {
            cells["n"] = json!({ "type": "$not", "port_directions": { "A": "input", "Y": "output" },
                "connections": { "A": [y[3]], "Y": [40] } });
        }
        json!({ "modules": { "top": {
            "ports": { "clock": { "direction": "input", "bits": [1] } },
            "cells": cells,
            "netnames": { "q": { "hide_name": 0, "bits": q, "attributes": { "init": "00000000" } } },
        } } })
        .to_string()
    }

    /// Net bits and constants, in order, as text.
    fn list(v: &[Value]) -> String {
        let one = |b: &Value| b.as_u64().map_or_else(|| b.as_str().unwrap_or("?").to_string(), |n| n.to_string());
        v.iter().map(one).collect::<Vec<_>>().join(" ")
    }

    #[test]
    fn a_product_into_one_plain_register_becomes_two_half_products_registered_and_their_sum() {
        let (text, soft, n) = split(&design(false, false), "top", &["m".into()]).unwrap();
        assert_eq!(n, 1);
        assert_eq!(soft, ["$bumprtl$softsplit$0$p0", "$bumprtl$softsplit$0$p1"]);
        let d: Value = serde_json::from_str(&text).unwrap();
        let m = &d["modules"]["top"];
        let cells = m["cells"].as_object().unwrap();
        assert!(!cells.contains_key("m") && !cells.contains_key("r"));
        let (lo, hi) = (&cells["$bumprtl$softsplit$0$p0"], &cells["$bumprtl$softsplit$0$p1"]);
        // b (6 bits, the narrower) split at 3: the low half's product keeps the register's 8 bits, the high one 5
        assert_eq!((list(bits(lo, "B")), list(bits(hi, "B"))), ("6 7 8".into(), "9 10 11".into()));
        assert_eq!((num(lo, "Y_WIDTH"), num(hi, "Y_WIDTH")), (Some(8), Some(5)));
        let sum = &cells["$bumprtl$softsplit$0$s1"];
        assert_eq!(list(bits(sum, "Y")), "30 31 32 33 34 35 36 37");
        // the high half enters the sum three places up
        let hi_q = list(bits(&cells["$bumprtl$softsplit$0$p1_q"], "Q"));
        assert_eq!(list(bits(sum, "B")), format!("0 0 0 {hi_q}"));
        // the old register's initial value is gone from its Q, and the new registers start at 0
        assert!(m["netnames"]["q"]["attributes"].get("init").is_none());
        assert_eq!(m["netnames"]["$bumprtl$softsplit$0$p0_q$q"]["attributes"]["init"], "00000000");
    }

    #[test]
    fn a_product_whose_register_is_copied_becomes_four_pieces_summed_over_both_registers() {
        let (text, soft, n) = split(&design(true, false), "top", &["m".into()]).unwrap();
        assert_eq!((n, soft.len()), (1, 4));
        let d: Value = serde_json::from_str(&text).unwrap();
        let cells = d["modules"]["top"]["cells"].as_object().unwrap();
        assert!(!cells.contains_key("r") && !cells.contains_key("c"));
        // b's six rows in pieces of 1, 2, 1, 2 (at 0, 1, 3, 4), each registered; their sum registered into c's Q
        let rows: Vec<String> =
            (0..4).map(|j| list(bits(&cells[&format!("$bumprtl$softsplit$0$p{j}")], "B"))).collect();
        assert_eq!(rows, ["6", "7 8", "9", "10 11"]);
        let q = |j: usize| list(bits(&cells[&format!("$bumprtl$softsplit$0$p{j}_q")], "Q"));
        for (m, zeros) in [(1, "0"), (2, "0 0 0"), (3, "0 0 0 0")] {
            let sum = &cells[&format!("$bumprtl$softsplit$0$s{m}")];
            assert_eq!(list(bits(sum, "B")), format!("{zeros} {}", q(m)), "s{m}");
        }
        let reg = &cells["$bumprtl$softsplit$0$sum_q"];
        assert_eq!(bits(reg, "D"), bits(&cells["$bumprtl$softsplit$0$s3"], "Y"));
        assert_eq!(list(bits(reg, "Q")), "50 51 52 53 54 55 56 57");
        assert_eq!(d["modules"]["top"]["netnames"]["$bumprtl$softsplit$0$sum_q$q"]["attributes"]["init"], "00000000");
    }

    #[test]
    fn a_product_read_by_anything_but_its_register_stays_whole() {
        let (text, soft, n) = split(&design(false, true), "top", &["m".into()]).unwrap();
        assert_eq!((n, soft), (0, vec!["m".to_string()]));
        let d: Value = serde_json::from_str(&text).unwrap();
        assert!(d["modules"]["top"]["cells"].as_object().unwrap().contains_key("m"));
    }
}
