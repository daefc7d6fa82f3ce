//! `blend`: the shade as alpha, combined with colours. `mode` 0 modulates, `out = round(src·α/255)`; mode 1
//! alpha-lerps, `out = round((src·α + dst·(255 − α))/255)`. The /255 is `t = num + 128; (t + (t >> 8)) >> 8`.
//! Latency 6: weights; the multipliers' operand register (it feeds nothing else, so it can sit beside the DSP);
//! products; the products again (on the ECP5 the first is the MULT18X18D's output register, and its route to the
//! sum's carry chain was `cart_pipeline`'s critical path: the copy takes the route alone; two registers a product,
//! its low and high bytes, for the reason `dot3` gives); the sum + 128; the /255.

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
        // stage 2b: the products again, low and high bytes
        s2b_ps_lo: [DFF<U8>; 3],
        s2b_ps_hi: [DFF<U8>; 3],
        s2b_pd_lo: [DFF<U8>; 3],
        s2b_pd_hi: [DFF<U8>; 3],
        // stage 3: t = src·α + dst·(255 − α) + 128 ≤ 65,153 (U16)
        s3_t: [DFF<U16>; 3],
        // stage 4: (t + (t >> 8)) >> 8, truncating: U8
        s4_out: [DFF<U8>; 3],
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
        inv_alpha: Signal<Local, U8>,
        w_ps: [Signal<Local, Bits<32>>; 3],
        w_pd: [Signal<Local, Bits<32>>; 3],
        w_ps2: [Signal<Local, U16>; 3], // src·α out of its two stage-2b registers
        w_pd2: [Signal<Local, U16>; 3], // dst·(255 − α) out of its two
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
        self.w_ps2[0].next =
            (bit_cast::<16, 8>(self.s2b_ps_hi[0].q.val()) << 8) | bit_cast::<16, 8>(self.s2b_ps_lo[0].q.val());
        self.w_ps2[1].next =
            (bit_cast::<16, 8>(self.s2b_ps_hi[1].q.val()) << 8) | bit_cast::<16, 8>(self.s2b_ps_lo[1].q.val());
        self.w_ps2[2].next =
            (bit_cast::<16, 8>(self.s2b_ps_hi[2].q.val()) << 8) | bit_cast::<16, 8>(self.s2b_ps_lo[2].q.val());
        self.w_pd2[0].next =
            (bit_cast::<16, 8>(self.s2b_pd_hi[0].q.val()) << 8) | bit_cast::<16, 8>(self.s2b_pd_lo[0].q.val());
        self.w_pd2[1].next =
            (bit_cast::<16, 8>(self.s2b_pd_hi[1].q.val()) << 8) | bit_cast::<16, 8>(self.s2b_pd_lo[1].q.val());
        self.w_pd2[2].next =
            (bit_cast::<16, 8>(self.s2b_pd_hi[2].q.val()) << 8) | bit_cast::<16, 8>(self.s2b_pd_lo[2].q.val());
        for i in 0..3 {
            self.s1_src[i].clock.next = self.clock.val();
            self.s1_dst[i].clock.next = self.clock.val();
            self.s1b_src[i].clock.next = self.clock.val();
            self.mop_wa[i].clock.next = self.clock.val();
            self.mop_wd[i].clock.next = self.clock.val();
            self.s1b_dst[i].clock.next = self.clock.val();
            self.s2_ps[i].clock.next = self.clock.val();
            self.s2_pd[i].clock.next = self.clock.val();
            self.s2b_ps_lo[i].clock.next = self.clock.val();
            self.s2b_ps_hi[i].clock.next = self.clock.val();
            self.s2b_pd_lo[i].clock.next = self.clock.val();
            self.s2b_pd_hi[i].clock.next = self.clock.val();
            self.s3_t[i].clock.next = self.clock.val();
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
            // stage 2b: carried
            self.s2b_ps_lo[i].d.next = self.s2_ps[i].q.val().get_bits::<8>(0);
            self.s2b_ps_hi[i].d.next = self.s2_ps[i].q.val().get_bits::<8>(8);
            self.s2b_pd_lo[i].d.next = self.s2_pd[i].q.val().get_bits::<8>(0);
            self.s2b_pd_hi[i].d.next = self.s2_pd[i].q.val().get_bits::<8>(8);
            // stage 3
            self.w_sum[i].next = self.w_ps2[i].val() + self.w_pd2[i].val();
            self.s3_t[i].d.next = self.w_sum[i].val() + 128;
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
