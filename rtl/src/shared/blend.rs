//! `blend`: the shade as alpha, combined with colours. `mode` 0 modulates, `out = round(src·α/255)`; mode 1
//! alpha-lerps, `out = round((src·α + dst·(255 − α))/255)`. The /255 is `t = num + 128; (t + (t >> 8)) >> 8`.
//!
//! Three products, not six: with d = (mode ? dst : 0), both numerators are 255·d + (src − d)·α, the same integer
//! (src·α + d·(255 − α), so 0 ..= 255·255), so each channel takes one product |src − d|·α, its sign beside it, and
//! 255·d = 256·d − d by a subtraction. The iCE40 UP5K has 8 SB_MAC16 blocks: the three saved are what let its
//! Cartesian pipelines keep their other products in them.
//!
//! Latency 6: src − d, d − src and the sign; the larger of the two, |src − d|, in the multipliers' operand register
//! (it feeds nothing else, so it can sit beside the DSP); products, and 255·d + 128 (+ 1 where the product is
//! subtracted); the products again (see `rtl/README.md`: the route out of a DSP, and on the UP5K the sum of the
//! pieces of a product built in logic, on a clock of their own); t = 255·d + 128 ± product; the /255. The + 128 rides in the 255·d beside the product: with the sum and the + 128 in one clock after
//! the product there were two adders in a row behind the route from the multiplier, `cart_pipeline`'s critical path
//! on the ECP5 (2.11 ns of logic, 4.13 ns of routing, 160 MHz).

use crate::prim::delay::Delay;
use crate::prim::q::{U16, U8};
use rust_hdl::prelude::*;

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 6;

crate::stream_block! {
    #[derive(Default)]
    pub struct Blend: unit("blend", LATENCY) {
        in {
            alpha: U8,
            mode: Bits<1>,
            src_r: U8,
            src_g: U8,
            src_b: U8,
            dst_r: U8,
            dst_g: U8,
            dst_b: U8,
        }
        out {
            out_r: U8,
            out_g: U8,
            out_b: U8,
        }
        // stage 1: α, widened to the multiplier's 16 bits; per channel src − d and d − src modulo 2^16 (U16; the
        // one that is not negative is |src − d| ≤ 255), the sign (src < d), and d. The width report shows 8 spare bits in the operand registers; they stay 16 wide because
        // narrowing them to U8 (widened by wires at the multipliers) was measured worse: 165 → 189 SB_DFF on the
        // UP5K, LUT4 unchanged at 60 (yosys already drops the constant top bytes of these)
        s1_wa: DFF<U16>,
        s1_dp: [DFF<U16>; 3],
        s1_dn: [DFF<U16>; 3],
        s1_neg: [DFF<Bit>; 3],
        s1_d: [DFF<U16>; 3], // ≤ 255
        // stage 1b: the operands, α once per multiplier (`mop_`: see `rtl/README.md`) and |src − d|
        mop_wa: [DFF<U16>; 3],
        s1b_m: [DFF<U16>; 3],
        s1b_neg: [DFF<Bit>; 3],
        s1b_d: [DFF<U16>; 3],
        // stage 2: |src − d|·α ≤ 255·255 (U16); 255·d + 128 + [src < d] ≤ 65,154 (U16)
        s2_p: [DFF<U16>; 3],
        s2_k: [DFF<U16>; 3],
        s2_neg: [DFF<Bit>; 3],
        // stage 2b: the products again, each in two registers (bits 0..7, 8..15: see `dot3` for why two)
        s2b_lo: [DFF<U8>; 3],
        s2b_hi: [DFF<U8>; 3],
        s2b_k: [DFF<U16>; 3],
        s2b_neg: [DFF<Bit>; 3],
        // stage 3: t = 255·d + 128 ± |src − d|·α = src·α + d·(255 − α) + 128 ≤ 65,153 (U16)
        s3_t: [DFF<U16>; 3],
        // stage 4: (t + (t >> 8)) >> 8, truncating: U8
        s4_out: [DFF<U8>; 3],
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
        w_src: [Signal<Local, U16>; 3], // src, d and |src − d| widened to the multiplier's 16 bits
        w_d: [Signal<Local, U16>; 3],
        w_m: [Signal<Local, U16>; 3], // |src − d|, chosen in stage 1b
        w_pw: [Signal<Local, Bits<32>>; 3],
        w_k: [Signal<Local, U16>; 3],
        w_p: [Signal<Local, U16>; 3], // a product out of its two stage-2b registers
        w_x: [Signal<Local, U16>; 3], // the product, or its ones' complement where src < d
        w_t: [Signal<Local, U16>; 3],
        w_th: [Signal<Local, U16>; 3],
        w_u: [Signal<Local, U16>; 3],
    }
}

impl Logic for Blend {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_wa);
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1
        self.s1_wa.d.next = bit_cast::<16, 8>(self.alpha.val());
        self.w_src[0].next = bit_cast::<16, 8>(self.src_r.val());
        self.w_src[1].next = bit_cast::<16, 8>(self.src_g.val());
        self.w_src[2].next = bit_cast::<16, 8>(self.src_b.val());
        if self.mode.val().any() {
            self.w_d[0].next = bit_cast::<16, 8>(self.dst_r.val());
            self.w_d[1].next = bit_cast::<16, 8>(self.dst_g.val());
            self.w_d[2].next = bit_cast::<16, 8>(self.dst_b.val());
        } else {
            self.w_d[0].next = 0.into();
            self.w_d[1].next = 0.into();
            self.w_d[2].next = 0.into();
        }
        // stage 3's product, out of its two stage-2b registers
        self.w_p[0].next = (bit_cast::<16, 8>(self.s2b_hi[0].q.val()) << 8) | bit_cast::<16, 8>(self.s2b_lo[0].q.val());
        self.w_p[1].next = (bit_cast::<16, 8>(self.s2b_hi[1].q.val()) << 8) | bit_cast::<16, 8>(self.s2b_lo[1].q.val());
        self.w_p[2].next = (bit_cast::<16, 8>(self.s2b_hi[2].q.val()) << 8) | bit_cast::<16, 8>(self.s2b_lo[2].q.val());
        for i in 0..3 {
            self.s1_dp[i].clock.next = self.clock.val();
            self.s1_dn[i].clock.next = self.clock.val();
            self.s1_neg[i].clock.next = self.clock.val();
            self.s1_d[i].clock.next = self.clock.val();
            self.mop_wa[i].clock.next = self.clock.val();
            self.s1b_m[i].clock.next = self.clock.val();
            self.s1b_neg[i].clock.next = self.clock.val();
            self.s1b_d[i].clock.next = self.clock.val();
            self.s2_p[i].clock.next = self.clock.val();
            self.s2_k[i].clock.next = self.clock.val();
            self.s2_neg[i].clock.next = self.clock.val();
            self.s2b_lo[i].clock.next = self.clock.val();
            self.s2b_hi[i].clock.next = self.clock.val();
            self.s2b_k[i].clock.next = self.clock.val();
            self.s2b_neg[i].clock.next = self.clock.val();
            self.s3_t[i].clock.next = self.clock.val();
            self.s4_out[i].clock.next = self.clock.val();
            // stage 1: both differences (modulo 2^16: the one chosen below is exact, 0 ..= 255) and the sign, side by
            // side; the choice waits a clock, so that the mode's choice of d, a carry chain and the choice of the
            // larger are not one path (the UP5K's, at 17 ns)
            self.s1_dp[i].d.next = self.w_src[i].val() - self.w_d[i].val();
            self.s1_dn[i].d.next = self.w_d[i].val() - self.w_src[i].val();
            self.s1_neg[i].d.next = self.w_src[i].val() < self.w_d[i].val();
            self.s1_d[i].d.next = self.w_d[i].val();
            // stage 1b: the larger minus the smaller, α and d carried
            if self.s1_neg[i].q.val() {
                self.w_m[i].next = self.s1_dn[i].q.val();
            } else {
                self.w_m[i].next = self.s1_dp[i].q.val();
            }
            self.mop_wa[i].d.next = self.s1_wa.q.val();
            self.s1b_m[i].d.next = self.w_m[i].val() & 255; // ≤ 255 already: the mask shows synthesis an 8-bit operand
            self.s1b_neg[i].d.next = self.s1_neg[i].q.val();
            self.s1b_d[i].d.next = self.s1_d[i].q.val();
            // stage 2: the product (≤ 255·255, so its low 16 bits are all of it), and k = 256·d + 128 + neg − d
            // (≤ 65,154, exact: d·256 has its low byte clear, so the OR is an add)
            self.w_pw[i].next = self.s1b_m[i].q.val() * self.mop_wa[i].q.val();
            self.s2_p[i].d.next = self.w_pw[i].val().get_bits::<16>(0);
            if self.s1b_neg[i].q.val() {
                self.w_k[i].next = (self.s1b_d[i].q.val() << 8) | 129;
            } else {
                self.w_k[i].next = (self.s1b_d[i].q.val() << 8) | 128;
            }
            self.s2_k[i].d.next = self.w_k[i].val() - self.s1b_d[i].q.val();
            self.s2_neg[i].d.next = self.s1b_neg[i].q.val();
            // stage 2b: carried, the product in two halves
            self.s2b_lo[i].d.next = self.s2_p[i].q.val().get_bits::<8>(0);
            self.s2b_hi[i].d.next = self.s2_p[i].q.val().get_bits::<8>(8);
            self.s2b_k[i].d.next = self.s2_k[i].q.val();
            self.s2b_neg[i].d.next = self.s2_neg[i].q.val();
            // stage 3: 255·d + 128 ± |src − d|·α, which is src·α + d·(255 − α) + 128: 128 ..= 65,153. The minus is
            // the plus of ~p + 1 modulo 2^16, its + 1 already in k, so that one carry chain serves both signs: with
            // an add and a subtract chosen after, yosys made the iCE40 two chains in a row
            if self.s2b_neg[i].q.val() {
                self.w_x[i].next = !self.w_p[i].val();
            } else {
                self.w_x[i].next = self.w_p[i].val();
            }
            self.w_t[i].next = self.s2b_k[i].q.val() + self.w_x[i].val(); // modulo 2^16: exact, as above
            self.s3_t[i].d.next = self.w_t[i].val();
            // stage 4
            self.w_th[i].next = self.s3_t[i].q.val() >> 8;
            self.w_u[i].next = self.s3_t[i].q.val() + self.w_th[i].val(); // ≤ 65,407: no wrap
            self.s4_out[i].d.next = self.w_u[i].val().get_bits::<8>(8); // U16 >> 8 (floor): U8, the /255 rounded
        }
        self.out_r.next = self.s4_out[0].q.val();
        self.out_g.next = self.s4_out[1].q.val();
        self.out_b.next = self.s4_out[2].q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
