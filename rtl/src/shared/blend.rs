//! `blend`: the shade as alpha, combined with colours. `mode` 0 modulates, `out = round(src·α/255)`; mode 1
//! alpha-lerps, `out = round((src·α + dst·(255 − α))/255)`. The /255 is `t = num + 128; (t + (t >> 8)) >> 8`.
//!
//! Three products, not six: with d = (mode ? dst : 0), both numerators are 255·d + (src − d)·α, the same integer
//! (src·α + d·(255 − α), so 0 ..= 255·255). Each channel takes one unsigned 9 × 8 product: with x = src − d in 9-bit
//! two's complement (−255 ..= 255) read as unsigned, x_u = x + 512·[x < 0], the numerator plus 128 is
//! k + x_u·α modulo 2^16, k = 255·d + 128 − 512·α·[x < 0] beside it: t exactly. The iCE40 UP5K has 8 SB_MAC16 blocks: the three saved are what let its Cartesian
//! pipelines keep their other products in them.
//!
//! Latency 7: src − dst and 255·dst + 128; x (src − dst, or src), and 255·d + 128 (that, or 128); x_u in the multipliers' operand register (it feeds nothing else,
//! so it can sit beside the DSP: on the UP5K the SB_MAC16 takes it as its input register, and a choice in front of
//! it was the polar pipeline's path), and k; products; the products again (see `rtl/README.md`: the route
//! out of a DSP, and on the UP5K the sum of the pieces of a product built in logic, on a clock of their own);
//! t = k + product; the /255. The + 128 rides in the 255·d beside the product: with the sum and the + 128
//! in one clock after the product there were two adders in a row behind the route from the multiplier,
//! `cart_pipeline`'s critical path on the ECP5 (2.11 ns of logic, 4.13 ns of routing, 160 MHz).

use crate::prim::delay::Delay;
use crate::prim::q::{U16, U8};
use rust_hdl::prelude::*;

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 7;

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
        // stage 1: α, widened to the multiplier's 16 bits; per channel src − dst modulo 2^16 (S16), src, and
        // 255·dst + 128 ≤ 65,153 (U16); the mode. The width report shows 8 spare bits in α's registers; they stay 16 wide because narrowing the
        // operands to U8 (widened by wires at the multipliers) was measured worse: 165 → 189 SB_DFF on the UP5K,
        // LUT4 unchanged at 60 (yosys already drops the constant top bytes of these)
        s1_wa: DFF<U16>,
        s1_dp: [DFF<U16>; 3],
        s1_src: [DFF<U16>; 3], // ≤ 255
        s1_kd: [DFF<U16>; 3],
        s1_mode: DFF<Bit>,
        // stage 1a: x = src − d, −255 ..= 255 (S16); 255·d + 128 ≤ 65,153 (U16); α carried
        s1a_wa: DFF<U16>,
        s1a_x: [DFF<U16>; 3],
        s1a_k: [DFF<U16>; 3],
        // stage 1b: the operands again, α once per multiplier (`mop_`: see `rtl/README.md`), x_u < 512 (U16); k
        // (U16, modulo 2^16)
        mop_wa: [DFF<U16>; 3],
        s1b_x: [DFF<U16>; 3],
        s1b_k: [DFF<U16>; 3],
        // stage 2: x_u·α modulo 2^16 (U16); k carried
        s2_p: [DFF<U16>; 3],
        s2_k: [DFF<U16>; 3],
        // stage 2b: the products again, each in two registers (bits 0..7, 8..15: see `dot3` for why two); k carried
        s2b_lo: [DFF<U8>; 3],
        s2b_hi: [DFF<U8>; 3],
        s2b_k: [DFF<U16>; 3],
        // stage 3: t = 255·d + 128 + (src − d)·α = src·α + d·(255 − α) + 128 ≤ 65,153 (U16)
        s3_t: [DFF<U16>; 3],
        // stage 4: (t + (t >> 8)) >> 8, truncating: U8
        s4_out: [DFF<U8>; 3],
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
        w_src: [Signal<Local, U16>; 3], // src and dst widened to the multiplier's 16 bits
        w_dst: [Signal<Local, U16>; 3],
        w_pw: [Signal<Local, Bits<32>>; 3],
        w_k: [Signal<Local, U16>; 3],
        w_a9: Signal<Local, U16>, // α·512 modulo 2^16
        w_p: [Signal<Local, U16>; 3], // a product out of its two stage-2b registers
        w_t: [Signal<Local, U16>; 3],
        w_th: [Signal<Local, U16>; 3],
        w_u: [Signal<Local, U16>; 3],
    }
}

impl Logic for Blend {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_wa, s1_mode, s1a_wa);
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1
        self.s1_wa.d.next = bit_cast::<16, 8>(self.alpha.val());
        self.w_src[0].next = bit_cast::<16, 8>(self.src_r.val());
        self.w_src[1].next = bit_cast::<16, 8>(self.src_g.val());
        self.w_src[2].next = bit_cast::<16, 8>(self.src_b.val());
        self.w_dst[0].next = bit_cast::<16, 8>(self.dst_r.val());
        self.w_dst[1].next = bit_cast::<16, 8>(self.dst_g.val());
        self.w_dst[2].next = bit_cast::<16, 8>(self.dst_b.val());
        self.s1_mode.d.next = self.mode.val().any();
        // stage 1a
        self.s1a_wa.d.next = self.s1_wa.q.val();
        // stage 1b: α·512 modulo 2^16, taken off k where x < 0
        self.w_a9.next = self.s1a_wa.q.val() << 9;
        // stage 3's product, out of its two stage-2b registers
        self.w_p[0].next = (bit_cast::<16, 8>(self.s2b_hi[0].q.val()) << 8) | bit_cast::<16, 8>(self.s2b_lo[0].q.val());
        self.w_p[1].next = (bit_cast::<16, 8>(self.s2b_hi[1].q.val()) << 8) | bit_cast::<16, 8>(self.s2b_lo[1].q.val());
        self.w_p[2].next = (bit_cast::<16, 8>(self.s2b_hi[2].q.val()) << 8) | bit_cast::<16, 8>(self.s2b_lo[2].q.val());
        for i in 0..3 {
            self.s1_dp[i].clock.next = self.clock.val();
            self.s1_src[i].clock.next = self.clock.val();
            self.s1_kd[i].clock.next = self.clock.val();
            self.s1a_x[i].clock.next = self.clock.val();
            self.s1a_k[i].clock.next = self.clock.val();
            self.mop_wa[i].clock.next = self.clock.val();
            self.s1b_x[i].clock.next = self.clock.val();
            self.s1b_k[i].clock.next = self.clock.val();
            self.s2_p[i].clock.next = self.clock.val();
            self.s2_k[i].clock.next = self.clock.val();
            self.s2b_lo[i].clock.next = self.clock.val();
            self.s2b_hi[i].clock.next = self.clock.val();
            self.s2b_k[i].clock.next = self.clock.val();
            self.s3_t[i].clock.next = self.clock.val();
            self.s4_out[i].clock.next = self.clock.val();
            // stage 1: src − dst modulo 2^16 and 256·dst + 128 − dst (exact: dst·256 has its low byte clear, so the
            // OR is an add), straight from the inputs; the mode's choice waits a clock, so that it and a carry chain
            // are not one path
            self.s1_dp[i].d.next = self.w_src[i].val() - self.w_dst[i].val();
            self.s1_src[i].d.next = self.w_src[i].val();
            self.w_k[i].next = (self.w_dst[i].val() << 8) | 128;
            self.s1_kd[i].d.next = self.w_k[i].val() - self.w_dst[i].val();
            // stage 1a: x = src − d and 255·d + 128: mode 1, src − dst and 255·dst + 128; mode 0, src and 128
            if self.s1_mode.q.val() {
                self.s1a_x[i].d.next = self.s1_dp[i].q.val();
                self.s1a_k[i].d.next = self.s1_kd[i].q.val();
            } else {
                self.s1a_x[i].d.next = self.s1_src[i].q.val();
                self.s1a_k[i].d.next = 128.into();
            }
            // stage 1b: x's low 9 bits, x_u; k less 512·α where x < 0 (its bit 8), modulo 2^16; α once per multiplier
            self.mop_wa[i].d.next = self.s1a_wa.q.val();
            self.s1b_x[i].d.next = self.s1a_x[i].q.val() & 511;
            if (self.s1a_x[i].q.val() & 256).any() {
                self.s1b_k[i].d.next = self.s1a_k[i].q.val() - self.w_a9.val();
            } else {
                self.s1b_k[i].d.next = self.s1a_k[i].q.val();
            }
            // stage 2: x_u·α's low 16 bits (< 2^17 whole); k carried
            self.w_pw[i].next = self.s1b_x[i].q.val() * self.mop_wa[i].q.val();
            self.s2_p[i].d.next = self.w_pw[i].val().get_bits::<16>(0);
            self.s2_k[i].d.next = self.s1b_k[i].q.val();
            // stage 2b: carried, the product in two halves
            self.s2b_lo[i].d.next = self.s2_p[i].q.val().get_bits::<8>(0);
            self.s2b_hi[i].d.next = self.s2_p[i].q.val().get_bits::<8>(8);
            self.s2b_k[i].d.next = self.s2_k[i].q.val();
            // stage 3: k + x_u·α modulo 2^16 = 255·d + 128 + (src − d)·α, which is src·α + d·(255 − α) + 128:
            // 128 ..= 65,153
            self.w_t[i].next = self.s2b_k[i].q.val() + self.w_p[i].val();
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
