//! `height_normal`: US 2004/0207631's normal unit [156]: N = 7·(−k·Tang1y, 2, −k·Tang2y) (16 fraction bits), brought to
//! S10 for the shared normaliser by one shift for all three components, the smallest that keeps the largest rounded
//! magnitude ≤ 511. See `vectors::height_normal`. Latency 12: 7k; the two `SmMulWide`s; the three comparisons of
//! the magnitudes; the largest; its leading one and, at each place, whether rounding there carries (its top ten bits
//! all ones); the shift s and 2^(s−1), both from those flags (no shifter); the three magnitudes + 2^(s−1); >> s; the
//! signs. (With the larger product chosen beside its comparison, and the shift found by a priority chain in one
//! stage, the ECP5-45F placed `height_pipeline` at 140.1 MHz, those two paths the critical ones: 2.35 ns of logic and
//! 4.79 of routing, 3.08 and 4.45.)

use crate::prim::delay::Delay;
use crate::prim::q::{SBits, Sq9_0, U8};
use crate::prim::sm_mul::{self, SmMulWide};
use rust_hdl::prelude::*;

pub const LATENCY: usize = 8 + sm_mul::WIDE_LATENCY;

crate::stream_block! {
    #[derive(Default)]
    pub struct HeightNormal: unit("height_normal", LATENCY) {
        in {
            t1: SBits<21>,
            t2: SBits<21>,
            scale: U8,
        }
        out {
            n_x: Sq9_0,
            n_y: Sq9_0,
            n_z: Sq9_0,
        }
        // stage 1: 7k = 8k − k (U11 in 16); the tangents
        s1_k7: DFF<Bits<16>>,
        s1_t1: DFF<SBits<21>>,
        s1_t2: DFF<SBits<21>>,
        // stages 2–5: 7k·|t| < 1785·2^20 < 2^31 (U31 in 32), with t's sign
        mul1: SmMulWide<21>,
        mul2: SmMulWide<21>,
        // stage 5b: which of the three magnitudes is larger, pair by pair; N's signs (x, z negative where the tangent
        // is positive: N = −7k·t)
        s5b_g12: DFF<Bit>,
        s5b_g1y: DFF<Bit>,
        s5b_g2y: DFF<Bit>,
        s5b_p1: DFF<Bits<32>>,
        s5b_p2: DFF<Bits<32>>,
        s5b_n1: DFF<Bit>,
        s5b_n2: DFF<Bit>,
        // stage 6: the largest magnitude of (7k·|t1|, 14·2^16, 7k·|t2|), U31 in 32
        s6_m: DFF<Bits<32>>,
        s6_p1: DFF<Bits<32>>,
        s6_p2: DFF<Bits<32>>,
        s6_n1: DFF<Bit>,
        s6_n2: DFF<Bit>,
        // stage 7: the largest's leading one, one-hot over places 19..30 (h), and whether its ten bits from each place
        // down are all ones (a)
        s7_h: [DFF<Bit>; 12],
        s7_a: [DFF<Bit>; 12],
        s7_p1: DFF<Bits<32>>,
        s7_p2: DFF<Bits<32>>,
        s7_n1: DFF<Bit>,
        s7_n2: DFF<Bit>,
        // stage 8: 2^(s−1)
        s8_half: DFF<Bits<32>>,
        s8_s: DFF<Bits<5>>,
        s8_p1: DFF<Bits<32>>,
        s8_p2: DFF<Bits<32>>,
        s8_n1: DFF<Bit>,
        s8_n2: DFF<Bit>,
        // stage 9: the magnitudes + 2^(s−1)
        s9_a1: DFF<Bits<32>>,
        s9_ay: DFF<Bits<32>>,
        s9_a2: DFF<Bits<32>>,
        s9_s: DFF<Bits<5>>,
        s9_n1: DFF<Bit>,
        s9_n2: DFF<Bit>,
        // stage 10: >> s, ≤ 511 (U9 in 10)
        s10_q1: DFF<Bits<10>>,
        s10_qy: DFF<Bits<10>>,
        s10_q2: DFF<Bits<10>>,
        s10_n1: DFF<Bit>,
        s10_n2: DFF<Bit>,
        // stage 11: the signs: S10
        s11_x: DFF<Sq9_0>,
        s11_y: DFF<Sq9_0>,
        s11_z: DFF<Sq9_0>,
        valid: Delay<Bit, LATENCY>,
        w_k: Signal<Local, Bits<16>>,
        w_k8: Signal<Local, Bits<16>>,
        w_ny: Signal<Local, Bits<32>>,
        w_half: Signal<Local, Bits<32>>,
        w_s: Signal<Local, Bits<5>>,
        w_r1: Signal<Local, Bits<32>>,
        w_ry: Signal<Local, Bits<32>>,
        w_r2: Signal<Local, Bits<32>>,
    }
}

impl Logic for HeightNormal {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_k7, s1_t1, s1_t2, s6_m, s6_p1, s6_p2, s6_n1, s6_n2, s7_p1, s7_p2, s7_n1);
        dff_setup!(self, clock, s7_n2, s8_half, s8_s, s8_p1, s8_p2, s8_n1, s8_n2, s9_a1, s9_ay, s9_a2, s9_s, s9_n1);
        dff_setup!(self, clock, s5b_g12, s5b_g1y, s5b_g2y, s5b_p1, s5b_p2, s5b_n1, s5b_n2);
        dff_setup!(self, clock, s9_n2, s10_q1, s10_qy, s10_q2, s10_n1, s10_n2, s11_x, s11_y, s11_z);
        clock!(self, clock, mul1, mul2, valid);
        for j in 0..12 {
            self.s7_h[j].clock.next = self.clock.val();
            self.s7_a[j].clock.next = self.clock.val();
        }
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
        // stage 5b: the three comparisons; N_x = −7k·t1 is negative where t1 is positive
        self.w_ny.next = 917_504.into(); // N_y = 7·2 with 16 fraction bits = 14·2^16
        self.s5b_g12.d.next = self.mul1.p.val() > self.mul2.p.val();
        self.s5b_g1y.d.next = self.mul1.p.val() > self.w_ny.val();
        self.s5b_g2y.d.next = self.mul2.p.val() > self.w_ny.val();
        self.s5b_p1.d.next = self.mul1.p.val();
        self.s5b_p2.d.next = self.mul2.p.val();
        self.s5b_n1.d.next = !self.mul1.neg.val();
        self.s5b_n2.d.next = !self.mul2.neg.val();
        // stage 6: the largest of the three magnitudes, chosen by the comparisons
        self.s6_m.d.next = self.w_ny.val();
        if self.s5b_g12.q.val() {
            if self.s5b_g1y.q.val() {
                self.s6_m.d.next = self.s5b_p1.q.val();
            }
        } else if self.s5b_g2y.q.val() {
            self.s6_m.d.next = self.s5b_p2.q.val();
        }
        self.s6_p1.d.next = self.s5b_p1.q.val();
        self.s6_p2.d.next = self.s5b_p2.q.val();
        self.s6_n1.d.next = self.s5b_n1.q.val();
        self.s6_n2.d.next = self.s5b_n2.q.val();
        // stage 7: the leading one of m is at a place p ≥ 19 (m ≥ 14·2^16), so m >> (p − 8) ∈ 256..511; rounding at
        // p − 8 reaches 512 exactly when the ten bits p..p − 9 are all ones, and then s = p − 7. Flag j is place
        // 19 + j; m < 2^31, so place 30 has nothing above it.
        self.s7_h[0].d.next = self.s6_m.q.val().get_bit(19) & !self.s6_m.q.val().get_bits::<11>(20).any();
        self.s7_a[0].d.next = self.s6_m.q.val().get_bits::<10>(10).all();
        self.s7_h[1].d.next = self.s6_m.q.val().get_bit(20) & !self.s6_m.q.val().get_bits::<10>(21).any();
        self.s7_a[1].d.next = self.s6_m.q.val().get_bits::<10>(11).all();
        self.s7_h[2].d.next = self.s6_m.q.val().get_bit(21) & !self.s6_m.q.val().get_bits::<9>(22).any();
        self.s7_a[2].d.next = self.s6_m.q.val().get_bits::<10>(12).all();
        self.s7_h[3].d.next = self.s6_m.q.val().get_bit(22) & !self.s6_m.q.val().get_bits::<8>(23).any();
        self.s7_a[3].d.next = self.s6_m.q.val().get_bits::<10>(13).all();
        self.s7_h[4].d.next = self.s6_m.q.val().get_bit(23) & !self.s6_m.q.val().get_bits::<7>(24).any();
        self.s7_a[4].d.next = self.s6_m.q.val().get_bits::<10>(14).all();
        self.s7_h[5].d.next = self.s6_m.q.val().get_bit(24) & !self.s6_m.q.val().get_bits::<6>(25).any();
        self.s7_a[5].d.next = self.s6_m.q.val().get_bits::<10>(15).all();
        self.s7_h[6].d.next = self.s6_m.q.val().get_bit(25) & !self.s6_m.q.val().get_bits::<5>(26).any();
        self.s7_a[6].d.next = self.s6_m.q.val().get_bits::<10>(16).all();
        self.s7_h[7].d.next = self.s6_m.q.val().get_bit(26) & !self.s6_m.q.val().get_bits::<4>(27).any();
        self.s7_a[7].d.next = self.s6_m.q.val().get_bits::<10>(17).all();
        self.s7_h[8].d.next = self.s6_m.q.val().get_bit(27) & !self.s6_m.q.val().get_bits::<3>(28).any();
        self.s7_a[8].d.next = self.s6_m.q.val().get_bits::<10>(18).all();
        self.s7_h[9].d.next = self.s6_m.q.val().get_bit(28) & !self.s6_m.q.val().get_bits::<2>(29).any();
        self.s7_a[9].d.next = self.s6_m.q.val().get_bits::<10>(19).all();
        self.s7_h[10].d.next = self.s6_m.q.val().get_bit(29) & !self.s6_m.q.val().get_bits::<1>(30).any();
        self.s7_a[10].d.next = self.s6_m.q.val().get_bits::<10>(20).all();
        self.s7_h[11].d.next = self.s6_m.q.val().get_bit(30);
        self.s7_a[11].d.next = self.s6_m.q.val().get_bits::<10>(21).all();
        self.s7_p1.d.next = self.s6_p1.q.val();
        self.s7_p2.d.next = self.s6_p2.q.val();
        self.s7_n1.d.next = self.s6_n1.q.val();
        self.s7_n2.d.next = self.s6_n2.q.val();
        // stage 8: s = k (11..23) where the leading one is at k + 8 and does not carry, or at k + 7 and carries: one k
        // exactly, so s and the rounding constant 2^(s−1) are ORs of constants
        self.w_half.next = 0.into();
        self.w_s.next = 0.into();
        if self.s7_h[0].q.val() & !self.s7_a[0].q.val() {
            self.w_half.next = self.w_half.val() | 1024;
            self.w_s.next = self.w_s.val() | 11;
        }
        if (self.s7_h[1].q.val() & !self.s7_a[1].q.val()) | (self.s7_h[0].q.val() & self.s7_a[0].q.val()) {
            self.w_half.next = self.w_half.val() | 2048;
            self.w_s.next = self.w_s.val() | 12;
        }
        if (self.s7_h[2].q.val() & !self.s7_a[2].q.val()) | (self.s7_h[1].q.val() & self.s7_a[1].q.val()) {
            self.w_half.next = self.w_half.val() | 4096;
            self.w_s.next = self.w_s.val() | 13;
        }
        if (self.s7_h[3].q.val() & !self.s7_a[3].q.val()) | (self.s7_h[2].q.val() & self.s7_a[2].q.val()) {
            self.w_half.next = self.w_half.val() | 8192;
            self.w_s.next = self.w_s.val() | 14;
        }
        if (self.s7_h[4].q.val() & !self.s7_a[4].q.val()) | (self.s7_h[3].q.val() & self.s7_a[3].q.val()) {
            self.w_half.next = self.w_half.val() | 16384;
            self.w_s.next = self.w_s.val() | 15;
        }
        if (self.s7_h[5].q.val() & !self.s7_a[5].q.val()) | (self.s7_h[4].q.val() & self.s7_a[4].q.val()) {
            self.w_half.next = self.w_half.val() | 32768;
            self.w_s.next = self.w_s.val() | 16;
        }
        if (self.s7_h[6].q.val() & !self.s7_a[6].q.val()) | (self.s7_h[5].q.val() & self.s7_a[5].q.val()) {
            self.w_half.next = self.w_half.val() | 65536;
            self.w_s.next = self.w_s.val() | 17;
        }
        if (self.s7_h[7].q.val() & !self.s7_a[7].q.val()) | (self.s7_h[6].q.val() & self.s7_a[6].q.val()) {
            self.w_half.next = self.w_half.val() | 131072;
            self.w_s.next = self.w_s.val() | 18;
        }
        if (self.s7_h[8].q.val() & !self.s7_a[8].q.val()) | (self.s7_h[7].q.val() & self.s7_a[7].q.val()) {
            self.w_half.next = self.w_half.val() | 262144;
            self.w_s.next = self.w_s.val() | 19;
        }
        if (self.s7_h[9].q.val() & !self.s7_a[9].q.val()) | (self.s7_h[8].q.val() & self.s7_a[8].q.val()) {
            self.w_half.next = self.w_half.val() | 524288;
            self.w_s.next = self.w_s.val() | 20;
        }
        if (self.s7_h[10].q.val() & !self.s7_a[10].q.val()) | (self.s7_h[9].q.val() & self.s7_a[9].q.val()) {
            self.w_half.next = self.w_half.val() | 1048576;
            self.w_s.next = self.w_s.val() | 21;
        }
        if (self.s7_h[11].q.val() & !self.s7_a[11].q.val()) | (self.s7_h[10].q.val() & self.s7_a[10].q.val()) {
            self.w_half.next = self.w_half.val() | 2097152;
            self.w_s.next = self.w_s.val() | 22;
        }
        if self.s7_h[11].q.val() & self.s7_a[11].q.val() {
            self.w_half.next = self.w_half.val() | 4194304;
            self.w_s.next = self.w_s.val() | 23;
        }
        self.s8_half.d.next = self.w_half.val(); // 2^(s−1): U32, exact
        self.s8_s.d.next = self.w_s.val();
        self.s8_p1.d.next = self.s7_p1.q.val();
        self.s8_p2.d.next = self.s7_p2.q.val();
        self.s8_n1.d.next = self.s7_n1.q.val();
        self.s8_n2.d.next = self.s7_n2.q.val();
        // stage 9: each magnitude + 2^(s−1) (< 2^31 + 2^22: U32, exact)
        self.s9_a1.d.next = self.s8_p1.q.val() + self.s8_half.q.val();
        self.s9_ay.d.next = self.w_ny.val() + self.s8_half.q.val();
        self.s9_a2.d.next = self.s8_p2.q.val() + self.s8_half.q.val();
        self.s9_s.d.next = self.s8_s.q.val();
        self.s9_n1.d.next = self.s8_n1.q.val();
        self.s9_n2.d.next = self.s8_n2.q.val();
        // stage 10: >> s: the magnitudes rounded half up, ≤ 511 by the choice of s (U9 in 10, exact)
        self.w_r1.next = self.s9_a1.q.val() >> self.s9_s.q.val();
        self.w_ry.next = self.s9_ay.q.val() >> self.s9_s.q.val();
        self.w_r2.next = self.s9_a2.q.val() >> self.s9_s.q.val();
        self.s10_q1.d.next = self.w_r1.val().get_bits::<10>(0); // ≤ 511: U9 in 10, exact
        self.s10_qy.d.next = self.w_ry.val().get_bits::<10>(0); // ≤ 511: U9 in 10, exact
        self.s10_q2.d.next = self.w_r2.val().get_bits::<10>(0); // ≤ 511: U9 in 10, exact
        self.s10_n1.d.next = self.s9_n1.q.val();
        self.s10_n2.d.next = self.s9_n2.q.val();
        // stage 11: the signs back: S10 (−511..511, exact)
        if self.s10_n1.q.val() {
            self.s11_x.d.next = !self.s10_q1.q.val() + 1;
        } else {
            self.s11_x.d.next = self.s10_q1.q.val();
        }
        self.s11_y.d.next = self.s10_qy.q.val();
        if self.s10_n2.q.val() {
            self.s11_z.d.next = !self.s10_q2.q.val() + 1;
        } else {
            self.s11_z.d.next = self.s10_q2.q.val();
        }
        self.n_x.next = self.s11_x.q.val();
        self.n_y.next = self.s11_y.q.val();
        self.n_z.next = self.s11_z.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
