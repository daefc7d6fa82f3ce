//! `tangent`: US 2004/0207631's tangent construction unit [155]: `Tang1y = lerp(V, G − R, A − B)`,
//! `Tang2y = lerp(U, B − R, A − G)` from the four bilinear units' exact results (U25, 17 fraction bits of a height
//! LSB) and the unadjusted blend factors. See `vectors::tangent` for the recipe. Latency 8: the results truncated to
//! 12 fraction bits and their differences; d2 − d1 and e2 − e1, d1·256 and e1·256; the two `SmMulWide`s (their
//! magnitudes reach 21 bits); the sums; the floor.

use crate::prim::delay::Delay;
use crate::prim::q::{SBits, U8};
use crate::prim::sm_mul::{self, SmMulWide};
use rust_hdl::prelude::*;

pub const LATENCY: usize = 4 + sm_mul::WIDE_LATENCY;

crate::stream_block! {
    #[derive(Default)]
    pub struct Tangent: unit("tangent", LATENCY) {
        in {
            red: Bits<25>,
            green: Bits<25>,
            blue: Bits<25>,
            alpha: Bits<25>,
            ublend: U8,
            vblend: U8,
        }
        out {
            t1: SBits<21>,
            t2: SBits<21>,
        }
        // stage 1: differences of the results at 12 fraction bits (S21: of two U20, exact in 21 bits); the factors
        s1_d1: DFF<SBits<21>>,
        s1_d2: DFF<SBits<21>>,
        s1_e1: DFF<SBits<21>>,
        s1_e2: DFF<SBits<21>>,
        s1_u: DFF<Bits<16>>,
        s1_v: DFF<Bits<16>>,
        // stage 2: d2 − d1 and e2 − e1 (S22), d1·256 and e1·256 (S29), each in its own width
        s2_dd: DFF<SBits<22>>,
        s2_ee: DFF<SBits<22>>,
        s2_b1: DFF<SBits<29>>,
        s2_b2: DFF<SBits<29>>,
        s2_u: DFF<Bits<16>>,
        s2_v: DFF<Bits<16>>,
        // stages 3–6: |d2 − d1|·V and |e2 − e1|·U < 2^21·2^8 (U29), the bases beside
        mul1: SmMulWide<22>,
        mul2: SmMulWide<22>,
        b1: Delay<SBits<29>, { sm_mul::WIDE_LATENCY }>,
        b2: Delay<SBits<29>, { sm_mul::WIDE_LATENCY }>,
        // stage 7: d1·256 ± |d2 − d1|·V (S30), the same for e
        s7_t1: DFF<SBits<30>>,
        s7_t2: DFF<SBits<30>>,
        // stage 8: >> 8, floor: S21
        s8_t1: DFF<SBits<21>>,
        s8_t2: DFF<SBits<21>>,
        valid: Delay<Bit, LATENCY>,
        w_r: Signal<Local, Bits<21>>,
        w_g: Signal<Local, Bits<21>>,
        w_b: Signal<Local, Bits<21>>,
        w_a: Signal<Local, Bits<21>>,
        // the differences sign-extended (S21 → S22) for their own difference, the bases (S29 → S30) and the
        // products (U29 of U32) for the sum
        w_d1x: Signal<Local, SBits<22>>,
        w_d2x: Signal<Local, SBits<22>>,
        w_e1x: Signal<Local, SBits<22>>,
        w_e2x: Signal<Local, SBits<22>>,
        w_b1x: Signal<Local, SBits<30>>,
        w_b2x: Signal<Local, SBits<30>>,
        w_p1: Signal<Local, Bits<30>>,
        w_p2: Signal<Local, Bits<30>>,
    }
}

impl Logic for Tangent {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_d1, s1_d2, s1_e1, s1_e2, s1_u, s1_v, s2_dd, s2_ee, s2_b1, s2_b2, s2_u, s2_v);
        dff_setup!(self, clock, s7_t1, s7_t2, s8_t1, s8_t2);
        clock!(self, clock, mul1, mul2, b1, b2, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1: each result's top 20 bits (U25 → U20, 12 fraction bits, floor), then the differences
        self.w_r.next = bit_cast::<21, 20>(self.red.val().get_bits::<20>(5)); // U20 in 21, floor
        self.w_g.next = bit_cast::<21, 20>(self.green.val().get_bits::<20>(5)); // U20 in 21, floor
        self.w_b.next = bit_cast::<21, 20>(self.blue.val().get_bits::<20>(5)); // U20 in 21, floor
        self.w_a.next = bit_cast::<21, 20>(self.alpha.val().get_bits::<20>(5)); // U20 in 21, floor
        self.s1_d1.d.next = self.w_g.val() - self.w_r.val(); // G − R: S21, wrapping in 21 to its two's complement
        self.s1_d2.d.next = self.w_a.val() - self.w_b.val(); // A − B: S21, likewise
        self.s1_e1.d.next = self.w_b.val() - self.w_r.val(); // B − R: S21, likewise
        self.s1_e2.d.next = self.w_a.val() - self.w_g.val(); // A − G: S21, likewise
        self.s1_u.d.next = bit_cast::<16, 8>(self.ublend.val()); // U8 in 16, widening
        self.s1_v.d.next = bit_cast::<16, 8>(self.vblend.val()); // U8 in 16, widening

        // stage 2: the lerps' spans (S22, exact) and bases (·256: S29, exact), in 32 bits
        self.w_d1x.next = bit_cast::<22, 21>(self.s1_d1.q.val()); // S21 → S22: sign extension, below
        self.w_d2x.next = bit_cast::<22, 21>(self.s1_d2.q.val()); // the same
        self.w_e1x.next = bit_cast::<22, 21>(self.s1_e1.q.val()); // the same
        self.w_e2x.next = bit_cast::<22, 21>(self.s1_e2.q.val()); // the same
        if self.s1_d1.q.val().get_bit(20) {
            self.w_d1x.next = self.w_d1x.val() | 0x20_0000;
        }
        if self.s1_d2.q.val().get_bit(20) {
            self.w_d2x.next = self.w_d2x.val() | 0x20_0000;
        }
        if self.s1_e1.q.val().get_bit(20) {
            self.w_e1x.next = self.w_e1x.val() | 0x20_0000;
        }
        if self.s1_e2.q.val().get_bit(20) {
            self.w_e2x.next = self.w_e2x.val() | 0x20_0000;
        }
        self.s2_dd.d.next = self.w_d2x.val() - self.w_d1x.val(); // S22, exact
        self.s2_ee.d.next = self.w_e2x.val() - self.w_e1x.val(); // S22, exact
        self.s2_b1.d.next = bit_cast::<29, 21>(self.s1_d1.q.val()) << 8; // d1·256: S29 (the sign lands in bit 28), exact
        self.s2_b2.d.next = bit_cast::<29, 21>(self.s1_e1.q.val()) << 8; // e1·256: the same
        self.s2_u.d.next = self.s1_u.q.val();
        self.s2_v.d.next = self.s1_v.q.val();
        // stages 3–6: the products, the bases beside them
        self.mul1.x.next = self.s2_dd.q.val();
        self.mul1.w.next = self.s2_v.q.val();
        self.mul2.x.next = self.s2_ee.q.val();
        self.mul2.w.next = self.s2_u.q.val();
        self.b1.d.next = self.s2_b1.q.val();
        self.b2.d.next = self.s2_b2.q.val();
        // stage 7: base ± product: S30, exact (the bases sign-extended to 30 bits)
        self.w_b1x.next = bit_cast::<30, 29>(self.b1.q.val());
        self.w_b2x.next = bit_cast::<30, 29>(self.b2.q.val());
        if self.b1.q.val().get_bit(28) {
            self.w_b1x.next = self.w_b1x.val() | 0x2000_0000;
        }
        if self.b2.q.val().get_bit(28) {
            self.w_b2x.next = self.w_b2x.val() | 0x2000_0000;
        }
        self.w_p1.next = self.mul1.p.val().get_bits::<30>(0); // |d2 − d1|·V < 2^29: U29 of U32, exact
        self.w_p2.next = self.mul2.p.val().get_bits::<30>(0); // the same

        // the sums: S30, exact
        if self.mul1.neg.val() {
            self.s7_t1.d.next = self.w_b1x.val() - self.w_p1.val();
        } else {
            self.s7_t1.d.next = self.w_b1x.val() + self.w_p1.val();
        }
        if self.mul2.neg.val() {
            self.s7_t2.d.next = self.w_b2x.val() - self.w_p2.val();
        } else {
            self.s7_t2.d.next = self.w_b2x.val() + self.w_p2.val();
        }
        // stage 8: bits 8..28 of the two's complement S30: >> 8, floor, S21 (a convex combination of S21 values)
        self.s8_t1.d.next = self.s7_t1.q.val().get_bits::<21>(8);
        self.s8_t2.d.next = self.s7_t2.q.val().get_bits::<21>(8);
        self.t1.next = self.s8_t1.q.val();
        self.t2.next = self.s8_t2.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
