//! What `bumprtl verilog` and `bumprtl synth` hand a user, run as a user would: the exported self-checking
//! testbench under Icarus and Verilator with nothing but the files the command wrote, and the placement targets.
use std::path::{Path, PathBuf};
use std::process::Command;

fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("exported-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn bumprtl(args: &[&str]) -> (i32, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_bumprtl")).args(args).output().unwrap();
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into(),
        String::from_utf8_lossy(&o.stderr).into(),
    )
}

/// Run a shell command line in `dir`; (exit code, stdout + stderr).
fn sh(dir: &Path, line: &str) -> (i32, String) {
    let o = Command::new("sh").arg("-c").arg(line).current_dir(dir).output().unwrap();
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr),
    )
}

fn rows(unit: &str) -> usize {
    let text = std::fs::read_to_string(format!("{}/vectors/data/{unit}.csv", env!("CARGO_MANIFEST_DIR"))).unwrap();
    text.lines().filter(|l| !l.starts_with('#')).count() - 1
}

/// The rows of a unit's golden file that give an output beat behind its wrapper (a map write gives none), by
/// their index among all the rows.
fn beat_rows(unit: &str) -> Vec<usize> {
    let text = std::fs::read_to_string(format!("{}/vectors/data/{unit}.csv", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let we = lines.next().unwrap().split(',').position(|c| c == "we");
    let rows: Vec<&str> = lines.collect();
    (0..rows.len()).filter(|&k| we.is_none_or(|c| rows[k].split(',').nth(c) == Some("0"))).collect()
}

/// Flip the lowest bit of expected word `k` (counted from 0, past the header comments) of a `.hex` file, a word of
/// any width.
fn flip_expected(path: &Path, k: usize) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let k = lines.iter().position(|l| !l.starts_with("//")).unwrap() + k;
    let (head, last) = lines[k].split_at(lines[k].len() - 1);
    let digit = u32::from_str_radix(last, 16).unwrap() ^ 1;
    lines[k] = format!("{head}{}", char::from_digit(digit, 16).unwrap());
    std::fs::write(path, lines.join("\n") + "\n").unwrap();
}

/// Run a command line in `dir` with the test command's PyPI venv first on the PATH (FuseSoC, cocotb).
fn sh_venv(dir: &Path, line: &str) -> (i32, String) {
    let o = Command::new("sh")
        .arg("-c")
        .arg(line)
        .current_dir(dir)
        .env("PATH", synth::tools::path_with_venv())
        .output()
        .unwrap();
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr),
    )
}

/// The two commands the README gives, as a user types them in the export folder: build the simulation, run it.
fn icarus(u: &str) -> [String; 2] {
    [format!("iverilog -o {u}_tb.vvp {u}_tb.v {u}.v"), format!("vvp -n {u}_tb.vvp")]
}
fn verilator(u: &str) -> [String; 2] {
    [format!("verilator --binary -Wno-fatal --top-module {u}_tb {u}_tb.v {u}.v"), format!("./obj_dir/V{u}_tb")]
}

/// Build and run both simulations, then run them again (the benches read the `.hex` files when they start, so no
/// rebuild) after flipping a bit of expected word `k`: `good(sim, output)` checks the first runs, `bad` the second.
fn both_simulators_pass_then_fail(
    d: &Path,
    sims: [(&str, [String; 2]); 2],
    out_hex: &str,
    k: usize,
    good: impl Fn(&str, i32, &str),
    bad: impl Fn(&str, i32, &str),
) {
    for (sim, [build, run]) in &sims {
        let (code, out) = sh(d, &format!("{build} && {run}"));
        good(sim, code, &out);
    }
    flip_expected(&d.join(out_hex), k);
    for (sim, [_, run]) in &sims {
        let (code, out) = sh(d, run);
        bad(sim, code, &out);
    }
}

#[test]
fn the_exported_testbench_passes_under_icarus_and_verilator_and_fails_on_a_wrong_vector() {
    for u in ["gloss", "normalise", "polar_pipeline"] {
        let d = scratch(u);
        let (code, _, err) = bumprtl(&["verilog", u, "--out", d.to_str().unwrap()]);
        assert_eq!(code, 0, "{err}");
        let n = rows(u);
        // one expected word off by one bit: both simulators must say so and exit non-zero
        both_simulators_pass_then_fail(
            &d,
            [("icarus", icarus(u)), ("verilator", verilator(u))],
            &format!("{u}_out.hex"),
            3,
            |sim, code, out| {
                assert_eq!(code, 0, "{u} under {sim}:\n{out}");
                assert!(out.lines().any(|l| l == format!("{n} passed, 0 failed")), "{u} under {sim}:\n{out}");
            },
            |sim, code, out| {
                assert_ne!(code, 0, "{u} under {sim} passed a wrong vector:\n{out}");
                assert!(out.lines().any(|l| l == format!("{} passed, 1 failed", n - 1)), "{u} under {sim}:\n{out}");
                assert!(out.contains("FAIL: vector 3:"), "{u} under {sim}:\n{out}");
            },
        );
    }
}

/// The AXI4-Stream wrapper's bench, as the export's header gives the commands.
fn axis_icarus(u: &str) -> [String; 2] {
    [format!("iverilog -o {u}_axis_tb.vvp {u}_axis_tb.v {u}_axis.v"), format!("vvp -n {u}_axis_tb.vvp +seed=3")]
}
fn axis_verilator(u: &str) -> [String; 2] {
    [
        format!("verilator --binary -Wno-fatal --top-module {u}_axis_tb {u}_axis_tb.v {u}_axis.v"),
        format!("./obj_dir/V{u}_axis_tb +seed=4"),
    ]
}

#[test]
fn the_exported_axis_wrapper_passes_its_bench_under_icarus_and_verilator_and_fails_on_a_wrong_vector() {
    // random gaps and stalls, a reset part way, the whole file again: every output in order
    // tex_fetch: a unit with a map write port, whose writes go on the second stream and give no beat
    for u in ["gloss", "cart_pipeline", "polar_pipeline", "tex_fetch"] {
        let d = scratch(&format!("axis-{u}"));
        let (code, out, err) = bumprtl(&["verilog", u, "--out", d.to_str().unwrap()]);
        assert_eq!(code, 0, "{err}");
        for f in [format!("{u}_axis.v"), format!("{u}_axis_tb.v")] {
            assert!(out.lines().any(|l| l.ends_with(&f)), "{out}");
        }
        let v = std::fs::read_to_string(d.join(format!("{u}_axis.v"))).unwrap();
        let head = v.lines().find(|l| l.starts_with(&format!("module {u}_axis("))).unwrap_or_else(|| panic!("{v}"));
        let map = if u == "tex_fetch" { "s_axis_map_tdata,s_axis_map_tvalid,s_axis_map_tready," } else { "" };
        assert_eq!(
            head,
            format!(
                "module {u}_axis(aclk,aresetn,s_axis_tdata,s_axis_tvalid,s_axis_tready,{map}m_axis_tdata,m_axis_tvalid,m_axis_tready);"
            )
        );
        let beats = beat_rows(u);
        let (n, k) = (beats.len(), beats[beats.len() - 2]);
        // one expected word off by one bit: the beat after the reset that carries it fails, under both
        both_simulators_pass_then_fail(
            &d,
            [("icarus", axis_icarus(u)), ("verilator", axis_verilator(u))],
            &format!("{u}_out.hex"),
            k,
            |sim, code, out| {
                assert_eq!(code, 0, "{u}_axis under {sim}:\n{out}");
                assert!(out.lines().any(|l| l == format!("{n} passed, 0 failed")), "{u}_axis under {sim}:\n{out}");
            },
            |sim, code, out| {
                assert_ne!(code, 0, "{u}_axis under {sim} passed a wrong vector:\n{out}");
                let counts = format!("{} passed, 1 failed", n - 1);
                assert!(out.lines().any(|l| l == counts), "{u}_axis under {sim}:\n{out}");
                assert!(out.contains(&format!("FAIL: output {k}:")), "{u}_axis under {sim}:\n{out}");
            },
        );
    }
}

#[test]
fn a_part_too_small_is_named_with_its_resource_and_a_placed_design_reports_its_fmax() {
    let d = scratch("targets");
    let dir = d.to_str().unwrap();
    let (code, _, err) = bumprtl(&["synth", "cart_pipeline", "--target", "ecp5-25f", "--dir", dir]);
    assert_eq!(code, 1);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("does not fit the ECP5 LFE5U-25F") && err.contains("MULT18X18D") && err.contains("has 28"),
        "{err}"
    );
    let (code, out, err) = bumprtl(&["synth", "cart_pipeline", "--target", "up5k", "--dir", dir]);
    assert_eq!(code, 1, "{out}");
    assert_eq!(err.lines().count(), 1, "{err}");
    // more products than the UP5K's 8 SB_MAC16: the smallest go into logic, and then the logic overflows
    assert!(err.contains("SB_LUT4") && err.contains("has 5280") && err.contains("products built in logic"), "{err}");
    // placing cart_pipeline itself on the 45F takes nextpnr minutes (`report` does it); a small unit shows the same,
    // at one seed (the median over seeds is `synth_places_at_several_seeds_each_cached_and_reports_their_median`'s)
    let (code, out, err) = bumprtl(&["synth", "gloss", "--target", "ecp5-45f", "--seeds", "1", "--dir", dir]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("gloss on the ECP5 LFE5U-45F"), "{out}");
    assert!(!out.contains("does not place"), "{out}");
    // a placed design reports an fmax figure (its value goes in the report, never in a test)
    let fmax = out.lines().find_map(|l| l.trim().strip_prefix("fmax")).and_then(|r| r.split_whitespace().next());
    assert!(fmax.is_some_and(|x| x.parse::<f64>().is_ok()), "no fmax figure in\n{out}");
    // gloss's three products placed with their operand and product flip-flops in the MULT18X18D registers, or,
    // asked, as yosys left them
    assert!(out.contains("6 multiplier operands and 3 products through the MULT18X18D registers"), "{out}");
    let (code, out, err) =
        bumprtl(&["synth", "gloss", "--target", "ecp5-45f", "--seeds", "1", "--fabric-registers", "--dir", dir]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("every one in the fabric") && !out.contains("MULT18X18D registers"), "{out}");
    let (code, _, err) = bumprtl(&["synth", "cart_pipeline", "--target", "ecp5-12f", "--dir", dir]);
    assert_eq!(code, 1);
    assert!(err.contains("unknown target `ecp5-12f`") && err.contains("ecp5-45f"), "{err}");
}

/// `synth`'s fmax line, its placements line ("the median of N placements …, slowest A, fastest B MHz") and the seed
/// of its critical path.
fn fmax_figures(out: &str) -> (f64, u32, f64, f64, u32) {
    let lines: Vec<&str> = out.lines().collect();
    let k =
        lines.iter().position(|l| l.trim_start().starts_with("fmax")).unwrap_or_else(|| panic!("no fmax in\n{out}"));
    let num = |t: &str| t.trim_end_matches([',', ' ']).parse::<f64>().unwrap_or_else(|_| panic!("{t}: {out}"));
    let median = num(lines[k].split_whitespace().nth(1).unwrap());
    let words: Vec<&str> = lines[k + 1].split_whitespace().collect();
    let after = |w: &str| words[words.iter().position(|x| *x == w).unwrap_or_else(|| panic!("{w}: {out}")) + 1];
    let seed = out.split("critical path at seed ").nth(1).and_then(|r| r.split(':').next()).unwrap();
    (median, after("of").parse().unwrap(), num(after("slowest")), num(after("fastest")), seed.parse().unwrap())
}

#[test]
fn synth_places_at_several_seeds_each_cached_and_reports_their_median() {
    let d = scratch("seeds");
    let cache = d.join("cache");
    let run_limited = |seeds: &str, limit: &str| {
        let o = Command::new(env!("CARGO_BIN_EXE_bumprtl"))
            .args(["synth", "gloss", "--target", "up5k", "--seeds", seeds, "--dir", d.join("work").to_str().unwrap()])
            .env("BUMPRTL_SYNTH_CACHE", &cache)
            .env("BUMPRTL_PLACE_LIMIT", limit)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let run = |seeds: &str| run_limited(seeds, "900");
    let placements = || {
        let mut v: Vec<String> = std::fs::read_dir(&cache)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.ends_with(".placement"))
            .collect();
        v.sort();
        v
    };
    let out = run("3");
    let (median, n, lo, hi, seed) = fmax_figures(&out);
    assert!(n == 3 && lo <= median && median <= hi && (1..=3).contains(&seed), "{out}");
    // one cache entry a placement, one nextpnr log a seed
    let three = placements();
    assert_eq!(three.len(), 3, "{three:?}");
    assert!((1..=3).all(|s| d.join("work/gloss").join(format!("nextpnr.seed{s}.log")).is_file()));
    // five seeds place only the two new ones: the three kept entries are read back, unchanged
    let kept: Vec<String> = three.iter().map(|n| std::fs::read_to_string(cache.join(n)).unwrap()).collect();
    std::fs::remove_file(d.join("work/gloss/nextpnr.seed1.log")).unwrap();
    let out = run("5");
    let (median, n, lo, hi, _) = fmax_figures(&out);
    assert!(n == 5 && lo <= median && median <= hi, "{out}");
    assert_eq!(placements().len(), 5);
    assert!(!d.join("work/gloss/nextpnr.seed1.log").exists(), "seed 1 was placed again");
    let again: Vec<String> = three.iter().map(|n| std::fs::read_to_string(cache.join(n)).unwrap()).collect();
    assert_eq!(again, kept);
    // a placement stopped at the time limit is named with its seed, the median is of the others; it is cached with
    // its limit, read back under the same limit and placed again under a longer one
    let out = run_limited("6", "0");
    let (m6, n, ..) = fmax_figures(&out);
    assert_eq!((m6, n), (median, 5), "{out}");
    assert!(out.contains("it did not place at seed 6: nextpnr had not finished after 0 s"), "{out}");
    assert_eq!(placements().len(), 6);
    let log6 = d.join("work/gloss/nextpnr.seed6.log");
    std::fs::remove_file(&log6).unwrap();
    let again = run_limited("6", "0");
    assert!(again.contains("it did not place at seed 6") && !log6.exists(), "{again}");
    let placed = run("6");
    let (_, n, ..) = fmax_figures(&placed);
    assert!(n == 6 && !placed.contains("did not place") && log6.exists(), "{placed}");
    // a limit that is not a number of seconds is refused in one line
    let o = Command::new(env!("CARGO_BIN_EXE_bumprtl"))
        .args(["synth", "gloss", "--target", "up5k", "--seeds", "7", "--dir", d.join("work").to_str().unwrap()])
        .env("BUMPRTL_SYNTH_CACHE", &cache)
        .env("BUMPRTL_PLACE_LIMIT", "15m")
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && err.lines().count() == 1 && err.contains("BUMPRTL_PLACE_LIMIT=15m"), "{err}");
    // the figures are the cached placements': seed 1's entry changed by hand is what one placement reports
    let first = three.iter().find(|n| std::fs::read_to_string(cache.join(n)).unwrap().contains("\nseed=1\n")).unwrap();
    let text = std::fs::read_to_string(cache.join(first)).unwrap();
    let fmax = text.lines().find(|l| l.starts_with("fmax_mhz=")).unwrap();
    std::fs::write(cache.join(first), text.replace(fmax, "fmax_mhz=999.5")).unwrap();
    let one = run("1");
    assert!(one.contains("999.5 MHz") && one.contains("one placement (nextpnr seed 1)"), "{one}");
}

/// Either toolchain synthesises and places: each says which tools made its figures, reads its own yosys's cell
/// table, and keeps its placement apart from the other's in the cache (the tools' versions are in the key).
#[test]
fn synth_runs_on_either_toolchain_and_keeps_their_results_apart() {
    let d = scratch("toolchains");
    let cache = d.join("cache");
    let run = |tc: &str| {
        let o = Command::new(env!("CARGO_BIN_EXE_bumprtl"))
            .args(["synth", "gloss", "--target", "up5k", "--seeds", "1", "--toolchain", tc])
            .args(["--dir", d.join(tc).to_str().unwrap()])
            .env("BUMPRTL_SYNTH_CACHE", &cache)
            .output()
            .unwrap();
        assert!(o.status.success(), "{tc}: {}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let count = |out: &str, cell: &str| -> u64 {
        let line = out.lines().find(|l| l.trim_start().starts_with(cell)).unwrap_or_else(|| panic!("{cell}: {out}"));
        line.split_whitespace().nth(1).unwrap().parse().unwrap()
    };
    let placements = || {
        std::fs::read_dir(&cache)
            .unwrap()
            .filter(|e| e.as_ref().unwrap().file_name().to_string_lossy().ends_with(".placement"))
            .count()
    };
    let debian = run("debian");
    assert!(debian.contains("Yosys 0.") && debian.contains("(--toolchain debian)"), "{debian}");
    assert_eq!(placements(), 1);
    let pypi = run("pypi");
    assert!(pypi.contains("Yosys 0.70") && pypi.contains("(--toolchain pypi)"), "{pypi}");
    assert_eq!(placements(), 2, "the two toolchains' placements are two entries");
    for out in [&debian, &pypi] {
        let (lut, mac) = (count(out, "SB_LUT4"), count(out, "SB_MAC16"));
        let fmax: f64 = out
            .lines()
            .find(|l| l.trim_start().starts_with("fmax"))
            .unwrap()
            .split_whitespace()
            .nth(1)
            .unwrap()
            .parse()
            .unwrap();
        assert!(lut > 20 && (1..=8).contains(&mac) && fmax > 20.0, "{out}");
    }
    let (code, _, err) = bumprtl(&["synth", "gloss", "--toolchain", "vivado"]);
    assert!(code == 2 && err.lines().count() == 1 && err.contains("`debian`") && err.contains("`pypi`"), "{err}");
}

#[test]
fn the_default_target_is_the_up5k_for_a_unit_that_fits_and_says_why() {
    let d = scratch("default");
    let (code, out, err) = bumprtl(&["synth", "gloss", "--dir", d.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("gloss on the iCE40 UP5K") && out.contains("it fits the iCE40 UP5K"), "{out}");
}

#[test]
fn a_missing_place_and_route_tool_is_an_error_not_a_design_that_does_not_place() {
    let d = scratch("missing");
    let o = Command::new(env!("CARGO_BIN_EXE_bumprtl"))
        .args(["synth", "gloss", "--target", "ecp5-25f", "--dir", d.to_str().unwrap()])
        .env("BUMPRTL_NEXTPNR_ECP5", d.join("no-such-nextpnr"))
        .output()
        .unwrap();
    let (out, err) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert_eq!(o.status.code(), Some(1), "{out}\n{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("cannot run") && err.contains("no-such-nextpnr"), "{err}");
    assert!(!out.contains("does not place"), "{out}");
}

/// Two units exported into one folder, as a user collects IP: the files each adds beside the other's.
fn two_units_in_one_folder(name: &str) -> PathBuf {
    let d = scratch(name);
    for u in ["gloss", "cart_pipeline"] {
        let (code, out, err) = bumprtl(&["verilog", u, "--out", d.to_str().unwrap()]);
        assert_eq!(code, 0, "{err}");
        for f in [format!("{u}.vlt"), format!("{u}.core"), format!("{u}_io.v"), format!("test_{u}.py")] {
            assert!(out.lines().any(|l| l.ends_with(&f)) && d.join(&f).is_file(), "{f}: {out}");
        }
    }
    d
}

#[test]
fn the_exported_cores_pass_their_sim_and_lint_targets_under_fusesoc_and_sim_fails_on_a_wrong_vector() {
    let d = two_units_in_one_folder("fusesoc");
    for u in ["gloss", "cart_pipeline"] {
        let n = rows(u);
        for target in ["sim", "sim_unit"] {
            let (code, out) = sh_venv(&d, &format!("fusesoc --cores-root . run --target {target} bumprtl:unit:{u}"));
            assert_eq!(code, 0, "{u} --target {target}:\n{out}");
            assert!(out.lines().any(|l| l == format!("{n} passed, 0 failed")), "{u} --target {target}:\n{out}");
        }
    }
    // Verilator -Wall with the core's waivers: silent, so the flow's warnings-as-errors passes
    let (code, out) = sh_venv(&d, "fusesoc --cores-root . run --target lint bumprtl:unit:gloss");
    assert_eq!(code, 0, "lint:\n{out}");
    assert!(!out.contains("%Warning"), "lint:\n{out}");
    flip_expected(&d.join("gloss_out.hex"), rows("gloss") - 2);
    let (code, out) = sh_venv(&d, "fusesoc --cores-root . run --target sim bumprtl:unit:gloss");
    assert_ne!(code, 0, "fusesoc passed a wrong vector:\n{out}");
    assert!(out.lines().any(|l| l == format!("{} passed, 1 failed", rows("gloss") - 1)), "{out}");
}

#[test]
fn the_exported_cocotb_tests_pass_under_icarus_and_fail_on_a_wrong_word() {
    let d = two_units_in_one_folder("cocotb");
    // and a unit with a map write port: its writes on the second stream, no beat for them
    let (code, _, err) = bumprtl(&["verilog", "tex_fetch", "--out", d.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    for u in ["gloss", "cart_pipeline", "tex_fetch"] {
        let n = beat_rows(u).len();
        let (code, out) = sh_venv(&d, &format!("make UNIT={u}"));
        assert_eq!(code, 0, "cocotb {u}:\n{out}");
        assert!(out.contains("TESTS=2 PASS=2 FAIL=0"), "cocotb {u}:\n{out}");
        // both tests, the plain stream and the one with a reset part way, checked every vector
        assert_eq!(out.matches(&format!("{n} passed, 0 failed ({u}_axis, seed 1)")).count(), 2, "{out}");
    }
    flip_expected(&d.join("cart_pipeline_out.hex"), 7);
    let (code, out) = sh_venv(&d, "make UNIT=cart_pipeline BUMPRTL_SEED=5");
    assert_ne!(code, 0, "cocotb passed a wrong word:\n{out}");
    assert!(out.contains("TESTS=2 PASS=0 FAIL=2"), "{out}");
    assert!(out.contains("vector 7: got"), "{out}");
}

/// Whether the unit's exported bench passes on a netlist `v` (with the ECP5 cell library) under Icarus, as
/// `N passed, 0 failed`; (passed, the simulator's output).
fn netlist_passes(d: &Path, u: &str, v: &str, n: usize) -> (bool, String) {
    let (code, out) = sh(d, &format!("iverilog -g2012 -o {v}.vvp {u}_tb.v {v} ecp5_cells.v && vvp -n {v}.vvp"));
    (code == 0 && out.lines().any(|l| l == format!("{n} passed, 0 failed")), out)
}

/// A block RAM delay line whose word yosys maps to the DP16KD's 36-bit (pseudo dual-port) mode, where one read
/// comes out on both ports' pins: `regpack` moves the flip-flops behind all of them into both ports' output
/// registers, and the placed netlist still delays every word by N clocks, as yosys's own does; with both registers
/// switched back off (their flip-flops still gone) it does not. The line is `RamDelay` as the pipelines hold it
/// (the trilinear ones' blend colours and light words are such lines): 48 bits, 128 words, 100 clocks.
#[test]
fn a_36_bit_block_ram_read_packed_into_both_ports_output_registers_still_delays_every_word_by_n_clocks() {
    const N: usize = 100;
    let d = scratch("ram-delay-36");
    let e = ::synth::export::named(rtl::prim::ram_delay::RamDelay::<48, 7, N>::default(), "ram_delay");
    // exported as every unit is: its memory marked, so that yosys puts no collision bypass behind the read
    assert!(e.text.contains("(* no_rw_check *) reg[47:0] mem[127:0];"), "{}", e.text);
    e.write(&d).unwrap();
    let p = ::synth::regpack::netlists(&d, "ram_delay", "ram_delay.v").unwrap();
    let both = "\"REGMODE_A\":\"OUTREG\",\"REGMODE_B\":\"OUTREG\"";
    let packed = std::fs::read_to_string(d.join("ram_delay.packed.json")).unwrap();
    // 48 bits: two DP16KD in the 36-bit mode, each read through both ports' output registers, 48 flip-flops gone
    assert_eq!((p.bram_outputs, p.ffs_removed, packed.matches(both).count()), (2, 48, 2), "{p}");
    // the bench: a random word a clock; after edge t the line gives the word taken at edge t − (N − 1)
    let bench = format!(
        "module ram_delay_tb;
  reg clock = 0;
  reg [47:0] d = 0;
  wire [47:0] q;
  reg [47:0] taken [0:1999];
  integer t, passed = 0, failed = 0;
  ram_delay dut(.clock(clock), .d(d), .q(q));
  initial begin
    for (t = 0; t < 2000; t = t + 1) begin
      d = {{$random, $random}};
      taken[t] = d;
      #1 clock = 1;
      #1 clock = 0;
      if (t >= {n1}) begin
        if (q === taken[t - {n1}]) passed = passed + 1;
        else failed = failed + 1;
      end
    end
    $display(\"%0d passed, %0d failed\", passed, failed);
    $finish;
  end
endmodule
",
        n1 = N - 1
    );
    std::fs::write(d.join("ram_delay_tb.v"), bench).unwrap();
    let runs =
        |v: &str| sh(&d, &format!("iverilog -g2012 -o {v}.vvp ram_delay_tb.v {v} ecp5_cells.v && vvp -n {v}.vvp"));
    let want = format!("{} passed, 0 failed", 2000 - (N - 1));
    for v in ["ram_delay.ecp5.v", "ram_delay.packed.v"] {
        let (code, out) = runs(v);
        assert!(code == 0 && out.lines().any(|l| l == want), "{v}:\n{out}");
    }
    let wrong = packed.replacen(both, "\"REGMODE_A\":\"NOREG\",\"REGMODE_B\":\"NOREG\"", 1);
    std::fs::write(d.join("wrong.json"), wrong).unwrap();
    ::synth::tools::netlist_verilog(&d, "wrong.json", "wrong.v").unwrap();
    let (_, out) = runs("wrong.v");
    assert!(!out.lines().any(|l| l == want) && out.contains(" passed, "), "a wrong packing passed:\n{out}");
}

/// The ECP5 netlist that is placed (its pipeline registers moved into the MULT18X18D and DP16KD registers by
/// `regpack`) computes the golden vectors, as yosys's own netlist does; a packing that loses a register does not
/// (one product's or one block RAM's output register switched back off, its fabric flip-flops gone).
#[test]
fn the_ecp5_netlist_with_its_registers_in_the_blocks_passes_the_golden_vectors_and_a_wrong_packing_fails() {
    // (unit, products packed at the output, block RAM reads packed): gloss, three products; polar, seven (the
    // blend's three among them), and the power unit's two tables (initial contents) behind their output flip-flops;
    // tex_fetch, the map memory's four
    // banks (32 DP16KD, written and read) behind theirs; normalise, six products and its seed table, whose word is
    // registered once behind the DP16KD (`s6c_r`) before its copies per product (`mop_r`)
    for (u, products, brams) in [("gloss", 3, 0), ("polar_pipeline", 7, 2), ("tex_fetch", 0, 32), ("normalise", 6, 1)] {
        let d = scratch(&format!("{u}-ecp5"));
        let (code, _, err) = bumprtl(&["verilog", u, "--out", d.to_str().unwrap()]);
        assert_eq!(code, 0, "{err}");
        let p = synth::regpack::netlists(&d, u, &format!("{u}.v")).unwrap();
        assert_eq!((p.mult_outputs, p.bram_outputs), (products, brams), "{u}: {p}");
        if u == "normalise" {
            // the copies are the products' input registers, beside the squarers' operands: every operand of the six
            // (a copy read straight from the block RAM would stay in the fabric, and so would the read's register)
            assert_eq!(p.mult_inputs, 12, "{u}: {p}");
        }
        let n = rows(u);
        for v in [format!("{u}.ecp5.v"), format!("{u}.packed.v")] {
            let (ok, out) = netlist_passes(&d, u, &v, n);
            assert!(ok, "{u}, {v}:\n{out}");
        }
        // a register the pass moved into a block, switched back off, its fabric flip-flops still gone
        let (from, to) = if products > 0 {
            ("\"REG_OUTPUT_CLK\":\"CLK0\"", "\"REG_OUTPUT_CLK\":\"NONE\"")
        } else {
            ("\"REGMODE_A\":\"OUTREG\"", "\"REGMODE_A\":\"NOREG\"")
        };
        let base = std::fs::read_to_string(d.join(format!("{u}.packed.json"))).unwrap();
        assert!(base.contains(from), "{u}: no {from} to change");
        let wrong = base.replacen(from, to, 1);
        std::fs::write(d.join("wrong.json"), wrong).unwrap();
        synth::tools::netlist_verilog(&d, "wrong.json", "wrong.v").unwrap();
        let (ok, out) = netlist_passes(&d, u, "wrong.v", n);
        assert!(!ok, "{u}: a wrong packing passed:\n{out}");
    }
}

/// The iCE40 flow's products in logic, each split across the register that takes it (`softsplit`), still compute
/// every golden vector: the unit prepared as the flow prepares it, every product split, run by the unit's exported
/// bench; a split whose high half enters the sum one place too low does not.
#[test]
fn products_split_across_their_registers_pass_the_golden_vectors_and_a_wrong_split_fails() {
    // blend: three 8 × 8 products, each into its stage-2 register; normalise: three squares and three products,
    // each into a register whose only reader is its copy
    for (u, split) in [("blend", 3), ("normalise", 6)] {
        let d = scratch(&format!("{u}-softsplit"));
        let (code, _, err) = bumprtl(&["verilog", u, "--out", d.to_str().unwrap()]);
        assert_eq!(code, 0, "{err}");
        assert_eq!(synth::softsplit::netlists(&d, u, &format!("{u}.v")).unwrap(), split, "{u}");
        let n = rows(u);
        let passes = |v: &str| {
            let (code, out) = sh(&d, &format!("iverilog -g2012 -o {v}.vvp {u}_tb.v {v} && vvp -n {v}.vvp"));
            (code == 0 && out.lines().any(|l| l == format!("{n} passed, 0 failed")), out)
        };
        for v in [format!("{u}.prepared.v"), format!("{u}.split.v")] {
            let (ok, out) = passes(&v);
            assert!(ok, "{u}, {v}:\n{out}");
        }
        // the first split's sum takes its high half one place lower: its B loses a low "0" and gains a high one
        let text = std::fs::read_to_string(d.join(format!("{u}.split.json"))).unwrap();
        let sum = text.find("\"$bumprtl$softsplit$0$s1\":").unwrap_or_else(|| panic!("{u}: no split"));
        let b = sum + text[sum..].find("\"B\":[\"0\",").expect("the high half shifted up");
        let end = b + text[b..].find(']').unwrap();
        let wrong = format!("{}\"B\":[{},\"0\"]{}", &text[..b], &text[b + 9..end], &text[end + 1..]);
        std::fs::write(d.join("wrong.json"), wrong).unwrap();
        synth::tools::netlist_verilog(&d, "wrong.json", "wrong.v").unwrap();
        let (ok, out) = passes("wrong.v");
        assert!(!ok && out.contains(" passed, "), "{u}: a wrong split passed:\n{out}");
    }
}
