//! Every unit behind its AXI4-Stream wrapper, from the table of units: each exported wrapper lints clean with its
//! unit's waivers (one of each family also read again with the waiver file written for it, silent), and one
//! pipeline of each family takes 100,000 random vectors through the exported wrapper and its bench under Verilator
//! (4,000 under Icarus, `BUMPRTL_ICARUS_VECTORS=100000` for all), under random gaps, stalls and a reset; the
//! two-clock unit under Verilator. The wrapper's rules in rust-hdl: `testbench/tests/axis.rs`.

use testbench::axis::FAMILIES;
use testbench::golden;

#[test]
fn every_unit_behind_its_wrapper_lints_clean() {
    // the unit's own waivers hold inside the wrapper: its module keeps its signal names under the `uut` prefix
    let mut bad = vec![];
    for u in sim::units::UNITS {
        let dir = testbench::work_dir("lint-axis", u.name());
        let module = u.axis.module();
        let file = format!("{module}.v");
        std::fs::create_dir_all(&dir).unwrap();
        synth::export::write_atomic(&dir.join(&file), u.axis.verilog().as_bytes()).unwrap();
        let (vlt, design) = synth::lint::write_waivers(&dir, u.name(), &[(&file, &module)], &u.waivers())
            .unwrap_or_else(|e| panic!("{e}"));
        bad.extend(design);
        // and with the waiver file it writes, as the exported `<unit>.vlt` carries it: silent. Read again for one
        // wrapper of each family: each unit's own `verilog_lints` reads its file again with its waivers, and the
        // wrapper's file is written by the same code
        if FAMILIES.iter().any(|f| f.0 == u.name()) {
            let again = synth::lint::warnings(&dir, &[&vlt, std::path::Path::new(&file)], &module).unwrap();
            bad.extend(again.into_iter().map(|w| format!("with the waivers: {w}")));
        }
    }
    assert!(bad.is_empty(), "design warnings:\n{}", bad.join("\n"));
}

/// `inputs` through the exported `<unit>_axis.v` and its bench under `sim` (`build`, `run`: command lines of the
/// wrapper's module name), the expected outputs the model's: random gaps and stalls, every output in order.
fn stream(
    name: &str,
    inputs: &[Vec<i64>],
    source: &str,
    sim: &str,
    build: &dyn Fn(&str) -> String,
    run: &dyn Fn(&str) -> String,
) {
    let u = sim::units::find(name).unwrap_or_else(|| panic!("{name}"));
    let m = u.model;
    let ins: Vec<Vec<u64>> = inputs.iter().map(|v| vectors::unit::to_patterns(v, m.inputs)).collect();
    let outs: Vec<Vec<u64>> = m.run(inputs).iter().map(|v| vectors::unit::to_patterns(v, m.outputs)).collect();
    let dir = testbench::work_dir(&format!("axis-{sim}"), name);
    let _ = std::fs::remove_dir_all(&dir);
    u.rtl.selfcheck(&dir, &ins, &outs, source).unwrap_or_else(|e| panic!("{e}"));
    u.axis.selfcheck(&dir, ins.len(), source).unwrap_or_else(|e| panic!("{e}"));
    let a = u.axis.module();
    for (k, line) in [build(&a), run(&a)].into_iter().enumerate() {
        let o = std::process::Command::new("sh").arg("-c").arg(&line).current_dir(&dir).output().unwrap();
        let text = String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr);
        assert!(o.status.success(), "{name}: {line}:\n{}", text.lines().rev().take(12).collect::<Vec<_>>().join("\n"));
        if k == 1 {
            let n = ins.iter().filter(|row| u.axis.emits(row)).count();
            assert!(text.lines().any(|l| l == format!("{n} passed, 0 failed")), "{name} under {sim}:\n{text}");
        }
    }
}

/// `n` of the model's random vectors (edges weighted in) through `stream`. The reset comes before the first beat
/// (`+cut=1`, which `run` passes): a random stream reads tables and maps before it writes them, and a reset clears
/// the wrapper's beats but not the unit's memories, so a stream sent again after a cut would read what the first
/// part wrote (the cut in the middle is tested on the golden streams, which write first).
fn random_stream(
    name: &str,
    seed: u64,
    n: usize,
    sim: &str,
    build: &dyn Fn(&str) -> String,
    run: &dyn Fn(&str) -> String,
) {
    use rand::SeedableRng;
    let m = sim::units::find(name).unwrap_or_else(|| panic!("{name}")).model;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let inputs: Vec<Vec<i64>> = (0..n).map(|_| (m.random)(&mut rng)).collect();
    stream(name, &inputs, &format!("{n} random vectors, seed {seed}"), sim, build, run);
}

#[test]
fn random_streams_through_each_familys_wrapper_under_back_pressure_in_verilator() {
    for (name, seed) in FAMILIES {
        random_stream(
            name,
            seed,
            100_000,
            "verilator",
            &|a| format!("verilator --binary -O3 -Wno-fatal --top-module {a}_tb {a}_tb.v {a}.v"),
            &|a| format!("./obj_dir/V{a}_tb +seed={seed} +cut=1"),
        );
    }
}

/// Icarus runs the same streams about a thousand clocks a second on these pipelines (the golden cart_pipeline
/// stream: 2.0 s), so 100,000 vectors a pipeline is minutes each: the suite sends 4,000, and
/// `BUMPRTL_ICARUS_VECTORS=100000` sends the full streams the Verilator test sends.
///
/// The texture unit's random stream is not among them: it reads texels it never wrote, which the model reads as 0
/// (as the FPGA's block RAM powers up) and two-state Verilator zeroes, but which four-state Icarus reads as x, since
/// the map's banks have no initial contents (measured with the earlier two-port banks: 207 of 4,000 outputs x). Its
/// golden stream, which loads the map before it reads it, goes through Icarus instead, the reset in its middle.
#[test]
fn random_streams_through_each_familys_wrapper_under_back_pressure_in_icarus() {
    let n = std::env::var("BUMPRTL_ICARUS_VECTORS").ok().and_then(|v| v.parse().ok()).unwrap_or(4_000);
    let build = |a: &str| format!("iverilog -o {a}_tb.vvp {a}_tb.v {a}.v");
    for (name, seed) in FAMILIES.into_iter().filter(|(name, _)| !name.starts_with("cart_tex")) {
        random_stream(name, seed, n, "icarus", &build, &|a| format!("vvp -n {a}_tb.vvp +seed={seed} +cut=1"));
    }
    let m = &vectors::cart_tex::trilinear_matte::MODEL;
    let (inputs, _) = golden(m);
    let source = format!("vectors/data/{}.csv", m.name);
    stream(m.name, &inputs, &source, "icarus", &build, &|a| format!("vvp -n {a}_tb.vvp +seed=26"));
}

/// The unit taking two clocks a vector, behind the exported wrapper and its bench under Verilator: every beat the
/// model's (its pace in rust-hdl: `testbench/tests/axis.rs`).
#[test]
fn a_two_clock_unit_behind_the_exported_wrapper_under_verilator() {
    let m = &vectors::cart_tex::trilinear_two_pass_matte::MODEL;
    let (inputs, _) = golden(m);
    let source = format!("vectors/data/{}.csv", m.name);
    stream(
        m.name,
        &inputs,
        &source,
        "verilator",
        &|a| format!("verilator --binary -O3 -Wno-fatal --top-module {a}_tb {a}_tb.v {a}.v"),
        &|a| format!("./obj_dir/V{a}_tb +seed=34"),
    );
}
