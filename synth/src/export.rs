//! Verilog export: rust-hdl's `generate_verilog`, with the top module (and its DFF submodules' prefix) renamed
//! from rust-hdl's `top` to the unit's name, so that several units can be read into one tool run.

use rtl::StreamUnit;
use rust_hdl::prelude::*;
use std::path::{Path, PathBuf};

pub struct Exported {
    pub module: String,
    pub text: String,
}

pub fn export<U: StreamUnit>() -> Exported {
    let mut uut = U::build();
    uut.connect_all();
    let text = generate_verilog(&uut);
    let module = U::NAME.to_string();
    let text = text.replace("module top(", &format!("module {module}(")).replace("top$", &format!("{module}$"));
    Exported { module, text }
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

/// Write a file whole or not at all.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), String> {
    let tmp = path.with_extension("partial");
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
