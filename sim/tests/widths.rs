//! The width report's reading of the rtl, for every unit of the table and every swept setting (`sim::units`):
//! every signal the rust-hdl probe sees (but the clocks) resolves through the declarations the compiler records
//! (`rtl::prim::declared`) to a format as wide as the simulator's signal, the range it takes over the hard cases and
//! 2,000 random vectors lies inside the range the interval analysis proves (the proof is sound, or this fails), and
//! no step may wrap unless `widths::wraps` lists it with its reason.
use sim::rtl_paths::RtlBlock;
use sim::units::{SETTINGS, UNITS};
use vectors::UnitModel;

/// Every block the width analysis reads: (what to call it, its model, its block).
fn blocks() -> Vec<(String, &'static UnitModel, &'static dyn RtlBlock)> {
    let mut v: Vec<(String, &'static UnitModel, &'static dyn RtlBlock)> =
        UNITS.iter().map(|u| (u.name().to_string(), u.model, u.rtl as &dyn RtlBlock)).collect();
    for s in SETTINGS {
        let m = sim::units::find(s.unit).expect("a setting's unit has a row").model;
        v.push((format!("{}<{}, {}>", s.unit, s.params.0, s.params.1), m, s.rtl));
    }
    v
}

/// The stages `widths::stages` reads from the hdl against the rtl: within a block a register named `sN_<name>` (N
/// its stage in the block's comments; some blocks number an inserted stage `s1b_`) comes after every `sM_` with M < N,
/// and each output of a unit that takes a vector a clock is at its latency. One line per disagreement.
fn stage_order(ranges: &widths::Ranges, latency: usize, interval: usize, outputs: &[&str]) -> Vec<String> {
    let mut bad = vec![];
    let mut by_block: std::collections::HashMap<&str, Vec<(u32, u32, &str)>> = Default::default();
    for s in &ranges.signals {
        let Some(reg) = s.name.strip_suffix(".q") else { continue };
        let Some((block, field)) = reg.rsplit_once('.') else { continue };
        let digits: String = field.strip_prefix('s').unwrap_or("").chars().take_while(char::is_ascii_digit).collect();
        if digits.is_empty() || !field[1 + digits.len()..].starts_with('_') {
            continue; // not a stage register by name (`s1b_lin`, `sum`)
        }
        // one with no single stage (a shared lane's operand, a constant through registers) has no order to keep
        if let Some(d) = s.stage {
            by_block.entry(block).or_default().push((digits.parse().unwrap(), d, &s.name));
        }
    }
    for regs in by_block.values() {
        for a in regs {
            if let Some(b) = regs.iter().find(|b| b.0 > a.0 && b.1 <= a.1) {
                bad.push(format!("{} at stage {}, yet {} after it by name is at {}", a.2, a.1, b.2, b.1));
            }
        }
    }
    if interval == 1 {
        for o in outputs {
            let n = format!("uut.{o}");
            let stage = ranges.signals.iter().find(|s| s.name == n).and_then(|s| s.stage);
            if stage != Some(latency as u32) {
                bad.push(format!("{n}: stage {stage:?}, the latency is {latency}"));
            }
        }
    }
    bad
}

#[test]
fn every_signal_of_every_unit_has_its_declared_format_and_stays_inside_its_proven_range_and_its_stage() {
    let mut failed = vec![];
    for (name, m, rtl) in blocks() {
        // the hard cases (every one) and 2,000 random vectors after them
        let inputs = vectors::unit::generate(m, false, 2_000, 7).expect("vectors");
        let ranges = rtl.seen(m, &inputs, &|_| {});
        assert!(!ranges.signals.is_empty(), "{name}: no signal probed");
        failed.extend(widths::audit(&ranges, &rtl.analyse(m)).into_iter().map(|b| format!("{name}: {b}")));
        let outputs: Vec<&str> = m.outputs.iter().map(|p| p.name).collect();
        let staged = stage_order(&ranges, rtl.latency(), rtl.interval(), &outputs);
        failed.extend(staged.into_iter().map(|b| format!("{name}: {b}")));
    }
    assert!(failed.is_empty(), "{} signals:\n{}", failed.len(), failed.join("\n"));
}

#[test]
fn a_register_reset_zero_before_the_first_vector_is_not_seen() {
    // cart_decode's BumpY is 1 .. 255 on every legal texel (US 6,819,319's decode; the guard's floor is 1): its
    // stage-3 register holds 0 only before the first vector, which the seen range no longer counts
    let u = sim::units::find("cart_decode").expect("cart_decode");
    let inputs = vectors::unit::generate(u.model, true, 0, 1).expect("every input");
    let ranges = u.rtl.seen(u.model, &inputs, &|_| {});
    let get = |n: &str| ranges.signals.iter().find(|s| s.name == n).unwrap_or_else(|| panic!("{n} probed"));
    for n in ["uut.s3_by.q", "uut.bump_y"] {
        let s = get(n);
        assert_eq!((s.umin, s.umax, s.every), (1, 255, false), "{n}");
    }
    // the valid flags themselves are read on every clock, and so see both values
    let v = get("uut.valid_out");
    assert_eq!((v.umin, v.umax, v.every), (0, 1, true));
}

#[test]
fn no_step_wraps_unless_it_is_listed_with_its_reason() {
    let waived = widths::wraps::WAIVED;
    let mut unlisted: Vec<String> = vec![];
    let mut used = vec![false; waived.len()];
    for (_, m, rtl) in blocks() {
        for s in rtl.analyse(m).sites() {
            match waived.iter().position(|w| w.block == s.owner && w.signal == s.local) {
                Some(k) => used[k] = true,
                None => unlisted.push(format!("{} {}: computes {} .. {}", s.owner, s.local, s.exact.0, s.exact.1)),
            }
        }
    }
    unlisted.sort();
    unlisted.dedup();
    assert!(
        unlisted.is_empty(),
        "{} steps may wrap and are not listed in widths::wraps:\n{}",
        unlisted.len(),
        unlisted.join("\n")
    );
    let stale: Vec<String> =
        waived.iter().zip(&used).filter(|(_, u)| !**u).map(|(w, _)| format!("{} {}", w.block, w.signal)).collect();
    assert!(stale.is_empty(), "listed, but no step of any unit wraps there: {stale:?}");
}
