//! `light_iter`: per-vertex S8 light directions interpolated across a triangle from U9 barycentric weights:
//! `L = l0·256 + (l1 − l0)·w1 + (l2 − l0)·w2` (S20, Sq11.8) → `truncate` 6 (floor) → `saturate` to S10 (Sq7.2).
//! Latency 7: differences; magnitudes; the multiplier's operand register; products; signs; the sum; the shift and
//! saturation. The operand register feeds nothing but the multiplier, so the placer can put it beside the DSP: the
//! long route lands on a register-to-register path instead of in front of the multiplier's 3.9 ns.

use crate::delay::Delay;
use rust_hdl::prelude::*;
use crate::q::{S8, Sq11_8, Sq7_2};

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 7;


crate::stream_block! {
    #[derive(Default)]
    pub struct LightIter: unit("light_iter", LATENCY) {
        in {
            l0_x: S8,
            l0_y: S8,
            l0_z: S8,
            l1_x: S8,
            l1_y: S8,
            l1_z: S8,
            l2_x: S8,
            l2_y: S8,
            l2_z: S8,
            w1: Bits<9>,
            w2: Bits<9>,
        }
        out {
            light_x: Sq7_2,
            light_y: Sq7_2,
            light_z: Sq7_2,
        }
        // stage 1: differences (S9), l0·256 (S20), weights widened
        s1_d1: [DFF<Bits<9>>; 3],
        s1_d2: [DFF<Bits<9>>; 3],
        s1_base: [DFF<Sq11_8>; 3],
        s1_w1: DFF<Bits<16>>,
        s1_w2: DFF<Bits<16>>,
        // stage 2: magnitudes ≤ 255 (in the multiplier's 16 bits), signs
        s2_m1: [DFF<Bits<16>>; 3],
        s2_m2: [DFF<Bits<16>>; 3],
        s2_n1: [DFF<Bit>; 3],
        s2_n2: [DFF<Bit>; 3],
        s2_base: [DFF<Sq11_8>; 3],
        s2_w1: DFF<Bits<16>>,
        s2_w2: DFF<Bits<16>>,
        // stage 2b: the multiplier's operands again, and what travels beside them
        s2b_m1: [DFF<Bits<16>>; 3],
        s2b_m2: [DFF<Bits<16>>; 3],
        s2b_n1: [DFF<Bit>; 3],
        s2b_n2: [DFF<Bit>; 3],
        s2b_base: [DFF<Sq11_8>; 3],
        mop_w1: [DFF<Bits<16>>; 3],
        mop_w2: [DFF<Bits<16>>; 3],
        // stage 3: |d|·w ≤ 255·511 (U17)
        s3_p1: [DFF<Bits<17>>; 3],
        s3_p2: [DFF<Bits<17>>; 3],
        s3_n1: [DFF<Bit>; 3],
        s3_n2: [DFF<Bit>; 3],
        s3_base: [DFF<Sq11_8>; 3],
        // stage 4: signed terms (S20)
        s4_t1: [DFF<Sq11_8>; 3],
        s4_t2: [DFF<Sq11_8>; 3],
        s4_base: [DFF<Sq11_8>; 3],
        // stage 5: the sum (S20; |L| ≤ 293,378 < 2^19)
        s5_acc: [DFF<Sq11_8>; 3],
        // stage 6: floor to Sq7.2 and saturate to S10
        s6_out: [DFF<Sq7_2>; 3],
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
        e9_0: [Signal<Local, Bits<9>>; 3],
        e9_1: [Signal<Local, Bits<9>>; 3],
        e9_2: [Signal<Local, Bits<9>>; 3],
        e20: [Signal<Local, Sq11_8>; 3],
        m9_1: [Signal<Local, Bits<9>>; 3],
        m9_2: [Signal<Local, Bits<9>>; 3],
        w_p1: [Signal<Local, Bits<32>>; 3],
        w_p2: [Signal<Local, Bits<32>>; 3],
        p20_1: [Signal<Local, Sq11_8>; 3],
        p20_2: [Signal<Local, Sq11_8>; 3],
        w_part: [Signal<Local, Sq11_8>; 3],
        w_q: [Signal<Local, Bits<14>>; 3],
        w_hi: [Signal<Local, Bits<5>>; 3],
    }
}

impl Logic for LightIter {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_w1, s1_w2, s2_w1, s2_w2);
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        self.s1_w1.d.next = bit_cast::<16, 9>(self.w1.val());
        self.s1_w2.d.next = bit_cast::<16, 9>(self.w2.val());
        self.s2_w1.d.next = self.s1_w1.q.val();
        self.s2_w2.d.next = self.s1_w2.q.val();
        // ---- component x
        // stage 1: l1 − l0, l2 − l0 in S9; l0·256 in S20 (sign-extended by hand)
        self.e9_0[0].next = bit_cast::<9, 8>(self.l0_x.val());
        if self.l0_x.val().get_bit(7) {
            self.e9_0[0].next = self.e9_0[0].val() | 0x100;
        }
        self.e9_1[0].next = bit_cast::<9, 8>(self.l1_x.val());
        if self.l1_x.val().get_bit(7) {
            self.e9_1[0].next = self.e9_1[0].val() | 0x100;
        }
        self.e9_2[0].next = bit_cast::<9, 8>(self.l2_x.val());
        if self.l2_x.val().get_bit(7) {
            self.e9_2[0].next = self.e9_2[0].val() | 0x100;
        }
        self.s1_d1[0].d.next = self.e9_1[0].val() - self.e9_0[0].val();
        self.s1_d2[0].d.next = self.e9_2[0].val() - self.e9_0[0].val();
        self.e20[0].next = bit_cast::<20, 8>(self.l0_x.val());
        if self.l0_x.val().get_bit(7) {
            self.e20[0].next = self.e20[0].val() | 0xFFF00;
        }
        self.s1_base[0].d.next = self.e20[0].val() << 8;
        // stage 2: magnitudes, widened for the multiplier
        self.m9_1[0].next = self.s1_d1[0].q.val();
        if self.s1_d1[0].q.val().get_bit(8) {
            self.m9_1[0].next = !self.s1_d1[0].q.val() + 1;
        }
        self.m9_2[0].next = self.s1_d2[0].q.val();
        if self.s1_d2[0].q.val().get_bit(8) {
            self.m9_2[0].next = !self.s1_d2[0].q.val() + 1;
        }
        self.s2_m1[0].d.next = bit_cast::<16, 9>(self.m9_1[0].val());
        self.s2_m2[0].d.next = bit_cast::<16, 9>(self.m9_2[0].val());
        // stage 4: signs back, S20
        self.p20_1[0].next = bit_cast::<20, 17>(self.s3_p1[0].q.val());
        self.p20_2[0].next = bit_cast::<20, 17>(self.s3_p2[0].q.val());
        // ---- component y
        // stage 1: l1 − l0, l2 − l0 in S9; l0·256 in S20 (sign-extended by hand)
        self.e9_0[1].next = bit_cast::<9, 8>(self.l0_y.val());
        if self.l0_y.val().get_bit(7) {
            self.e9_0[1].next = self.e9_0[1].val() | 0x100;
        }
        self.e9_1[1].next = bit_cast::<9, 8>(self.l1_y.val());
        if self.l1_y.val().get_bit(7) {
            self.e9_1[1].next = self.e9_1[1].val() | 0x100;
        }
        self.e9_2[1].next = bit_cast::<9, 8>(self.l2_y.val());
        if self.l2_y.val().get_bit(7) {
            self.e9_2[1].next = self.e9_2[1].val() | 0x100;
        }
        self.s1_d1[1].d.next = self.e9_1[1].val() - self.e9_0[1].val();
        self.s1_d2[1].d.next = self.e9_2[1].val() - self.e9_0[1].val();
        self.e20[1].next = bit_cast::<20, 8>(self.l0_y.val());
        if self.l0_y.val().get_bit(7) {
            self.e20[1].next = self.e20[1].val() | 0xFFF00;
        }
        self.s1_base[1].d.next = self.e20[1].val() << 8;
        // stage 2: magnitudes, widened for the multiplier
        self.m9_1[1].next = self.s1_d1[1].q.val();
        if self.s1_d1[1].q.val().get_bit(8) {
            self.m9_1[1].next = !self.s1_d1[1].q.val() + 1;
        }
        self.m9_2[1].next = self.s1_d2[1].q.val();
        if self.s1_d2[1].q.val().get_bit(8) {
            self.m9_2[1].next = !self.s1_d2[1].q.val() + 1;
        }
        self.s2_m1[1].d.next = bit_cast::<16, 9>(self.m9_1[1].val());
        self.s2_m2[1].d.next = bit_cast::<16, 9>(self.m9_2[1].val());
        // stage 4: signs back, S20
        self.p20_1[1].next = bit_cast::<20, 17>(self.s3_p1[1].q.val());
        self.p20_2[1].next = bit_cast::<20, 17>(self.s3_p2[1].q.val());
        // ---- component z
        // stage 1: l1 − l0, l2 − l0 in S9; l0·256 in S20 (sign-extended by hand)
        self.e9_0[2].next = bit_cast::<9, 8>(self.l0_z.val());
        if self.l0_z.val().get_bit(7) {
            self.e9_0[2].next = self.e9_0[2].val() | 0x100;
        }
        self.e9_1[2].next = bit_cast::<9, 8>(self.l1_z.val());
        if self.l1_z.val().get_bit(7) {
            self.e9_1[2].next = self.e9_1[2].val() | 0x100;
        }
        self.e9_2[2].next = bit_cast::<9, 8>(self.l2_z.val());
        if self.l2_z.val().get_bit(7) {
            self.e9_2[2].next = self.e9_2[2].val() | 0x100;
        }
        self.s1_d1[2].d.next = self.e9_1[2].val() - self.e9_0[2].val();
        self.s1_d2[2].d.next = self.e9_2[2].val() - self.e9_0[2].val();
        self.e20[2].next = bit_cast::<20, 8>(self.l0_z.val());
        if self.l0_z.val().get_bit(7) {
            self.e20[2].next = self.e20[2].val() | 0xFFF00;
        }
        self.s1_base[2].d.next = self.e20[2].val() << 8;
        // stage 2: magnitudes, widened for the multiplier
        self.m9_1[2].next = self.s1_d1[2].q.val();
        if self.s1_d1[2].q.val().get_bit(8) {
            self.m9_1[2].next = !self.s1_d1[2].q.val() + 1;
        }
        self.m9_2[2].next = self.s1_d2[2].q.val();
        if self.s1_d2[2].q.val().get_bit(8) {
            self.m9_2[2].next = !self.s1_d2[2].q.val() + 1;
        }
        self.s2_m1[2].d.next = bit_cast::<16, 9>(self.m9_1[2].val());
        self.s2_m2[2].d.next = bit_cast::<16, 9>(self.m9_2[2].val());
        // stage 4: signs back, S20
        self.p20_1[2].next = bit_cast::<20, 17>(self.s3_p1[2].q.val());
        self.p20_2[2].next = bit_cast::<20, 17>(self.s3_p2[2].q.val());
        for i in 0..3 {
            self.s1_d1[i].clock.next = self.clock.val();
            self.s1_d2[i].clock.next = self.clock.val();
            self.s1_base[i].clock.next = self.clock.val();
            self.s2_m1[i].clock.next = self.clock.val();
            self.s2_m2[i].clock.next = self.clock.val();
            self.s2_n1[i].clock.next = self.clock.val();
            self.s2_n2[i].clock.next = self.clock.val();
            self.s2_base[i].clock.next = self.clock.val();
            self.s2b_m1[i].clock.next = self.clock.val();
            self.s2b_m2[i].clock.next = self.clock.val();
            self.s2b_n1[i].clock.next = self.clock.val();
            self.s2b_n2[i].clock.next = self.clock.val();
            self.s2b_base[i].clock.next = self.clock.val();
            self.mop_w1[i].clock.next = self.clock.val();
            self.mop_w2[i].clock.next = self.clock.val();
            self.s3_p1[i].clock.next = self.clock.val();
            self.s3_p2[i].clock.next = self.clock.val();
            self.s3_n1[i].clock.next = self.clock.val();
            self.s3_n2[i].clock.next = self.clock.val();
            self.s3_base[i].clock.next = self.clock.val();
            self.s4_t1[i].clock.next = self.clock.val();
            self.s4_t2[i].clock.next = self.clock.val();
            self.s4_base[i].clock.next = self.clock.val();
            self.s5_acc[i].clock.next = self.clock.val();
            self.s6_out[i].clock.next = self.clock.val();
            // stage 2 (magnitudes are computed above, per component)
            self.s2_n1[i].d.next = self.s1_d1[i].q.val().get_bit(8);
            self.s2_n2[i].d.next = self.s1_d2[i].q.val().get_bit(8);
            self.s2_base[i].d.next = self.s1_base[i].q.val();
            // stage 2b: carried; the weights once per component (`mop_`: see `rtl/README.md`)
            self.s2b_m1[i].d.next = self.s2_m1[i].q.val();
            self.s2b_m2[i].d.next = self.s2_m2[i].q.val();
            self.s2b_n1[i].d.next = self.s2_n1[i].q.val();
            self.s2b_n2[i].d.next = self.s2_n2[i].q.val();
            self.s2b_base[i].d.next = self.s2_base[i].q.val();
            self.mop_w1[i].d.next = self.s2_w1.q.val();
            self.mop_w2[i].d.next = self.s2_w2.q.val();
            // stage 3: 16 × 16 → 32, of which 17 bits are used
            self.w_p1[i].next = self.s2b_m1[i].q.val() * self.mop_w1[i].q.val();
            self.w_p2[i].next = self.s2b_m2[i].q.val() * self.mop_w2[i].q.val();
            self.s3_p1[i].d.next = self.w_p1[i].val().get_bits::<17>(0);
            self.s3_p2[i].d.next = self.w_p2[i].val().get_bits::<17>(0);
            self.s3_n1[i].d.next = self.s2b_n1[i].q.val();
            self.s3_n2[i].d.next = self.s2b_n2[i].q.val();
            self.s3_base[i].d.next = self.s2b_base[i].q.val();
            // stage 4
            if self.s3_n1[i].q.val() {
                self.s4_t1[i].d.next = !self.p20_1[i].val() + 1;
            } else {
                self.s4_t1[i].d.next = self.p20_1[i].val();
            }
            if self.s3_n2[i].q.val() {
                self.s4_t2[i].d.next = !self.p20_2[i].val() + 1;
            } else {
                self.s4_t2[i].d.next = self.p20_2[i].val();
            }
            self.s4_base[i].d.next = self.s3_base[i].q.val();
            // stage 5
            self.w_part[i].next = self.s4_base[i].q.val() + self.s4_t1[i].q.val();
            self.s5_acc[i].d.next = self.w_part[i].val() + self.s4_t2[i].q.val();
            // stage 6: acc >> 6 keeps its sign in 14 bits; it fits S10 when bits 13..9 are all equal
            self.w_q[i].next = self.s5_acc[i].q.val().get_bits::<14>(6);
            self.w_hi[i].next = self.w_q[i].val().get_bits::<5>(9);
            if self.w_q[i].val().get_bit(13) {
                if self.w_hi[i].val().all() {
                    self.s6_out[i].d.next = self.w_q[i].val().get_bits::<10>(0);
                } else {
                    self.s6_out[i].d.next = 0x200.into(); // −512
                }
            } else {
                if self.w_hi[i].val().any() {
                    self.s6_out[i].d.next = 0x1FF.into(); // +511
                } else {
                    self.s6_out[i].d.next = self.w_q[i].val().get_bits::<10>(0);
                }
            }
        }
        self.light_x.next = self.s6_out[0].q.val();
        self.light_y.next = self.s6_out[1].q.val();
        self.light_z.next = self.s6_out[2].q.val();
        self.valid_out.next = self.valid.q.val();
    }
}

