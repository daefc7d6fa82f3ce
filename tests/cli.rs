//! Bad input gets one clear line and a non-zero exit, and leaves no partial file behind.
use std::process::Command;

fn bumprtl(args: &[&str]) -> (i32, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_bumprtl")).args(args).output().unwrap();
    (o.status.code().unwrap_or(-1), String::from_utf8_lossy(&o.stdout).into(), String::from_utf8_lossy(&o.stderr).into())
}

#[test]
fn unknown_unit_is_one_line_naming_the_units() {
    let (code, _, err) = bumprtl(&["vectors", "glos"]);
    assert_ne!(code, 0);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("unknown unit `glos`") && err.contains("gloss"), "{err}");
}

#[test]
fn exhaustive_above_2_20_is_refused_with_the_reason() {
    let (code, _, err) = bumprtl(&["vectors", "bilinear", "--exhaustive"]);
    assert_ne!(code, 0);
    assert!(err.contains("above 2^20"), "{err}");
}

#[test]
fn software_only_units_say_so() {
    for u in ["cart_encode", "polar_encode"] {
        let (code, _, err) = bumprtl(&["vectors", u]);
        assert_ne!(code, 0);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains("software only") && err.contains("accuracy"), "{err}");
    }
}

#[test]
fn software_only_unit_has_no_verilog() {
    let d = std::env::temp_dir().join(format!("bumprtl-cli-{}", std::process::id()));
    let (code, _, err) = bumprtl(&["verilog", "cart_encode", "--out", d.to_str().unwrap()]);
    assert_ne!(code, 0);
    assert_eq!(err.lines().count(), 1, "{err}");
}

#[test]
fn unwritable_output_fails_cleanly_and_leaves_nothing() {
    let (code, _, err) = bumprtl(&["vectors", "gloss", "--out", "/proc/bumprtl-cannot-write/gloss.csv"]);
    assert_ne!(code, 0);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("cannot write"), "{err}");
    let (code, _, err) = bumprtl(&["wave", "gloss", "--out", "/proc/bumprtl-cannot-write/g.vcd"]);
    assert_ne!(code, 0);
    assert!(err.contains("cannot write"), "{err}");
}

#[test]
fn bad_flag_values_are_refused() {
    let (code, _, err) = bumprtl(&["vectors", "gloss", "--count", "many"]);
    assert_ne!(code, 0);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("invalid value 'many'"), "{err}");
    let (code, _, err) = bumprtl(&["demo", "--size", "4"]);
    assert_ne!(code, 0);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("invalid value '4'"), "{err}");
    let (code, _, err) = bumprtl(&["synth", "gloss", "--freq", "0"]);
    assert_ne!(code, 0);
    assert!(err.contains("between 1 and 500 MHz"), "{err}");
}

#[test]
fn bad_command_lines_are_one_line_each() {
    for (args, says) in [
        (&["demoo"][..], "a similar subcommand exists: 'demo'"),
        (&["vectors"][..], "<UNIT>"),
        (&["wave", "gloss", "--frobnicate"][..], "--frobnicate"),
    ] {
        let (code, out, err) = bumprtl(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty(), "{args:?}: {out}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("bumprtl: ") && err.contains(says), "{args:?}: {err}");
    }
    let (code, out, _) = bumprtl(&["--help"]);
    assert_eq!(code, 0);
    assert!(out.contains("Usage: bumprtl"), "{out}");
}

#[test]
fn vectors_command_reproduces_the_committed_golden_file() {
    let (code, out, err) = bumprtl(&["vectors", "gloss", "--count", "1000", "--seed", "1"]);
    assert_eq!(code, 0, "{err}");
    let golden = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/vectors/data/gloss.csv")).unwrap();
    assert_eq!(out, golden);
}

#[test]
fn demo_runs_on_a_machine_without_the_eda_tools_and_says_what_it_skipped() {
    let d = std::env::temp_dir().join(format!("bumprtl-demo-notools-{}", std::process::id()));
    let o = Command::new(env!("CARGO_BIN_EXE_bumprtl"))
        .args(["demo", "--size", "16", "--out", d.to_str().unwrap()])
        .env("PATH", "")
        .output()
        .unwrap();
    let (out, err) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{out}\n{err}");
    assert!(out.contains("Verilator path skipped") && out.contains("UP5K figures skipped"), "{out}");
    for f in ["model.png", "rust_hdl.png", "polar_model.png", "cart_pipeline.vcd", "polar_pipeline.vcd", "verilog/cart_pipeline.v"] {
        assert!(d.join(f).is_file(), "{f} missing");
    }
    assert!(!d.join("verilator.png").exists());
    let _ = std::fs::remove_dir_all(&d);
}
