//! The width report's claims under the solver (`sim::prove`: yosys-smtbmc with z3 on the exported Verilog), on
//! three units whose proofs take seconds: what it proves, what it refutes and that a claim one bit too narrow is
//! refuted.

use sim::prove::{prove, Options, Status};
use widths::formal::Kind;
use widths::wraps::Kind as WrapKind;

fn run(unit: &str, o: &Options) -> sim::prove::Proved {
    // a folder per call: two tests may prove the same unit at once
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir =
        std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("prove-{unit}-{}-{k}", std::process::id()));
    let p = prove(sim::units::unit(unit).unwrap(), &dir, o).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    p
}

/// cart_decode proves every claim. Its `twice_sum = s2_sum << 1` wraps where the sum is 128 or more (the solver
/// refuted its bound when the wrap list argued it in range) and is listed as a split, read only where it does not
/// wrap: no claim. The argued steps are claimed where their stage holds a pixel, from the unit's own valid chain.
#[test]
fn cart_decode_proves_every_claim_and_its_argued_steps_on_the_clocks_that_hold_a_pixel() {
    let p = run("cart_decode", &Options::default());
    assert_eq!((p.count("refuted"), p.count("not tried")), (0, 0));
    assert!(p.count("proven") >= 40, "{} proven", p.count("proven"));
    assert!(p.skipped.iter().any(|(s, why)| s == "uut.twice_sum" && why.contains("split")), "{:?}", p.skipped);
    // the argued steps the solver proves: s2_sum (a sum of two magnitudes below 128), s3_mx and s3_mz, at the
    // stage that computes them (stage 1 makes s2_sum.d, stage 2 the magnitudes)
    for (s, stage) in [("uut.s2_sum.d", 1), ("uut.s3_mx.d", 2), ("uut.s3_mz.d", 2)] {
        let o = p.outcomes.iter().find(|o| o.prop.signal == s && o.prop.kind == Kind::Exact).expect(s);
        assert_eq!(
            (o.listed.map(|w| w.kind), o.prop.stage, &o.status),
            (Some(WrapKind::Bound), Some(stage), &Status::Proven),
            "{s}"
        );
    }
    // a claim the wrap list does not argue holds on every clock, idle ones too
    assert!(p.outcomes.iter().filter(|o| o.listed.is_none()).all(|o| o.prop.stage.is_none()));
}

#[test]
fn dot3_and_gloss_prove_every_claim_their_argued_steps_included() {
    for unit in ["dot3", "gloss"] {
        let p = run(unit, &Options::default());
        assert_eq!((p.count("refuted"), p.count("not tried")), (0, 0), "{unit}");
        let argued = p.outcomes.iter().filter(|o| o.listed.map(|w| w.kind) == Some(WrapKind::Bound)).count();
        assert!(argued >= 2, "{unit}: {argued} argued steps");
        assert!(p.outcomes.iter().any(|o| o.prop.kind == Kind::Range), "{unit}");
        assert!(p.depth > sim::units::unit(unit).unwrap().rtl.latency(), "{unit}: depth {}", p.depth);
    }
}

/// The interval proof bounds a normal component's magnitude by 2048, which the inputs reach (Sq1.11 at −1): a
/// claim of 2047 (11 bits, not 12) is one bit too narrow, and the solver finds the input that breaks it.
#[test]
fn a_range_one_bit_too_narrow_is_refuted() {
    let signal = "uut.s1_nm$0.q";
    let o = Options { narrow: Some(signal.into()), exact_only: true, ..Options::default() };
    let p = run("dot3", &o);
    let narrowed: Vec<_> = p.outcomes.iter().filter(|o| o.prop.kind == Kind::Range).collect();
    assert_eq!(narrowed.len(), 1);
    assert_eq!((narrowed[0].prop.signal.as_str(), narrowed[0].prop.lo, narrowed[0].prop.hi), (signal, 0, 2047));
    assert!(matches!(narrowed[0].status, Status::Refuted(_)), "{:?}", narrowed[0].status);
    // the same claim at the interval proof's own bound is proven
    let full = run("dot3", &Options::default());
    let at = full.outcomes.iter().find(|o| o.prop.signal == signal && o.prop.kind == Kind::Range).unwrap();
    assert_eq!((at.prop.lo, at.prop.hi, &at.status), (0, 2048, &Status::Proven));
}

#[test]
fn narrower_takes_one_bit_off_either_reading() {
    assert_eq!(sim::prove::narrower(0, 2048, false), (0, 2047));
    assert_eq!(sim::prove::narrower(0, 255, false), (0, 127));
    assert_eq!(sim::prove::narrower(-255, 255, true), (-128, 127));
    assert_eq!(sim::prove::narrower(-1, 100, true), (-1, 63));
}

/// The miter finds a difference where there is one (cart_decode with TexelZ held at 127, the flat texel, against
/// cart_decode with it free) and none where there is none (cart_decode against itself, fed the same inputs).
#[test]
fn a_miter_refutes_a_false_equivalence_and_proves_a_true_one() {
    use sim::prove::{equivalence, Miter};
    use std::time::Duration;
    let decode = sim::units::unit("cart_decode").unwrap();
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("prove-miter-{}", std::process::id()));
    let same =
        equivalence(&Miter { a: decode, b: decode, fix: &[], bind: &[] }, &dir.join("same"), Duration::from_secs(300));
    let held = equivalence(
        &Miter { a: decode, b: decode, fix: &[("texel_z", 127)], bind: &[("texel_z", "b_texel_z")] },
        &dir.join("held"),
        Duration::from_secs(300),
    );
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(same.unwrap().status, Status::Proven);
    let held = held.unwrap();
    let Status::Refuted(trace) = &held.status else { panic!("{:?}", held.status) };
    assert!(trace.contains("b_texel_z="), "{trace}");
}

/// The sub-blocks where the claimed equivalences' pipelines part, proven where the whole miters are too large:
/// gloss at C = 0 passes N·L through unchanged, and the light interpolator with three equal lights passes the
/// light through (as Sq7.2, four times the S8 vertex light).
#[test]
fn gloss_at_c_0_and_light_iter_with_equal_lights_pass_their_input_through() {
    use sim::prove::echo;
    use std::time::Duration;
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("prove-echo-{}", std::process::id()));
    let u = |n| sim::units::unit(n).unwrap();
    let gloss = echo(u("gloss"), &[("conc", 0)], &[], &[("p", "x", 0)], &dir.join("gloss"), Duration::from_secs(300));
    let same =
        [("l1_x", "l0_x"), ("l1_y", "l0_y"), ("l1_z", "l0_z"), ("l2_x", "l0_x"), ("l2_y", "l0_y"), ("l2_z", "l0_z")];
    let pairs = [("light_x", "l0_x", 2), ("light_y", "l0_y", 2), ("light_z", "l0_z", 2)];
    let light = echo(u("light_iter"), &[], &same, &pairs, &dir.join("light"), Duration::from_secs(300));
    // and the same claim without the scale is false: the trace shows it
    let unscaled = [("light_x", "l0_x", 0)];
    let wrong = echo(u("light_iter"), &[], &same, &unscaled, &dir.join("wrong"), Duration::from_secs(300));
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(gloss.unwrap().status, Status::Proven);
    assert_eq!(light.unwrap().status, Status::Proven);
    assert!(matches!(wrong.unwrap().status, Status::Refuted(_)));
}

/// cart_decode's AXI4-Stream wrapper keeps its rules, against the bare unit, over every trace of 16 clocks from
/// reset (the flush after a reset, then beats through the unit and out); "none lost" over 20 (its quiet clocks, the
/// latency, the FIFO and two, come after a beat taken). And the check can fail: "none lost" after only the unit's
/// latency in quiet clocks is refuted, since a beat takes one clock more to leave (which also shows the traces
/// are long enough for beats to come out). The default depth, 20 for every rule, is `prove --axis`'s.
#[test]
fn the_axis_wrapper_keeps_its_rules_and_a_drain_too_short_is_refuted() {
    use sim::axis_rules::{prove_rules, RULES};
    use std::time::Duration;
    let u = sim::units::unit("cart_decode").unwrap();
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("prove-axis-{}", std::process::id()));
    let limit = Duration::from_secs(300);
    let rest: Vec<&str> = RULES.iter().copied().filter(|r| *r != "none lost").collect();
    let good = prove_rules(u, &dir.join("good"), 16, None, limit, &rest).unwrap();
    let lost = prove_rules(u, &dir.join("lost"), 0, None, limit, &["none lost"]).unwrap();
    let short = prove_rules(u, &dir.join("short"), 0, Some(u.rtl.latency()), limit, &["none lost"]).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(good.rules.len(), RULES.len());
    for r in good.rules.iter().chain(&lost.rules) {
        assert_eq!(r.status, Status::Proven, "{}", r.name);
    }
    assert_eq!(lost.depth, 2 * u.rtl.latency() + u.axis.fifo().0 + 6);
    let r = short.rules.iter().find(|r| r.name == "none lost").unwrap();
    assert!(matches!(r.status, Status::Refuted(_)), "{:?}", r.status);
}

/// A unit with a map write port (height_fetch) has its structural rule proven on its wrapper's netlist and every
/// rule that needs the bare unit as a reference not tried, with the reason, rather than an error.
#[test]
fn a_map_units_wrapper_proves_its_structural_rule_and_says_why_the_rest_are_not_tried() {
    use sim::axis_rules::{prove, RULES, STRUCTURAL};
    use std::time::Duration;
    let u = sim::units::unit("height_fetch").unwrap();
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("prove-axis-map-{}", std::process::id()));
    let p = prove(u, &dir, 0, None, Duration::from_secs(300)).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(p.rules.len(), RULES.len() + 1);
    for r in &p.rules {
        if r.name == STRUCTURAL {
            assert_eq!(r.status, Status::Proven);
            assert!(r.unbounded());
        } else {
            assert!(
                matches!(&r.status, Status::NotTried(w) if w.contains("map write port")),
                "{}: {:?}",
                r.name,
                r.status
            );
            assert!(!r.unbounded());
        }
    }
}
