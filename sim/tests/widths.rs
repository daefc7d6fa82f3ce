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

#[test]
fn every_signal_of_every_unit_has_its_declared_format_and_stays_inside_its_proven_range() {
    let mut failed = vec![];
    for (name, m, rtl) in blocks() {
        // the hard cases (every one) and 2,000 random vectors after them
        let inputs = vectors::unit::generate(m, false, 2_000, 7).expect("vectors");
        let ranges = rtl.seen(m, &inputs, &|_| {});
        assert!(!ranges.signals.is_empty(), "{name}: no signal probed");
        failed.extend(widths::audit(&ranges, &rtl.analyse(m)).into_iter().map(|b| format!("{name}: {b}")));
    }
    assert!(failed.is_empty(), "{} signals:\n{}", failed.len(), failed.join("\n"));
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
