//! The width analysis on one block whose proof needs more than intervals: a magnitude written before its sign test.
//! The analysis of every unit of the table, and of every swept setting, is held in `sim/tests/widths.rs`.
#[test]
fn a_magnitude_written_before_its_sign_test_is_proven_on_both_sides() {
    // normalise: s1_m = v; if v < 0 { s1_m = −v }: |v| ≤ 512 for an S10 v, so its square fits U19 and the sum of three
    // U20; at the end the sign goes back on, `!n + 1` (−n, two's complement written out), which fits S12 on both
    // sides while the magnitude is proven below 2^11
    let proof = widths::analyse::<rtl::normalise::Normalise>(&vectors::normalise::MODEL).proof;
    assert_eq!(proof.values["uut.s1_m$0.d"].range(false), (0, 512));
    assert_eq!(proof.values["uut.s2_sq$1.q"].range(false), (0, 512 * 512));
    let flagged: Vec<&str> = proof.wraps.keys().map(|(_, n)| n.as_str()).collect();
    assert!(!flagged.iter().any(|n| n.contains("s1_m") || n.contains("s2_sq") || n.contains("s3_s")), "{flagged:?}");
    let n = proof.values["uut.s8_n$0.q"].range(false);
    assert!(n.0 == 0 && n.1 < 2048, "{n:?}");
    assert!(!flagged.iter().any(|n| n.contains("s9_out")), "{flagged:?}");
}
