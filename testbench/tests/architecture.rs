//! ARCHITECTURE.md's invariants that a test can check, one test each, read from the source tree itself. The ones
//! the simulators check (bit-exactness, latency, Verilog keywords, one wrap per signal) are in every unit's tests.
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The `[dependencies]` table of a crate's manifest, as the crate names it lists.
fn dependencies(krate: &str) -> Vec<String> {
    let text = std::fs::read_to_string(root().join(krate).join("Cargo.toml")).unwrap();
    let mut in_deps = false;
    let mut deps = vec![];
    for line in text.lines() {
        let l = line.trim();
        if l.starts_with('[') {
            in_deps = l == "[dependencies]";
        } else if in_deps && !l.is_empty() && !l.starts_with('#') {
            deps.push(l.split(['=', '.', ' ']).next().unwrap().to_string());
        }
    }
    deps
}

#[test]
fn the_model_and_the_rtl_do_not_depend_on_each_other() {
    let (v, r) = (dependencies("vectors"), dependencies("rtl"));
    assert!(!v.is_empty() && !r.is_empty(), "both manifests read");
    assert!(!v.contains(&"rtl".to_string()), "vectors depends on rtl: {v:?}");
    assert!(!r.contains(&"vectors".to_string()), "rtl depends on vectors: {r:?}");
}

/// The testbench's test binary compiles beside `sim`, the longest crate to build, not after it: the lint reads a
/// unit's waivers from its block (`rtl::StreamUnit::waivers`), and what needs the table of units is tested in
/// `sim/tests`.
#[test]
fn the_testbench_does_not_wait_for_sim() {
    let text = std::fs::read_to_string(root().join("testbench/Cargo.toml")).unwrap();
    assert!(dependencies("testbench").contains(&"rtl".to_string()), "the testbench's manifest read");
    let sim: Vec<&str> = text.lines().filter(|l| l.trim_start().starts_with("sim")).collect();
    assert!(sim.is_empty(), "testbench/Cargo.toml names sim: {sim:?}");
}

/// Every file under `dir`, skipping build output (`target/`, and `out/`, the commands' default output folder, both
/// ignored by git) and version control.
fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_name().unwrap().to_string_lossy().to_string();
        if p.is_dir() {
            if name != "target" && name != "out" && !name.starts_with('.') {
                files(&p, out);
            }
        } else {
            out.push(p);
        }
    }
}

#[test]
fn no_generated_file_lives_in_the_source_tree() {
    let mut all = vec![];
    files(&root(), &mut all);
    assert!(all.iter().any(|p| p.ends_with("vectors/data/gloss.csv")), "the walk sees the golden files");
    let generated: Vec<&PathBuf> = all
        .iter()
        .filter(|p| {
            matches!(
                p.extension().and_then(|e| e.to_str()),
                Some("v" | "sv" | "vcd" | "png" | "hex" | "json" | "asc" | "bin")
            )
        })
        // the few images the docs show: under docs/, small, and each shown by a document; and the colour maps the
        // example scenes read
        .filter(|p| !shown_by_a_doc(p) && !named_by_a_scene(p))
        .collect();
    assert!(generated.is_empty(), "generated files outside target/: {generated:?}");
}

/// A PNG under docs/ of at most 64 KB that README.md or ARCHITECTURE.md shows.
fn shown_by_a_doc(p: &std::path::Path) -> bool {
    let Ok(rel) = p.strip_prefix(root()) else { return false };
    let docs: String =
        ["README.md", "ARCHITECTURE.md"].iter().filter_map(|d| std::fs::read_to_string(root().join(d)).ok()).collect();
    rel.starts_with("docs")
        && p.extension().is_some_and(|e| e == "png")
        && std::fs::metadata(p).is_ok_and(|m| m.len() <= 64 * 1024)
        && docs.contains(&format!("({})", rel.to_string_lossy()))
}

/// A PNG under scenes/maps/ of at most 64 KB that a scene in scenes/ names: an input, not an output.
fn named_by_a_scene(p: &std::path::Path) -> bool {
    let Ok(rel) = p.strip_prefix(root().join("scenes")) else { return false };
    let mut scenes = vec![];
    files(&root().join("scenes"), &mut scenes);
    let named = scenes
        .iter()
        .filter(|s| s.extension().is_some_and(|e| e == "toml"))
        .filter_map(|s| std::fs::read_to_string(s).ok())
        .any(|t| t.contains(&format!("\"{}\"", rel.to_string_lossy())));
    rel.starts_with("maps")
        && p.extension().is_some_and(|e| e == "png")
        && std::fs::metadata(p).is_ok_and(|m| m.len() <= 64 * 1024)
        && named
}

fn rust_sources(dir: &str) -> Vec<(PathBuf, String)> {
    let mut all = vec![];
    files(&root().join(dir), &mut all);
    all.into_iter()
        .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        .map(|p| (p.clone(), std::fs::read_to_string(&p).unwrap()))
        .collect()
}

#[test]
fn fixed_point_types_are_declared_once_in_q_rs() {
    let src = rust_sources("rtl/src");
    assert!(src.len() > 10);
    for (path, text) in &src {
        if path.ends_with("q.rs") {
            continue;
        }
        for (n, line) in text.lines().enumerate() {
            let l = line.trim_start();
            assert!(
                !(l.starts_with("type ") || l.starts_with("pub type ")) || !l.contains("= Bits<"),
                "{}:{}: a fixed-point type outside q.rs: {l}",
                path.display(),
                n + 1
            );
        }
    }
}

#[test]
fn no_block_uses_rust_hdl_signed() {
    for (path, text) in rust_sources("rtl/src") {
        for (n, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap();
            assert!(
                !code.contains("Signed<") && !code.contains("signed_bit_cast"),
                "{}:{}: {line}",
                path.display(),
                n + 1
            );
        }
    }
}

#[test]
fn signed_products_go_through_the_one_sign_magnitude_multiplier() {
    // the blocks built on `SmMul` write no sign-magnitude idiom of their own
    for file in ["rtl/src/shared/bilinear.rs", "rtl/src/cartesian/light_iter.rs"] {
        let text = std::fs::read_to_string(root().join(file)).unwrap();
        assert!(text.contains("SmMul<"), "{file} uses SmMul");
        assert!(!text.contains("!self."), "{file} negates by hand again");
    }
}

#[test]
fn nothing_writes_into_the_system_temp_folder() {
    for dir in ["src", "sim", "synth", "testbench", "rtl/src", "vectors/src", "tests", "widths"] {
        for (path, text) in rust_sources(dir) {
            if path.ends_with("architecture.rs") {
                continue;
            }
            assert!(
                !text.contains("temp_dir()") && !text.contains("\"/tmp"),
                "{} writes into the system temp folder",
                path.display()
            );
        }
    }
}

/// Whether an rtl line computes a value: an assignment whose right side does arithmetic, shifts, slices or casts
/// (index arithmetic such as `[i - 1]` does not count).
fn computes(line: &str) -> bool {
    let code = line.split("//").next().unwrap();
    let Some((_, rhs)) = code.split_once(".next =") else { return false };
    let mut depth = 0;
    let rhs: String = rhs
        .chars()
        .filter(|&c| {
            match c {
                '[' => depth += 1,
                ']' => depth -= 1,
                _ => {}
            }
            depth == 0 && c != ']'
        })
        .collect();
    ["+", "-", "*", ">>", "<<", "get_bits", "bit_cast"].iter().any(|op| rhs.contains(op))
}

#[test]
fn every_rtl_datapath_line_says_its_width() {
    // a line that computes carries a comment, or sits in a run of assignments (and their if/else) under one
    let mut bare = vec![];
    for (path, text) in rust_sources("rtl/src") {
        if path.ends_with("stream.rs") {
            continue; // the harness, not a datapath
        }
        let lines: Vec<&str> = text.lines().take_while(|l| !l.starts_with("#[cfg(test)]")).collect();
        for (i, line) in lines.iter().enumerate() {
            if !computes(line) || line.contains("//") {
                continue;
            }
            let covered = lines[..i]
                .iter()
                .rev()
                .map(|l| l.trim())
                .find(|t| {
                    !(t.starts_with("if ")
                        || t.starts_with("} else")
                        || *t == "}"
                        || (t.contains(".next =") && !t.contains("//")))
                })
                .is_some_and(|t| t.starts_with("//"));
            if !covered {
                bare.push(format!("{}:{}: {}", path.display(), i + 1, line.trim()));
            }
        }
    }
    assert!(bare.is_empty(), "datapath lines without a width comment:\n{}", bare.join("\n"));
}

#[test]
fn the_width_rule_sees_a_bare_line() {
    assert!(computes("        self.s1_d.d.next = self.a.val() - self.b.val();"));
    assert!(computes("        self.s2_q.d.next = self.w_u.val().get_bits::<8>(8);"));
    assert!(!computes("        self.line[i].d.next = self.line[i - 1].q.val();"));
    assert!(!computes("        self.valid.d.next = self.valid_in.val();"));
}
