//! `height_normal`: seed 001's normal unit [156]: N = 7·(−k·Tang1y, 2, −k·Tang2y) (16 fraction bits), brought to
//! S10 for the shared normaliser by one shift for all three components, the smallest that keeps the largest rounded
//! magnitude ≤ 511. See `vectors::height_normal`. Latency 10: 7k; the two `SmMulWide`s; the largest magnitude; its
//! leading one; the shift (one more if the rounding carries); the three magnitudes shifted and rounded; the signs.

use crate::delay::Delay;
use crate::q::U8;
use crate::sm_mul::{self, SmMulWide};
use rust_hdl::prelude::*;

pub const LATENCY: usize = 6 + sm_mul::WIDE_LATENCY;

crate::stream_block! {
    #[derive(Default)]
    pub struct HeightNormal: unit("height_normal", LATENCY) {
        in {
            t1: Bits<21>,
            t2: Bits<21>,
            scale: U8,
        }
        out {
            n_x: Bits<10>,
            n_y: Bits<10>,
            n_z: Bits<10>,
        }
        // stage 1: 7k = 8k − k (U11 in 16); the tangents
        s1_k7: DFF<Bits<16>>,
        s1_t1: DFF<Bits<21>>,
        s1_t2: DFF<Bits<21>>,
        // stages 2–5: 7k·|t| < 1785·2^20 < 2^31 (U31 in 32), with t's sign
        mul1: SmMulWide<21>,
        mul2: SmMulWide<21>,
        // stage 6: the largest magnitude of (7k·|t1|, 14·2^16, 7k·|t2|), U31 in 32; N's signs (x, z negative where
        // the tangent is positive: N = −7k·t)
        s6_m: DFF<Bits<32>>,
        s6_p1: DFF<Bits<32>>,
        s6_p2: DFF<Bits<32>>,
        s6_n1: DFF<Bit>,
        s6_n2: DFF<Bit>,
        // stage 7: s0 = (the largest's leading one) − 8, 11..22: m >> s0 ∈ 256..511
        s7_s0: DFF<Bits<5>>,
        s7_m: DFF<Bits<32>>,
        s7_p1: DFF<Bits<32>>,
        s7_p2: DFF<Bits<32>>,
        s7_n1: DFF<Bit>,
        s7_n2: DFF<Bit>,
        // stage 8: s = s0, or s0 + 1 where rounding m at s0 reaches 512
        s8_s: DFF<Bits<5>>,
        s8_p1: DFF<Bits<32>>,
        s8_p2: DFF<Bits<32>>,
        s8_n1: DFF<Bit>,
        s8_n2: DFF<Bit>,
        // stage 9: the three magnitudes at s, rounded half up: ≤ 511 (U9 in 10)
        s9_q1: DFF<Bits<10>>,
        s9_qy: DFF<Bits<10>>,
        s9_q2: DFF<Bits<10>>,
        s9_n1: DFF<Bit>,
        s9_n2: DFF<Bit>,
        // stage 10: the signs: S10
        s10_x: DFF<Bits<10>>,
        s10_y: DFF<Bits<10>>,
        s10_z: DFF<Bits<10>>,
        valid: Delay<Bit, LATENCY>,
        w_k: Signal<Local, Bits<16>>,
        w_k8: Signal<Local, Bits<16>>,
        w_ny: Signal<Local, Bits<32>>,
        w_m12: Signal<Local, Bits<32>>,
        w_one: Signal<Local, Bits<32>>,
        w_s0m1: Signal<Local, Bits<5>>,
        w_half0: Signal<Local, Bits<32>>,
        w_r0: Signal<Local, Bits<32>>,
        w_sm1: Signal<Local, Bits<5>>,
        w_half: Signal<Local, Bits<32>>,
        w_q0: Signal<Local, Bits<32>>,
        w_a1: Signal<Local, Bits<32>>,
        w_ay: Signal<Local, Bits<32>>,
        w_a2: Signal<Local, Bits<32>>,
        w_r1: Signal<Local, Bits<32>>,
        w_ry: Signal<Local, Bits<32>>,
        w_r2: Signal<Local, Bits<32>>,
    }
}

impl Logic for HeightNormal {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_k7, s1_t1, s1_t2, s6_m, s6_p1, s6_p2, s6_n1, s6_n2, s7_s0, s7_m, s7_p1, s7_p2);
        dff_setup!(self, clock, s7_n1, s7_n2, s8_s, s8_p1, s8_p2, s8_n1, s8_n2, s9_q1, s9_qy, s9_q2, s9_n1, s9_n2);
        dff_setup!(self, clock, s10_x, s10_y, s10_z);
        clock!(self, clock, mul1, mul2, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1: 7k = 8k − k, U11, exact
        self.w_k.next = bit_cast::<16, 8>(self.scale.val()); // U8 in 16, widening
        self.w_k8.next = self.w_k.val() << 3; // 8k ≤ 2040: U11, exact
        self.s1_k7.d.next = self.w_k8.val() - self.w_k.val(); // 7k ≤ 1785: U11, exact
        self.s1_t1.d.next = self.t1.val();
        self.s1_t2.d.next = self.t2.val();
        // stages 2–5: the products
        self.mul1.x.next = self.s1_t1.q.val();
        self.mul1.w.next = self.s1_k7.q.val();
        self.mul2.x.next = self.s1_t2.q.val();
        self.mul2.w.next = self.s1_k7.q.val();
        // stage 6: the largest of the three magnitudes; N_x = −7k·t1 is negative where t1 is positive
        self.w_ny.next = 917_504.into(); // N_y = 7·2 with 16 fraction bits = 14·2^16
        if self.mul1.p.val() > self.mul2.p.val() {
            self.w_m12.next = self.mul1.p.val();
        } else {
            self.w_m12.next = self.mul2.p.val();
        }
        if self.w_m12.val() > self.w_ny.val() {
            self.s6_m.d.next = self.w_m12.val();
        } else {
            self.s6_m.d.next = self.w_ny.val();
        }
        self.s6_p1.d.next = self.mul1.p.val();
        self.s6_p2.d.next = self.mul2.p.val();
        self.s6_n1.d.next = !self.mul1.neg.val();
        self.s6_n2.d.next = !self.mul2.neg.val();
        // stage 7: the leading one of m (bit 19 at least: m ≥ 14·2^16), s0 = its position − 8 (a priority chain)
        if self.s6_m.q.val().get_bit(30) {
            self.s7_s0.d.next = 22.into();
        } else if self.s6_m.q.val().get_bit(29) {
            self.s7_s0.d.next = 21.into();
        } else if self.s6_m.q.val().get_bit(28) {
            self.s7_s0.d.next = 20.into();
        } else if self.s6_m.q.val().get_bit(27) {
            self.s7_s0.d.next = 19.into();
        } else if self.s6_m.q.val().get_bit(26) {
            self.s7_s0.d.next = 18.into();
        } else if self.s6_m.q.val().get_bit(25) {
            self.s7_s0.d.next = 17.into();
        } else if self.s6_m.q.val().get_bit(24) {
            self.s7_s0.d.next = 16.into();
        } else if self.s6_m.q.val().get_bit(23) {
            self.s7_s0.d.next = 15.into();
        } else if self.s6_m.q.val().get_bit(22) {
            self.s7_s0.d.next = 14.into();
        } else if self.s6_m.q.val().get_bit(21) {
            self.s7_s0.d.next = 13.into();
        } else if self.s6_m.q.val().get_bit(20) {
            self.s7_s0.d.next = 12.into();
        } else {
            self.s7_s0.d.next = 11.into();
        }
        self.s7_m.d.next = self.s6_m.q.val();
        self.s7_p1.d.next = self.s6_p1.q.val();
        self.s7_p2.d.next = self.s6_p2.q.val();
        self.s7_n1.d.next = self.s6_n1.q.val();
        self.s7_n2.d.next = self.s6_n2.q.val();
        // stage 8: m rounded half up at s0; if that reaches 512 the shift is s0 + 1 (saturate the shift, not the value)
        self.w_one.next = 1.into();
        self.w_s0m1.next = self.s7_s0.q.val() - 1; // s0 − 1 ≥ 10: U5, exact
        self.w_half0.next = self.w_one.val() << self.w_s0m1.val(); // 2^(s0−1): U32, exact
        self.w_r0.next = self.s7_m.q.val() + self.w_half0.val(); // < 2^31 + 2^21: U32, exact
        self.w_q0.next = self.w_r0.val() >> self.s7_s0.q.val(); // m rounded at s0: ≤ 512, exact
        if self.w_q0.val() > 511 {
            self.s8_s.d.next = self.s7_s0.q.val() + 1; // ≤ 23: U5, exact
        } else {
            self.s8_s.d.next = self.s7_s0.q.val();
        }
        self.s8_p1.d.next = self.s7_p1.q.val();
        self.s8_p2.d.next = self.s7_p2.q.val();
        self.s8_n1.d.next = self.s7_n1.q.val();
        self.s8_n2.d.next = self.s7_n2.q.val();
        // stage 9: each magnitude + 2^(s−1), >> s (round half up): ≤ 511 by the choice of s
        self.w_sm1.next = self.s8_s.q.val() - 1; // s − 1 ≥ 10: U5, exact
        self.w_half.next = self.w_one.val() << self.w_sm1.val(); // 2^(s−1): U32, exact
        self.w_a1.next = self.s8_p1.q.val() + self.w_half.val(); // < 2^31 + 2^22: U32, exact
        self.w_ay.next = self.w_ny.val() + self.w_half.val(); // U32, exact
        self.w_a2.next = self.s8_p2.q.val() + self.w_half.val(); // U32, exact
        self.w_r1.next = self.w_a1.val() >> self.s8_s.q.val(); // ≤ 511 (U9 in 32), rounded half up
        self.w_ry.next = self.w_ay.val() >> self.s8_s.q.val(); // ≤ 511, rounded half up
        self.w_r2.next = self.w_a2.val() >> self.s8_s.q.val(); // ≤ 511, rounded half up
        self.s9_q1.d.next = self.w_r1.val().get_bits::<10>(0); // U9 in 10: exact
        self.s9_qy.d.next = self.w_ry.val().get_bits::<10>(0); // U9 in 10: exact
        self.s9_q2.d.next = self.w_r2.val().get_bits::<10>(0); // U9 in 10: exact
        self.s9_n1.d.next = self.s8_n1.q.val();
        self.s9_n2.d.next = self.s8_n2.q.val();
        // stage 10: the signs back: S10 (−511..511, exact)
        if self.s9_n1.q.val() {
            self.s10_x.d.next = !self.s9_q1.q.val() + 1;
        } else {
            self.s10_x.d.next = self.s9_q1.q.val();
        }
        self.s10_y.d.next = self.s9_qy.q.val();
        if self.s9_n2.q.val() {
            self.s10_z.d.next = !self.s9_q2.q.val() + 1;
        } else {
            self.s10_z.d.next = self.s9_q2.q.val();
        }
        self.n_x.next = self.s10_x.q.val();
        self.n_y.next = self.s10_y.q.val();
        self.n_z.next = self.s10_z.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
