//! The table of units (`sim::units`) against what it stands for: each row's model and rtl block carry its name, its
//! golden vector file is committed and every committed one has its row, its testbench runs the standard tests,
//! every waiver it lists names a signal its Verilog really has, and every swept setting builds its own unit inside
//! the range its model's tests cover, with the model's tables (power, sincos, cos_sign); and the latencies
//! rtl/README.md gives are the blocks' own.
use sim::units::{SETTINGS, SOFTWARE_ONLY, UNITS};
use std::collections::BTreeSet;

fn root() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

#[test]
fn every_row_names_its_model_and_its_block_alike_and_no_name_twice() {
    let mut names = BTreeSet::new();
    for u in UNITS {
        assert_eq!(u.rtl.name(), u.model.name, "the rtl block of `{}`", u.model.name);
        assert!(names.insert(u.name()), "`{}` twice", u.name());
    }
    for s in SOFTWARE_ONLY {
        assert!(!names.contains(s), "`{s}` is software only and has a row");
    }
}

#[test]
fn every_row_has_its_golden_file_and_its_standard_tests_and_every_golden_file_its_row() {
    let tests: String = std::fs::read_dir(root().join("testbench/tests"))
        .expect("testbench/tests")
        .filter_map(|e| std::fs::read_to_string(e.ok()?.path()).ok())
        .collect();
    // rustfmt breaks a long invocation over lines: the call matched with its whitespace taken out
    let tests: String = tests.chars().filter(|c| !c.is_whitespace()).collect();
    for u in UNITS {
        let name = u.name();
        assert!(
            root().join("vectors/data").join(format!("{name}.csv")).is_file(),
            "no vectors/data/{name}.csv: `bumprtl vectors {name}` writes it"
        );
        assert!(tests.contains(&format!("unit_tests!({name},")), "no `unit_tests!({name}, ...)` in testbench/tests");
    }
    for e in std::fs::read_dir(root().join("vectors/data")).expect("vectors/data") {
        let p = e.expect("an entry").path();
        if p.extension().is_some_and(|x| x == "csv") {
            let stem = p.file_stem().unwrap().to_string_lossy().into_owned();
            assert!(sim::units::find(&stem).is_some(), "vectors/data/{stem}.csv has no row in sim::units::UNITS");
        }
    }
}

#[test]
fn every_waiver_names_a_signal_of_its_unit_and_says_why() {
    for u in UNITS.iter().filter(|u| !u.waivers().is_empty()) {
        let verilog = u.rtl.verilog();
        let waivers = u.waivers();
        for (k, (sig, why)) in waivers.iter().enumerate() {
            assert!(
                !waivers[..k].iter().any(|(s, _)| s == sig),
                "`{}` waives `{sig}` twice (its own list and a shared one, or two shared ones)",
                u.name()
            );
            let (inst, port) = sig.split_once('$').expect("instance$port");
            assert!(
                verilog.contains(&format!("{inst}${port}")),
                "`{}` waives `{sig}`, which its Verilog does not have",
                u.name()
            );
            assert!(!why.trim().is_empty(), "`{}` waives `{sig}` without a reason", u.name());
        }
    }
}

#[test]
fn software_only_units_have_no_vectors() {
    for name in SOFTWARE_ONLY {
        assert!(sim::units::find(name).is_none(), "{name} has a row");
        assert!(!root().join("vectors/data").join(format!("{name}.csv")).exists(), "{name}");
    }
}

#[test]
fn every_unit_but_a_pipeline_measures_its_own_accuracy() {
    // a pipeline's error is measured on a scene (the demo, `sim::pipeline`), and may be measured here too; every
    // other unit states its own
    for u in UNITS {
        let m = u.model;
        let pipeline = m.name.contains("pipeline") || sim::pipelines::named(m.name).is_some();
        assert!(m.accuracy.is_some() || pipeline, "`{}`: UnitModel::with_accuracy", m.name);
        if let Some(f) = m.accuracy {
            let rows = f(1_000, 1);
            assert!(!rows.is_empty() && rows.iter().all(|r| r.stats.count > 0), "`{}` measures something", m.name);
        }
    }
}

#[test]
fn every_swept_setting_builds_its_own_unit_once_and_the_units_own_setting_first() {
    // the unit's own parameters, as its model states them
    let own = |unit: &str| match unit {
        "normalise" => (vectors::normalise::TABLE_BITS, vectors::normalise::NEWTON),
        "sincos" => (vectors::sincos::TABLE_BITS, vectors::sincos::WIDTH),
        "cos_sign" => (vectors::cos_sign::TABLE_BITS, vectors::cos_sign::WIDTH),
        "bilinear" => (vectors::bilinear::F, 0),
        "power" => (vectors::power::LOG_FRAC, vectors::power::EXP_BITS),
        other => panic!("a swept setting of `{other}`, whose own parameters this test does not know"),
    };
    let mut seen = BTreeSet::new();
    for s in SETTINGS {
        assert!(sim::units::find(s.unit).is_some(), "a setting of `{}`, which has no row", s.unit);
        assert_eq!(s.rtl.name(), s.unit, "the block of {} {:?}", s.unit, s.params);
        assert!(seen.insert((s.unit, s.params)), "{} {:?} twice", s.unit, s.params);
    }
    for unit in ["normalise", "bilinear", "power"] {
        assert_eq!(sim::units::settings(unit).next().map(|s| s.params), Some(own(unit)), "{unit}: its own first");
    }
    for unit in ["sincos", "cos_sign"] {
        // the LUT-size tables go by size; the unit's own is among them
        assert!(sim::units::setting(unit, own(unit)).is_some(), "{unit}");
    }
}

#[test]
fn the_models_tests_of_every_size_cover_every_swept_setting() {
    // vectors::normalise's Newton-step widths are tested for tables of 6 to 12 bits, vectors::power's ends and
    // widths for L of 8 to LOG_FRAC fraction bits and E of 6 to 9 index bits: a setting outside them is untested
    for s in SETTINGS {
        let (a, b) = s.params;
        let covered = match s.unit {
            "normalise" => (6..=12).contains(&a) && b <= 1,
            "power" => (8..=vectors::power::LOG_FRAC).contains(&a) && (6..=9).contains(&b),
            _ => true,
        };
        assert!(covered, "{} {:?}", s.unit, s.params);
    }
}

// The rtl tables of every swept size (the block built with them is the unit's own or the width sweep's) against
// the model's entries.

#[test]
fn power_rtl_tables_of_every_swept_size_are_the_models() {
    for (lf, eb) in sim::units::settings("power").map(|s| s.params) {
        for (x, &l) in rtl::tables::log2_of(lf as usize).iter().enumerate() {
            assert_eq!(l as i64, vectors::power::log_entry(x as u64, lf), "L, {lf} fraction bits, x {x}");
        }
        let e = rtl::tables::exp2_of(eb as usize);
        assert_eq!(e.len(), 1 << eb);
        for (f, &v) in e.iter().enumerate() {
            assert_eq!(v as i64, vectors::power::exp_entry(f as u64, eb), "E, {eb} bits, f {f}");
        }
    }
}

#[test]
fn sincos_rtl_entries_are_the_models_for_every_swept_size() {
    for (tb, w) in sim::units::settings("sincos").map(|s| s.params) {
        let m = vectors::sincos::elevation_table(vectors::polar_encode::Scale::Seed, tb, w);
        let r = rtl::tables::elevation(false, tb as usize, w as usize);
        assert_eq!(r.len(), m.len());
        for k in 0..m.len() {
            assert_eq!((r[k].0 as i64, r[k].1 as i64), m[k], "{}x{w}, entry {k}", 1 << tb);
        }
    }
}

#[test]
fn cos_sign_rtl_entries_are_the_models_for_every_swept_size() {
    for (tb, w) in sim::units::settings("cos_sign").map(|s| s.params) {
        let r = rtl::tables::cos_sign(false, tb as usize, w as usize);
        for (i, e) in r.iter().enumerate() {
            let d = (i as i64) << (8 - tb);
            let (m, n) = vectors::cos_sign::exact_with(tb, w, d);
            assert_eq!((e.0 as i64, e.1), (m, n), "{}x{w}, entry {i}", 1 << tb);
        }
    }
}

/// Blocks a README gives the latency of that are not units of the table (each is a part of several units): the
/// height-map patent's tangent → normal, and the texture unit's fronts.
const PARTS: &[(&str, usize)] = &[
    ("tangent_to_normal", rtl::height::tangent_to_normal::LATENCY),
    ("TexNearest", rtl::texture::front::nearest::LATENCY),
    ("TexBilinear", rtl::texture::front::bilinear::LATENCY),
    ("TexNearestMip", rtl::texture::front::nearest_mip::LATENCY),
    ("TexNearestColour", rtl::texture::front::nearest_colour::LATENCY),
    ("TexNearestMipColour", rtl::texture::front::nearest_mip_colour::LATENCY),
    ("TexBilinearColour", rtl::texture::front::bilinear_colour::LATENCY),
    ("TexTrilinear", rtl::texture::front::trilinear::LATENCY),
    ("TexTrilinearColour", rtl::texture::front::trilinear_colour::LATENCY),
    ("TexTrilinearTwoPass", rtl::texture::front::trilinear_two_pass::LATENCY),
];

/// Every "`block` (N" that rtl/README.md, README.md and ARCHITECTURE.md give (a unit's name, or a part's in `PARTS`,
/// then its latency in brackets, a line break allowed between them) says the block's own latency: the figures are
/// written by hand, and a stage added to a shared block changes every pipeline that holds it.
#[test]
fn every_latency_a_readme_gives_is_the_blocks_own() {
    let mut wrong = vec![];
    let mut seen = 0;
    for readme in ["rtl/README.md", "README.md", "ARCHITECTURE.md"] {
        let text = std::fs::read_to_string(root().join(readme)).unwrap_or_else(|e| panic!("{readme}: {e}"));
        for (k, _) in text.match_indices('`') {
            let Some(open) = text[..k].rfind('`') else { continue };
            let name = &text[open + 1..k];
            let latency = match UNITS.iter().find(|u| u.name() == name) {
                Some(u) => u.rtl.latency(),
                None => match PARTS.iter().find(|p| p.0 == name) {
                    Some(p) => p.1,
                    None => continue,
                },
            };
            let Some(rest) = text[k + 1..].trim_start().strip_prefix('(') else { continue };
            let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
            // "(52)", "(72; two clocks a pixel ...", "(32: tangent → normal ...", "(39, the one that ..."
            if digits.is_empty() || !rest[digits.len()..].starts_with([')', ';', ':', ',']) {
                continue;
            }
            seen += 1;
            if digits.parse::<usize>().ok() != Some(latency) {
                wrong.push(format!("{readme}: `{name}` ({digits}): its latency is {latency}"));
            }
        }
    }
    assert!(seen > 20, "only {seen} latencies found: has the READMEs' form changed?");
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
