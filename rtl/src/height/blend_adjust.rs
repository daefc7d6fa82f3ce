//! `blend_adjust`: US 2004/0207631's blend-factor adjust unit [153]: `U0 = ½ + U/2`, `U1 = U/2` (V likewise) in 1/512
//! (U9),
//! exact: U0 is U with a 1 above it, U1 is U itself. "Completely trivial", as the seed says: wires and one register.
//! Latency 1.

use crate::prim::delay::Delay;
use crate::prim::q::U8;
use rust_hdl::prelude::*;

pub const LATENCY: usize = 1;

crate::stream_block! {
    #[derive(Default)]
    pub struct BlendAdjust: unit("blend_adjust", LATENCY) {
        in {
            ublend: U8,
            vblend: U8,
        }
        out {
            u0: Bits<9>,
            u1: Bits<9>,
            v0: Bits<9>,
            v1: Bits<9>,
        }
        s1_u0: DFF<Bits<9>>,
        s1_u1: DFF<Bits<9>>,
        s1_v0: DFF<Bits<9>>,
        s1_v1: DFF<Bits<9>>,
        valid: Delay<Bit, LATENCY>,
    }
}

impl Logic for BlendAdjust {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_u0, s1_u1, s1_v0, s1_v1);
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        self.s1_u0.d.next = bit_cast::<9, 8>(self.ublend.val()) | 0x100; // 256 + U: ½ + U/2 in 1/512, U9, exact
        self.s1_u1.d.next = bit_cast::<9, 8>(self.ublend.val()); // U: U/2 in 1/512, U9, exact
        self.s1_v0.d.next = bit_cast::<9, 8>(self.vblend.val()) | 0x100; // as U0
        self.s1_v1.d.next = bit_cast::<9, 8>(self.vblend.val()); // as U1
        self.u0.next = self.s1_u0.q.val();
        self.u1.next = self.s1_u1.q.val();
        self.v0.next = self.s1_v0.q.val();
        self.v1.next = self.s1_v1.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
