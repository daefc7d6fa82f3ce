//! `light_iter`: per-vertex S8 light directions interpolated across a triangle from U9 barycentric weights:
//! `L = l0·256 + (l1 − l0)·w1 + (l2 − l0)·w2` (S20, Sq11.8) → `truncate` 6 (floor) → `saturate` to S10 (Sq7.2).
//! Each component is a `LightLane`; latency 8: the differences; the two `SmMul`s (|d|, the operand registers, |d|·w,
//! the product carried); l0·256 ± |d1|·w1; ± |d2|·w2; the shift and saturation. The operand register feeds nothing but the multiplier, so
//! the placer can put it beside the DSP: the long route lands on a register-to-register path.

use crate::prim::delay::Delay;
use crate::prim::q::{SBits, Sq11_8, Sq7_2, S8, S9};
use crate::prim::sm_mul::{self, SmMul};
use rust_hdl::prelude::*;

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 1 + sm_mul::LATENCY + 3;

crate::block! {
    /// One component of the light: `l0·256 + (l1 − l0)·w1 + (l2 − l0)·w2`, floored to Sq7.2 and saturated to S10.
    /// The weights arrive one clock after the components, as the differences leave stage 1.
    #[derive(Default)]
    pub struct LightLane {
        pub clock: Signal<In, Clock>,
        pub l0: Signal<In, S8>,
        pub l1: Signal<In, S8>,
        pub l2: Signal<In, S8>,
        /// U9 weights in 16 bits, one clock after l0, l1, l2.
        pub w1: Signal<In, Bits<16>>,
        pub w2: Signal<In, Bits<16>>,
        pub light: Signal<Out, Sq7_2>,
        // stage 1: the differences (S9) and l0·256 (S20)
        s1_d1: DFF<S9>,
        s1_d2: DFF<S9>,
        // l0·256 in 20 bits although 16 carry it (the width report's spare bits): its low 8 bits are zero and its top
        // 4 copies of the sign, which yosys drops and merges; carrying l0 alone and widening at the sum was measured
        // the same (645 SB_LUT4, 688 SB_DFF on the UP5K either way)
        s1_base: DFF<Sq11_8>,
        // stages 2–5: |d|·w ≤ 255·511 < 2^17, the base beside
        mul1: SmMul<9>, // S9: |d| ≤ 255 leaves SmMul as 8 bits, so the DSP's operand is 8 bits wide
        mul2: SmMul<9>,
        base: Delay<Sq11_8, { sm_mul::LATENCY }>,
        // stage 6: l0·256 ± |d1|·w1 (S20), the second product beside
        s5_part: DFF<Sq11_8>,
        s5_p2: DFF<Sq11_8>,
        s5_n2: DFF<Bit>,
        // stage 7: the sum (S20; |L| ≤ 127·256 + 2·255·511 = 293,122 < 2^19)
        s6_acc: DFF<Sq11_8>,
        // stage 8: floor to Sq7.2, saturate to S10
        s7_out: DFF<Sq7_2>,
        w_e0: Signal<Local, S9>, // l0 sign-extended to S9
        w_e1: Signal<Local, S9>,
        w_e2: Signal<Local, S9>,
        w_e20: Signal<Local, Sq11_8>,  // l0 sign-extended to 20 bits
        w_p1: Signal<Local, Sq11_8>,   // |d1|·w1 (U17 in 20 bits)
        w_q: Signal<Local, SBits<14>>, // acc >> 6 (floor): S14
        w_hi: Signal<Local, Bits<5>>,  // its bits 13..9: all equal when it fits S10
    }
}

impl Logic for LightLane {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_d1, s1_d2, s1_base, s5_part, s5_p2, s5_n2, s6_acc, s7_out);
        clock!(self, clock, mul1, mul2, base);
        // stage 1: sign-extend S8 → S9, the differences S9 (−255..255: exact in 9 bits)
        self.w_e0.next = bit_cast::<9, 8>(self.l0.val()); // S8 in 9, extended below
        if self.l0.val().get_bit(7) {
            self.w_e0.next = self.w_e0.val() | 0x100;
        }
        self.w_e1.next = bit_cast::<9, 8>(self.l1.val()); // S8 in 9
        if self.l1.val().get_bit(7) {
            self.w_e1.next = self.w_e1.val() | 0x100;
        }
        self.w_e2.next = bit_cast::<9, 8>(self.l2.val()); // S8 in 9
        if self.l2.val().get_bit(7) {
            self.w_e2.next = self.w_e2.val() | 0x100;
        }
        self.s1_d1.d.next = self.w_e1.val() - self.w_e0.val(); // S9 ∈ −255..255, exact
        self.s1_d2.d.next = self.w_e2.val() - self.w_e0.val(); // S9, exact
        self.w_e20.next = bit_cast::<20, 8>(self.l0.val()); // S8 in 20, extended below
        if self.l0.val().get_bit(7) {
            self.w_e20.next = self.w_e20.val() | 0xFFF00;
        }
        self.s1_base.d.next = self.w_e20.val() << 8; // l0·256: S16 in S20, exact

        // stages 2–5: the products, the base beside them
        self.mul1.x.next = self.s1_d1.q.val();
        self.mul1.w.next = self.w1.val();
        self.mul2.x.next = self.s1_d2.q.val();
        self.mul2.w.next = self.w2.val();
        self.base.d.next = self.s1_base.q.val();
        // stage 6: l0·256 ± |d1|·w1 (S20, exact); the products are < 2^17, so their low 20 bits are all of them
        self.w_p1.next = self.mul1.p.val().get_bits::<20>(0); // U17 in 20, exact
        if self.mul1.neg.val() {
            self.s5_part.d.next = self.base.q.val() - self.w_p1.val(); // S20, exact
        } else {
            self.s5_part.d.next = self.base.q.val() + self.w_p1.val(); // S20, exact
        }
        self.s5_p2.d.next = self.mul2.p.val().get_bits::<20>(0); // U17 in 20, exact
        self.s5_n2.d.next = self.mul2.neg.val();
        // stage 7: ± |d2|·w2 (S20, exact)
        if self.s5_n2.q.val() {
            self.s6_acc.d.next = self.s5_part.q.val() - self.s5_p2.q.val();
        } else {
            self.s6_acc.d.next = self.s5_part.q.val() + self.s5_p2.q.val();
        }
        // stage 8: acc >> 6 (floor) keeps its sign in 14 bits; it fits S10 when bits 13..9 are all equal (saturate)
        self.w_q.next = self.s6_acc.q.val().get_bits::<14>(6); // S20 → S14, floor
        self.w_hi.next = self.w_q.val().get_bits::<5>(9); // the top 5 bits, a test only
        if self.w_q.val().get_bit(13) {
            if self.w_hi.val().all() {
                self.s7_out.d.next = self.w_q.val().get_bits::<10>(0); // fits S10
            } else {
                self.s7_out.d.next = 0x200.into(); // −512
            }
        } else {
            if self.w_hi.val().any() {
                self.s7_out.d.next = 0x1FF.into(); // +511
            } else {
                self.s7_out.d.next = self.w_q.val().get_bits::<10>(0); // fits S10
            }
        }
        self.light.next = self.s7_out.q.val();
    }
}

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
        pub lane: [LightLane; 3], // x, y, z
        // stage 1: the weights widened to the multipliers' 16 bits, to meet the differences
        s1_w1: DFF<Bits<16>>,
        s1_w2: DFF<Bits<16>>,
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the lanes
    }
}

impl Logic for LightIter {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_w1, s1_w2);
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        self.s1_w1.d.next = bit_cast::<16, 9>(self.w1.val()); // U9 in 16, widening
        self.s1_w2.d.next = bit_cast::<16, 9>(self.w2.val()); // U9 in 16, widening
        for i in 0..3 {
            self.lane[i].clock.next = self.clock.val();
            self.lane[i].w1.next = self.s1_w1.q.val();
            self.lane[i].w2.next = self.s1_w2.q.val();
        }
        self.lane[0].l0.next = self.l0_x.val();
        self.lane[0].l1.next = self.l1_x.val();
        self.lane[0].l2.next = self.l2_x.val();
        self.lane[1].l0.next = self.l0_y.val();
        self.lane[1].l1.next = self.l1_y.val();
        self.lane[1].l2.next = self.l2_y.val();
        self.lane[2].l0.next = self.l0_z.val();
        self.lane[2].l1.next = self.l1_z.val();
        self.lane[2].l2.next = self.l2_z.val();
        self.light_x.next = self.lane[0].light.val();
        self.light_y.next = self.lane[1].light.val();
        self.light_z.next = self.lane[2].light.val();
        self.valid_out.next = self.valid.q.val();
    }
}
