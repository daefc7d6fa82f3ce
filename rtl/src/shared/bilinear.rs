//! `bilinear`: the texture filter's bilinear units (US 2004/0207631, units 65–68).
//!
//! `BilinearUnit<W, F, D>` is one unit: one channel of `W` bits (W ≤ 8), `F` blend-factor bits (F ≤ 9), the patent's
//! "four (usually identical) bilinear units, each of which computes one of the four colour channels". The colour
//! filter holds four, the Cartesian pipeline two (its texel's two components), and the height-map normal generator
//! will feed the same four with heights. Per channel:
//! `a = t00·2^F + (t10 − t00)·u`, `b = t01·2^F + (t11 − t01)·u` (exact, U(W+F)), then
//! `a' = a >> D`, `b' = b >> D` (truncation: `D` bits dropped so that |b' − a'| fits the multiplier's 16 bits; exact
//! when u is a multiple of 2^D, as in colour mode with F = 9), then `wide = a'·2^F + (b' − a')·v` (U(W + 2F − D),
//! exact) and `out = (wide + 2^(2F−D−1)) >> (2F − D)` (UW, rounded half up). With D = 0 this is the model's
//! `a·(2^F − v) + b·v` rounded half up. The colour filter reads `out`; the height-map path reads `wide`, whose
//! 2F − D fraction bits the tangents need.
//! The rounding constant goes into a' before the last product arrives: `a'_h = a' + 2^(F−D−1)`, so that
//! `a'_h·2^F = a'·2^F + 2^(2F−D−1)` and the last stage is one add or subtract for each output, not two in a row.
//! Latency 13: widen; differences; the two `SmMul`s (4: |d|, operand registers, ·u, the product carried); a and b;
//! b − a; the `SmMul` (|b − a|, operand registers, ·v, carried); the rounded sum.
//!
//! `Bilinear` is the unit `bilinear`: four `BilinearUnit<8, 8>` on the RGBA channels, with one valid flag.
//! Values are carried in 16/32-bit containers (rust-hdl multiplies only 16 × 16 → 32); the comments give their real
//! widths, and yosys removes the constant upper bits.

use crate::prim::delay::Delay;
use crate::prim::q::{SBits, U8};
use crate::prim::sm_mul::{self, SmMul};
use rust_hdl::prelude::*;

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 2 + sm_mul::LATENCY + 2 + sm_mul::LATENCY + 1;

crate::block! {
    /// One bilinear unit: `W`-bit texels, `F`-bit blend factors (`u`, `v` ∈ 0..2^F, the second texel's weight u/2^F),
    /// `D` bits dropped between its two stages.
    pub struct BilinearUnit<const W: usize, const F: usize, const D: usize = 0> {
        pub clock: Signal<In, Clock>,
        pub t00: Signal<In, Bits<W>>,
        pub t10: Signal<In, Bits<W>>,
        pub t01: Signal<In, Bits<W>>,
        pub t11: Signal<In, Bits<W>>,
        pub ublend: Signal<In, Bits<F>>,
        pub vblend: Signal<In, Bits<F>>,
        /// The filtered channel, LATENCY clocks later (UW, rounded half up).
        pub out: Signal<Out, Bits<W>>,
        /// The same, exact before the rounding: U(W + 2F − D), 2F − D fraction bits.
        pub wide: Signal<Out, Bits<32>>,
        shift_f: Constant<Bits<8>>,   // F
        shift_d: Constant<Bits<8>>,   // D
        shift_out: Constant<Bits<5>>, // 2F − D, an index into 32 bits
        half: Constant<Bits<17>>,     // 2^(F−D−1): the rounding constant 2^(2F−D−1) before the · 2^F
        u: Delay<Bits<16>, 2>,        // u, to meet the differences at the multipliers (UF)
        v: Delay<Bits<16>, { 4 + sm_mul::LATENCY }>, // v, to meet b − a (UF)
        // stage 1: the texels widened (UW in 16 bits), the two bases (UW in 32)
        s1_t00: DFF<Bits<16>>,
        s1_t10: DFF<Bits<16>>,
        s1_t01: DFF<Bits<16>>,
        s1_t11: DFF<Bits<16>>,
        s1_b0: DFF<Bits<32>>,
        s1_b1: DFF<Bits<32>>,
        // stage 2: t10 − t00, t11 − t01 (S(W), two's complement in 16 bits; |d| ≤ 2^W − 1 fits SmMul's 16)
        s2_d0: DFF<SBits<16>>,
        s2_d1: DFF<SBits<16>>,
        s2_b0: DFF<Bits<32>>,
        s2_b1: DFF<Bits<32>>,
        // stages 3–6: |d|·u ≤ (2^W − 1)(2^F − 1) < 2^(W+F), with the bases carried beside the multipliers
        mul0: SmMul<16>,
        mul1: SmMul<16>,
        b0: Delay<Bits<32>, { sm_mul::LATENCY }>,
        b1: Delay<Bits<32>, { sm_mul::LATENCY }>,
        w_base0: Signal<Local, Bits<32>>, // t00·2^F (U(W+F))
        w_base1: Signal<Local, Bits<32>>, // t01·2^F (U(W+F))
        // stage 7: a, b ∈ 0..(2^W − 1)·2^F (U(W+F) ≤ U17: W ≤ 8, F ≤ 9), exact; the sums in 32 bits before
        s6_a: DFF<Bits<17>>,
        s6_b: DFF<Bits<17>>,
        w_sa: Signal<Local, Bits<32>>,
        w_sb: Signal<Local, Bits<32>>,
        // stage 8: b' − a' (S(W+F−D), two's complement in 32 bits; |b' − a'| ≤ (2^W − 1)·2^(F−D) < 2^16 fits SmMul's
        // 16)
        s7_e: DFF<SBits<17>>,
        s7_a: DFF<Bits<17>>,
        s7_ah: DFF<Bits<17>>, // a' + 2^(F−D−1) < 2^16 + 2^15 (U17), exact
        // stages 9–12: |b − a|·v < 2^(W+2F), a and a_h carried (a block reading only one output keeps one of them)
        mul2: SmMul<17>,
        a: Delay<Bits<17>, { sm_mul::LATENCY }>,
        ah: Delay<Bits<17>, { sm_mul::LATENCY }>,
        w_ad: Signal<Local, Bits<17>>,   // a >> D (U(W+F−D)), truncated
        w_bd: Signal<Local, Bits<17>>,   // b >> D, truncated
        w_a: Signal<Local, Bits<32>>,    // a'·2^F (U(W+2F−D))
        w_ah: Signal<Local, Bits<32>>,   // a'_h·2^F = a'·2^F + 2^(2F−D−1) (U(W+2F−D+1))
        w_wide: Signal<Local, Bits<32>>, // a'·2^F ± |b' − a'|·v ∈ 0..2^(W+2F−D) (≤ 25 bits), exact
        w_r: Signal<Local, Bits<32>>,    // a'_h·2^F ± |b' − a'|·v = wide + 2^(2F−D−1) < 2^26, exact
        // stage 13: the top W bits of W + 2F − D: truncation of the rounded sum, so round half up overall; and wide
        s11_out: DFF<Bits<W>>,
        s11_wide: DFF<Bits<32>>,
    }
}

impl<const W: usize, const F: usize, const D: usize> Default for BilinearUnit<W, F, D> {
    fn default() -> Self {
        assert!(
            W <= 8 && (1..=9).contains(&F) && D < F && W + F - D <= 16,
            "BilinearUnit<{W}, {F}, {D}>: W ≤ 8, 1 ≤ F ≤ 9 and W + F − D ≤ 16 keep |b' − a'| in 16 bits"
        );
        Self {
            clock: Default::default(),
            t00: Default::default(),
            t10: Default::default(),
            t01: Default::default(),
            t11: Default::default(),
            ublend: Default::default(),
            vblend: Default::default(),
            out: Default::default(),
            wide: Default::default(),
            shift_f: Constant::new(Bits::from(F as u64)),
            shift_d: Constant::new(Bits::from(D as u64)),
            shift_out: Constant::new(Bits::from((2 * F - D) as u64)),
            half: Constant::new(Bits::from(1u64 << (F - D - 1))),
            u: Default::default(),
            v: Default::default(),
            s1_t00: Default::default(),
            s1_t10: Default::default(),
            s1_t01: Default::default(),
            s1_t11: Default::default(),
            s1_b0: Default::default(),
            s1_b1: Default::default(),
            s2_d0: Default::default(),
            s2_d1: Default::default(),
            s2_b0: Default::default(),
            s2_b1: Default::default(),
            mul0: Default::default(),
            mul1: Default::default(),
            b0: Default::default(),
            b1: Default::default(),
            w_base0: Default::default(),
            w_base1: Default::default(),
            s6_a: Default::default(),
            s6_b: Default::default(),
            w_sa: Default::default(),
            w_sb: Default::default(),
            s7_e: Default::default(),
            s7_a: Default::default(),
            s7_ah: Default::default(),
            mul2: Default::default(),
            a: Default::default(),
            ah: Default::default(),
            w_ad: Default::default(),
            w_bd: Default::default(),
            w_a: Default::default(),
            w_ah: Default::default(),
            w_wide: Default::default(),
            w_r: Default::default(),
            s11_out: Default::default(),
            s11_wide: Default::default(),
        }
    }
}

impl<const W: usize, const F: usize, const D: usize> Logic for BilinearUnit<W, F, D> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, u, v, s1_t00, s1_t10, s1_t01, s1_t11, s1_b0, s1_b1, s2_d0, s2_d1, s2_b0, s2_b1);
        clock!(self, clock, mul0, mul1, b0, b1, s6_a, s6_b, s7_e, s7_a, s7_ah, mul2, a, ah, s11_out, s11_wide);
        self.u.d.next = bit_cast::<16, F>(self.ublend.val()); // UF in 16, widening
        self.v.d.next = bit_cast::<16, F>(self.vblend.val()); // UF in 16, widening

        // stage 1: widening only
        self.s1_t00.d.next = bit_cast::<16, W>(self.t00.val());
        self.s1_t10.d.next = bit_cast::<16, W>(self.t10.val());
        self.s1_t01.d.next = bit_cast::<16, W>(self.t01.val());
        self.s1_t11.d.next = bit_cast::<16, W>(self.t11.val());
        self.s1_b0.d.next = bit_cast::<32, W>(self.t00.val());
        self.s1_b1.d.next = bit_cast::<32, W>(self.t01.val());
        // stage 2: S(W) differences, wrapping in 16 bits to their two's complement
        self.s2_d0.d.next = self.s1_t10.q.val() - self.s1_t00.q.val();
        self.s2_d1.d.next = self.s1_t11.q.val() - self.s1_t01.q.val();
        self.s2_b0.d.next = self.s1_b0.q.val();
        self.s2_b1.d.next = self.s1_b1.q.val();
        // stages 3–6: |d|·u, the bases beside
        self.mul0.x.next = self.s2_d0.q.val();
        self.mul0.w.next = self.u.q.val();
        self.mul1.x.next = self.s2_d1.q.val();
        self.mul1.w.next = self.u.q.val();
        self.b0.d.next = self.s2_b0.q.val();
        self.b1.d.next = self.s2_b1.q.val();
        // stage 7: t·2^F ± |d|·u, exact (U(W+F); the result is a weighted mean of two UW values times 2^F)
        self.w_base0.next = self.b0.q.val() << self.shift_f.val();
        self.w_base1.next = self.b1.q.val() << self.shift_f.val();
        if self.mul0.neg.val() {
            self.w_sa.next = self.w_base0.val() - self.mul0.p.val();
        } else {
            self.w_sa.next = self.w_base0.val() + self.mul0.p.val();
        }
        if self.mul1.neg.val() {
            self.w_sb.next = self.w_base1.val() - self.mul1.p.val();
        } else {
            self.w_sb.next = self.w_base1.val() + self.mul1.p.val();
        }
        self.s6_a.d.next = self.w_sa.val().get_bits::<17>(0); // the weighted mean's U(W+F) ≤ U17: exact
        self.s6_b.d.next = self.w_sb.val().get_bits::<17>(0); // the same

        // stage 8: b − a, wrapping in 32 bits to its two's complement
        self.w_ad.next = self.s6_a.q.val() >> self.shift_d.val(); // U(W+F) → U(W+F−D), truncated
        self.w_bd.next = self.s6_b.q.val() >> self.shift_d.val(); // the same
        self.s7_e.d.next = self.w_bd.val() - self.w_ad.val(); // S(W+F−D), |b' − a'| < 2^16: wrapping in 17 bits to its two's complement
        self.s7_a.d.next = self.w_ad.val();
        self.s7_ah.d.next = self.w_ad.val() + self.half.val(); // + 2^(F−D−1): < 2^17, exact

        // stages 9–12: |b − a|·v, a and a_h beside
        self.mul2.x.next = self.s7_e.q.val();
        self.mul2.w.next = self.v.q.val();
        self.a.d.next = self.s7_a.q.val();
        self.ah.d.next = self.s7_ah.q.val();
        // stage 13: a'·2^F ± |b' − a'|·v (wide); a'_h·2^F ± |b' − a'|·v (wide + 2^(2F−D−1)), then its bits
        // 2F − D.. (truncation of the rounded sum: round half up)
        self.w_a.next = bit_cast::<32, 17>(self.a.q.val()) << self.shift_f.val(); // U17 in 32, widening, then · 2^F
        self.w_ah.next = bit_cast::<32, 17>(self.ah.q.val()) << self.shift_f.val(); // the same
        if self.mul2.neg.val() {
            self.w_wide.next = self.w_a.val() - self.mul2.p.val(); // U(W+2F−D), exact (a weighted mean)
            self.w_r.next = self.w_ah.val() - self.mul2.p.val(); // that + 2^(2F−D−1): < 2^26, exact
        } else {
            self.w_wide.next = self.w_a.val() + self.mul2.p.val(); // the same
            self.w_r.next = self.w_ah.val() + self.mul2.p.val(); // the same
        }
        self.s11_out.d.next = self.w_r.val().get_bits::<W>(self.shift_out.val().index()); // >> (2F − D): UW, the rounding's floor
        self.s11_wide.d.next = self.w_wide.val();
        self.out.next = self.s11_out.q.val();
        self.wide.next = self.s11_wide.q.val();
    }
}

/// The signals the block's Verilog leaves unused on purpose (`StreamUnit::waivers`).
const WAIVERS: &[crate::stream::Waiver] = &[
    (
        "unit$0$wide",
        "the colour filter reads each bilinear unit's rounded output; the exact one is the height-map path's",
    ),
    ("unit$1$wide", "as unit$0$wide"),
    ("unit$2$wide", "as unit$0$wide"),
    ("unit$3$wide", "as unit$0$wide"),
];

crate::stream_block! {
    /// The unit `bilinear`: the colour filter's four bilinear units on R, G, B and A, 8-bit texels, 8-bit blend
    /// positions. `Bilinear<F, D>` keeps the top F bits of each position (truncation) and drops D bits between the
    /// two stages: the unit has F = 8, D = 0; the other settings are the width sweep's.
    pub struct Bilinear<const F: usize = 8, const D: usize = 0>: unit("bilinear", LATENCY, waivers = WAIVERS) {
        in {
            t00_r: U8,
            t00_g: U8,
            t00_b: U8,
            t00_a: U8,
            t10_r: U8,
            t10_g: U8,
            t10_b: U8,
            t10_a: U8,
            t01_r: U8,
            t01_g: U8,
            t01_b: U8,
            t01_a: U8,
            t11_r: U8,
            t11_g: U8,
            t11_b: U8,
            t11_a: U8,
            ublend: U8,
            vblend: U8,
        }
        out {
            out_r: U8,
            out_g: U8,
            out_b: U8,
            out_a: U8,
        }
        pub unit: [BilinearUnit<8, F, D>; 4], // R, G, B, A
        valid: Delay<Bit, LATENCY>,           // the valid flag, beside the units
        blend_at: Constant<Bits<3>>,          // 8 − F: the position's top F bits (an index into 8 bits)
    }
}

impl<const F: usize, const D: usize> Default for Bilinear<F, D> {
    fn default() -> Self {
        assert!((1..=8).contains(&F), "Bilinear<F, D>: 1 to 8 blend bits of the 8-bit position (F = {F})");
        Self {
            clock: Default::default(),
            valid_in: Default::default(),
            valid_out: Default::default(),
            t00_r: Default::default(),
            t00_g: Default::default(),
            t00_b: Default::default(),
            t00_a: Default::default(),
            t10_r: Default::default(),
            t10_g: Default::default(),
            t10_b: Default::default(),
            t10_a: Default::default(),
            t01_r: Default::default(),
            t01_g: Default::default(),
            t01_b: Default::default(),
            t01_a: Default::default(),
            t11_r: Default::default(),
            t11_g: Default::default(),
            t11_b: Default::default(),
            t11_a: Default::default(),
            ublend: Default::default(),
            vblend: Default::default(),
            out_r: Default::default(),
            out_g: Default::default(),
            out_b: Default::default(),
            out_a: Default::default(),
            unit: Default::default(),
            valid: Default::default(),
            blend_at: Constant::new(Bits::from(8 - F as u64)),
        }
    }
}

impl<const F: usize, const D: usize> Logic for Bilinear<F, D> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, valid);
        for i in 0..4 {
            self.unit[i].clock.next = self.clock.val();
            // the top F bits of each blend factor, floor
            self.unit[i].ublend.next = self.ublend.val().get_bits::<F>(self.blend_at.val().index());
            self.unit[i].vblend.next = self.vblend.val().get_bits::<F>(self.blend_at.val().index());
        }
        self.valid.d.next = self.valid_in.val();
        self.unit[0].t00.next = self.t00_r.val();
        self.unit[0].t10.next = self.t10_r.val();
        self.unit[0].t01.next = self.t01_r.val();
        self.unit[0].t11.next = self.t11_r.val();
        self.unit[1].t00.next = self.t00_g.val();
        self.unit[1].t10.next = self.t10_g.val();
        self.unit[1].t01.next = self.t01_g.val();
        self.unit[1].t11.next = self.t11_g.val();
        self.unit[2].t00.next = self.t00_b.val();
        self.unit[2].t10.next = self.t10_b.val();
        self.unit[2].t01.next = self.t01_b.val();
        self.unit[2].t11.next = self.t11_b.val();
        self.unit[3].t00.next = self.t00_a.val();
        self.unit[3].t10.next = self.t10_a.val();
        self.unit[3].t01.next = self.t01_a.val();
        self.unit[3].t11.next = self.t11_a.val();
        self.out_r.next = self.unit[0].out.val();
        self.out_g.next = self.unit[1].out.val();
        self.out_b.next = self.unit[2].out.val();
        self.out_a.next = self.unit[3].out.val();
        self.valid_out.next = self.valid.q.val();
    }
}
