//! This is the bumprtl testbench crate: one driver, one monitor and one checker for every streaming unit, run
//! against rust-hdl's simulation and against the exported Verilog under Verilator and Icarus.
//!
//! - driver: `slots` turns model vectors into clock slots, with bubbles (idle cycles) or back to back;
//! - monitor: `rtl::stream::Collected` (rust-hdl) or the external harness's output: what left the unit, and when;
//! - checker: `check` compares every output with `exact()` and every latency with the unit's stated one.

pub mod axis;

use rand::{Rng, SeedableRng};
use rtl::stream::{Collected, Runner};
use rtl::StreamUnit;
use std::path::{Path, PathBuf};
use synth::cosim::{self, Compile, Simulator};
use vectors::fixed::from_pattern;
use vectors::UnitModel;

/// How the driver spaces the vectors.
#[derive(Clone, Copy, Debug)]
pub enum Bubbles {
    /// one vector every clock
    BackToBack,
    /// an idle cycle before a vector with probability 1/n, and occasional bursts of idles
    Random { one_in: u32, seed: u64 },
}

/// The driver: model vectors → clock slots of bit patterns, each vector followed by `interval − 1` empty slots for
/// a unit that takes `interval` clocks a vector (`StreamUnit::INTERVAL`), the bubbles on top of those.
pub fn slots(model: &UnitModel, interval: usize, inputs: &[Vec<i64>], bubbles: Bubbles) -> Vec<Option<Vec<u64>>> {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(match bubbles {
        Bubbles::Random { seed, .. } => seed,
        Bubbles::BackToBack => 0,
    });
    let mut s = Vec::with_capacity(inputs.len() * 5 / 4);
    for v in inputs {
        if let Bubbles::Random { one_in, .. } = bubbles {
            if rng.gen_range(0..one_in) == 0 {
                for _ in 0..rng.gen_range(1..4) {
                    s.push(None);
                }
            }
        }
        s.push(Some(vectors::unit::to_patterns(v, model.inputs)));
        s.extend(std::iter::repeat_n(None, interval - 1));
    }
    s
}

/// What the checker found.
#[derive(Debug, Default)]
pub struct Report {
    pub vectors: usize,
    pub outputs: usize,
    pub mismatches: usize,
    pub latency_errors: usize,
    pub first: Vec<String>,
}

impl Report {
    pub fn assert_clean(&self, what: &str) {
        assert!(
            self.mismatches == 0 && self.latency_errors == 0 && self.outputs == self.vectors,
            "{what}: {} vectors, {} outputs, {} mismatches, {} latency errors; first: {:#?}",
            self.vectors,
            self.outputs,
            self.mismatches,
            self.latency_errors,
            self.first
        );
    }
}

/// The checker: every output against `exact()`, in order, and its cycle against the input's slot + latency − 1.
pub fn check(
    model: &UnitModel,
    latency: usize,
    inputs: &[Vec<i64>],
    slots: &[Option<Vec<u64>>],
    got: &Collected,
) -> Report {
    let issued: Vec<usize> = slots.iter().enumerate().filter(|(_, s)| s.is_some()).map(|(k, _)| k).collect();
    let mut r = Report { vectors: inputs.len(), outputs: got.outputs.len(), ..Default::default() };
    for (k, (inp, want)) in inputs.iter().zip(model.run(inputs)).enumerate() {
        let Some(out) = got.outputs.get(k) else { break };
        let have: Vec<i64> =
            out.iter().zip(model.outputs).map(|(&p, port)| from_pattern(p, port.bits, port.signed)).collect();
        if have != want {
            r.mismatches += 1;
            if r.first.len() < 5 {
                r.first.push(format!("inputs {inp:?}: rtl {have:?}, model {want:?}"));
            }
        }
        if got.cycles[k] as usize != issued[k] + latency - 1 {
            r.latency_errors += 1;
            if r.first.len() < 5 {
                r.first.push(format!("vector {k} issued in slot {} came out in cycle {}", issued[k], got.cycles[k]));
            }
        }
    }
    r
}

/// The rtl port list must be the model's, name for name and width for width.
pub fn assert_ports_agree<U: StreamUnit>(model: &UnitModel) {
    let m: Vec<(&str, usize)> = model.inputs.iter().map(|p| (p.name, p.bits as usize)).collect();
    assert_eq!(U::INPUTS, m.as_slice(), "{} inputs", model.name);
    let m: Vec<(&str, usize)> = model.outputs.iter().map(|p| (p.name, p.bits as usize)).collect();
    assert_eq!(U::OUTPUTS, m.as_slice(), "{} outputs", model.name);
}

/// rust-hdl's simulation of the unit on these vectors.
pub fn rust_hdl<U: StreamUnit>(model: &UnitModel, inputs: &[Vec<i64>], bubbles: Bubbles) -> Report {
    let s = slots(model, U::INTERVAL, inputs, bubbles);
    let got = Runner::<U>::new().run(s.iter().cloned());
    check(model, U::LATENCY, inputs, &s, &got)
}

/// The same vectors through rust-hdl (with bubbles), and back to back through the exported Verilog under Verilator
/// and Icarus, each checked against the model. `tag` names the build folders, for a block built in several sizes.
pub fn three_ways<U: StreamUnit>(model: &UnitModel, inputs: &[Vec<i64>], tag: &str) {
    rust_hdl::<U>(model, inputs, Bubbles::Random { one_in: 4, seed: 1 }).assert_clean(&format!("rust-hdl, {tag}"));
    for (sim, name) in [(Simulator::Verilator, "verilator"), (Simulator::Icarus, "icarus")] {
        let built = cosim::build_as(&synth::Unit::of::<U>(), sim, &work_dir(name, tag), Compile::Quick)
            .unwrap_or_else(|e| panic!("{e}"));
        let s = slots(model, U::INTERVAL, inputs, Bubbles::BackToBack);
        let got = built.run(&s).unwrap_or_else(|e| panic!("{e}"));
        check(model, U::LATENCY, inputs, &s, &got).assert_clean(&format!("{name}, {tag}"));
    }
}

/// Where co-simulation builds live: under the workspace's target directory.
pub fn work_dir(sim: &str, unit: &str) -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..").join("target"));
    target.join("cosim").join(sim).join(unit)
}

/// The exported Verilog of the unit under Verilator or Icarus on these vectors.
pub fn external<U: StreamUnit>(sim: Simulator, model: &UnitModel, inputs: &[Vec<i64>], bubbles: Bubbles) -> Report {
    let name = match sim {
        Simulator::Verilator => "verilator",
        Simulator::Icarus => "icarus",
    };
    let built = cosim::build_as(&synth::Unit::of::<U>(), sim, &work_dir(name, U::NAME), Compile::Quick)
        .unwrap_or_else(|e| panic!("{e}"));
    let s = slots(model, U::INTERVAL, inputs, bubbles);
    let got = built.run(&s).unwrap_or_else(|e| panic!("{e}"));
    check(model, U::LATENCY, inputs, &s, &got)
}

/// The committed golden file of a unit, parsed; and whether the model still reproduces it byte for byte.
pub fn golden(model: &UnitModel) -> (Vec<Vec<i64>>, bool) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../vectors/data").join(format!("{}.csv", model.name));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let file = vectors::csv::parse(model, &text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let n_in = model.inputs.len();
    let inputs: Vec<Vec<i64>> = file.rows.iter().map(|r| r[..n_in].to_vec()).collect();
    let command = text
        .lines()
        .next()
        .unwrap_or("")
        .trim_start_matches("# generated by `")
        .trim_end_matches("`, do not edit")
        .to_string();
    let again = vectors::csv::render(model, &inputs, &command);
    (inputs, again == text)
}

/// Lint the unit's Verilog, write its `<unit>.vlt` as `bumprtl verilog` does, and lint it again with that file:
/// returns the design warnings and whatever Verilator still says with the waivers (there must be none of either).
pub fn lint<U: StreamUnit>() -> Vec<String> {
    let dir = work_dir("lint", U::NAME);
    synth::export::<U>().write(&dir).unwrap_or_else(|e| panic!("{e}"));
    let waivers = U::waivers();
    let file = format!("{}.v", U::NAME);
    let (vlt, mut found) =
        synth::lint::write_waivers(&dir, U::NAME, &[(&file, U::NAME)], &waivers).unwrap_or_else(|e| panic!("{e}"));
    let again = synth::lint::warnings(&dir, &[&vlt, Path::new(&file)], U::NAME).unwrap_or_else(|e| panic!("{e}"));
    found.extend(again.into_iter().map(|w| format!("with {}.vlt: {w}", U::NAME)));
    found
}

/// The standard tests every unit gets: golden vectors, three-way identity, bubbles, lint; and, for a unit whose
/// input space is enumerable, `exhaustive: [rust_hdl, verilator, icarus] with <bubbles>` runs all of it through the
/// simulators named. Every test sits in a module named after the unit: `gloss::exhaustive_verilator`.
#[macro_export]
macro_rules! unit_tests {
    ($unit:ident, $block:ty, $model:expr $(, exhaustive: [$($sim:ident),*] with $bubbles:expr)? $(,)?) => {
        mod $unit {
            use super::*;
            use synth::cosim::Simulator;
            use $crate::{Bubbles, assert_ports_agree, external, golden, lint, rust_hdl};

            #[test]
            fn ports_agree_with_the_model() {
                assert_ports_agree::<$block>(&$model);
            }

            #[test]
            fn matches_vectors() {
                let (inputs, reproduced) = golden(&$model);
                assert!(reproduced, "the model no longer reproduces vectors/data/{}.csv: regenerate it with `bumprtl vectors {}` if the change is meant", $model.name, $model.name);
                rust_hdl::<$block>(&$model, &inputs, Bubbles::BackToBack).assert_clean("rust-hdl, golden vectors");
            }

            #[test]
            fn hard_cases_with_bubbles() {
                let inputs = ($model.hard_cases)();
                rust_hdl::<$block>(&$model, &inputs, Bubbles::Random { one_in: 2, seed: 7 }).assert_clean("rust-hdl, hard cases, bubbles");
            }

            #[test]
            fn verilog_lints() {
                let design = lint::<$block>();
                assert!(design.is_empty(), "design warnings:\n{}", design.join("\n"));
            }

            #[test]
            fn verilator_matches_model() {
                let (inputs, _) = golden(&$model);
                external::<$block>(Simulator::Verilator, &$model, &inputs, Bubbles::Random { one_in: 5, seed: 3 }).assert_clean("verilator");
            }

            // back to back: the same Verilog takes its bubbles under Verilator above, and Icarus, the slower
            // simulator by far (seconds a pipeline), spends its time on the vectors themselves
            #[test]
            fn icarus_matches_model() {
                let (inputs, _) = golden(&$model);
                external::<$block>(Simulator::Icarus, &$model, &inputs, Bubbles::BackToBack).assert_clean("icarus");
            }

            $($($crate::unit_tests!(@exhaustive $sim, $block, $model, $bubbles);)*)?
        }
    };
    // every input of the unit's exhaustive set (≤ 2^20), through one simulator: rust-hdl with the given bubbles,
    // the external simulators back to back
    (@exhaustive rust_hdl, $block:ty, $model:expr, $bubbles:expr) => {
        #[test]
        fn exhaustive_rust_hdl() {
            let all = ($model.exhaustive.expect("an exhaustive set"))();
            rust_hdl::<$block>(&$model, &all, $bubbles).assert_clean("rust-hdl, every input");
        }
    };
    (@exhaustive verilator, $block:ty, $model:expr, $bubbles:expr) => {
        #[test]
        fn exhaustive_verilator() {
            let all = ($model.exhaustive.expect("an exhaustive set"))();
            external::<$block>(Simulator::Verilator, &$model, &all, Bubbles::BackToBack).assert_clean("verilator, every input");
        }
    };
    (@exhaustive icarus, $block:ty, $model:expr, $bubbles:expr) => {
        #[test]
        fn exhaustive_icarus() {
            let all = ($model.exhaustive.expect("an exhaustive set"))();
            external::<$block>(Simulator::Icarus, &$model, &all, Bubbles::BackToBack).assert_clean("icarus, every input");
        }
    };
}

/// Random streams through rust-hdl (from an empty memory, which both read as zero), and a long random stream under
/// Verilator after the hard cases have loaded the chain it reads (the hard cases with bubbles in rust-hdl are
/// `unit_tests!`'s `hard_cases_with_bubbles`): a pipeline on the texture unit, whose random reads find their texels
/// only once the hard cases have written them.
pub fn three_streams<U: StreamUnit>(m: &'static UnitModel, seed: u64) {
    random_vs_model::<U>(m, 4, 500);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut inputs = (m.hard_cases)();
    inputs.extend((0..30_000).map(|_| (m.random)(&mut rng)));
    external::<U>(Simulator::Verilator, m, &inputs, Bubbles::Random { one_in: 3, seed })
        .assert_clean("verilator, random after the hard cases");
}

/// Property-based check above 2^20 inputs: proptest draws `cases` stream seeds and bubble densities; each case
/// streams `per_case` vectors from the model's generator (edges weighted in) through rust-hdl and checks them all.
pub fn random_vs_model<U: StreamUnit>(model: &'static UnitModel, cases: u32, per_case: usize) {
    use proptest::prelude::*;
    use proptest::test_runner::{Config, TestRunner};
    let mut runner = TestRunner::new(Config { cases, failure_persistence: None, ..Config::default() });
    runner
        .run(&(any::<u64>(), 0u32..4), |(seed, density)| {
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
            let inputs: Vec<Vec<i64>> = (0..per_case).map(|_| (model.random)(&mut rng)).collect();
            let bubbles =
                if density == 0 { Bubbles::BackToBack } else { Bubbles::Random { one_in: density + 1, seed } };
            let r = rust_hdl::<U>(model, &inputs, bubbles);
            prop_assert!(r.mismatches == 0 && r.latency_errors == 0 && r.outputs == r.vectors, "{:?}", r);
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{}: {e}", model.name));
}

/// The same streams under Verilator, in one run.
pub fn random_vs_model_verilator<U: StreamUnit>(model: &'static UnitModel, count: usize, seed: u64) {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let inputs: Vec<Vec<i64>> = (0..count).map(|_| (model.random)(&mut rng)).collect();
    external::<U>(Simulator::Verilator, model, &inputs, Bubbles::Random { one_in: 3, seed })
        .assert_clean("verilator, random");
}
