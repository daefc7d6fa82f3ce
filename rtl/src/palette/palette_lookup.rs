//! `palette_lookup`: Tarini et al.'s colour-table read, one pixel per clock, with the next frame's table written beside
//! it: one block RAM of two tables (address `{table, index}`), a pixel reading table `frame`, a write going to table
//! `!frame`, so a frame never reads an entry of the table being built. See `vectors::palette_lookup`.
//! `A` is the index width (⌈log2 s_N⌉), `R` = A + 1 the RAM's address width (rust-hdl's const generics cannot add).
//! The tables start at zero (the model's empty tables), written into the Verilog as the RAM's initial contents.
//! Latency 3: the addresses and the write, registered; the RAM's read; the entry registered again (a block RAM's
//! output is slow) and split into its bytes.

use crate::prim::delay::Delay;
use crate::prim::q::U8;
use rust_hdl::prelude::*;

pub const LATENCY: usize = 3;

crate::stream_block! {
    pub struct PaletteLookup<const A: usize, const R: usize>: unit("palette_lookup", LATENCY) {
        in {
            frame: Bits<1>,
            idx: Bits<A>,
            we: Bits<1>,
            waddr: Bits<A>,
            wdata: Bits<32>,
        }
        out {
            out_r: U8,
            out_g: U8,
            out_b: U8,
            out_a: U8,
        }
        /// the two tables, table t at addresses t·2^A + index. The field's name marks its memory in the exported
        /// Verilog `(* no_rw_check *)` (see `synth::export`): a pixel never reads the table being written
        pub tables: RAM<Bits<32>, R>,
        top: Constant<Bits<R>>, // 2^A: table 1's first address
        // stage 1: the read address, the write (enable, address, data)
        s1_ra: DFF<Bits<R>>,
        s1_we: DFF<Bit>,
        s1_wa: DFF<Bits<R>>,
        s1_wd: DFF<Bits<32>>,
        // stage 3: the entry
        s3_e: DFF<Bits<32>>,
        valid: Delay<Bit, LATENCY>,
        w_i: Signal<Local, Bits<R>>,
        w_w: Signal<Local, Bits<R>>,
    }
}

impl<const A: usize, const R: usize> Default for PaletteLookup<A, R> {
    fn default() -> Self {
        assert!(
            R == A + 1 && (1..=16).contains(&A),
            "PaletteLookup<A, R>: R = A + 1, A from 1 to 16 (A = {A}, R = {R})"
        );
        Self {
            clock: Default::default(),
            valid_in: Default::default(),
            frame: Default::default(),
            idx: Default::default(),
            we: Default::default(),
            waddr: Default::default(),
            wdata: Default::default(),
            valid_out: Default::default(),
            out_r: Default::default(),
            out_g: Default::default(),
            out_b: Default::default(),
            out_a: Default::default(),
            // both tables start at zero, as a block RAM comes up from the bitstream (an `initial` block in the Verilog)
            tables: RAM::new((0..1u64 << R).map(|a| (Bits::<R>::from(a), Bits::<32>::from(0u64))).collect()),
            top: Constant::new(Bits::<R>::from(1u64 << A)),
            s1_ra: Default::default(),
            s1_we: Default::default(),
            s1_wa: Default::default(),
            s1_wd: Default::default(),
            s3_e: Default::default(),
            valid: Default::default(),
            w_i: Default::default(),
            w_w: Default::default(),
        }
    }
}

impl<const A: usize, const R: usize> Logic for PaletteLookup<A, R> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_ra, s1_we, s1_wa, s1_wd, s3_e);
        clock!(self, clock, valid);
        self.tables.read_clock.next = self.clock.val();
        self.tables.write_clock.next = self.clock.val();
        self.valid.d.next = self.valid_in.val();
        // stage 1: {frame, idx} to read, {!frame, waddr} to write (the top bit chooses the table)
        self.w_i.next = bit_cast::<R, A>(self.idx.val()); // UA in R, widening
        self.w_w.next = bit_cast::<R, A>(self.waddr.val()); // UA in R, widening
        if self.frame.val().any() {
            self.s1_ra.d.next = self.w_i.val() | self.top.val(); // table 1: UR, fields side by side
            self.s1_wa.d.next = self.w_w.val(); // table 0
        } else {
            self.s1_ra.d.next = self.w_i.val(); // table 0
            self.s1_wa.d.next = self.w_w.val() | self.top.val(); // table 1: UR, fields side by side
        }
        self.s1_we.d.next = self.we.val().any() & self.valid_in.val();
        self.s1_wd.d.next = self.wdata.val();
        // stage 2: the RAM reads table `frame` and writes table `!frame` on the same edge (never the same table)
        self.tables.read_address.next = self.s1_ra.q.val();
        self.tables.write_address.next = self.s1_wa.q.val();
        self.tables.write_data.next = self.s1_wd.q.val();
        self.tables.write_enable.next = self.s1_we.q.val();
        // stage 3: the entry, registered, split into RGBA (r in the low byte)
        self.s3_e.d.next = self.tables.read_data.val();
        self.out_r.next = self.s3_e.q.val().get_bits::<8>(0); // a split
        self.out_g.next = self.s3_e.q.val().get_bits::<8>(8); // a split
        self.out_b.next = self.s3_e.q.val().get_bits::<8>(16); // a split
        self.out_a.next = self.s3_e.q.val().get_bits::<8>(24); // a split
        self.valid_out.next = self.valid.q.val();
    }
}
