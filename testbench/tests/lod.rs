//! lod: the level of detail three ways, the hard cases of the rule (a zero footprint, ρ exactly at a level and a
//! step either side, λ below 0 and past the last level, the largest derivatives, maps of 1 × 1 and 2 × 2), ≥ 100,000
//! random footprints, and the table entry by entry against the model's.
use rtl::lod::Lod;
use testbench::{rust_hdl, unit_tests, Bubbles};
use vectors::lod::MODEL;

unit_tests!(lod, Lod, MODEL);

#[test]
fn lod_random_vs_model() {
    testbench::random_vs_model::<Lod>(&MODEL, 16, 2_000);
    testbench::random_vs_model_verilator::<Lod>(&MODEL, 100_000, 11);
}

#[test]
fn lod_hard_cases_back_to_back_and_worked_by_hand() {
    let inputs = (MODEL.hard_cases)();
    rust_hdl::<Lod>(&MODEL, &inputs, Bubbles::BackToBack).assert_clean("hard cases");
    // worked by hand: u_x = 3, v_x = 4 texels a pixel: ρ = 5, λ = log2 5 = 2.3219; m = 25·2^8, leading one at
    // bit 12 (p − 8 = 4 = 2·2), the 8 bits below it 0b1001_0000 = 144: T = round(log2(1 + 144.5/256)·512) = 331;
    // λ·2^10 = 4·512 + 331 = 2,379: level 2, frac (2,379 − 2,048) >> 2 = 82 (0.3203 of a level), nearest 2
    assert_eq!((MODEL.exact)(&[3 * 256, 4 * 256, 0, 0, 8, 0]), vec![2, 82, 2]);
    // the same footprint on a 2 × 2 map (n = 1): the last level, no fraction; on a 1 × 1 map: level 0
    assert_eq!((MODEL.exact)(&[3 * 256, 4 * 256, 0, 0, 1, 0]), vec![1, 0, 1]);
    assert_eq!((MODEL.exact)(&[3 * 256, 4 * 256, 0, 0, 0, 0]), vec![0, 0, 0]);
    // ρ = 1.5 (λ = 0.585): m = 2.25·2^8, p = 9, f = 0b0010_0000 = 32: T = round(log2(1 + 32.5/256)·512) = 88;
    // λ·2^10 = 512 + 88 = 600: level 0, frac 600 >> 2 = 150 (0.586 of a level), nearest (600 + 512) >> 10 = 1
    assert_eq!((MODEL.exact)(&[0, 0, 384, 0, 8, 0]), vec![0, 150, 1]);
    // the bias, in 1/256 of a level, joins λ·2^10 as bias·4. ρ = 5 at −1.25 levels (−320): 2,379 − 1,280 = 1,099:
    // level 1, frac (1,099 − 1,024) >> 2 = 18, nearest (1,099 + 512) >> 10 = 1; at +2 levels (512): 2,379 + 2,048 =
    // 4,427: level 4, frac (4,427 − 4,096) >> 2 = 82, nearest (4,427 + 512) >> 10 = 4
    assert_eq!((MODEL.exact)(&[3 * 256, 4 * 256, 0, 0, 8, -320]), vec![1, 18, 1]);
    assert_eq!((MODEL.exact)(&[3 * 256, 4 * 256, 0, 0, 8, 512]), vec![4, 82, 4]);
    // ρ = 1.5 at −1 level (−256): 600 − 1,024 < 0, below level 0: level 0, no fraction, nearest 0
    assert_eq!((MODEL.exact)(&[0, 0, 384, 0, 8, -256]), vec![0, 0, 0]);
    // ρ = 1/16 (u_x = 16/256): m = 1, p = 0, f = 0: T = round(log2(1 + 0.5/256)·512) = round(1.441) = 1;
    // λ·2^10 = −8·512 + 1 = −4,095, a negative exponent; at the largest bias, 2,047 (8 − 1/256 levels):
    // −4,095 + 8,188 = 4,093: level 3, frac (4,093 − 3,072) >> 2 = 255, nearest (4,093 + 512) >> 10 = 4
    assert_eq!((MODEL.exact)(&[16, 0, 0, 0, 8, 2047]), vec![3, 255, 4]);
}

#[test]
fn lod_table_is_the_models_entry_by_entry() {
    let r = rtl::lod::table();
    assert_eq!(r.len(), 256);
    for (f, &e) in r.iter().enumerate() {
        assert_eq!(e as i64, vectors::lod::table_entry(f as u64), "entry {f}");
    }
}
