//! `dot3`: N·L of two Sq1.10 vectors (S12) → X (Uq0.10): `saturate(truncate(Σ n·l, 10), 0, 1023)`.
//! Latency 7: magnitudes; the multipliers' operand register (it feeds nothing else, so it can sit beside the DSP);
//! products (|n|·|l| ≤ 2^22); the products again (on the ECP5 the first is the MULT18X18D's output register, and
//! its route to the sign's carry chain was `cart_pipeline`'s critical path: the copy takes the route alone); signs
//! restored (S25); the sum; the clamp.
//!
//! The sign is restored in two carry chains side by side, not one of 25 bits: −p = (~p + 1) is the low 12 bits'
//! ~lo + 1 beside the high bits' ~hi + [lo = 0] (the carry out of the low half is 1 exactly when lo = 0), with
//! lo = 0 found in the copy's stage. On the UP5K the 25-bit chain was `palette_pipeline_shared`'s critical path
//! (9.6 ns of logic, 8.2 ns of routing, 55.9 MHz).
//!
//! The copy is two registers a product, its low 12 bits and its high 11, not one of 23: yosys 0.23's `ice40_dsp`
//! pass takes a second whole register behind a product's first as the SB_MAC16's `PIPELINE_16x16_MULT_REG2` and,
//! with no input register found, crashes (segmentation fault). Split, the first is still packed into the block.

use crate::prim::delay::Delay;
use crate::prim::q::{SBits, Sq1_10, Sq4_20};
use rust_hdl::prelude::*;

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 7;

crate::stream_block! {
    #[derive(Default)]
    pub struct Dot3: unit("dot3", LATENCY) {
        in {
            n_x: Sq1_10,
            n_y: Sq1_10,
            n_z: Sq1_10,
            l_x: Sq1_10,
            l_y: Sq1_10,
            l_z: Sq1_10,
        }
        out {
            x: Bits<10>,
        }
        s1_nm: [DFF<Bits<12>>; 3], // |n| ≤ 2048 (U12)
        s1_lm: [DFF<Bits<12>>; 3],
        s1_neg: [DFF<Bit>; 3],
        s1b_nm: [DFF<Bits<12>>; 3], // the operands again
        s1b_lm: [DFF<Bits<12>>; 3],
        s1b_neg: [DFF<Bit>; 3],
        s2_p: [DFF<Bits<23>>; 3], // |n|·|l| ≤ 2^22 (U23)
        s2_neg: [DFF<Bit>; 3],
        s2b_lo: [DFF<Bits<12>>; 3], // the products again: bits 0..11
        s2b_hi: [DFF<Bits<11>>; 3], // and bits 12..22 (two registers: see the module's comment)
        s2b_z: [DFF<Bits<13>>; 3],  // 1 where bits 0..11 are all 0, else 0 (U1 in 13): the low half's carry out in −p
        s2b_neg: [DFF<Bit>; 3],
        s3_t: [DFF<Sq4_20>; 3],
        s4_sum: DFF<Sq4_20>,
        s5_x: DFF<Bits<10>>,
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
        n_in: [Signal<Local, Sq1_10>; 3],
        l_in: [Signal<Local, Sq1_10>; 3],
        w_n: [Signal<Local, Bits<16>>; 3],
        w_l: [Signal<Local, Bits<16>>; 3],
        w_p: [Signal<Local, Bits<32>>; 3],
        w_lo: [Signal<Local, Bits<12>>; 3], // the copy's low half
        w_hi: [Signal<Local, Bits<13>>; 3], // its high half, widened to the 13 bits above bit 12 of S25
        w_tlo: [Signal<Local, Bits<12>>; 3], // bits 0..11 of ±p: −lo mod 2^12 = ~lo + 1 (wrapping on purpose), or lo
        w_thi: [Signal<Local, Bits<13>>; 3], // bits 12..24 of ±p: ~hi + [lo = 0] mod 2^13 (wrapping on purpose), or hi
        w_partial: Signal<Local, Sq4_20>,
        w_q: Signal<Local, SBits<15>>, // Σ >> 10, floor: S15 (read only where Σ ≥ 0)
    }
}

impl Logic for Dot3 {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s4_sum, s5_x);
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        self.n_in[0].next = self.n_x.val();
        self.n_in[1].next = self.n_y.val();
        self.n_in[2].next = self.n_z.val();
        self.l_in[0].next = self.l_x.val();
        self.l_in[1].next = self.l_y.val();
        self.l_in[2].next = self.l_z.val();
        // bit_cast cannot stand inside an hdl_gen loop (its width is taken outside the loop): unrolled
        self.w_n[0].next = bit_cast::<16, 12>(self.s1b_nm[0].q.val());
        self.w_n[1].next = bit_cast::<16, 12>(self.s1b_nm[1].q.val());
        self.w_n[2].next = bit_cast::<16, 12>(self.s1b_nm[2].q.val());
        self.w_l[0].next = bit_cast::<16, 12>(self.s1b_lm[0].q.val());
        self.w_l[1].next = bit_cast::<16, 12>(self.s1b_lm[1].q.val());
        self.w_l[2].next = bit_cast::<16, 12>(self.s1b_lm[2].q.val());
        self.w_hi[0].next = bit_cast::<13, 11>(self.s2b_hi[0].q.val());
        self.w_hi[1].next = bit_cast::<13, 11>(self.s2b_hi[1].q.val());
        self.w_hi[2].next = bit_cast::<13, 11>(self.s2b_hi[2].q.val());
        for i in 0..3 {
            self.s1_nm[i].clock.next = self.clock.val();
            self.s1_lm[i].clock.next = self.clock.val();
            self.s1_neg[i].clock.next = self.clock.val();
            self.s1b_nm[i].clock.next = self.clock.val();
            self.s1b_lm[i].clock.next = self.clock.val();
            self.s1b_neg[i].clock.next = self.clock.val();
            self.s2_p[i].clock.next = self.clock.val();
            self.s2_neg[i].clock.next = self.clock.val();
            self.s2b_lo[i].clock.next = self.clock.val();
            self.s2b_hi[i].clock.next = self.clock.val();
            self.s2b_z[i].clock.next = self.clock.val();
            self.s2b_neg[i].clock.next = self.clock.val();
            self.s3_t[i].clock.next = self.clock.val();
            // stage 1: magnitudes (−2048 → 2048 fits U12) and the product's sign
            if self.n_in[i].val().get_bit(11) {
                self.s1_nm[i].d.next = !self.n_in[i].val() + 1;
            } else {
                self.s1_nm[i].d.next = self.n_in[i].val();
            }
            if self.l_in[i].val().get_bit(11) {
                self.s1_lm[i].d.next = !self.l_in[i].val() + 1;
            } else {
                self.s1_lm[i].d.next = self.l_in[i].val();
            }
            self.s1_neg[i].d.next = self.n_in[i].val().get_bit(11) ^ self.l_in[i].val().get_bit(11);
            // stage 1b: carried
            self.s1b_nm[i].d.next = self.s1_nm[i].q.val();
            self.s1b_lm[i].d.next = self.s1_lm[i].q.val();
            self.s1b_neg[i].d.next = self.s1_neg[i].q.val();
            // stage 2: 12 × 12 → 23 bits
            self.w_p[i].next = self.w_n[i].val() * self.w_l[i].val();
            self.s2_p[i].d.next = self.w_p[i].val().get_bits::<23>(0);
            self.s2_neg[i].d.next = self.s1b_neg[i].q.val();
            // stage 2b: carried
            self.s2b_lo[i].d.next = self.s2_p[i].q.val().get_bits::<12>(0);
            self.s2b_hi[i].d.next = self.s2_p[i].q.val().get_bits::<11>(12);
            if self.s2_p[i].q.val().get_bits::<12>(0).any() {
                self.s2b_z[i].d.next = 0.into();
            } else {
                self.s2b_z[i].d.next = 1.into();
            }
            self.s2b_neg[i].d.next = self.s2_neg[i].q.val();
            // stage 3: the sign back (S25), in two chains: ~p + 1 = (~hi + [lo = 0]) · 2^12 + (~lo + 1) mod 2^12
            self.w_lo[i].next = self.s2b_lo[i].q.val();
            if self.s2b_neg[i].q.val() {
                self.w_tlo[i].next = !self.w_lo[i].val() + 1;
                self.w_thi[i].next = !self.w_hi[i].val() + self.s2b_z[i].q.val();
            } else {
                self.w_tlo[i].next = self.w_lo[i].val();
                self.w_thi[i].next = self.w_hi[i].val();
            }
        }
        // stage 3: the two halves side by side (after the loop that writes them: bit_cast cannot stand inside it)
        self.s3_t[0].d.next = (bit_cast::<25, 13>(self.w_thi[0].val()) << 12) | bit_cast::<25, 12>(self.w_tlo[0].val());
        self.s3_t[1].d.next = (bit_cast::<25, 13>(self.w_thi[1].val()) << 12) | bit_cast::<25, 12>(self.w_tlo[1].val());
        self.s3_t[2].d.next = (bit_cast::<25, 13>(self.w_thi[2].val()) << 12) | bit_cast::<25, 12>(self.w_tlo[2].val());
        // stage 4: the sum of three, |Σ| ≤ 3·2^22 < 2^24
        self.w_partial.next = self.s3_t[0].q.val() + self.s3_t[1].q.val();
        self.s4_sum.d.next = self.w_partial.val() + self.s3_t[2].q.val();
        // stage 5: negative → 0; else floor(Σ / 1024), saturated at 1023
        self.w_q.next = self.s4_sum.q.val().get_bits::<15>(10);
        if self.s4_sum.q.val().get_bit(24) {
            self.s5_x.d.next = 0.into();
        } else if self.w_q.val() > 1023 {
            self.s5_x.d.next = 1023.into();
        } else {
            self.s5_x.d.next = self.w_q.val().get_bits::<10>(0);
        }
        self.x.next = self.s5_x.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
