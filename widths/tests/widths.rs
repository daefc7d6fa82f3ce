//! The width report's reading of the rtl, for every unit of the table: every signal the rust-hdl probe sees (but the
//! clocks) resolves through the declarations the compiler records (`rtl::prim::declared`) to a format as wide as the
//! simulator's signal, and the range it takes over the hard cases and 2,000 random vectors lies inside the range the
//! interval analysis proves (the proof is sound, or this fails).
use widths::{bounds, seen, Formats};

macro_rules! every_unit {
    ([] rtl { $($name:ident: $model:expr, $block:ty, [$($waiver:tt)*];)* } software { $($soft:ident),* }) => {
        /// (unit, signals probed, signals without a format, and why each failed)
        fn check_all() -> Vec<(&'static str, usize, Vec<String>)> {
            vec![$(check::<$block>(stringify!($name), &$model)),*]
        }
        /// Every step that may wrap, in every unit: (owner block, its signal, what it computes, its format)
        fn wraps_all() -> Vec<(String, String, (i128, i128), String)> {
            let mut v = vec![];
            $(v.extend(wraps::<$block>(&$model));)*
            v
        }
    };
}
vectors::unit_table!(every_unit);

// The width sweep's other settings of the units that have them (same ports as the unit): held to the same tests.
macro_rules! normalise_settings {
    ($($t:literal),* $(,)?) => {
        fn normalise_settings() -> Vec<(String, Box<dyn Fn() -> (&'static str, usize, Vec<String>)>, Box<dyn Fn() -> Vec<Site>>)> {
            vec![$(
                (format!("normalise<{}, 0>", $t), Box::new(|| check::<rtl::normalise::Normalise<$t, 0>>("normalise", &vectors::normalise::MODEL)), Box::new(|| wraps::<rtl::normalise::Normalise<$t, 0>>(&vectors::normalise::MODEL))),
                (format!("normalise<{}, 1>", $t), Box::new(|| check::<rtl::normalise::Normalise<$t, 1>>("normalise", &vectors::normalise::MODEL)), Box::new(|| wraps::<rtl::normalise::Normalise<$t, 1>>(&vectors::normalise::MODEL))),
            )*]
        }
    };
}
vectors::normalise_table_sizes!(normalise_settings);

macro_rules! power_settings {
    ($(($lf:literal, $eb:literal)),* $(,)?) => {
        fn power_settings() -> Vec<(String, Box<dyn Fn() -> (&'static str, usize, Vec<String>)>, Box<dyn Fn() -> Vec<Site>>)> {
            vec![$(
                (format!("power<{}, {}>", $lf, $eb), Box::new(|| check::<rtl::power::Power<$lf, $eb>>("power", &vectors::power::MODEL)), Box::new(|| wraps::<rtl::power::Power<$lf, $eb>>(&vectors::power::MODEL))),
            )*]
        }
    };
}
vectors::power_sizes!(power_settings);

/// Every swept setting's name, its check and its wrap sites.
fn settings() -> Vec<(String, Box<dyn Fn() -> (&'static str, usize, Vec<String>)>, Box<dyn Fn() -> Vec<Site>>)> {
    let mut v = normalise_settings();
    v.extend(power_settings());
    v
}

type Site = (String, String, (i128, i128), String);

fn check<U: rtl::StreamUnit>(name: &'static str, m: &vectors::UnitModel) -> (&'static str, usize, Vec<String>) {
    // the hard cases (every one) and 2,000 random vectors after them
    let inputs = vectors::unit::generate(m, false, 2_000, 7).expect("vectors");
    let ranges = seen::<U>(m, &inputs);
    let f = Formats::of::<U>();
    let ports: Vec<(&str, i64, i64)> = m.inputs.iter().map(|p| (p.name, p.range().0, p.range().1)).collect();
    let signed = |n: &str| f.format(n).is_some_and(|x| x.signed);
    let proven = bounds::prove(&U::build(), &ports, &signed).values;
    let mut bad = vec![];
    for s in &ranges.signals {
        if s.name.ends_with("clock") || s.name.ends_with("_clock") {
            continue;
        }
        match f.format(&s.name) {
            Some(fmt) if fmt.bits == s.bits => {
                // sound: what the simulation took lies inside what the analysis proves
                let (lo, hi) =
                    if fmt.signed { (s.smin as i128, s.smax as i128) } else { (s.umin as i128, s.umax as i128) };
                match proven.get(&s.name) {
                    Some(p) => {
                        let pieces = if fmt.signed { p.signed() } else { p.unsigned() };
                        for x in [lo, hi] {
                            if !pieces.iter().any(|&(a, b)| a <= x && x <= b) {
                                bad.push(format!("{}: seen {x} outside the proven {pieces:?}", s.name));
                            }
                        }
                    }
                    None => bad.push(format!("{}: no proven range", s.name)),
                }
                let fits = if fmt.signed {
                    s.smin >= -(1i64 << (s.bits - 1)) && s.smax < 1i64 << (s.bits - 1)
                } else {
                    s.bits >= 64 || s.umax < 1u64 << s.bits
                };
                if !fits {
                    bad.push(format!("{}: seen outside {}", s.name, fmt.q()));
                }
            }
            Some(fmt) => {
                bad.push(format!("{}: declared {} ({} bits), simulated {} bits", s.name, fmt.name, fmt.bits, s.bits))
            }
            None => bad.push(format!("{}: no declared format", s.name)),
        }
    }
    (name, ranges.signals.len(), bad)
}

#[test]
fn every_signal_of_every_unit_has_its_declared_format_and_stays_inside_its_proven_range() {
    let mut failed = vec![];
    for (name, n, bad) in check_all() {
        assert!(n > 0, "{name}: no signal probed");
        failed.extend(bad.into_iter().map(|b| format!("{name}: {b}")));
    }
    for (setting, check, _) in settings() {
        let (_, n, bad) = check();
        assert!(n > 0, "{setting}: no signal probed");
        failed.extend(bad.into_iter().map(|b| format!("{setting}: {b}")));
    }
    assert!(failed.is_empty(), "{} signals:\n{}", failed.len(), failed.join("\n"));
}

#[test]
fn a_magnitude_written_before_its_sign_test_is_proven_on_both_sides() {
    // normalise: s1_m = v; if v < 0 { s1_m = −v }: |v| ≤ 512 for an S10 v, so its square fits U19 and the sum of three
    // U20; at the end the sign goes back on, `!n + 1` (−n, two's complement written out), which fits S12 on both
    // sides while the magnitude is proven below 2^11
    use rtl::StreamUnit;
    let m = &vectors::normalise::MODEL;
    let f = Formats::of::<rtl::normalise::Normalise>();
    let ports: Vec<(&str, i64, i64)> = m.inputs.iter().map(|p| (p.name, p.range().0, p.range().1)).collect();
    let signed = |n: &str| f.format(n).is_some_and(|x| x.signed);
    let proof = bounds::prove(&<rtl::normalise::Normalise>::build(), &ports, &signed);
    assert_eq!(proof.values["uut.s1_m$0.d"].range(false), (0, 512));
    assert_eq!(proof.values["uut.s2_sq$1.q"].range(false), (0, 512 * 512));
    let flagged: Vec<&str> = proof.wraps.keys().map(|(_, n)| n.as_str()).collect();
    assert!(!flagged.iter().any(|n| n.contains("s1_m") || n.contains("s2_sq") || n.contains("s3_s")), "{flagged:?}");
    let n = proof.values["uut.s8_n$0.q"].range(false);
    assert!(n.0 == 0 && n.1 < 2048, "{n:?}");
    assert!(!flagged.iter().any(|n| n.contains("s9_out")), "{flagged:?}");
}

fn wraps<U: rtl::StreamUnit>(m: &vectors::UnitModel) -> Vec<Site> {
    let f = Formats::of::<U>();
    let ports: Vec<(&str, i64, i64)> = m.inputs.iter().map(|p| (p.name, p.range().0, p.range().1)).collect();
    let signed = |n: &str| f.format(n).is_some_and(|x| x.signed);
    let proof = bounds::prove(&U::build(), &ports, &signed);
    widths::sites(&f, &proof)
        .into_iter()
        .map(|s| {
            let q = f.format(&s.name).map(|x| x.q()).unwrap_or_default();
            (s.owner, s.local, s.exact, q)
        })
        .collect()
}

#[test]
fn no_step_wraps_unless_it_is_listed_with_its_reason() {
    let waived = widths::wraps::WAIVED;
    let mut unlisted: Vec<String> = vec![];
    let mut used = vec![false; waived.len()];
    let mut sites = wraps_all();
    for (_, _, sites_of) in settings() {
        sites.extend(sites_of());
    }
    for (owner, local, exact, q) in sites {
        match waived.iter().position(|w| w.block == owner && w.signal == local) {
            Some(k) => used[k] = true,
            None => unlisted.push(format!("{owner} {local}: computes {} .. {}, {q}", exact.0, exact.1)),
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
