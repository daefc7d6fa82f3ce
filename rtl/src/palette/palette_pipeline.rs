//! `palette_pipeline`: the table builder writing the next frame's colour table while this frame's pixels read theirs,
//! one normal and one pixel a clock. The pixel's frame and index wait beside the builder (32 clocks), so that a
//! vector's write and its read reach the table RAM together: a read sees every entry built by the vectors before it,
//! however many idle clocks lie between them, and a flip of `frame` shows a table whose last entry has already
//! landed. See `vectors::palette_pipeline`. Latency 41 = table_builder 38 + palette_lookup 3.
//! `A` is the index width, ⌈log2 s_N⌉, and `R` = A + 1 the table RAM's address width: `PalettePipeline<8, 9>` is
//! `palette_pipeline` (s_N up to 256), `PalettePipeline<12, 13>` is `palette_pipeline_12` (up to 4,096).

use crate::palette_lookup::{self, PaletteLookup};
use crate::prim::delay::Delay;
use crate::prim::q::{Sq1_10, Sq9_0, U8};
use crate::table_builder::{self, TableBuilder};
use rust_hdl::prelude::*;

pub const LATENCY: usize = table_builder::LATENCY + palette_lookup::LATENCY;

/// The unit's name for an index of `a` bits; the two widths in the unit table, and no other.
pub const fn name(a: usize) -> &'static str {
    match a {
        8 => "palette_pipeline",
        12 => "palette_pipeline_12",
        _ => panic!("PalettePipeline<A, R>: A is 8 or 12"),
    }
}

crate::stream_block! {
    #[derive(Default)]
    pub struct PalettePipeline<const A: usize, const R: usize>: unit(name(A), LATENCY, waivers = crate::table_builder::WAIVERS) {
        in {
            frame: Bits<1>,
            idx: Bits<A>,
            build: Bits<1>,
            b_idx: Bits<A>,
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
            out_r: U8,
            out_g: U8,
            out_b: U8,
            out_a: U8,
        }
        pub builder: TableBuilder,
        pub lookup: PaletteLookup<A, R>,
        frame_dly: Delay<Bits<1>, { table_builder::LATENCY }>,
        idx_dly: Delay<Bits<A>, { table_builder::LATENCY }>,
        valid_dly: Delay<Bit, { table_builder::LATENCY }>,
        w_b_idx: Signal<Local, Bits<14>>,
        w_g: Signal<Local, Bits<32>>,
        w_b: Signal<Local, Bits<32>>,
        w_a: Signal<Local, Bits<32>>,
        w_r: Signal<Local, Bits<32>>,
    }
}

impl<const A: usize, const R: usize> Logic for PalettePipeline<A, R> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, builder, lookup, frame_dly, idx_dly, valid_dly);
        // the builder takes the vector's normal when it builds
        self.builder.valid_in.next = self.valid_in.val() & self.build.val().any();
        self.w_b_idx.next = bit_cast::<14, A>(self.b_idx.val()); // UA in 14, widening
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
        self.lookup.waddr.next = self.builder.addr.val().get_bits::<A>(0); // UA of U14: the index as it came, exact
        self.lookup.wdata.next = self.w_r.val() | self.w_g.val() | self.w_b.val() | self.w_a.val(); // four U8 side by side
        self.out_r.next = self.lookup.out_r.val();
        self.out_g.next = self.lookup.out_g.val();
        self.out_b.next = self.lookup.out_b.val();
        self.out_a.next = self.lookup.out_a.val();
        self.valid_out.next = self.lookup.valid_out.val();
    }
}
