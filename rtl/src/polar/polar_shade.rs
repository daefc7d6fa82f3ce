//! `polar_shade`: US 6,819,319's FIG. 3 up to the clamp, `k1 + k2·sin S + k3·cos S·cos(R − Q)`, one texel per clock.
//! See `vectors::polar_shade` for the recipe. Latency 11:
//! 1 S, R − Q (mod 256, the subtractor [16]) and the k's registered (S and R − Q as the table blocks' addresses);
//! 2 the tables: the sine/cosine unit [10] and the cosine unit [18], the tested `sincos` and `cos_sign` blocks;
//! 2b the multipliers' operands registered alone (on the ECP5 the MULT18X18D's input register: without it that
//!    register took the tables' own, and the sine table's read into the multiplier was polar_pipeline's critical
//!    path, 1.73 ns of logic and 4.66 ns of routing, 156 MHz);
//! 3 the products k2·sin S [12] and k3·cos S [14];
//! 4–5 both divided by 255 (`Div255`);
//! 6 the product t14·|cos(R − Q)| [20] and the adder k1 + t12 [22];
//! 7–8 that product divided by 255;
//! 9 the sum and the difference [24], side by side: S11;
//! 10 the one the cosine's sign bit chooses [26], and the clamp to U8 [28]. (With the choice in stage 9, an add and a
//!    subtract behind one another's multiplexer, the UP5K placed polar_pipeline at 73.4 MHz, that path the critical
//!    one.)

use crate::cos_sign::CosSign;
use crate::div255::Div255;
use crate::prim::delay::Delay;
use crate::prim::q::{S11, U8};
use crate::sincos::SinCos;
use rust_hdl::prelude::*;

pub const LATENCY: usize = 11;
// the two table blocks run side by side, so they must take as long as each other
const _: () = assert!(crate::sincos::LATENCY == crate::cos_sign::LATENCY);

crate::stream_block! {
    /// `DC`: the Dreamcast toolchains' angle scale (255 steps) in both tables; the seed's (256) when false.
    #[derive(Default)]
    pub struct PolarShade<const DC: bool>: unit(if DC { "polar_shade_dc" } else { "polar_shade" }, LATENCY) {
        in {
            s: U8,
            r: U8,
            q: U8,
            k1: U8,
            k2: U8,
            k3: U8,
        }
        out {
            sum: S11,
            shade: U8,
        }
        // stages 1–2: the table blocks register their address, then their data
        pub sin_cos: SinCos<8, 8, DC>,
        pub cos_sign: CosSign<8, 8, DC>,
        // stage 1
        s1_k1: DFF<U8>,
        s1_k2: DFF<U8>,
        s1_k3: DFF<U8>,
        // stage 2
        s2_k1: DFF<U8>,
        s2_k2: DFF<U8>,
        s2_k3: DFF<U8>,
        // stage 2b: the multipliers' operands (`mop_`: see `rtl/README.md`), the rest beside them
        mop_a: [DFF<Bits<16>>; 2],
        mop_b: [DFF<Bits<16>>; 2],
        s2b_k1: DFF<U8>,
        s2b_cd: DFF<U8>,
        s2b_neg: DFF<Bit>,
        // stage 3: k2·sin S, k3·cos S (U16)
        s3_p12: DFF<Bits<16>>,
        s3_p14: DFF<Bits<16>>,
        s3_k1: DFF<U8>,
        s3_cd: DFF<U8>,
        s3_neg: DFF<Bit>,
        // stages 4–5
        div12: Div255,
        div14: Div255,
        k1_dly: Delay<U8, 2>,
        cd_dly: Delay<U8, 2>,
        neg_dly: Delay<Bit, 2>,
        // stage 6: t14·|cos| (U16), a22 = k1 + t12 (U9)
        s6_p20: DFF<Bits<16>>,
        s6_a22: DFF<Bits<9>>,
        s6_neg: DFF<Bit>,
        // stages 7–8
        div20: Div255,
        a22_dly: Delay<Bits<9>, 2>,
        neg2_dly: Delay<Bit, 2>,
        // stage 9: a22 + t20 and a22 − t20 (S11), the sign beside them
        s9_add: DFF<S11>,
        s9_sub: DFF<S11>,
        s9_neg: DFF<Bit>,
        // stage 10: the clamp
        s10_shade: DFF<U8>,
        s10_sum: DFF<S11>,
        valid: Delay<Bit, { LATENCY - crate::sincos::LATENCY }>, // the valid flag after the table blocks'
        w_d: Signal<Local, U8>,
        w_s10: Signal<Local, Bits<10>>,
        w_a: [Signal<Local, Bits<16>>; 2],
        w_b: [Signal<Local, Bits<16>>; 2],
        w_p: [Signal<Local, Bits<32>>; 2],
        w_c: Signal<Local, Bits<16>>,
        w_cd: Signal<Local, Bits<16>>,
        w_p20: Signal<Local, Bits<32>>,
        w_a22: Signal<Local, S11>,
        w_t20: Signal<Local, S11>,
        w_sum: Signal<Local, S11>,
    }
}

impl<const DC: bool> Logic for PolarShade<DC> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s1_k1, s1_k2, s1_k3, s2_k1, s2_k2, s2_k3, s2b_k1, s2b_cd, s2b_neg, s3_p12, s3_p14, s3_k1,
            s3_cd, s3_neg, s6_p20, s6_a22, s6_neg, s9_add, s9_sub, s9_neg, s10_shade, s10_sum
        );
        clock!(self, clock, sin_cos, cos_sign);
        clock!(self, clock, div12, div14, div20, k1_dly, cd_dly, neg_dly, a22_dly, neg2_dly, valid);
        // the table blocks carry the valid flag through stages 1–2 (both the same flag), the chain the rest
        self.valid.d.next = self.sin_cos.valid_out.val() & self.cos_sign.valid_out.val();
        // stage 1: the subtractor [16], modulo 256 (the 8-bit difference wraps in both simulators)
        self.w_d.next = self.r.val() - self.q.val();
        self.cos_sign.valid_in.next = self.valid_in.val();
        self.cos_sign.d.next = self.w_d.val();
        // S (U8, 256 = 90°) as the sine/cosine block's 10-bit angle (1024 = 90°): S·4, whose top 8 bits are S
        self.w_s10.next = bit_cast::<10, 8>(self.s.val());
        self.sin_cos.valid_in.next = self.valid_in.val();
        self.sin_cos.angle.next = self.w_s10.val() << 2;
        self.s1_k1.d.next = self.k1.val();
        self.s1_k2.d.next = self.k2.val();
        self.s1_k3.d.next = self.k3.val();
        // stage 2: the tables, inside their blocks
        self.s2_k1.d.next = self.s1_k1.q.val();
        self.s2_k2.d.next = self.s1_k2.q.val();
        self.s2_k3.d.next = self.s1_k3.q.val();
        // stage 2b: the operands, widened to the multipliers' 16 bits, registered alone
        self.w_a[0].next = bit_cast::<16, 8>(self.s2_k2.q.val());
        self.w_b[0].next = bit_cast::<16, 8>(self.sin_cos.sin.val());
        self.w_a[1].next = bit_cast::<16, 8>(self.s2_k3.q.val());
        self.w_b[1].next = bit_cast::<16, 8>(self.sin_cos.cos.val());
        for i in 0..2 {
            self.mop_a[i].clock.next = self.clock.val();
            self.mop_b[i].clock.next = self.clock.val();
            self.mop_a[i].d.next = self.w_a[i].val();
            self.mop_b[i].d.next = self.w_b[i].val();
        }
        self.s2b_k1.d.next = self.s2_k1.q.val();
        self.s2b_cd.d.next = self.cos_sign.mag.val();
        self.s2b_neg.d.next = self.cos_sign.neg.val().any(); // Bits<1> → Bit (a scalar in Verilog: no bit select)

        // stage 3: multipliers [12] and [14], U8 × U8 → U16
        self.w_p[0].next = self.mop_a[0].q.val() * self.mop_b[0].q.val();
        self.w_p[1].next = self.mop_a[1].q.val() * self.mop_b[1].q.val();
        self.s3_p12.d.next = self.w_p[0].val().get_bits::<16>(0);
        self.s3_p14.d.next = self.w_p[1].val().get_bits::<16>(0);
        self.s3_k1.d.next = self.s2b_k1.q.val();
        self.s3_cd.d.next = self.s2b_cd.q.val();
        self.s3_neg.d.next = self.s2b_neg.q.val();

        // stages 4–5: /255, rounded
        self.div12.num.next = self.s3_p12.q.val();
        self.div14.num.next = self.s3_p14.q.val();
        self.k1_dly.d.next = self.s3_k1.q.val();
        self.cd_dly.d.next = self.s3_cd.q.val();
        self.neg_dly.d.next = self.s3_neg.q.val();
        // stage 6: multiplier [20] and adder [22]
        self.w_c.next = bit_cast::<16, 8>(self.div14.quot.val());
        self.w_cd.next = bit_cast::<16, 8>(self.cd_dly.q.val());
        self.w_p20.next = self.w_c.val() * self.w_cd.val();
        self.s6_p20.d.next = self.w_p20.val().get_bits::<16>(0);
        self.s6_a22.d.next = bit_cast::<9, 8>(self.k1_dly.q.val()) + bit_cast::<9, 8>(self.div12.quot.val());
        self.s6_neg.d.next = self.neg_dly.q.val();
        // stages 7–8: /255, rounded
        self.div20.num.next = self.s6_p20.q.val();
        self.a22_dly.d.next = self.s6_a22.q.val();
        self.neg2_dly.d.next = self.s6_neg.q.val();
        // stage 9: the adder [24] both ways; 11-bit two's complement, no wrap (a22 + t20 ≤ 765, a22 − t20 ≥ −255)
        self.w_a22.next = bit_cast::<11, 9>(self.a22_dly.q.val());
        self.w_t20.next = bit_cast::<11, 8>(self.div20.quot.val());
        self.s9_add.d.next = self.w_a22.val() + self.w_t20.val();
        self.s9_sub.d.next = self.w_a22.val() - self.w_t20.val();
        self.s9_neg.d.next = self.neg2_dly.q.val();
        // stage 10: the sign bit [26] chooses, then the clamp [28]: negative → 0, above 255 → 255
        if self.s9_neg.q.val() {
            self.w_sum.next = self.s9_sub.q.val();
        } else {
            self.w_sum.next = self.s9_add.q.val();
        }
        if self.w_sum.val().get_bit(10) {
            self.s10_shade.d.next = 0.into();
        } else if self.w_sum.val().get_bits::<2>(8).any() {
            self.s10_shade.d.next = 255.into();
        } else {
            self.s10_shade.d.next = self.w_sum.val().get_bits::<8>(0);
        }
        self.s10_sum.d.next = self.w_sum.val();
        self.sum.next = self.s10_sum.q.val();
        self.shade.next = self.s10_shade.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
