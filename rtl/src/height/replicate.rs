//! `replicate`: US 2004/0207631's replicate unit [152]: the 3×3 heights `a b c / d e f / g h k` out as the four
//! bilinear
//! units' overlapping 2×2 grids, red `[a b; d e]`, green `[b c; e f]`, blue `[d e; g h]`, alpha `[e f; h k]`, each
//! in the bilinear unit's texel order (t00, t10, t01, t11). Wires and one register. Latency 1.

use crate::prim::delay::Delay;
use crate::prim::q::U8;
use rust_hdl::prelude::*;

pub const LATENCY: usize = 1;

crate::stream_block! {
    #[derive(Default)]
    pub struct Replicate: unit("replicate", LATENCY) {
        in {
            a: U8,
            b: U8,
            c: U8,
            d: U8,
            e: U8,
            f: U8,
            g: U8,
            h: U8,
            k: U8,
        }
        out {
            r00: U8,
            r10: U8,
            r01: U8,
            r11: U8,
            g00: U8,
            g10: U8,
            g01: U8,
            g11: U8,
            b00: U8,
            b10: U8,
            b01: U8,
            b11: U8,
            a00: U8,
            a10: U8,
            a01: U8,
            a11: U8,
        }
        // the 3×3 window, registered once; the grids are its overlapping corners
        s1_w: [DFF<U8>; 9],
        valid: Delay<Bit, LATENCY>,
    }
}

impl Logic for Replicate {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, valid);
        for i in 0..9 {
            self.s1_w[i].clock.next = self.clock.val();
        }
        self.valid.d.next = self.valid_in.val();
        self.s1_w[0].d.next = self.a.val();
        self.s1_w[1].d.next = self.b.val();
        self.s1_w[2].d.next = self.c.val();
        self.s1_w[3].d.next = self.d.val();
        self.s1_w[4].d.next = self.e.val();
        self.s1_w[5].d.next = self.f.val();
        self.s1_w[6].d.next = self.g.val();
        self.s1_w[7].d.next = self.h.val();
        self.s1_w[8].d.next = self.k.val();
        // red [a b; d e]
        self.r00.next = self.s1_w[0].q.val();
        self.r10.next = self.s1_w[1].q.val();
        self.r01.next = self.s1_w[3].q.val();
        self.r11.next = self.s1_w[4].q.val();
        // green [b c; e f]
        self.g00.next = self.s1_w[1].q.val();
        self.g10.next = self.s1_w[2].q.val();
        self.g01.next = self.s1_w[4].q.val();
        self.g11.next = self.s1_w[5].q.val();
        // blue [d e; g h]
        self.b00.next = self.s1_w[3].q.val();
        self.b10.next = self.s1_w[4].q.val();
        self.b01.next = self.s1_w[6].q.val();
        self.b11.next = self.s1_w[7].q.val();
        // alpha [e f; h k]
        self.a00.next = self.s1_w[4].q.val();
        self.a10.next = self.s1_w[5].q.val();
        self.a01.next = self.s1_w[7].q.val();
        self.a11.next = self.s1_w[8].q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
