//! `palette_pipeline_shared`: `palette_pipeline` on the iCE40 UP5K: the shared builder (`TableBuilderShared`: the
//! palette's normals stored normalised, one dot product and two colour multipliers time-shared, one normal every two
//! clocks, 8 multipliers) writing the next frame's table while this frame's pixels read theirs, still one pixel a
//! clock. s_N up to 256 (8 index bits: two tables in 4 of the UP5K's 30 block RAMs).
//!
//! A vector's build is taken unless the vector before it (the last valid one, however many idle clocks lie
//! between) had its build taken: taken builds are then never on consecutive clocks, as the shared builder needs, and
//! what is built does not depend on the idle clocks. A table of s_N entries takes 2·s_N vectors, builds alternating
//! with pixels alone. Everything else is `palette_pipeline`'s: a write and the read of the same vector reach the RAM
//! together, writes go to the table the frame does not show. See `vectors::palette_pipeline::shared`.
//! Latency 30 = the shared builder 27 + palette_lookup 3.

use crate::palette_lookup::{self, PaletteLookup};
use crate::prim::delay::Delay;
use crate::prim::q::{Sq1_10, U8};
use crate::table_builder_shared::{self, TableBuilderShared};
use rust_hdl::prelude::*;

pub const LATENCY: usize = table_builder_shared::LATENCY + palette_lookup::LATENCY;

crate::stream_block! {
    #[derive(Default)]
    pub struct PalettePipelineShared: unit("palette_pipeline_shared", LATENCY) {
        in {
            frame: Bits<1>,
            idx: Bits<8>,
            build: Bits<1>,
            b_idx: Bits<8>,
            n_x: Sq1_10,
            n_y: Sq1_10,
            n_z: Sq1_10,
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
            out_r: U8,
            out_g: U8,
            out_b: U8,
            out_a: U8,
        }
        pub builder: TableBuilderShared,
        pub lookup: PaletteLookup<8, 9>,
        /// the last valid vector's build was taken
        taken: DFF<Bit>,
        frame_dly: Delay<Bits<1>, { table_builder_shared::LATENCY }>,
        idx_dly: Delay<Bits<8>, { table_builder_shared::LATENCY }>,
        valid_dly: Delay<Bit, { table_builder_shared::LATENCY }>,
        w_take: Signal<Local, Bit>,
        w_b_idx: Signal<Local, Bits<14>>,
        w_g: Signal<Local, Bits<32>>,
        w_b: Signal<Local, Bits<32>>,
        w_a: Signal<Local, Bits<32>>,
        w_r: Signal<Local, Bits<32>>,
    }
}

impl Logic for PalettePipelineShared {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, taken);
        clock!(self, clock, builder, lookup, frame_dly, idx_dly, valid_dly);
        // a build is taken unless the last vector's was; the flag moves only with a valid vector
        self.w_take.next = self.valid_in.val() & self.build.val().any() & !self.taken.q.val();
        if self.valid_in.val() {
            self.taken.d.next = self.w_take.val();
        }
        self.builder.valid_in.next = self.w_take.val();
        self.w_b_idx.next = bit_cast::<14, 8>(self.b_idx.val()); // U8 in 14, widening
        self.builder.idx.next = self.w_b_idx.val();
        self.builder.n_x.next = self.n_x.val();
        self.builder.n_y.next = self.n_y.val();
        self.builder.n_z.next = self.n_z.val();
        self.builder.l_x.next = self.l_x.val();
        self.builder.l_y.next = self.l_y.val();
        self.builder.l_z.next = self.l_z.val();
        self.builder.h_x.next = self.h_x.val();
        self.builder.h_y.next = self.h_y.val();
        self.builder.h_z.next = self.h_z.val();
        self.builder.conc.next = self.conc.val();
        self.builder.spec_r.next = self.spec_r.val();
        self.builder.spec_g.next = self.spec_g.val();
        self.builder.spec_b.next = self.spec_b.val();
        // the pixel waits beside the builder
        self.frame_dly.d.next = self.frame.val();
        self.idx_dly.d.next = self.idx.val();
        self.valid_dly.d.next = self.valid_in.val();
        // the table RAM: this vector's read and its write (the entry packed, r in the low byte) on the same clock
        self.w_g.next = bit_cast::<32, 8>(self.builder.g.val()) << 8; // g in bits 8..15
        self.w_b.next = bit_cast::<32, 8>(self.builder.b.val()) << 16; // b in bits 16..23
        self.w_a.next = bit_cast::<32, 8>(self.builder.a.val()) << 24; // α in bits 24..31
        self.w_r.next = bit_cast::<32, 8>(self.builder.r.val()); // r in bits 0..7
        self.lookup.valid_in.next = self.valid_dly.q.val();
        self.lookup.frame.next = self.frame_dly.q.val();
        self.lookup.idx.next = self.idx_dly.q.val();
        self.lookup.we.next = self.builder.valid_out.val().into();
        self.lookup.waddr.next = self.builder.addr.val().get_bits::<8>(0); // U8 of U14: the index as it came, exact
        self.lookup.wdata.next = self.w_r.val() | self.w_g.val() | self.w_b.val() | self.w_a.val(); // four U8 side by side
        self.out_r.next = self.lookup.out_r.val();
        self.out_g.next = self.lookup.out_g.val();
        self.out_b.next = self.lookup.out_b.val();
        self.out_a.next = self.lookup.out_a.val();
        self.valid_out.next = self.lookup.valid_out.val();
    }
}
