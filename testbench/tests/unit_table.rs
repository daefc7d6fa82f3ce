//! The unit table (`vectors::unit_table!`) against what it stands for: each entry's model and rtl block carry its
//! name, its golden vector file is committed, its testbench runs the standard tests, and every waiver it lists
//! names a signal its Verilog really has.
use rtl::StreamUnit;

macro_rules! entries {
    ([] rtl { $($name:ident: $model:expr, $block:ty, [$(($sig:literal, $why:literal)),* $(,)?];)* } software { $($soft:ident),* }) => {
        /// (name, model's name, block's name, exported Verilog, waived signals)
        fn entries() -> Vec<(&'static str, &'static str, &'static str, String, Vec<&'static str>)> {
            vec![$((stringify!($name), $model.name, <$block as StreamUnit>::NAME, synth::export::<$block>().text, vec![$($sig),*])),*]
        }
        fn software() -> Vec<&'static str> {
            vec![$(stringify!($soft)),*]
        }
    };
}
vectors::unit_table!(entries);

fn root() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

#[test]
fn every_entry_names_its_model_and_its_block_alike() {
    for (name, model, block, _, _) in entries() {
        assert_eq!(model, name, "the model of `{name}`");
        assert_eq!(block, name, "the rtl block of `{name}`");
    }
    assert_eq!(vectors::UNITS.len(), entries().len());
}

#[test]
fn every_entry_has_its_golden_file_and_its_standard_tests() {
    let tests: String = std::fs::read_dir(root().join("testbench/tests"))
        .expect("testbench/tests")
        .filter_map(|e| std::fs::read_to_string(e.ok()?.path()).ok())
        .collect();
    for (name, ..) in entries() {
        assert!(
            root().join("vectors/data").join(format!("{name}.csv")).is_file(),
            "no vectors/data/{name}.csv: `bumprtl vectors {name}` writes it"
        );
        assert!(tests.contains(&format!("unit_tests!({name},")), "no `unit_tests!({name}, ...)` in testbench/tests");
    }
}

#[test]
fn every_waiver_names_a_signal_of_its_unit() {
    for (name, _, _, verilog, waived) in entries() {
        for sig in waived {
            let (inst, port) = sig.split_once('$').expect("instance$port");
            assert!(
                verilog.contains(&format!("{inst}${port}")),
                "`{name}` waives `{sig}`, which its Verilog does not have"
            );
        }
    }
}

#[test]
fn software_only_units_have_no_vectors() {
    for name in software() {
        assert!(vectors::unit::find(name).is_none(), "{name}");
        assert!(!root().join("vectors/data").join(format!("{name}.csv")).exists(), "{name}");
    }
}

#[test]
fn every_unit_but_a_pipeline_measures_its_own_accuracy() {
    // a pipeline's error is measured on a scene (the demo, `sim::pipeline`), and may be measured here too; every
    // other unit states its own
    for m in vectors::UNITS {
        let pipeline = m.name.contains("pipeline");
        assert!(m.accuracy.is_some() || pipeline, "`{}`: UnitModel::with_accuracy", m.name);
        if let Some(f) = m.accuracy {
            let rows = f(1_000, 1);
            assert!(!rows.is_empty() && rows.iter().all(|r| r.stats.count > 0), "`{}` measures something", m.name);
        }
    }
}
