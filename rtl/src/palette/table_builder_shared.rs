//! `TableBuilderShared`: Tarini et al.'s per-frame colour table on eight multipliers, the iCE40 UP5K's eight SB_MAC16,
//! for `palette_pipeline_shared`. It computes `table_builder`'s entry from a normal already normalised, taking one
//! normal every two clocks:
//! - the palette changes per map, not per frame (§4 renormalises it once, after the quantizer), so the palette RAM
//!   holds each normal as the shared normaliser leaves it (Sq1.10, `vectors::normalise::exact`) and the per-frame
//!   builder needs no normaliser (6 multipliers);
//! - one `Dot3` takes N·L on a normal's first clock and N·H on its second (3 multipliers, not 6);
//! - the three channels' P·s take two multipliers: r and g on the first clock, b on the second (2, not 3).
//!
//! With `Gloss`'s three that is 8 products a clock. The entry is `vectors::table_builder::exact_normalised`, bit for
//! bit: the same blocks in the same order, only time-shared.
//!
//! The caller must leave a clock between two taken normals (`palette_pipeline_shared` refuses a build that would
//! not). Latency 27 = the dot product's operands chosen 1 (N and L, or N and H held: a register, so that the choice
//! and its 72-bit fan-out are not in front of the dot product's first stage) + dot3 7 + N·H's clock 1 + gloss 14 +
//! the colour 4 (operands; products; rounding; b's product rounded a clock after r's and g's, r and g held for it).

use crate::dot3::{self, Dot3};
use crate::gloss::{self, Gloss};
use crate::prim::delay::Delay;
use crate::prim::q::{Sq1_10, Uq0_10, U8};
use rust_hdl::prelude::*;

/// Clocks to the dot product's output (N·L; N·H a clock later), to the gloss unit's input, to its output, and in all.
pub const AT_DOT_OUT: usize = 1 + dot3::LATENCY;
pub const AT_GLOSS: usize = AT_DOT_OUT + 1;
pub const AT_COLOUR: usize = AT_GLOSS + gloss::LATENCY;
pub const LATENCY: usize = AT_COLOUR + 4;

crate::block! {
    #[derive(Default)]
    pub struct TableBuilderShared {
        pub clock: Signal<In, Clock>,
        /// a normal taken: high for one clock, never on the clock after one
        pub valid_in: Signal<In, Bit>,
        pub idx: Signal<In, Bits<14>>,
        /// the normal, normalised (Sq1.10)
        pub n_x: Signal<In, Sq1_10>,
        pub n_y: Signal<In, Sq1_10>,
        pub n_z: Signal<In, Sq1_10>,
        pub l_x: Signal<In, Sq1_10>,
        pub l_y: Signal<In, Sq1_10>,
        pub l_z: Signal<In, Sq1_10>,
        pub h_x: Signal<In, Sq1_10>,
        pub h_y: Signal<In, Sq1_10>,
        pub h_z: Signal<In, Sq1_10>,
        pub conc: Signal<In, U8>,
        pub spec_r: Signal<In, U8>,
        pub spec_g: Signal<In, U8>,
        pub spec_b: Signal<In, U8>,
        pub valid_out: Signal<Out, Bit>,
        pub addr: Signal<Out, Bits<14>>,
        pub r: Signal<Out, U8>,
        pub g: Signal<Out, U8>,
        pub b: Signal<Out, U8>,
        pub a: Signal<Out, U8>,
        pub dot: Dot3,
        pub gloss: Gloss,
        // the normal's second clock: N and H held for the dot product
        second: DFF<Bit>,
        hold_n: [DFF<Sq1_10>; 3],
        hold_h: [DFF<Sq1_10>; 3],
        // the dot product's operands: N and L on the first clock, N and H on the second
        op_valid: DFF<Bit>,
        op_n: [DFF<Sq1_10>; 3],
        op_l: [DFF<Sq1_10>; 3],
        // which of the dot product's two results leaves now (N·L first), and N·L held a clock for N·H
        first_out: Delay<Bit, AT_DOT_OUT>,
        x_hold: DFF<Uq0_10>,
        // what waits beside the blocks: C to the gloss unit, the colours to the products, α (N·L) and the index to the
        // end
        conc_dly: Delay<U8, AT_GLOSS>,
        spec_dly: [Delay<U8, AT_COLOUR>; 3],
        x_dly: Delay<Uq0_10, { gloss::LATENCY + 4 }>,
        idx_dly: Delay<Bits<14>, LATENCY>,
        valid_c: Delay<Bit, 4>,
        // the colour: P and s_b held for b's product on the second clock; the operands (U16, feeding the multipliers
        // alone); the products (U18); the roundings (U8); r and g held a clock for b
        p_hold: DFF<Uq0_10>,
        sb_hold: DFF<U8>,
        mop_p: [DFF<Bits<16>>; 2],
        mop_s: [DFF<Bits<16>>; 2],
        s2_prod: [DFF<Bits<18>>; 2],
        s3_c: [DFF<U8>; 2],
        s4_r: DFF<U8>,
        s4_g: DFF<U8>,
        w_p: Signal<Local, Bits<16>>,
        w_prod: [Signal<Local, Bits<32>>; 2],
        w_round: [Signal<Local, Bits<18>>; 2],
    }
}

impl Logic for TableBuilderShared {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, second, op_valid, x_hold, p_hold, sb_hold, s4_r, s4_g);
        clock!(self, clock, dot, gloss, first_out, conc_dly, x_dly, idx_dly, valid_c);
        for i in 0..3 {
            self.hold_n[i].clock.next = self.clock.val();
            self.hold_h[i].clock.next = self.clock.val();
            self.spec_dly[i].clock.next = self.clock.val();
            self.op_n[i].clock.next = self.clock.val();
            self.op_l[i].clock.next = self.clock.val();
        }
        for i in 0..2 {
            self.mop_p[i].clock.next = self.clock.val();
            self.mop_s[i].clock.next = self.clock.val();
            self.s2_prod[i].clock.next = self.clock.val();
            self.s3_c[i].clock.next = self.clock.val();
        }
        // N·L on the normal's clock, N·H (N and H held) on the next
        self.second.d.next = self.valid_in.val();
        self.hold_n[0].d.next = self.n_x.val();
        self.hold_n[1].d.next = self.n_y.val();
        self.hold_n[2].d.next = self.n_z.val();
        self.hold_h[0].d.next = self.h_x.val();
        self.hold_h[1].d.next = self.h_y.val();
        self.hold_h[2].d.next = self.h_z.val();
        self.op_valid.d.next = self.valid_in.val() | self.second.q.val();
        if self.valid_in.val() {
            self.op_n[0].d.next = self.n_x.val();
            self.op_n[1].d.next = self.n_y.val();
            self.op_n[2].d.next = self.n_z.val();
            self.op_l[0].d.next = self.l_x.val();
            self.op_l[1].d.next = self.l_y.val();
            self.op_l[2].d.next = self.l_z.val();
        } else {
            self.op_n[0].d.next = self.hold_n[0].q.val();
            self.op_n[1].d.next = self.hold_n[1].q.val();
            self.op_n[2].d.next = self.hold_n[2].q.val();
            self.op_l[0].d.next = self.hold_h[0].q.val();
            self.op_l[1].d.next = self.hold_h[1].q.val();
            self.op_l[2].d.next = self.hold_h[2].q.val();
        }
        self.dot.valid_in.next = self.op_valid.q.val();
        self.dot.n_x.next = self.op_n[0].q.val();
        self.dot.n_y.next = self.op_n[1].q.val();
        self.dot.n_z.next = self.op_n[2].q.val();
        self.dot.l_x.next = self.op_l[0].q.val();
        self.dot.l_y.next = self.op_l[1].q.val();
        self.dot.l_z.next = self.op_l[2].q.val();
        self.first_out.d.next = self.valid_in.val();
        self.conc_dly.d.next = self.conc.val();
        self.spec_dly[0].d.next = self.spec_r.val();
        self.spec_dly[1].d.next = self.spec_g.val();
        self.spec_dly[2].d.next = self.spec_b.val();
        self.idx_dly.d.next = self.idx.val();
        // N·L waits a clock for N·H, then beside the gloss unit and the colour
        self.x_hold.d.next = self.dot.x.val();
        self.x_dly.d.next = self.x_hold.q.val();
        // the specular power of N·H: the dot product's second result
        self.gloss.valid_in.next = self.dot.valid_out.val() & !self.first_out.q.val();
        self.gloss.conc.next = self.conc_dly.q.val();
        self.gloss.x.next = self.dot.x.val();
        // the colour, first clock: P·s_r and P·s_g; second clock: P·s_b on the first multiplier
        self.p_hold.d.next = self.gloss.p.val();
        self.sb_hold.d.next = self.spec_dly[2].q.val();
        self.w_p.next = bit_cast::<16, 10>(self.gloss.p.val()); // Uq0.10 in 16, widening
        self.mop_p[1].d.next = self.w_p.val();
        self.mop_s[1].d.next = bit_cast::<16, 8>(self.spec_dly[1].q.val()); // U8 in 16, widening
        if self.gloss.valid_out.val() {
            self.mop_p[0].d.next = self.w_p.val();
            self.mop_s[0].d.next = bit_cast::<16, 8>(self.spec_dly[0].q.val()); // U8 in 16, widening
        } else {
            self.mop_p[0].d.next = bit_cast::<16, 10>(self.p_hold.q.val()); // Uq0.10 in 16, widening
            self.mop_s[0].d.next = bit_cast::<16, 8>(self.sb_hold.q.val()); // U8 in 16, widening
        }
        // P·s (U10 × U8 → U18, exact), then (P·s + 512) >> 10, rounded half up: U8 (1023·255 + 512 < 2^18)
        for i in 0..2 {
            self.w_prod[i].next = self.mop_p[i].q.val() * self.mop_s[i].q.val(); // U18 in 32, exact
            self.s2_prod[i].d.next = self.w_prod[i].val().get_bits::<18>(0); // its range, exact
            self.w_round[i].next = self.s2_prod[i].q.val() + 512; // U18, exact
            self.s3_c[i].d.next = self.w_round[i].val().get_bits::<8>(10); // >> 10: U8, the rounding's floor
        }
        // r and g rounded a clock before b: held for it
        self.s4_r.d.next = self.s3_c[0].q.val();
        self.s4_g.d.next = self.s3_c[1].q.val();
        self.valid_c.d.next = self.gloss.valid_out.val();
        self.addr.next = self.idx_dly.q.val();
        self.r.next = self.s4_r.q.val();
        self.g.next = self.s4_g.q.val();
        self.b.next = self.s3_c[0].q.val();
        self.a.next = self.x_dly.q.val().get_bits::<8>(2); // α = X >> 2: U10 → U8, floor
        self.valid_out.next = self.valid_c.q.val();
    }
}
