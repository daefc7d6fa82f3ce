//! Embeds every committed golden vector file (`data/<unit>.csv`) in the crate, so that `bumprtl verilog` can hand a
//! user the unit's own golden vectors wherever the binary runs.

use std::fmt::Write as _;

fn main() {
    let data = std::path::Path::new(&std::env::var("CARGO_MANIFEST_DIR").unwrap()).join("data");
    println!("cargo:rerun-if-changed={}", data.display());
    let mut files: Vec<_> = std::fs::read_dir(&data)
        .map(|d| {
            d.filter_map(Result::ok).map(|e| e.path()).filter(|p| p.extension().is_some_and(|x| x == "csv")).collect()
        })
        .unwrap_or_default();
    files.sort();
    let mut s = String::from(
        "/// (unit, the committed `data/<unit>.csv`), by unit name.\npub const GOLDEN: &[(&str, &str)] = &[\n",
    );
    for f in files {
        println!("cargo:rerun-if-changed={}", f.display());
        let unit = f.file_stem().unwrap().to_string_lossy().into_owned();
        let _ = writeln!(s, "    ({unit:?}, include_str!({:?})),", f.display().to_string());
    }
    s.push_str("];\n");
    std::fs::write(std::path::Path::new(&std::env::var("OUT_DIR").unwrap()).join("golden.rs"), s).unwrap();
}
