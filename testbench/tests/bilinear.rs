//! bilinear: at least 100,000 proptest-driven vectors through rust-hdl, 100,000 under Verilator, hard cases.
use rtl::bilinear::Bilinear;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::bilinear::MODEL;

unit_tests!(bilinear, Bilinear, MODEL);

#[test]
fn bilinear_random_vs_model() {
    random_vs_model::<Bilinear>(&MODEL, 50, 2_000);
}

#[test]
fn bilinear_random_vs_model_verilator() {
    random_vs_model_verilator::<Bilinear>(&MODEL, 100_000, 11);
}

#[test]
fn bilinear_hard_cases() {
    rust_hdl::<Bilinear>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
    let e = |v: &[i64]| (MODEL.exact)(v);
    // u = v = 0 returns t00 exactly; the largest factors (255/256) stay within the four texels
    assert_eq!(e(&[vec![7, 8, 9, 10], vec![255; 12], vec![0, 0]].concat()), vec![7, 8, 9, 10]);
    assert_eq!(e(&[vec![255; 16], vec![255, 255]].concat()), vec![255; 4]);
    // half-way between 0 and 1 rounds up
    assert_eq!(e(&[vec![0; 4], vec![1; 4], vec![0; 4], vec![1; 4], vec![128, 0]].concat()), vec![1; 4]);
    // 0 → 255 at u = 255/256: 254.0 exactly
    assert_eq!(e(&[vec![0; 4], vec![255; 4], vec![0; 4], vec![255; 4], vec![255, 0]].concat()), vec![254; 4]);
}

/// One `BilinearUnit<W, F, D>` driven directly, one vector per clock: (t00, t10, t01, t11, u, v) → (out, wide).
fn run_unit<const W: usize, const F: usize, const D: usize>(vecs: &[[i64; 6]]) -> Vec<(i64, i64)> {
    use rtl::bilinear::{BilinearUnit, LATENCY};
    use rust_hdl::prelude::*;
    let mut uut = BilinearUnit::<W, F, D>::default();
    uut.connect_all();
    let mut out = vec![];
    for k in 0..vecs.len() + LATENCY - 1 {
        let x = vecs.get(k).copied().unwrap_or([0; 6]);
        uut.t00.next = Bits::from(x[0] as u64);
        uut.t10.next = Bits::from(x[1] as u64);
        uut.t01.next = Bits::from(x[2] as u64);
        uut.t11.next = Bits::from(x[3] as u64);
        uut.ublend.next = Bits::from(x[4] as u64);
        uut.vblend.next = Bits::from(x[5] as u64);
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 10_000));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 10_000));
        if k + 1 >= LATENCY {
            out.push((uut.out.val().to_u64() as i64, uut.wide.val().to_u64() as i64));
        }
    }
    out
}

/// The unit at other widths than the colour filter's: every blend-factor pair on the texels' extremes and on a
/// random draw, against the model's channel at the same F and D, both outputs. 4-bit texels are 4-bit heights.
fn unit_matches_the_model_at<const W: usize, const F: usize, const D: usize>() {
    use rand::{Rng, SeedableRng};
    let top = (1i64 << W) - 1;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(W as u64 * 100 + F as u64);
    let mut vecs = vec![];
    for corners in 0..16 {
        let t: Vec<i64> = (0..4).map(|b| if corners >> b & 1 == 1 { top } else { 0 }).collect();
        for u in 0..1i64 << F {
            for v in 0..1i64 << F {
                vecs.push([t[0], t[1], t[2], t[3], u, v]);
            }
        }
    }
    for _ in 0..20_000 {
        let t: [i64; 4] = std::array::from_fn(|_| rng.gen_range(0..=top));
        vecs.push([t[0], t[1], t[2], t[3], rng.gen_range(0..1 << F), rng.gen_range(0..1 << F)]);
    }
    let got = run_unit::<W, F, D>(&vecs);
    assert_eq!(got.len(), vecs.len());
    let (f, d) = (F as u32, D as u32);
    for (x, g) in vecs.iter().zip(got) {
        let out = vectors::bilinear::exact_channel_with(x[0], x[1], x[2], x[3], x[4], x[5], f, d);
        let wide = vectors::bilinear::exact_wide(x[0], x[1], x[2], x[3], x[4], x[5], f, d);
        assert_eq!(g, (out, wide), "BilinearUnit<{W}, {F}, {D}> on {x:?}");
    }
}

#[test]
fn bilinear_unit_at_4_bit_texels_and_4_blend_bits() {
    unit_matches_the_model_at::<4, 4, 0>();
}

#[test]
fn bilinear_unit_at_8_bit_texels_and_6_blend_bits() {
    unit_matches_the_model_at::<8, 6, 0>();
}

#[test]
fn bilinear_unit_at_9_blend_bits_one_dropped() {
    // the shared unit of the texture filter: 9 blend bits (the height path's adjusted factors, ½ + u/2, exact) and
    // one bit dropped between the stages so that |b' − a'| fits 16 bits
    unit_matches_the_model_at::<8, 9, 1>();
}

#[test]
fn nine_blend_bits_with_one_dropped_filter_colour_exactly_as_eight() {
    // colour mode through the shared unit: u, v at 9 bits are the 8-bit factors doubled, so a and b are even and
    // dropping their last bit loses nothing: the rounded output is the 8-bit unit's, on every factor pair
    let t = [[0, 255, 17, 200], [255, 255, 255, 255], [3, 250, 128, 0], [1, 0, 0, 1]];
    for q in t {
        for u in 0..256 {
            for v in 0..256 {
                let e8 = vectors::bilinear::exact_channel(q[0], q[1], q[2], q[3], u, v, 8);
                let e9 = vectors::bilinear::exact_channel_with(q[0], q[1], q[2], q[3], 2 * u, 2 * v, 9, 1);
                assert_eq!(e8, e9, "{q:?} u {u} v {v}");
            }
        }
    }
}

// Other widths of the same block (the width sweep's): fewer blend bits, bits dropped between the stages.
fn exact_at<const F: u32, const D: u32>(i: &[i64]) -> Vec<i64> {
    vectors::bilinear::exact_sized(i, F, D)
}

const fn sized(exact: fn(&[i64]) -> Vec<i64>) -> vectors::UnitModel {
    vectors::UnitModel { exact, accuracy: None, ..vectors::bilinear::MODEL }
}

static F6: vectors::UnitModel = sized(exact_at::<6, 0>);
static F8D4: vectors::UnitModel = sized(exact_at::<8, 4>);

#[test]
fn other_widths_three_ways() {
    let v = vectors::unit::generate(&vectors::bilinear::MODEL, false, 3_000, 19).unwrap();
    testbench::three_ways::<rtl::bilinear::Bilinear<6, 0>>(&F6, &v, "bilinear_f6");
    testbench::three_ways::<rtl::bilinear::Bilinear<8, 4>>(&F8D4, &v, "bilinear_f8d4");
    let own = vectors::bilinear::MODEL.exact;
    assert!(v.iter().any(|i| (F6.exact)(i) != own(i)) && v.iter().any(|i| (F8D4.exact)(i) != own(i)));
}
