//! Bad input gets one clear line and a non-zero exit, and leaves no partial file behind.
use std::process::Command;

fn bumprtl(args: &[&str]) -> (i32, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_bumprtl")).args(args).output().unwrap();
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into(),
        String::from_utf8_lossy(&o.stderr).into(),
    )
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
    let d = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("bumprtl-cli-{}", std::process::id()));
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
        (&["prove"][..], "<UNITS>"),
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

/// The row of a table in the demo's summary.md whose second cell is `unit` (a pipeline's label, then its unit), as
/// cells.
fn md_row<'a>(md: &'a str, unit: &str) -> Vec<&'a str> {
    md.lines()
        .find(|l| l.split(" | ").nth(1) == Some(unit))
        .map(|l| l.trim_matches('|').split(" | ").map(str::trim).collect())
        .unwrap_or_default()
}

#[test]
fn demo_runs_on_a_machine_without_the_eda_tools_and_says_what_it_skipped() {
    let d =
        std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("bumprtl-demo-notools-{}", std::process::id()));
    let o = Command::new(env!("CARGO_BIN_EXE_bumprtl"))
        .args(["demo", "--size", "16", "--out", d.to_str().unwrap()])
        .env("PATH", "")
        .output()
        .unwrap();
    let (out, err) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{out}\n{err}");
    assert!(out.contains("Verilator path skipped") && out.contains("synthesis figures skipped"), "{out}");
    // one screen: at most 40 lines of at most 100 columns, the page's path last
    assert!(out.lines().count() <= 40, "{out}");
    assert!(out.lines().all(|l| l.chars().count() <= 100), "{out}");
    assert!(out.trim_end().ends_with(&format!("the page: {}", d.join("index.html").display())), "{out}");
    // standard error is no terminal here: a line a step, what, how many, how long
    assert!(err.lines().any(|l| l.starts_with("cart_tex_bilinear: rust-hdl: ") && l.ends_with(" s")), "{err}");
    // the full tables in summary.md: the palette rows' ⌈log2 s_N⌉ bits a texel beside the Cartesian map's 16 and the
    // height map's 8
    let md = std::fs::read_to_string(d.join("summary.md")).unwrap();
    let bits: Vec<&str> = ["cart_tex_bilinear", "cart_tex_bilinear_hemi_oct", "polar_tex_bilinear", "height_pipeline"]
        .into_iter()
        .chain(["palette_pipeline", "palette_pipeline_12"])
        .map(|u| md_row(&md, u).get(2).copied().unwrap_or("none"))
        .collect();
    assert_eq!(bits, ["16", "16", "16", "8", "8", "12"], "{md}");
    assert!(md.contains("palette 256 shade vs the ideal under its one light"), "{md}");
    let html = std::fs::read_to_string(d.join("index.html")).unwrap();
    assert!(html.contains("Verilator path skipped") && !html.contains("http"), "the page reaches for the network");
    for f in [
        "img/cart_tex_bilinear_model.png",
        "img/cart_tex_bilinear_rust_hdl.png",
        "img/polar_tex_bilinear_model.png",
        "img/cart_tex_bilinear_hemi_oct_model.png",
        "wave/cart_tex_bilinear.vcd",
        "wave/cart_tex_bilinear.gtkw",
        "wave/polar_tex_bilinear.vcd",
        "wave/cart_tex_bilinear_hemi_oct.vcd",
        "verilog/cart_tex_bilinear.v",
        "verilog/cart_tex_bilinear_tb.v",
        "verilog/cart_tex_bilinear_axis_tb.v",
        "img/fig8a_blinn.png",
        "img/fig8b_bspline.png",
        "img/colour_reference.png",
        "img/colour_bilinear.png",
        "img/colour_bspline.png",
        "img/palette_pipeline_model.png",
        "img/palette_pipeline_rust_hdl.png",
        "img/palette_pipeline_12_model.png",
        "wave/palette_pipeline.vcd",
        "wave/palette_pipeline_12.vcd",
        "verilog/palette_pipeline_12.v",
        "img/torus_model.png",
        "wave/cart_tex_bilinear_matte.vcd",
        "verilog/cart_tex_bilinear_matte.v",
    ] {
        assert!(d.join(f).is_file(), "{f} missing");
        assert!(html.contains(&format!("\"{f}\"")), "the page does not show or link {f}");
    }
    assert!(!d.join("img/cart_tex_bilinear_verilator.png").exists());
    // a heat map carries its colour bar under the frame
    let heat = image::open(d.join("img/torus_error_heat.png")).unwrap();
    assert_eq!((heat.width(), heat.height()), (16, 16 + 19));
    let _ = std::fs::remove_dir_all(&d);
}

fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn exhaustive_writes_every_input_exactly_once() {
    let (code, out, err) = bumprtl(&["vectors", "gloss", "--exhaustive"]);
    assert_eq!(code, 0, "{err}");
    let rows: Vec<&str> = out.lines().skip(2).collect();
    assert_eq!(rows.len(), 256 * 1024, "one row per (conc, x)");
    let inputs: std::collections::HashSet<(&str, &str)> = rows
        .iter()
        .map(|r| {
            let mut f = r.split(',');
            (f.next().unwrap(), f.next().unwrap())
        })
        .collect();
    assert_eq!(inputs.len(), rows.len(), "an input written twice");
    // the random mode keeps the hard cases first
    let (_, random, _) = bumprtl(&["vectors", "gloss", "--count", "3"]);
    let hard = (vectors::gloss::MODEL.hard_cases)();
    let first: Vec<&str> = random.lines().skip(2).take(hard.len()).collect();
    let want: Vec<String> =
        hard.iter().map(|h| h.iter().map(|v| v.to_string()).collect::<Vec<_>>().join(",")).collect();
    for (row, h) in first.iter().zip(&want) {
        assert!(row.starts_with(&format!("{h},")), "{row} is not the hard case {h}");
    }
    assert_eq!(random.lines().count(), 2 + hard.len() + 3);
}

#[test]
fn out_dash_is_standard_output_and_creates_no_file() {
    let d = scratch("dash");
    let run = |args: &[&str]| Command::new(env!("CARGO_BIN_EXE_bumprtl")).args(args).current_dir(&d).output().unwrap();
    let o = run(&["vectors", "gloss", "--out", "-"]);
    assert!(o.status.success());
    let golden = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/vectors/data/gloss.csv")).unwrap();
    assert_eq!(o.stdout, golden);
    let o = run(&["wave", "gloss", "--count", "4", "--out", "-"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let vcd = String::from_utf8_lossy(&o.stdout);
    assert!(vcd.contains("$enddefinitions") && vcd.contains("$var"), "not a VCD: {}", &vcd[..vcd.len().min(200)]);
    let o = run(&["verilog", "gloss", "--out", "-"]);
    assert!(o.status.success());
    let v = String::from_utf8_lossy(&o.stdout);
    assert!(v.contains("module gloss(") && !v.contains("gloss_tb"), "{v}");
    let o = run(&["demo", "--out", "-"]);
    assert!(!o.status.success());
    assert_eq!(String::from_utf8_lossy(&o.stderr).lines().count(), 1);
    assert_eq!(std::fs::read_dir(&d).unwrap().count(), 0, "a file was left in the working folder");
}

#[test]
fn non_utf8_output_paths_work_or_fail_cleanly() {
    use std::os::unix::ffi::OsStrExt;
    let d = scratch("utf8");
    let bad = d.join(std::ffi::OsStr::from_bytes(b"out-\xff"));
    for args in [
        vec![std::ffi::OsStr::new("vectors"), "gloss".as_ref(), "--out".as_ref(), bad.join("g.csv").as_os_str()],
        vec![
            "wave".as_ref(),
            "gloss".as_ref(),
            "--count".as_ref(),
            "4".as_ref(),
            "--out".as_ref(),
            bad.join("g.vcd").as_os_str(),
        ],
        vec!["verilog".as_ref(), "gloss".as_ref(), "--out".as_ref(), bad.as_os_str()],
    ] {
        let _ = std::fs::create_dir_all(&bad);
        let o = Command::new(env!("CARGO_BIN_EXE_bumprtl")).args(&args).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(o.status.success(), "{args:?}: {err}");
    }
    assert!(bad.join("g.csv").is_file() && bad.join("g.vcd").is_file() && bad.join("gloss_tb.v").is_file());
}

#[test]
fn wave_fst_writes_the_trace_beside_the_vcd_and_refuses_standard_output_or_an_fst_name() {
    let d = scratch("fst");
    let vcd = d.join("gloss.vcd");
    let (code, out, err) = bumprtl(&["wave", "gloss", "--count", "16", "--fst", "--out", vcd.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let fst = d.join("gloss.fst");
    assert!(out.lines().any(|l| l.starts_with(&fst.display().to_string()) && l.ends_with("value changes)")), "{out}");
    // FST's header block: type 0, then its length, 329 bytes, big-endian
    let bytes = std::fs::read(&fst).unwrap();
    assert_eq!(bytes[..9], [0, 0, 0, 0, 0, 0, 0, 1, 0x49], "not an FST header");
    for (args, says) in [
        (vec!["wave", "gloss", "--fst", "--out", "-"], "--out must name the VCD file"),
        (vec!["wave", "gloss", "--fst", "--out", "x.fst"], "the FST goes beside it"),
    ] {
        let (code, out, err) = bumprtl(&args);
        assert_eq!((code, out.as_str(), err.lines().count()), (1, "", 1), "{args:?}: {err}");
        assert!(err.contains(says), "{err}");
    }
    assert!(!std::path::Path::new("x.fst").exists() && !std::path::Path::new("x.vcd").exists());
}

#[test]
fn verilog_writes_the_module_its_testbench_the_golden_vectors_the_axis_wrapper_and_the_package() {
    let d = scratch("tb");
    let (code, out, err) = bumprtl(&["verilog", "dot3", "--out", d.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let files = ["dot3.v", "dot3_tb.v", "dot3_in.hex", "dot3_out.hex", "dot3_axis.v", "dot3_axis_tb.v", "dot3.vlt"];
    for f in files.into_iter().chain(["dot3_io.v", "dot3.core", "test_dot3.py", "Makefile"]) {
        assert!(d.join(f).is_file() && out.contains(f), "{f}: {out}");
    }
    let golden = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/vectors/data/dot3.csv")).unwrap();
    let rows = golden.lines().filter(|l| !l.starts_with('#')).count() - 1;
    let hex = std::fs::read_to_string(d.join("dot3_in.hex")).unwrap();
    assert_eq!(hex.lines().filter(|l| !l.starts_with("//")).count(), rows);
}

#[test]
fn a_bad_height_map_is_one_line_naming_it_and_nothing_is_written() {
    let d = scratch("bad-map");
    let (empty, text, tiny) = (d.join("empty.png"), d.join("text.png"), d.join("tiny.png"));
    std::fs::write(&empty, b"").unwrap();
    std::fs::write(&text, b"P2 2 2 255 0 0 0 0").unwrap();
    image::GrayImage::new(1, 1).save(&tiny).unwrap();
    for (map, what) in
        [(&empty, "empty"), (&text, "not a PNG"), (&tiny, "at least 2 × 2"), (&d.join("absent.png"), "cannot read")]
    {
        let out = d.join("out");
        let (code, _, err) = bumprtl(&[
            "demo",
            "--no-synth",
            "--size",
            "16",
            "--height-map",
            map.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_ne!(code, 0);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(map.to_str().unwrap()) && err.contains(what), "{err}");
        assert!(!out.exists(), "{} was created for a refused map", out.display());
    }
    let (code, _, err) = bumprtl(&["demo", "--relief", "0", "--height-map", tiny.to_str().unwrap()]);
    assert_ne!(code, 0);
    assert!(err.contains("relief"), "{err}");
}

#[test]
fn a_users_height_map_goes_through_the_height_cartesian_polar_and_palette_paths() {
    // a 5 × 3 colour map: read as luma and resampled to 8 × 8, both said; rendered without the EDA tools
    let d = scratch("user-map");
    let map = d.join("map.png");
    image::RgbImage::from_fn(5, 3, |x, y| image::Rgb([(x * 50) as u8, (y * 90) as u8, 30])).save(&map).unwrap();
    let out = d.join("out");
    let o = Command::new(env!("CARGO_BIN_EXE_bumprtl"))
        .args(["demo", "--size", "16", "--height-map", map.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .env("PATH", "")
        .output()
        .unwrap();
    let (stdout, err) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{stdout}\n{err}");
    assert!(stdout.contains("read as its luma") && stdout.contains("5 × 3 resampled (bilinear) to 8 × 8"), "{stdout}");
    assert!(stdout.contains("map.png (8x8"), "{stdout}");
    // 64 texels: both palettes hold every distinct normal
    let md = std::fs::read_to_string(out.join("summary.md")).unwrap();
    assert!(md.contains("s_N = 256: ") && md.contains("0.00° mean / 0.00° max"), "{md}");
    for f in [
        "img/height_pipeline_model.png",
        "img/height_pipeline_rust_hdl.png",
        // 8 × 8, a side the texture unit's memory holds
        "img/cart_tex_bilinear_model.png",
        "img/polar_tex_bilinear_model.png",
        "img/palette_pipeline_model.png",
        "img/palette_pipeline_12_model.png",
    ] {
        assert!(out.join(f).is_file(), "{f} missing");
    }
}

#[test]
fn quantize_writes_the_palette_the_index_map_and_its_mips() {
    let d = scratch("quantize");
    // an RGB normal map of 5 × 3 texels (not a power of two): 15 distinct normals at most
    let map = d.join("n.png");
    image::RgbImage::from_fn(5, 3, |x, y| image::Rgb([100 + 20 * x as u8, 128 + 30 * y as u8, 230]))
        .save(&map)
        .unwrap();
    let out = d.join("q");
    let (code, stdout, err) =
        bumprtl(&["quantize", map.to_str().unwrap(), "--size", "4", "--dither", "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(stdout.contains("distinct normals: 15") && stdout.contains("palette: 4 normals"), "{stdout}");
    let csv = std::fs::read_to_string(out.join("palette.csv")).unwrap();
    assert_eq!(csv.lines().filter(|l| !l.starts_with('#')).count(), 1 + 4, "{csv}");
    for row in csv.lines().skip(2) {
        let v: Vec<f64> = row.split(',').skip(1).map(|x| x.parse().unwrap()).collect();
        assert!((v.iter().map(|c| c * c).sum::<f64>() - 1.0).abs() < 1e-6, "{row} is not a unit normal");
    }
    assert_eq!(std::fs::read(out.join("index.raw")).unwrap().len(), 15 * 2);
    let index = image::open(out.join("index.png")).unwrap();
    assert_eq!((index.width(), index.height()), (5, 3));
    assert!(index.to_luma16().pixels().all(|p| p.0[0] < 4));
    // 5 × 3 → 3 × 2 → 2 × 1 → 1 × 1
    let mips: Vec<(u32, u32)> = (1..=3)
        .map(|l| image::open(out.join(format!("mip{l}.png"))).unwrap())
        .map(|i| (i.width(), i.height()))
        .collect();
    assert_eq!(mips, [(3, 2), (2, 1), (1, 1)]);
    assert!(!out.join("mip4.png").exists());
    // enough normals: lossless
    let (_, stdout, _) =
        bumprtl(&["quantize", map.to_str().unwrap(), "--size", "16", "--out", d.join("all").to_str().unwrap()]);
    assert!(stdout.contains("mean 0.0000°, max 0.0000°"), "{stdout}");
    // a grey map is a height map
    let grey = d.join("h.png");
    image::GrayImage::from_fn(8, 8, |x, _| image::Luma([x as u8 * 30])).save(&grey).unwrap();
    let (code, stdout, err) =
        bumprtl(&["quantize", grey.to_str().unwrap(), "--size", "8", "--out", d.join("h").to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(stdout.contains("a height map") && stdout.contains("plane over 8 neighbours"), "{stdout}");
}

#[test]
fn quantize_refuses_a_bad_map_in_one_line_and_writes_nothing() {
    let d = scratch("quantize-bad");
    let (empty, text) = (d.join("e.png"), d.join("t.png"));
    std::fs::write(&empty, b"").unwrap();
    std::fs::write(&text, b"not a png").unwrap();
    for (map, what) in [(&empty, "empty"), (&text, "not a PNG"), (&d.join("absent.png"), "cannot read")] {
        let out = d.join("out");
        let (code, _, err) =
            bumprtl(&["quantize", map.to_str().unwrap(), "--size", "16", "--out", out.to_str().unwrap()]);
        assert_ne!(code, 0);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(map.to_str().unwrap()) && err.contains(what), "{err}");
        assert!(!out.exists());
    }
    for (bad, what) in [
        (["--size", "0", "--q", "8"], "size"),
        (["--size", "16385", "--q", "8"], "size"),
        (["--size", "16", "--q", "5"], "4 or 8"),
    ] {
        let args = [&["quantize", empty.to_str().unwrap(), "--out", "x"][..], &bad[..]].concat();
        let (code, _, err) = bumprtl(&args);
        assert_ne!(code, 0, "{bad:?}");
        assert!(err.contains(what), "{bad:?}: {err}");
    }
}

#[test]
fn palette_table_prints_table_1_with_its_added_columns() {
    let pics = scratch("palette-table");
    let (code, out, err) = bumprtl(&["palette-table", "--no-synth", "--out", pics.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    // the quantizer at every size, its error falling as s_N grows; Figure 3's pictures, each a 512 x 512 PNG
    let sweep: Vec<f64> = out
        .lines()
        .skip_while(|l| !l.starts_with("the quantizer"))
        .filter_map(|l| l.split_whitespace().last()?.split('/').next()?.parse().ok())
        .collect();
    assert_eq!(sweep.len(), 11, "{out}");
    assert!(sweep.windows(2).all(|w| w[1] < w[0]), "{sweep:?}");
    for s_n in ["unquantized", "16", "32", "64", "128", "256", "512", "1024", "2048"] {
        let img = image::open(pics.join(format!("figure3_{s_n}.png"))).unwrap();
        assert_eq!((img.width(), img.height()), (512, 512));
    }
    let (code, _, err) = bumprtl(&["palette-table", "--no-synth", "--out", "/proc/no-such-folder"]);
    assert_ne!(code, 0);
    assert!(err.lines().count() == 1 && err.contains("/proc/no-such-folder"), "{err}");
    for model in ["Lambert ", "Lambert + specular", "chrome", "environment"] {
        let rows: Vec<&str> = out.lines().filter(|l| l.starts_with(model)).collect();
        assert_eq!(rows.len(), if model == "Lambert " { 6 } else { 3 }, "{model}: {out}");
    }
    // the paper's 16,348-normal Lambert + specular figure stands beside this machine's
    assert!(
        out.lines().any(|l| l.starts_with("Lambert + specular") && l.contains("16384") && l.contains("12.5")),
        "{out}"
    );
    assert!(out.contains("angle mean/max") && out.contains("image LSB mean/max"));
}

#[test]
fn widths_lists_every_signal_with_its_format_and_the_range_it_took() {
    let d = scratch("widths");
    let csv = d.join("dot3.csv");
    let (code, out, err) = bumprtl(&["widths", "dot3", "--count", "3000", "--csv", csv.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("3000 random vectors") && out.contains("spare"), "{out}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let rows: Vec<Vec<&str>> = text.lines().skip(1).map(|l| l.split(',').collect()).collect();
    let row =
        |name: &str| rows.iter().find(|r| r[0] == name).unwrap_or_else(|| panic!("{name} missing:\n{text}")).clone();
    // the sum of three products is signed (Sq4.20); the magnitudes before the multipliers reach 2048 (−2048 negated)
    assert_eq!(&row("uut.s4_sum.q")[1..5], ["Sq4_20", "sQ4.20", "25", "1"]);
    assert!(row("uut.s4_sum.q")[5].parse::<i64>().unwrap() < 0);
    assert_eq!(row("uut.s1_nm$0.d")[6], "2048");
    // proven over every input: |n|·|l| ≤ 2048 · 2048 = 2^22. The copy of each product is two registers, its low 12
    // bits (≤ 4095) and its high 11 (≤ 2^22 >> 12 = 1024); the sign comes back in two carry chains, −lo modulo 2^12
    // and ~hi + [lo = 0] modulo 2^13, which intervals see as two unsigned numbers: the sum of three is argued from
    // the proven products (each term ±2^22), not proven, and the listed steps are exactly those
    assert_eq!(&row("uut.s2_p$0.q")[10..12], ["0", "4194304"]);
    assert_eq!(&row("uut.s2b_hi$0.q")[10..12], ["0", "1024"]);
    assert_eq!(row("uut.s4_sum.d")[17], "bound", "{text}");
    let seen = |name: &str| -> (i64, i64) { (row(name)[5].parse().unwrap(), row(name)[6].parse().unwrap()) };
    for (name, bound) in [("uut.s3_t$0.q", 1 << 22), ("uut.s4_sum.q", 3 << 22), ("uut.w_q", (3 << 22) / 1024)] {
        let (lo, hi) = seen(name);
        assert!(-bound <= lo && hi <= bound && lo < 0 && hi > 0, "{name}: seen {lo} .. {hi}");
    }
    let listed = |r: &Vec<&str>| match r[17] {
        "split" => r[0].starts_with("uut.s2b_lo$"),
        "modular" => r[0].starts_with("uut.w_tlo$") || r[0].starts_with("uut.w_thi$"),
        "bound" => r[0] == "uut.w_partial" || r[0] == "uut.s4_sum.d",
        _ => false,
    };
    assert!(rows.iter().all(|r| r[14] == "0" || listed(r)), "{text}");
    assert!(
        out.contains("0 risks (W), 9 wraps on purpose (w), 2 argued (a)") && out.contains("0 of 3008 differ"),
        "{out}"
    );
    for r in &rows {
        let (bits, needed): (usize, usize) = (r[3].parse().unwrap(), r[7].parse().unwrap());
        assert!(needed <= bits, "{r:?}");
    }
    // a unit of 2^18 inputs without state: every input applied, the ranges exact
    let (code, out, err) = bumprtl(&["widths", "gloss"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("every input (262144)") && out.contains("proven by exhaustion"), "{out}");
    // gloss's L − Q ≥ 0 (Q = ⌊L²/1024⌋ ≤ L) is beyond intervals: argued, with every input behind it. Q comes out
    // of two 5-bit registers (its low and high halves), so intervals see it anywhere in 0 .. 1023
    assert!(out.contains("0 risks (W)") && out.contains("  a uut.s5_d.d: computes -1023 .. 1023"), "{out}");
    assert!(
        out.contains("argued: L − Q with Q") && out.contains("every input applied, rtl = model on all 262144"),
        "{out}"
    );
    assert!(!bumprtl(&["widths", "dot3", "--count", "10"]).1.contains("proven by exhaustion"));
    // a --csv that cannot be written is refused before the simulation, in one line, and nothing is left
    let (code, _, err) = bumprtl(&["widths", "dot3", "--csv", "/proc/no-such-folder/w.csv"]);
    assert_ne!(code, 0);
    assert!(err.lines().count() == 1 && err.contains("/proc/no-such-folder/w.csv"), "{err}");
    let (code, _, err) = bumprtl(&["widths", "dot3", "--csv", d.to_str().unwrap()]);
    assert_ne!(code, 0);
    assert!(err.contains("is a folder"), "{err}");
    let (code, _, err) = bumprtl(&["widths", "no_such_unit"]);
    assert_ne!(code, 0);
    assert_eq!(err.lines().count(), 1, "{err}");
}

#[test]
fn widths_budget_sweeps_the_table_sizes_and_marks_the_cheapest_within_it() {
    let d = scratch("widths-budget");
    let (code, out, err) = bumprtl(&["widths", "sincos", "--budget", "1.0", "--dir", d.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    // the rows: setting, mean, max, LUT4, FF, DSP, BRAM, marks
    let rows: Vec<(String, f64, [u64; 4], String)> = out
        .lines()
        .filter(|l| l.contains(" entries of "))
        .filter_map(|l| {
            let (name, rest) = l.split_at(34);
            let f: Vec<&str> = rest.split_whitespace().collect();
            let n = |k: usize| f[k].parse::<u64>().ok();
            Some((name.trim().to_string(), f[1].parse().ok()?, [n(2)?, n(3)?, n(4)?, n(5)?], f[6..].join(" ")))
        })
        .collect();
    assert_eq!(rows.len(), 9, "{out}");
    assert_eq!(
        rows.iter().filter(|r| r.3.contains('*')).map(|r| r.0.as_str()).collect::<Vec<_>>(),
        ["256 entries of 8 bits"],
        "{out}"
    );
    // the cheapest within 1 LSB: its max within the budget, and no row within it cheaper (DSP, BRAM, LUT4, FF)
    let key = |c: &[u64; 4]| (c[2], c[3], c[0], c[1]);
    let chosen: Vec<_> = rows.iter().filter(|r| r.3.contains("cheapest")).collect();
    assert_eq!(chosen.len(), 1, "{out}");
    assert!(chosen[0].1 <= 1.0, "{out}");
    assert!(rows.iter().filter(|r| r.1 <= 1.0).all(|r| key(&r.2) >= key(&chosen[0].2)), "{out}");
    // more entries or bits never cost accuracy: the 1,024-entry 12-bit table is the most accurate
    assert!(rows.iter().all(|r| r.1 >= rows[8].1), "{out}");
    // bad budgets and units without width parameters: one line, non-zero
    for args in [
        &["widths", "sincos", "--budget", "-1"][..],
        &["widths", "sincos", "--budget", "nan"],
        &["widths", "gloss", "--budget", "1"],
        &["widths", "sincos", "--budget", "1", "--dir", "/proc/no-such-folder"],
        &["widths", "sincos", "--budget", "1", "--csv", "w.csv"],
        &["widths", "sincos", "--target", "ecp5-25f"],
    ] {
        let (code, _, err) = bumprtl(args);
        assert_ne!(code, 0, "{args:?}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    }
}

fn scenes() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

#[test]
fn render_runs_a_scene_file_on_every_path_and_the_rtl_equals_the_model() {
    let d = scratch("render");
    let scene = scenes().join("directional.toml");
    let w = synth::tools::missing(&["verilator", "make", "g++"]).is_empty();
    let (code, out, err) =
        bumprtl(&["render", scene.to_str().unwrap(), "--out", d.to_str().unwrap(), "--window", "100,60,6,5"]);
    assert_eq!(code, 0, "{err}");
    // one directional light per surface and C = 0: no light interpolator, no light normaliser, no gloss unit, the
    // texels from the texture unit
    assert!(
        out.contains("pipeline: cart_tex_bilinear_surface_matte")
            && out.contains("units: tex_addr → tex_fetch → bilinear → cart_decode → normalise → dot3 → blend\n"),
        "{out}"
    );
    assert!(out.contains("rust-hdl, window 6×5 at (100, 60)"), "{out}");
    for f in [
        "directional_ideal.png",
        "directional_model.png",
        "directional_shade.png",
        "directional_error_heat.png",
        "directional_window.vcd",
    ] {
        assert!(d.join(f).is_file(), "{f}");
    }
    assert_eq!(d.join("directional_verilator.png").is_file(), w);
    // the page shows the pictures (the heat map with its scale) and links the window's waveform
    let html = std::fs::read_to_string(d.join("directional.html")).unwrap();
    assert!(html.contains("src=\"directional_error_heat.png\"") && html.contains("class=\"bar\""), "{html}");
    assert!(html.contains("href=\"directional_window.gtkw\"") && d.join("directional.md").is_file());
    // the window's VCD holds its 30 pixels' clocks and the pipeline's signals
    let vcd = std::fs::read_to_string(d.join("directional_window.vcd")).unwrap();
    assert!(vcd.contains("$scope") && vcd.contains("valid_out"), "VCD");
    let model = image::open(d.join("directional_model.png")).unwrap().to_rgb8();
    assert_eq!(model.dimensions(), (256, 256));
    if w {
        assert_eq!(model, image::open(d.join("directional_verilator.png")).unwrap().to_rgb8());
    }
    // a window outside the frame, and a malformed one: one line, nothing written
    for (win, says) in [("250,250,8,8", "outside the 256 × 256 frame"), ("1,2,3", "four whole numbers")] {
        let e = scratch(&format!("render-bad-{}", win.len()));
        let (code, _, err) = bumprtl(&[
            "render",
            scene.to_str().unwrap(),
            "--out",
            e.to_str().unwrap(),
            "--window",
            win,
            "--no-verilator",
        ]);
        assert_ne!(code, 0);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(says), "{err}");
        assert!(!e.exists() || std::fs::read_dir(&e).unwrap().next().is_none(), "{win}: files written");
    }
}

#[test]
fn a_bad_scene_is_one_line_at_its_place_and_nothing_is_written() {
    let d = scratch("render-bad-scene");
    std::fs::create_dir_all(&d).unwrap();
    let cases: [(&str, &str, &str); 5] = [
        ("malformed.toml", "size = 64\n[bump\nsource = \"procedural\"\n", "malformed.toml:2:"),
        ("unknown.toml", "size = 64\ncolor = 1\n[bump]\nsource = \"procedural\"\n", "unknown field `color`"),
        ("nan.toml", "size = 64\n[bump]\nsource = \"procedural\"\nrelief = nan\n", "nan.toml:4:10:"),
        (
            "zero-light.toml",
            "size = 64\n[bump]\nsource = \"procedural\"\n[light]\nkind = \"directional\"\ndirection = [0, 0, 0]\n",
            "zero length",
        ),
        ("no-map.toml", "size = 64\n[bump]\nsource = \"height_map\"\npath = \"absent.png\"\n", "absent.png"),
    ];
    for (name, text, says) in cases {
        let scene = d.join(name);
        std::fs::write(&scene, text).unwrap();
        let out = d.join(format!("out-{name}"));
        let (code, _, err) = bumprtl(&["render", scene.to_str().unwrap(), "--out", out.to_str().unwrap()]);
        assert_ne!(code, 0, "{name}");
        assert_eq!(err.lines().count(), 1, "{name}: {err}");
        assert!(err.contains(name) && err.contains(says), "{name}: {err}");
        assert!(!out.exists(), "{name}: the output folder was made");
    }
    let (code, _, err) =
        bumprtl(&["render", d.join("absent.toml").to_str().unwrap(), "--out", d.join("o").to_str().unwrap()]);
    assert_ne!(code, 0);
    assert!(err.contains("absent.toml") && err.contains("cannot read"), "{err}");
}

#[test]
fn hardcases_prints_every_row_passing_and_covers_what_the_seeds_warn_about() {
    let (code, out, err) = bumprtl(&["hardcases"]);
    assert_eq!(code, 0, "{err}{out}");
    let rows: Vec<&str> =
        out.lines().filter(|l| l.starts_with("| ") && !l.starts_with("| unit") && !l.starts_with("| ---")).collect();
    assert!(rows.len() >= 45, "{} rows", rows.len());
    assert!(rows.iter().all(|r| r.ends_with("| pass |")), "{out}");
    for covered in [
        "invalid texel",
        "texel 255",
        "below the horizon",
        "on the horizon",
        "180° apart",
        "120° apart",
        "zero-length vector",
        "R's wrap",
        "steepest step",
        "s_N = 1",
        "most negative",
        "the zero light",
    ] {
        assert!(rows.iter().any(|r| r.contains(covered)), "no row for {covered}");
    }
    assert!(out.contains(&format!("{} hard cases over", rows.len())) && out.contains(" 0 fail"), "{out}");
    // five columns a row: every `|` inside a cell is escaped
    for r in &rows {
        assert_eq!(r.replace("\\|", "").matches('|').count(), 6, "{r}");
    }
}

#[test]
fn render_draws_a_torus_and_a_sphere_on_a_background_and_the_rtl_equals_the_model() {
    let w = synth::tools::missing(&["verilator", "make", "g++"]).is_empty();
    for stem in ["torus", "sphere_polar"] {
        let d = scratch(&format!("render-{stem}"));
        let scene = scenes().join(format!("{stem}.toml"));
        let (code, out, err) = bumprtl(&["render", scene.to_str().unwrap(), "--out", d.to_str().unwrap()]);
        assert_eq!(code, 0, "{err}");
        let covered: usize = out
            .lines()
            .find_map(|l| l.strip_suffix(" pixels of the surface in the 256 × 256 frame"))
            .unwrap()
            .parse()
            .unwrap();
        // a torus or a sphere of radius 1 in a square of side 2.2 covers far from all of the frame
        assert!((15_000..50_000).contains(&covered), "{stem}: {covered}");
        let img = image::open(d.join(format!("{stem}_model.png"))).unwrap().to_rgb8();
        let background = img.pixels().filter(|p| p.0 == [12, 12, 16]).count();
        assert!(background >= 65_536 - covered && img.get_pixel(0, 0).0 == [12, 12, 16], "{stem}: {background}");
        if w {
            assert_eq!(img, image::open(d.join(format!("{stem}_verilator.png"))).unwrap().to_rgb8(), "{stem}");
            assert!(out.contains("Verilator, whole frame"), "{out}");
        }
        // the default window sits on the surface
        assert!(out.lines().any(|l| l.starts_with("rust-hdl, window 8×8") && l.trim_end().ends_with(" 0")), "{out}");
        // a window on the background only: one line, before any simulation, nothing written
        let e = scratch(&format!("render-{stem}-corner"));
        let (code, _, err) =
            bumprtl(&["render", scene.to_str().unwrap(), "--out", e.to_str().unwrap(), "--window", "0,0,8,8"]);
        assert!(code != 0 && err.lines().count() == 1 && err.contains("covers no pixel"), "{err}");
        assert!(std::fs::read_dir(&e).unwrap().next().is_none(), "{stem}: files written");
    }
}

#[test]
fn render_reads_a_users_normal_map_in_either_green_convention() {
    let d = scratch("render-normal-map");
    // a 32 × 32 normal map of one slope, its green high: leaning up the image in OpenGL's convention (towards −v),
    // down it in DirectX's (towards +v)
    image::RgbImage::from_fn(32, 32, |_, _| image::Rgb([128, 220, 200])).save(d.join("lean.png")).unwrap();
    // a light from up the image (−v): bright where the map is read as OpenGL, dark where it is read as DirectX
    for (green, bright) in [("opengl", true), ("directx", false)] {
        let scene = d.join(format!("{green}.toml"));
        std::fs::write(&scene, format!(
            "size = 32\n[bump]\nsource = \"normal_map\"\npath = \"lean.png\"\ngreen = \"{green}\"\n[light]\nkind = \"directional\"\ndirection = [0.0, 0.35, -0.94]\nper = \"surface\"\n[material]\ngloss = 0\nsrc = [255, 255, 255]\ndst = [0, 0, 0]\n"
        )).unwrap();
        let out = d.join(format!("out-{green}"));
        let (code, text, err) =
            bumprtl(&["render", scene.to_str().unwrap(), "--out", out.to_str().unwrap(), "--no-verilator"]);
        assert_eq!(code, 0, "{err}");
        assert!(text.contains("rust-hdl, window") && text.contains("normal angle"), "{text}");
        let img = image::open(out.join(format!("{green}_model.png"))).unwrap().to_luma8();
        let mean = img.pixels().map(|p| p.0[0] as f64).sum::<f64>() / 1024.0;
        assert!(if bright { mean > 180.0 } else { mean < 90.0 }, "{green}: mean {mean}");
    }
}

#[test]
fn synthesis_results_are_cached_under_a_content_hash_and_reused() {
    if !synth::tools::missing(&["yosys"]).is_empty() {
        return; // the test command installs yosys; without it there is nothing to cache
    }
    let d = scratch("synth-cache");
    let cache = d.join("cache");
    let run = || {
        let o = Command::new(env!("CARGO_BIN_EXE_bumprtl"))
            .args(["widths", "sincos", "--budget", "1.0", "--dir", d.join("work").to_str().unwrap()])
            .env("BUMPRTL_SYNTH_CACHE", &cache)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        // the table without its first line (which says how long the sweep took)
        String::from_utf8_lossy(&o.stdout).lines().skip(1).collect::<Vec<_>>().join("\n")
    };
    let first = run();
    // the store's files, beside its `locks/` folder (a lock file for each result made, held while it was made)
    let files = || -> Vec<String> {
        std::fs::read_dir(&cache)
            .unwrap()
            .map(|e| e.unwrap())
            .filter(|e| e.file_name() != "locks")
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect()
    };
    let kept = files();
    // one result per setting of the sweep, each named by a 128-bit hash and its kind
    assert_eq!(kept.len(), sim::units::settings("sincos").count(), "{kept:?}");
    assert!(kept.iter().all(|n| n.len() == 32 + ".cells".len() && n.ends_with(".cells")), "{kept:?}");
    // the second run reads them back: the same table, and no new entry
    assert_eq!(run(), first);
    assert_eq!(files().len(), kept.len());
    // and it reads them rather than synthesising again: an entry changed by hand shows in the table
    std::fs::write(cache.join(&kept[0]), "4242 4343 0 0 0 0").unwrap();
    let third = run();
    assert!(third.contains("4242") && third.contains("4343") && !first.contains("4242"), "{third}");
}

#[test]
fn verilog_exports_the_pipeline_a_scene_is_rendered_by() {
    let d = scratch("verilog-scene");
    let (code, module, err) =
        bumprtl(&["verilog", "--scene", scenes().join("torus.toml").to_str().unwrap(), "--out", "-"]);
    assert_eq!(code, 0, "{err}");
    // the torus with one light per triangle and a little gloss, on the texture unit: cart_tex_bilinear_surface,
    // which holds a gloss unit and no light interpolator
    let (_, unit, _) = bumprtl(&["verilog", "cart_tex_bilinear_surface", "--out", "-"]);
    assert_eq!(module, unit);
    assert!(
        !module.contains("l0_x")
            && !module.contains("$light_norm")
            && module.contains("module cart_tex_bilinear_surface(")
    );
    // into a folder, the scene's pipeline is exported as its unit is: bench, wrapper, waivers, package
    let (code, out, err) = bumprtl(&[
        "verilog",
        "--scene",
        scenes().join("sphere_polar.toml").to_str().unwrap(),
        "--out",
        d.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.lines().next().is_some_and(|l| l.contains(": polar_pipeline (")), "{out}");
    let files = ["polar_pipeline.v", "polar_pipeline_tb.v", "polar_pipeline_axis.v", "polar_pipeline_axis_tb.v"];
    for f in files.into_iter().chain(["polar_pipeline.core", "test_polar_pipeline.py", "Makefile"]) {
        assert!(d.join(f).is_file() && out.lines().any(|l| l.ends_with(f)), "{f}: {out}");
    }
    let (_, unit, _) = bumprtl(&["verilog", "polar_pipeline", "--out", "-"]);
    assert_eq!(std::fs::read_to_string(d.join("polar_pipeline.v")).unwrap(), unit);
    // the demo's torus: on the texture unit (its memory's write port, the bilinear front), lights per vertex (so the
    // light interpolator and its normaliser) and C = 0 (so no gloss unit)
    let (code, text, _) = bumprtl(&["verilog", "--scene", scenes().join("demo.toml").to_str().unwrap(), "--out", "-"]);
    assert_eq!(code, 0);
    assert!(
        text.contains("module cart_tex_bilinear_matte(")
            && text.contains("wdata")
            && text.contains("module cart_tex_bilinear_matte$texture$fetch(")
            && text.contains("l0_x")
            && text.contains("$light_norm"),
        "{}",
        &text[..text.len().min(200)]
    );
    assert!(!text.contains("gloss") && !text.contains("conc"), "the matte pipeline holds no gloss unit and no C port");
    let (code, text, _) =
        bumprtl(&["verilog", "--scene", scenes().join("sphere_polar.toml").to_str().unwrap(), "--out", "-"]);
    assert_eq!(code, 0);
    assert!(text.contains("module polar_pipeline("), "{}", &text[..text.len().min(200)]);
    // a bad scene, and a unit and a scene at once: one line, non-zero, nothing written
    let bad = d.join("bad.toml");
    std::fs::write(&bad, "size = 64\n[bump]\nsource = \"procedural\"\nencoding = \"seedy\"\n").unwrap();
    let e = d.join("out-bad");
    let (code, _, err) = bumprtl(&["verilog", "--scene", bad.to_str().unwrap(), "--out", e.to_str().unwrap()]);
    assert!(code != 0 && err.lines().count() == 1 && err.contains("bad.toml:4:12:"), "{err}");
    assert!(!e.exists());
    let (code, _, err) = bumprtl(&["verilog", "gloss", "--scene", bad.to_str().unwrap(), "--out", "-"]);
    assert!(code != 0 && err.lines().count() == 1, "{err}");
}

/// The report's table with the model's speed (its last column, the one figure a rerun changes) cut off.
fn without_speed(md: &str) -> String {
    md.lines()
        .map(|l| if l.starts_with("| ") { l.rsplitn(3, '|').nth(2).unwrap_or(l) } else { l })
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn a_report_plan_run_through_gnu_parallel_merges_into_the_report_run_in_one_process() {
    if !synth::tools::missing(&["yosys", "parallel"]).is_empty() {
        eprintln!("skipped: yosys or GNU parallel not installed (`bash .ci/run` installs them)");
        return;
    }
    let d = scratch("report-plan");
    let (one, many) = (d.join("one"), d.join("many"));
    let only = ["--only", "quad.cart_surface_nearest", "--no-place", "--budget", "20", "--budget", "0.5"];
    let mut args = vec!["report", "--out", one.to_str().unwrap()];
    args.extend(only);
    let (code, out, err) = bumprtl(&args);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("quad.cart_surface_nearest_hemi_oct") && one.join("pareto.png").is_file(), "{out}");
    // the same report as a page: the plot, then each point a row of its table
    let html = std::fs::read_to_string(one.join("index.html")).unwrap();
    assert!(html.contains("<img src=\"pareto.png\"") && html.contains("<th>quad.cart_surface_nearest_hemi_oct</th>"));
    // the plan: one command per point, the merge step, the Slurm array
    let plan = d.join("plan.txt");
    let mut args = vec!["report", "--out", many.to_str().unwrap(), "--plan", plan.to_str().unwrap()];
    args.extend(only);
    let (code, _, err) = bumprtl(&args);
    assert_eq!(code, 0, "{err}");
    let lines = std::fs::read_to_string(&plan).unwrap();
    assert_eq!(lines.lines().count(), 2, "{lines}");
    assert!(lines.lines().all(|l| l.contains(" report ") && l.contains(" --point ")), "{lines}");
    // each point synthesises with the toolchain the plan was made with
    assert!(lines.lines().all(|l| l.contains(" --toolchain debian")), "{lines}");
    let slurm = std::fs::read_to_string(d.join("plan.txt.slurm")).unwrap();
    assert!(slurm.contains("#SBATCH --array=1-2") && slurm.contains("SLURM_ARRAY_TASK_ID"), "{slurm}");
    let p = Command::new("parallel")
        .args(["-j", "2", "--halt", "now,fail=1"])
        .stdin(std::fs::File::open(&plan).unwrap())
        .output()
        .unwrap();
    assert!(p.status.success(), "{}", String::from_utf8_lossy(&p.stderr));
    let m = Command::new("bash").arg(d.join("plan.txt.merge")).output().unwrap();
    assert!(m.status.success(), "{}", String::from_utf8_lossy(&m.stderr));
    let (a, b) = (
        std::fs::read_to_string(one.join("report.md")).unwrap(),
        std::fs::read_to_string(many.join("report.md")).unwrap(),
    );
    assert_eq!(without_speed(&a), without_speed(&b));
    assert!(
        a.contains("Budget 20 8-bit LSB")
            && a.contains("- quad: quad.cart_surface_nearest")
            && a.contains("no configuration meets it"),
        "{a}"
    );
    // the AXI4-Stream wrapper's row for each pipeline: a FIFO of latency + 2 places in a RAM of the next power of two
    for pipe in ["cart_surface_nearest", "cart_surface_nearest_hemi_oct"] {
        let row = a.lines().find(|l| l.starts_with(&format!("| {pipe} | "))).unwrap_or_else(|| panic!("{a}"));
        let f: Vec<&str> = row.split('|').map(str::trim).collect();
        let (latency, places): (usize, usize) = (f[2].parse().unwrap(), f[3].parse().unwrap());
        let (words, bits) = f[4].split_once(" × ").unwrap();
        let words: usize = words.parse().unwrap();
        assert!(places == latency + 2 && words.is_power_of_two() && words >= places && words < 2 * places, "{row}");
        assert!(bits.parse::<usize>().unwrap() % 8 == 0 && f[5].parse::<u64>().unwrap() > 0, "{row}");
    }
    assert!(many.join("pareto.png").is_file());
    // a point not computed is named when merging, in one line
    std::fs::remove_file(many.join("points").join("quad.cart_surface_nearest.txt")).unwrap();
    let m = Command::new("bash").arg(d.join("plan.txt.merge")).output().unwrap();
    let err = String::from_utf8_lossy(&m.stderr);
    assert!(!m.status.success() && err.lines().count() == 1 && err.contains("quad.cart_surface_nearest"), "{err}");
}

/// `minify`: the four filters of the texture unit against the supersampled ideal on the demo's torus, as a table
/// and pictures; a glossy scene (the filters' pipelines are matte) is refused in one line naming the file, with
/// nothing written.
#[test]
fn minify_measures_every_filter_of_the_texture_unit_and_refuses_a_glossy_scene() {
    let d = scratch("minify");
    let out = d.join("out");
    let (code, text, err) = bumprtl(&["minify", "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    for f in ["nearest", "nearest_mip", "bilinear", "trilinear"] {
        assert!(text.contains(&format!("| {f} | cart_tex_{f}_matte |")), "{text}");
        assert!(image::open(out.join(format!("minify_{f}.png"))).is_ok_and(|i| i.width() == 512), "{f}");
    }
    assert_eq!(
        std::fs::read_to_string(out.join("minify.md")).unwrap().trim_end(),
        text.lines().take_while(|l| !l.starts_with("wrote")).collect::<Vec<_>>().join("\n").trim_end()
    );
    let glossy = d.join("glossy.toml");
    std::fs::write(&glossy, sim::scene_file::DEMO.replace("gloss = 0", "gloss = 40")).unwrap();
    let none = d.join("none");
    let (code, _, err) = bumprtl(&["minify", glossy.to_str().unwrap(), "--out", none.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(err.lines().count() == 1 && err.contains("glossy.toml") && err.contains("gloss is 40"), "{err}");
    assert!(!none.exists());
    // the MIP filters swept over LOD biases; a bias past the LOD unit's Sq3.8 refused in one line, nothing written
    assert!(text.contains("| bias | nearest_mip | trilinear |") && text.contains("| -1.25 | "), "{text}");
    assert!(text.contains("Trilinear's best bias of the sweep is"), "{text}");
    for bad in ["8", "-8.5", "0.001"] {
        let (code, _, err) = bumprtl(&["minify", "--lod-bias", bad, "--out", none.to_str().unwrap()]);
        assert_eq!(code, 1, "{bad}");
        assert!(err.lines().count() == 1 && err.contains(&format!("--lod-bias {bad}")), "{bad}: {err}");
        assert!(!none.exists());
    }
}

/// The demo's page in a real browser (headless Chromium, which the test command installs): every picture loaded, by
/// the page's own check read back from the DOM Chromium dumps; every picture and link a file that exists; and a
/// screenshot, `target/tmp/demo-page.png`, to look at.
#[test]
fn the_demo_page_loads_in_a_browser_with_every_picture_and_every_link_a_file() {
    let browser = ["chromium", "chromium-browser", "google-chrome"]
        .into_iter()
        .find(|b| synth::tools::missing(&[b]).is_empty())
        .expect("no Chromium on the PATH (`bash .ci/run` installs Debian's chromium)");
    let d = scratch("demo-page");
    let o = Command::new(env!("CARGO_BIN_EXE_bumprtl"))
        .args(["demo", "--size", "32", "--out", d.to_str().unwrap()])
        .env("PATH", "")
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let html = std::fs::read_to_string(d.join("index.html")).unwrap();
    let mut n_img = 0;
    for attr in ["src=\"", "href=\""] {
        for (at, _) in html.match_indices(attr) {
            let rest = &html[at + attr.len()..];
            let link = &rest[..rest.find('"').unwrap()];
            if link.starts_with('#') {
                continue;
            }
            assert!(!link.contains(':'), "{link}: the page points off the machine");
            let mut path = String::new();
            let b = link.as_bytes();
            let mut i = 0;
            while i < b.len() {
                if b[i] == b'%' {
                    path.push(u8::from_str_radix(&link[i + 1..i + 3], 16).unwrap() as char);
                    i += 3;
                } else {
                    path.push(b[i] as char);
                    i += 1;
                }
            }
            assert!(d.join(&path).is_file(), "{link} does not resolve to a file");
            n_img += (attr == "src=\"") as usize;
        }
    }
    assert!(n_img >= 40, "{n_img} pictures");
    let url = format!("file://{}", d.join("index.html").display());
    let chrome = |extra: &[&str]| {
        let mut args = vec!["120", browser, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars"];
        args.extend(extra);
        args.push(&url);
        Command::new("timeout").args(&args).output().unwrap()
    };
    let dom = chrome(&["--dump-dom"]);
    let dom = String::from_utf8_lossy(&dom.stdout);
    let want = format!("data-ok=\"yes\">pictures loaded: {n_img} of {n_img}<");
    assert!(dom.contains(&want), "{}", dom.lines().find(|l| l.contains("selfcheck")).unwrap_or("no check in the DOM"));
    let shot = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("demo-page.png");
    let _ = std::fs::remove_file(&shot);
    let out = chrome(&["--window-size=1300,2400", &format!("--screenshot={}", shot.display())]);
    assert!(shot.is_file(), "no screenshot: {}", String::from_utf8_lossy(&out.stderr));
    let img = image::open(&shot).unwrap();
    assert_eq!((img.width(), img.height()), (1300, 2400));
    let _ = std::fs::remove_dir_all(&d);
}

/// Off a terminal each step says one line when it ends (what, how many, how long): with BUMPRTL_PROGRESS=every for
/// every step, however short, so the test needs no step to be slow; a step that fails says nothing, and the error
/// stays the command's one line.
#[test]
fn off_a_terminal_each_step_is_a_line_and_a_failed_step_none() {
    let run = |args: &[&str]| {
        let o =
            Command::new(env!("CARGO_BIN_EXE_bumprtl")).args(args).env("BUMPRTL_PROGRESS", "every").output().unwrap();
        (o.status.code().unwrap_or(-1), String::from_utf8_lossy(&o.stderr).to_string())
    };
    let line = |l: &str| {
        let (what, rest) = l.rsplit_once(": ").unwrap_or(("", ""));
        let (how_many, secs) = rest.rsplit_once(", ").unwrap_or(("", ""));
        !what.is_empty() && !how_many.is_empty() && secs.strip_suffix(" s").is_some_and(|s| s.parse::<f64>().is_ok())
    };
    let (code, err) = run(&["accuracy", "--directions", "1000", "--samples", "1000"]);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 3, "{err}");
    assert!(lines.iter().all(|l| line(l)), "{err}");
    assert!(
        lines[0].starts_with("every unit's model against its ideal: ") && lines[2].contains(": 8 filters, "),
        "{err}"
    );

    let dir = scratch("progress");
    let vcd = dir.join("gloss.vcd");
    let (code, err) = run(&["wave", "gloss", "--count", "10", "--out", vcd.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("gloss: rust-hdl, every signal traced: ") && line(err.trim_end()), "{err}");

    // the trace's write fails inside the step: no step line, one error line
    let (code, err) = run(&["wave", "gloss", "--out", dir.join("no/such/folder.vcd").to_str().unwrap()]);
    assert_ne!(code, 0);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("bumprtl: cannot write "), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
