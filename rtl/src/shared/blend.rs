//! `blend`: the shade as alpha, combined with colours. `mode` 0 modulates, `out = round(src·α/255)`; mode 1
//! alpha-lerps, `out = round((src·α + dst·(255 − α))/255)`. The /255 is `t = num + 128; (t + (t >> 8)) >> 8`.
//! Latency 6: weights; the multipliers' operand register (it feeds nothing else, so it can sit beside the DSP);
//! products; the sum; + 128; the /255. The sum and the + 128 are a clock each: in one clock they were two adders in a
//! row behind the route from the multiplier, `cart_pipeline`'s critical path on the ECP5 (2.11 ns of logic, 4.13 ns
//! of routing, 160 MHz).

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
        // stage 1: the two weights, α and (mode ? 255 − α : 0), and the colours, widened to the multiplier's 16 bits.
        // The width report shows 8 spare bits in each of these and the operand registers below; they stay 16 wide
        // because narrowing them to U8 (widened by wires at the multipliers) was measured worse: 165 → 189 SB_DFF
        // on the UP5K, LUT4 unchanged at 60 (yosys already drops the constant top bytes of these)
        s1_wa: DFF<U16>,
        s1_wd: DFF<U16>,
        s1_src: [DFF<U16>; 3],
        s1_dst: [DFF<U16>; 3],
        // stage 1b: the operands again, the weights once per multiplier (`mop_`: see `rtl/README.md`)
        mop_wa: [DFF<U16>; 3],
        mop_wd: [DFF<U16>; 3],
        s1b_src: [DFF<U16>; 3],
        s1b_dst: [DFF<U16>; 3],
        // stage 2: src·α, dst·(255 − α), each ≤ 255·255 (U16)
        s2_ps: [DFF<U16>; 3],
        s2_pd: [DFF<U16>; 3],
        // stage 3: src·α + dst·(255 − α) ≤ 65,025 (U16)
        s3_s: [DFF<U16>; 3],
        // stage 3b: t = that + 128 ≤ 65,153 (U16)
        s3b_t: [DFF<U16>; 3],
        // stage 4: (t + (t >> 8)) >> 8, truncating: U8
        s4_out: [DFF<U8>; 3],
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
        inv_alpha: Signal<Local, U8>,
        w_ps: [Signal<Local, Bits<32>>; 3],
        w_pd: [Signal<Local, Bits<32>>; 3],
        w_sum: [Signal<Local, U16>; 3],
        w_th: [Signal<Local, U16>; 3],
        w_u: [Signal<Local, U16>; 3],
    }
}

impl Logic for Blend {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_wa, s1_wd);
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1
        self.inv_alpha.next = 255 - self.alpha.val();
        self.s1_wa.d.next = bit_cast::<16, 8>(self.alpha.val());
        if self.mode.val().any() {
            self.s1_wd.d.next = bit_cast::<16, 8>(self.inv_alpha.val());
        } else {
            self.s1_wd.d.next = 0.into();
        }
        self.s1_src[0].d.next = bit_cast::<16, 8>(self.src_r.val());
        self.s1_src[1].d.next = bit_cast::<16, 8>(self.src_g.val());
        self.s1_src[2].d.next = bit_cast::<16, 8>(self.src_b.val());
        self.s1_dst[0].d.next = bit_cast::<16, 8>(self.dst_r.val());
        self.s1_dst[1].d.next = bit_cast::<16, 8>(self.dst_g.val());
        self.s1_dst[2].d.next = bit_cast::<16, 8>(self.dst_b.val());
        for i in 0..3 {
            self.s1_src[i].clock.next = self.clock.val();
            self.s1_dst[i].clock.next = self.clock.val();
            self.s1b_src[i].clock.next = self.clock.val();
            self.mop_wa[i].clock.next = self.clock.val();
            self.mop_wd[i].clock.next = self.clock.val();
            self.s1b_dst[i].clock.next = self.clock.val();
            self.s2_ps[i].clock.next = self.clock.val();
            self.s2_pd[i].clock.next = self.clock.val();
            self.s3_s[i].clock.next = self.clock.val();
            self.s3b_t[i].clock.next = self.clock.val();
            self.s4_out[i].clock.next = self.clock.val();
            // stage 1b: carried
            self.s1b_src[i].d.next = self.s1_src[i].q.val();
            self.s1b_dst[i].d.next = self.s1_dst[i].q.val();
            self.mop_wa[i].d.next = self.s1_wa.q.val();
            self.mop_wd[i].d.next = self.s1_wd.q.val();
            // stage 2
            self.w_ps[i].next = self.s1b_src[i].q.val() * self.mop_wa[i].q.val();
            self.w_pd[i].next = self.s1b_dst[i].q.val() * self.mop_wd[i].q.val();
            self.s2_ps[i].d.next = self.w_ps[i].val().get_bits::<16>(0);
            self.s2_pd[i].d.next = self.w_pd[i].val().get_bits::<16>(0);
            // stage 3
            self.w_sum[i].next = self.s2_ps[i].q.val() + self.s2_pd[i].q.val();
            self.s3_s[i].d.next = self.w_sum[i].val();
            // stage 3b
            self.s3b_t[i].d.next = self.s3_s[i].q.val() + 128;
            // stage 4
            self.w_th[i].next = self.s3b_t[i].q.val() >> 8;
            self.w_u[i].next = self.s3b_t[i].q.val() + self.w_th[i].val(); // ≤ 65,407: no wrap
            self.s4_out[i].d.next = self.w_u[i].val().get_bits::<8>(8); // U16 >> 8 (floor): U8, the /255 rounded
        }
        self.out_r.next = self.s4_out[0].q.val();
        self.out_g.next = self.s4_out[1].q.val();
        self.out_b.next = self.s4_out[2].q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
