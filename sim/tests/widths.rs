//! The width report's reading of the rtl, for every unit of the table: every signal the rust-hdl probe sees (but the
//! clocks) resolves through the source's declarations to a format as wide as the simulator's signal, and a probed
//! range lies inside that width.
use sim::widths::{seen, Formats};

macro_rules! every_unit {
    ([] rtl { $($name:ident: $model:expr, $block:ty, [$($waiver:tt)*];)* } software { $($soft:ident),* }) => {
        /// (unit, signals probed, signals without a format, and why each failed)
        fn check_all() -> Vec<(&'static str, usize, Vec<String>)> {
            vec![$(check::<$block>(stringify!($name), &$model)),*]
        }
    };
}
vectors::unit_table!(every_unit);

fn check<U: rtl::StreamUnit>(name: &'static str, m: &vectors::UnitModel) -> (&'static str, usize, Vec<String>) {
    let inputs: Vec<Vec<i64>> = (m.hard_cases)().into_iter().take(40).collect();
    let ranges = seen::<U>(m, &inputs);
    let f = Formats::of::<U>();
    let mut bad = vec![];
    for s in &ranges.signals {
        if s.name.ends_with("clock") || s.name.ends_with("_clock") {
            continue;
        }
        match f.format(&s.name) {
            Some(fmt) if fmt.bits == s.bits => {
                let fits = if fmt.signed { s.smin >= -(1i64 << (s.bits - 1)) && s.smax < 1i64 << (s.bits - 1) } else { s.bits >= 64 || s.umax < 1u64 << s.bits };
                if !fits {
                    bad.push(format!("{}: seen outside {}", s.name, fmt.q()));
                }
            }
            Some(fmt) => bad.push(format!("{}: declared {} ({} bits), simulated {} bits", s.name, fmt.name, fmt.bits, s.bits)),
            None => bad.push(format!("{}: no declared format", s.name)),
        }
    }
    (name, ranges.signals.len(), bad)
}

#[test]
fn every_signal_of_every_unit_has_its_declared_format() {
    let mut failed = vec![];
    for (name, n, bad) in check_all() {
        assert!(n > 0, "{name}: no signal probed");
        failed.extend(bad.into_iter().map(|b| format!("{name}: {b}")));
    }
    assert!(failed.is_empty(), "{} signals:\n{}", failed.len(), failed.join("\n"));
}
