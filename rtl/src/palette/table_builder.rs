//! `table_builder`: Tarini et al.'s per-frame colour table built by the project's shading blocks, one palette normal a
//! clock: the shared `Normalise`, two `Dot3`s (N·L, N·H), `Gloss` (the specular power), then the entry of equation
//! (1): α = N·L >> 2, the colour (P·s + 512) >> 10 per channel. The entry leaves with its index, for the table RAM.
//! See `vectors::table_builder`.
//! Latency 38 = normalise 14 + dot3 7 + gloss 14 + the colour 3 (operands, products, the rounding).

use crate::dot3::{self, Dot3};
use crate::gloss::{self, Gloss};
use crate::normalise::{self, Normalise};
use crate::prim::delay::Delay;
use crate::prim::q::{Sq1_10, Sq9_0, Uq0_10, U8};
use rust_hdl::prelude::*;

/// Clocks to the two dot products, to the gloss unit's output, and in all.
pub const AT_DOT: usize = normalise::LATENCY;
pub const AT_GLOSS: usize = AT_DOT + dot3::LATENCY;
pub const AT_COLOUR: usize = AT_GLOSS + gloss::LATENCY;
pub const LATENCY: usize = AT_COLOUR + 3;

/// The signals the block's Verilog leaves unused on purpose (`StreamUnit::waivers`); `palette_pipeline`, which
/// holds the builder, waives them too.
pub const WAIVERS: &[crate::stream::Waiver] =
    &[("diffuse$valid_out", "the two dot products run in lockstep; the highlight's valid is used")];

crate::stream_block! {
    #[derive(Default)]
    pub struct TableBuilder: unit("table_builder", LATENCY, waivers = WAIVERS) {
        in {
            idx: Bits<14>,
            n_x: Sq9_0,
            n_y: Sq9_0,
            n_z: Sq9_0,
            l_x: Sq1_10,
            l_y: Sq1_10,
            l_z: Sq1_10,
            h_x: Sq1_10,
            h_y: Sq1_10,
            h_z: Sq1_10,
            conc: U8,
            spec_r: U8,
            spec_g: U8,
            spec_b: U8,
        }
        out {
            addr: Bits<14>,
            r: U8,
            g: U8,
            b: U8,
            a: U8,
        }
        pub norm: Normalise,
        pub diffuse: Dot3,
        pub highlight: Dot3,
        pub gloss: Gloss,
        // what waits beside the blocks: L and H for the normaliser, C for the normaliser and the dot products, the
        // colours and the index all the way, N·L beside the gloss unit
        l_dly: [Delay<Sq1_10, AT_DOT>; 3],
        h_dly: [Delay<Sq1_10, AT_DOT>; 3],
        conc_dly: Delay<U8, AT_GLOSS>,
        spec_dly: [Delay<U8, AT_COLOUR>; 3],
        x_dly: Delay<Uq0_10, { gloss::LATENCY }>,
        idx_dly: Delay<Bits<14>, LATENCY>,
        valid_c: Delay<Bit, 3>,
        // the colour: stage 1 the operands P and s (U16 each, feeding the multipliers alone); stage 2 the products
        // (U18); stage 3 the rounding; α beside
        mop_p: [DFF<Bits<16>>; 3],
        mop_s: [DFF<Bits<16>>; 3],
        s2_prod: [DFF<Bits<18>>; 3],
        s3_c: [DFF<U8>; 3],
        s1_a: DFF<U8>,
        s2_a: DFF<U8>,
        s3_a: DFF<U8>,
        w_p: Signal<Local, Bits<16>>,
        w_prod: [Signal<Local, Bits<32>>; 3],
        w_round: [Signal<Local, Bits<18>>; 3],
    }
}

impl Logic for TableBuilder {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_a, s2_a, s3_a);
        clock!(self, clock, norm, diffuse, highlight, gloss, conc_dly, x_dly, idx_dly, valid_c);
        for i in 0..3 {
            self.l_dly[i].clock.next = self.clock.val();
            self.h_dly[i].clock.next = self.clock.val();
            self.spec_dly[i].clock.next = self.clock.val();
            self.mop_p[i].clock.next = self.clock.val();
            self.mop_s[i].clock.next = self.clock.val();
            self.s2_prod[i].clock.next = self.clock.val();
            self.s3_c[i].clock.next = self.clock.val();
        }
        // the normal: normalised (the scale-free normaliser reads the S10 as it is)
        self.norm.valid_in.next = self.valid_in.val();
        self.norm.vec_x.next = self.n_x.val();
        self.norm.vec_y.next = self.n_y.val();
        self.norm.vec_z.next = self.n_z.val();
        self.l_dly[0].d.next = self.l_x.val();
        self.l_dly[1].d.next = self.l_y.val();
        self.l_dly[2].d.next = self.l_z.val();
        self.h_dly[0].d.next = self.h_x.val();
        self.h_dly[1].d.next = self.h_y.val();
        self.h_dly[2].d.next = self.h_z.val();
        self.conc_dly.d.next = self.conc.val();
        self.spec_dly[0].d.next = self.spec_r.val();
        self.spec_dly[1].d.next = self.spec_g.val();
        self.spec_dly[2].d.next = self.spec_b.val();
        self.idx_dly.d.next = self.idx.val();
        // N·L and N·H
        self.diffuse.valid_in.next = self.norm.valid_out.val();
        self.diffuse.n_x.next = self.norm.norm_x.val();
        self.diffuse.n_y.next = self.norm.norm_y.val();
        self.diffuse.n_z.next = self.norm.norm_z.val();
        self.diffuse.l_x.next = self.l_dly[0].q.val();
        self.diffuse.l_y.next = self.l_dly[1].q.val();
        self.diffuse.l_z.next = self.l_dly[2].q.val();
        self.highlight.valid_in.next = self.norm.valid_out.val();
        self.highlight.n_x.next = self.norm.norm_x.val();
        self.highlight.n_y.next = self.norm.norm_y.val();
        self.highlight.n_z.next = self.norm.norm_z.val();
        self.highlight.l_x.next = self.h_dly[0].q.val();
        self.highlight.l_y.next = self.h_dly[1].q.val();
        self.highlight.l_z.next = self.h_dly[2].q.val();
        // the specular power of N·H; N·L waits beside the gloss unit
        self.gloss.valid_in.next = self.highlight.valid_out.val();
        self.gloss.conc.next = self.conc_dly.q.val();
        self.gloss.x.next = self.highlight.x.val();
        self.x_dly.d.next = self.diffuse.x.val();
        // the colour: stage 1 the operands
        self.w_p.next = bit_cast::<16, 10>(self.gloss.p.val()); // Uq0.10 in 16, widening
        for i in 0..3 {
            self.mop_p[i].d.next = self.w_p.val(); // one copy per multiplier
        }
        self.mop_s[0].d.next = bit_cast::<16, 8>(self.spec_dly[0].q.val()); // U8 in 16, widening
        self.mop_s[1].d.next = bit_cast::<16, 8>(self.spec_dly[1].q.val()); // U8 in 16, widening
        self.mop_s[2].d.next = bit_cast::<16, 8>(self.spec_dly[2].q.val()); // U8 in 16, widening
        self.s1_a.d.next = self.x_dly.q.val().get_bits::<8>(2); // α = X >> 2: U10 → U8, floor

        // stage 2: P·s (U10 × U8 → U18, exact)
        for i in 0..3 {
            self.w_prod[i].next = self.mop_p[i].q.val() * self.mop_s[i].q.val(); // U18 in 32, exact
            self.s2_prod[i].d.next = self.w_prod[i].val().get_bits::<18>(0); // its range, exact
        }
        self.s2_a.d.next = self.s1_a.q.val();
        // stage 3: (P·s + 512) >> 10, rounded half up: U8 (1023·255 + 512 < 2^18)
        for i in 0..3 {
            self.w_round[i].next = self.s2_prod[i].q.val() + 512; // U18, exact
            self.s3_c[i].d.next = self.w_round[i].val().get_bits::<8>(10); // >> 10: U8, the rounding's floor
        }
        self.s3_a.d.next = self.s2_a.q.val();
        self.addr.next = self.idx_dly.q.val();
        self.r.next = self.s3_c[0].q.val();
        self.g.next = self.s3_c[1].q.val();
        self.b.next = self.s3_c[2].q.val();
        self.a.next = self.s3_a.q.val();
        self.valid_c.d.next = self.gloss.valid_out.val();
        self.valid_out.next = self.valid_c.q.val();
    }
}
