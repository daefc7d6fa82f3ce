//! `gloss`: the quadratic glossiness of US 6,819,319, `P = L + ((C·(Q − L)) >> 8)` with
//! `L = max(0, 1023 − (k·(1023 − X) >> 3))`, `k = C + 8`, `Q = (L·L) >> 10`. Since Q ≤ L the signed step is done on the magnitude:
//! `(C·(Q − L)) >> 8` (arithmetic, floor) = `−((C·(L − Q) + 255) >> 8)`, so every signal here is unsigned.
//! Latency 14: k, t; their operand register; k·t; k·t again; the L clamp; its operand register; L·L; Q again; L − Q;
//! its operand register; C·(L − Q); C·(L − Q) again; the ceiling shift; the final subtract. An operand register feeds
//! nothing but its multiplier, so the placer can put it beside the DSP and the long route lands on a
//! register-to-register path; each product is copied once before the logic that reads it for the same reason on the
//! way out (on the ECP5 the first register is the MULT18X18D's output register: the product into the L clamp was
//! `cart_pipeline`'s critical path), in two registers, low and high bits, for the reason `dot3` gives.

use crate::prim::delay::Delay;
use crate::prim::q::{Uq0_10, Uq6_3, U8};
use rust_hdl::prelude::*;

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 14;

crate::stream_block! {
    #[derive(Default)]
    pub struct Gloss: unit("gloss", LATENCY) {
        in {
            conc: U8,
            x: Uq0_10,
        }
        out {
            p: Uq0_10,
        }
        // stage 1: k = C + 8, t = 1023 − X
        s1_k: DFF<Uq6_3>,
        s1_t: DFF<Uq0_10>,
        s1_c: DFF<U8>,
        // stage 1b: the operands again
        s1b_k: DFF<Uq6_3>,
        s1b_t: DFF<Uq0_10>,
        s1b_c: DFF<U8>,
        // stage 2: m = k·t (U19)
        s2_m: DFF<Bits<19>>,
        s2_c: DFF<U8>,
        // stage 2b: m again, bits 0..9 and 10..18
        s2b_m_lo: DFF<Bits<10>>,
        s2b_m_hi: DFF<Bits<9>>,
        s2b_c: DFF<U8>,
        // stage 3: L = max(0, 1023 − (m >> 3))
        s3_l: DFF<Uq0_10>,
        s3_c: DFF<U8>,
        // stage 3b: the operand again
        s3b_l: DFF<Uq0_10>,
        s3b_c: DFF<U8>,
        // stage 4: L·L (U20)
        s4_ll: DFF<Bits<20>>,
        s4_l: DFF<Uq0_10>,
        s4_c: DFF<U8>,
        // stage 4b: Q = (L·L) >> 10 (floor) again, its bits 0..4 and 5..9 (the product's only bits read)
        s4b_q_lo: DFF<Bits<5>>,
        s4b_q_hi: DFF<Bits<5>>,
        s4b_l: DFF<Uq0_10>,
        s4b_c: DFF<U8>,
        // stage 5: L − Q, Q = (L·L) >> 10
        s5_d: DFF<Uq0_10>,
        s5_l: DFF<Uq0_10>,
        s5_c: DFF<U8>,
        // stage 5b: the operands again
        s5b_d: DFF<Uq0_10>,
        s5b_l: DFF<Uq0_10>,
        s5b_c: DFF<U8>,
        // stage 6: C·(L − Q) (U18)
        s6_prod: DFF<Bits<18>>,
        s6_l: DFF<Uq0_10>,
        // stage 6b: C·(L − Q) again, bits 0..8 and 9..17
        s6b_lo: DFF<Bits<9>>,
        s6b_hi: DFF<Bits<9>>,
        s6b_l: DFF<Uq0_10>,
        // stage 7: ceil((C·(L − Q)) / 256)
        s7_q: DFF<Uq0_10>,
        s7_l: DFF<Uq0_10>,
        // stage 8: P = L − that
        s8_p: DFF<Uq0_10>,
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
        w_k: Signal<Local, Bits<16>>,
        w_t: Signal<Local, Bits<16>>,
        w_m: Signal<Local, Bits<32>>,
        w_m2: Signal<Local, Bits<19>>, // m out of its two stage-2b registers
        m3: Signal<Local, Bits<16>>,
        m3_lo: Signal<Local, Uq0_10>,
        w_l: Signal<Local, Bits<16>>,
        w_ll: Signal<Local, Bits<32>>,
        w_c: Signal<Local, Bits<16>>,
        w_d: Signal<Local, Bits<16>>,
        w_q: Signal<Local, Uq0_10>, // Q out of its two stage-4b registers
        w_prod: Signal<Local, Bits<32>>,
        w_prod2: Signal<Local, Bits<18>>, // C·(L − Q) out of its two stage-6b registers
        ceil_sum: Signal<Local, Bits<18>>,
    }
}

impl Logic for Gloss {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s1_k, s1_t, s1_c, s1b_k, s1b_t, s1b_c, s2_m, s2_c, s2b_m_lo, s2b_m_hi, s2b_c, s3_l, s3_c,
            s3b_l, s3b_c, s4_ll, s4_l, s4_c, s4b_q_lo, s4b_q_hi, s4b_l, s4b_c, s5_d, s5_l, s5_c, s5b_d, s5b_l, s5b_c,
            s6_prod, s6_l, s6b_lo, s6b_hi, s6b_l, s7_q, s7_l, s8_p
        );
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1
        self.s1_k.d.next = bit_cast::<9, 8>(self.conc.val()) + 8; // U9, no overflow (≤ 263)
        self.s1_t.d.next = 1023 - self.x.val(); // U10, X ≤ 1023
        self.s1_c.d.next = self.conc.val();
        // stage 1b: carried
        self.s1b_k.d.next = self.s1_k.q.val();
        self.s1b_t.d.next = self.s1_t.q.val();
        self.s1b_c.d.next = self.s1_c.q.val();
        // stage 2: k·t, 9 × 10 bits → 19 bits
        self.w_k.next = bit_cast::<16, 9>(self.s1b_k.q.val());
        self.w_t.next = bit_cast::<16, 10>(self.s1b_t.q.val());
        self.w_m.next = self.w_k.val() * self.w_t.val();
        self.s2_m.d.next = self.w_m.val().get_bits::<19>(0); // ≤ 263·1023 < 2^19: exact
        self.s2_c.d.next = self.s1b_c.q.val();
        // stage 2b: carried
        self.s2b_m_lo.d.next = self.s2_m.q.val().get_bits::<10>(0);
        self.s2b_m_hi.d.next = self.s2_m.q.val().get_bits::<9>(10);
        self.s2b_c.d.next = self.s2_c.q.val();
        self.w_m2.next = (bit_cast::<19, 9>(self.s2b_m_hi.q.val()) << 10) | bit_cast::<19, 10>(self.s2b_m_lo.q.val());
        // stage 3: m >> 3 (floor), then 1023 − that, saturated at 0
        self.m3.next = self.w_m2.val().get_bits::<16>(3);
        self.m3_lo.next = self.m3.val().get_bits::<10>(0);
        if self.m3.val() > 1023 {
            self.s3_l.d.next = 0.into();
        } else {
            self.s3_l.d.next = 1023 - self.m3_lo.val();
        }
        self.s3_c.d.next = self.s2b_c.q.val();
        // stage 3b: carried
        self.s3b_l.d.next = self.s3_l.q.val();
        self.s3b_c.d.next = self.s3_c.q.val();
        // stage 4: L·L, 10 × 10 bits → 20 bits
        self.w_l.next = bit_cast::<16, 10>(self.s3b_l.q.val());
        self.w_ll.next = self.w_l.val() * self.w_l.val();
        self.s4_ll.d.next = self.w_ll.val().get_bits::<20>(0);
        self.s4_l.d.next = self.s3b_l.q.val();
        self.s4_c.d.next = self.s3b_c.q.val();
        // stage 4b: Q = (L·L) >> 10 (floor), carried
        self.s4b_q_lo.d.next = self.s4_ll.q.val().get_bits::<5>(10);
        self.s4b_q_hi.d.next = self.s4_ll.q.val().get_bits::<5>(15);
        self.s4b_l.d.next = self.s4_l.q.val();
        self.s4b_c.d.next = self.s4_c.q.val();
        self.w_q.next = (bit_cast::<10, 5>(self.s4b_q_hi.q.val()) << 5) | bit_cast::<10, 5>(self.s4b_q_lo.q.val());
        // stage 5: d = L − Q; Q ≤ L so d ≥ 0
        self.s5_d.d.next = self.s4b_l.q.val() - self.w_q.val();
        self.s5_l.d.next = self.s4b_l.q.val();
        self.s5_c.d.next = self.s4b_c.q.val();
        // stage 5b: carried
        self.s5b_d.d.next = self.s5_d.q.val();
        self.s5b_l.d.next = self.s5_l.q.val();
        self.s5b_c.d.next = self.s5_c.q.val();
        // stage 6: C·d, 8 × 10 bits → 18 bits
        self.w_c.next = bit_cast::<16, 8>(self.s5b_c.q.val());
        self.w_d.next = bit_cast::<16, 10>(self.s5b_d.q.val());
        self.w_prod.next = self.w_c.val() * self.w_d.val();
        self.s6_prod.d.next = self.w_prod.val().get_bits::<18>(0);
        self.s6_l.d.next = self.s5b_l.q.val();
        // stage 6b: carried
        self.s6b_lo.d.next = self.s6_prod.q.val().get_bits::<9>(0);
        self.s6b_hi.d.next = self.s6_prod.q.val().get_bits::<9>(9);
        self.s6b_l.d.next = self.s6_l.q.val();
        self.w_prod2.next = (bit_cast::<18, 9>(self.s6b_hi.q.val()) << 9) | bit_cast::<18, 9>(self.s6b_lo.q.val());
        // stage 7: ceil(C·d / 256) = (C·d + 255) >> 8, which is −((C·(Q − L)) >> 8)
        self.ceil_sum.next = self.w_prod2.val() + 255; // ≤ 255·1023 + 255 < 2^18
        self.s7_q.d.next = self.ceil_sum.val().get_bits::<10>(8); // U18 >> 8 (floor of the + 255: a ceiling): U10
        self.s7_l.d.next = self.s6b_l.q.val();
        // stage 8: P = L − ceil(...)
        self.s8_p.d.next = self.s7_l.q.val() - self.s7_q.q.val();
        self.p.next = self.s8_p.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
