//! The docs against the tree: each member crate's README says what the crate is and names every module it has; the
//! front pages stay short; every invariant ARCHITECTURE.md states is held by a test that exists.
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The workspace's member crates, as the root Cargo.toml lists them.
fn members() -> Vec<String> {
    let text = std::fs::read_to_string(root().join("Cargo.toml")).unwrap();
    let list = text.split("members = [").nth(1).and_then(|s| s.split(']').next()).expect("a members list");
    list.split(',').map(|m| m.trim().trim_matches('"').to_string()).filter(|m| !m.is_empty()).collect()
}

/// A module's name as a README names it: the file's stem, or its folder's for a `mod.rs`.
fn module_name(file: &Path) -> Option<String> {
    let stem = file.file_stem()?.to_str()?;
    match stem {
        "lib" | "main" => None,
        "mod" => Some(file.parent()?.file_name()?.to_str()?.to_string()),
        s => Some(s.to_string()),
    }
}

#[test]
fn every_crate_readme_says_what_it_is_and_names_every_module() {
    let members = members();
    assert!(members.len() >= 5, "{members:?}");
    let mut missing = vec![];
    for m in &members {
        let dir = root().join(m);
        let readme = std::fs::read_to_string(dir.join("README.md")).unwrap_or_else(|_| panic!("{m}/README.md"));
        assert!(readme.starts_with("This is the "), "{m}/README.md: the first line says what the crate is");
        let mut files = vec![];
        rust_files(&dir.join("src"), &mut files);
        for f in files {
            let Some(name) = module_name(&f) else { continue };
            if !readme.contains(&format!("`{name}`"))
                && !readme.contains(&format!("{name}.rs`"))
                && !readme.contains(&format!("/{name}/`"))
            {
                missing.push(format!("{m}/README.md does not name {}", f.strip_prefix(&dir).unwrap().display()));
            }
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n"));
}

#[test]
fn the_front_pages_stay_within_8_kb() {
    for doc in ["README.md", "ARCHITECTURE.md"] {
        let n = std::fs::metadata(root().join(doc)).unwrap().len();
        assert!(n <= 8 * 1024, "{doc} is {n} bytes");
    }
}

#[test]
fn every_architecture_invariant_names_a_test_that_exists() {
    let text = std::fs::read_to_string(root().join("ARCHITECTURE.md")).unwrap();
    let mut sources = String::new();
    for dir in ["src", "tests", "vectors", "rtl", "testbench", "sim", "synth", "widths"] {
        let mut files = vec![];
        rust_files(&root().join(dir), &mut files);
        for f in files {
            sources.push_str(&std::fs::read_to_string(f).unwrap());
        }
    }
    let mut invariants = 0;
    for para in text.split("\n\n").filter(|p| p.contains("**Architecture Invariant:**")) {
        invariants += 1;
        // "Held by `test_a` and `test_b`": every test named after "Held by" exists
        let held =
            para.split("Held by").nth(1).unwrap_or_else(|| panic!("an invariant says no test holds it:\n{para}"));
        let named: Vec<&str> = held.split('`').skip(1).step_by(2).collect();
        assert!(!named.is_empty(), "an invariant names no test:\n{para}");
        for t in named {
            assert!(sources.contains(&format!("fn {t}(")), "no test `{t}`, which this invariant names:\n{para}");
        }
    }
    assert!(invariants >= 5, "{invariants} invariants");
}
