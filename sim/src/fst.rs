//! FST beside VCD: a VCD rust-hdl wrote, rewritten as an FST (the compressed, indexed trace format GTKWave and
//! Surfer open; a long run's VCD is many times its size and slow to open).
//!
//! The FST holds what the VCD holds: the same scopes and variables in the same order (variables that share a VCD
//! identifier code become aliases of one FST signal), the same timescale, and every value change at its time, each
//! vector left-extended to its declared width as VCD's rule says (with 0, or with x or z when the value's first bit
//! is one). The file is built in memory and written whole (`synth::export::write_atomic`), so a failed run leaves
//! none.

use fst_writer::{FstFileType, FstInfo, FstScopeType, FstSignalId, FstSignalType, FstVarDirection, FstVarType};
use std::collections::HashMap;
use std::path::Path;
use vcd::{Command, ScopeItem, Value};

/// FST's timescale exponent for a VCD `$timescale` of `n` `unit`s (n a power of ten, as VCD allows: 1, 10, 100).
fn exponent(n: u32, unit: vcd::TimescaleUnit) -> Result<i8, String> {
    let mut e = -(unit.divisor().ilog10() as i8);
    let mut n = n.max(1);
    while n.is_multiple_of(10) {
        n /= 10;
        e += 1;
    }
    if n == 1 {
        Ok(e)
    } else {
        Err(format!("timescale factor {n} is not a power of ten"))
    }
}

/// A VCD value as FST's value bytes, left-extended to `width` characters.
fn bits(values: &[Value], width: usize) -> Vec<u8> {
    let ch = |v: &Value| match v {
        Value::V0 => b'0',
        Value::V1 => b'1',
        Value::X => b'x',
        Value::Z => b'z',
    };
    let mut out: Vec<u8> = values.iter().map(ch).collect();
    if out.len() < width {
        let fill = match out.first() {
            Some(b'x') => b'x',
            Some(b'z') => b'z',
            _ => b'0',
        };
        let mut padded = vec![fill; width - out.len()];
        padded.append(&mut out);
        out = padded;
    }
    // a value wider than its variable keeps its low bits
    out.split_off(out.len() - width)
}

/// The VCD at `vcd` as an FST at `fst`: the number of value changes written.
pub fn vcd_to_fst(vcd: &Path, fst: &Path) -> Result<usize, String> {
    let at = |e: String| format!("{}: {e}", vcd.display());
    let file = std::fs::File::open(vcd).map_err(|e| at(e.to_string()))?;
    let mut parser = vcd::Parser::new(std::io::BufReader::new(file));
    let header = parser.parse_header().map_err(|e| at(e.to_string()))?;
    let (n, unit) = header.timescale.unwrap_or((1, vcd::TimescaleUnit::S));
    let info = FstInfo {
        start_time: 0,
        timescale_exponent: exponent(n, unit).map_err(at)?,
        version: header.version.clone().unwrap_or_default(),
        date: header.date.clone().unwrap_or_default(),
        file_type: FstFileType::Verilog,
    };
    // built in memory, then written whole or not at all
    let (bytes, changes) = write(&mut parser, &header, &info, vcd, fst)?;
    synth::export::write_atomic(fst, &bytes)?;
    Ok(changes)
}

fn write<R: std::io::BufRead>(
    parser: &mut vcd::Parser<R>,
    header: &vcd::Header,
    info: &FstInfo,
    vcd: &Path,
    fst: &Path,
) -> Result<(Vec<u8>, usize), String> {
    let out_err = |e: fst_writer::FstWriteError| format!("cannot write {}: {e}", fst.display());
    let mut h = fst_writer::FstHeaderWriter::write_to_mem(info).map_err(out_err)?;
    // the VCD's identifier code → (the FST signal, its width)
    let mut ids: HashMap<vcd::IdCode, (FstSignalId, usize)> = HashMap::new();
    fn walk<W: std::io::Write + std::io::Seek>(
        items: &[ScopeItem],
        h: &mut fst_writer::FstHeaderWriter<W>,
        ids: &mut HashMap<vcd::IdCode, (FstSignalId, usize)>,
    ) -> fst_writer::Result<()> {
        for item in items {
            match item {
                ScopeItem::Scope(s) => {
                    h.scope(&s.identifier, "", FstScopeType::Module)?;
                    walk(&s.items, h, ids)?;
                    h.up_scope()?;
                }
                ScopeItem::Var(v) => {
                    let alias = ids.get(&v.code).map(|x| x.0);
                    let tpe = match v.var_type {
                        vcd::VarType::Reg => FstVarType::Reg,
                        vcd::VarType::Integer => FstVarType::Integer,
                        _ => FstVarType::Wire,
                    };
                    let id =
                        h.var(&v.reference, FstSignalType::bit_vec(v.size), tpe, FstVarDirection::Implicit, alias)?;
                    ids.entry(v.code).or_insert((id, v.size as usize));
                }
                _ => {} // comments
            }
        }
        Ok(())
    }
    walk(&header.items, &mut h, &mut ids).map_err(out_err)?;
    let mut body = h.finish().map_err(out_err)?;
    // every change is kept, as the VCD has it (a reader counts them alike)
    body.set_deduplicate(false);
    let mut changes = 0;
    for cmd in parser {
        let cmd = cmd.map_err(|e| format!("{}: {e}", vcd.display()))?;
        let (code, values): (vcd::IdCode, Vec<Value>) = match cmd {
            Command::Timestamp(t) => {
                body.time_change(t).map_err(out_err)?;
                continue;
            }
            Command::ChangeScalar(c, v) => (c, vec![v]),
            Command::ChangeVector(c, v) => (c, v.iter().collect()),
            Command::ChangeReal(..) | Command::ChangeString(..) => {
                return Err(format!("{}: a real or string value, which this trace never holds", vcd.display()));
            }
            _ => continue,
        };
        let &(id, width) =
            ids.get(&code).ok_or_else(|| format!("{}: a change to an undeclared code {code}", vcd.display()))?;
        body.signal_change(id, &bits(&values, width)).map_err(out_err)?;
        changes += 1;
    }
    let bytes = body.finish().map_err(out_err)?.into_inner();
    Ok((bytes, changes))
}
