//! Embeds the rtl's own source text (`rtl::source::FILES`), so that the width report can read each signal's declared
//! fixed-point type (the `SqM_N` / `UqM_N` aliases the simulator does not keep) from the binary alone.

use std::path::{Path, PathBuf};

fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> =
        std::fs::read_dir(dir).expect("src/ is readable").map(|e| e.expect("entry").path()).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            walk(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

fn main() {
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets it")).join("src");
    let mut files = vec![];
    walk(&root, &mut files);
    let mut text = String::from(
        "/// Every source file of the rtl crate: (path under src/, text).\npub const FILES: &[(&str, &str)] = &[\n",
    );
    for f in &files {
        let rel = f.strip_prefix(&root).expect("under src").to_string_lossy().replace('\\', "/");
        text.push_str(&format!("    ({rel:?}, include_str!({:?})),\n", f.to_string_lossy()));
    }
    text.push_str("];\n");
    let out = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets it")).join("sources.rs");
    std::fs::write(out, text).expect("OUT_DIR is writable");
    println!("cargo:rerun-if-changed=src");
}
