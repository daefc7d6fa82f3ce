//! `height_fetch`: US 2004/0207631's texel fetch [151] in height mode with the map's memory, 2×2-interleaved (¶55):
//! word
//! (X, Y) holds heights (2X + x, 2Y + y) in byte x + 2y, and the words sit in four banks by (X mod 2, Y mod 2), so
//! the (at most) two word columns and two word rows that any 3×3 window touches come from four different banks in
//! one clock. See `vectors::height_fetch` for the ports and the write/read protocol.
//!
//! Why two words per axis are always enough, and always of different parity: the window's three columns, wrapped
//! or clamped, are consecutive or repeat the edge (clamp) or straddle the map's last and first column (wrap); their
//! word columns x >> 1 are then at most two, adjacent or the last and the first of an even count (a map of ≥ 4
//! texels), or all one (a map of 1 or 2 texels). The bank of parity p reads whichever of the first and the last
//! column's words has that parity.
//!
//! Latency 5: the three coordinates of each axis and its last texel; the coordinates wrapped or clamped (and the
//! write, registered); the banks' read (their own register);
//! the four words registered (a block RAM's output is slow: straight into the select it held the ECP5 to 83 MHz);
//! each of the nine heights picked from the four words.

use crate::prim::delay::Delay;
use crate::prim::q::{SBits, U8};
use rust_hdl::prelude::*;

pub const LATENCY: usize = 5;
/// The write port (`StreamUnit::MAP`): a write beat writes one word of four heights and reads nothing.
pub const MAP: &[&str] = &["we", "waddr", "wdata"];

crate::stream_block! {
    #[derive(Default)]
    pub struct HeightFetch: unit("height_fetch", LATENCY, map = MAP) {
        in {
            i: U8,
            j: U8,
            ulog2: Bits<4>,
            vlog2: Bits<4>,
            uwrap: Bits<1>,
            vwrap: Bits<1>,
            we: Bits<1>,
            waddr: Bits<14>,
            wdata: Bits<32>,
        }
        out {
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
        /// the four banks, (X mod 2) + 2·(Y mod 2): 64 × 64 words of four heights, address (Y >> 1)·64 + (X >> 1)
        pub bank: [RAM<Bits<32>, 12>; 4],
        // stage 0: the three columns and rows (S10), each axis's last texel (U8 in 10) and border mode
        s0_x: [DFF<SBits<10>>; 3],
        s0_y: [DFF<SBits<10>>; 3],
        s0_um: DFF<Bits<10>>,
        s0_vm: DFF<Bits<10>>,
        s0_uwrap: DFF<Bit>,
        s0_vwrap: DFF<Bit>,
        s0_rd: DFF<Bit>,
        s0_we: DFF<Bit>,
        s0_waddr: DFF<Bits<14>>,
        s0_wdata: DFF<Bits<32>>,
        // stage 1: the three columns and rows, wrapped or clamped (U8); whether the vector reads; the write
        s1_x: [DFF<U8>; 3],
        s1_y: [DFF<U8>; 3],
        s1_rd: DFF<Bit>,
        wr_en: DFF<Bit>,
        wr_addr: DFF<Bits<14>>,
        wr_data: DFF<Bits<32>>,
        // stage 2: each height's bit offset in the four words side by side, 32·bank + 8·byte (U7)
        s2_sh: [DFF<Bits<7>>; 9],
        s2_rd: DFF<Bit>,
        // stage 3: the four words, the offsets; stage 4: the nine heights
        s3_word: [DFF<Bits<32>>; 4],
        s3_sh: [DFF<Bits<7>>; 9],
        s3_rd: DFF<Bit>,
        s4_out: [DFF<U8>; 9],
        valid: Delay<Bit, LATENCY>,
        // stage 0, per axis: the last texel 2^s − 1 (s = min(log2, 8)), the three coordinates (S10) and masked
        w_one: Signal<Local, Bits<10>>,
        w_ul: Signal<Local, Bits<10>>,
        w_upow: Signal<Local, Bits<10>>,
        w_um: Signal<Local, Bits<10>>,
        w_ic: Signal<Local, Bits<10>>,
        w_x: [Signal<Local, SBits<10>>; 3],
        w_xm: [Signal<Local, Bits<10>>; 3],
        w_vl: Signal<Local, Bits<10>>,
        w_vpow: Signal<Local, Bits<10>>,
        w_vm: Signal<Local, Bits<10>>,
        w_jc: Signal<Local, Bits<10>>,
        w_y: [Signal<Local, SBits<10>>; 3],
        w_ym: [Signal<Local, Bits<10>>; 3],
        // stage 1: each parity's word column and row (U6, widened to the bank address), the write's address
        w_cx0: Signal<Local, Bits<12>>,
        w_cx1: Signal<Local, Bits<12>>,
        w_ry0: Signal<Local, Bits<12>>,
        w_ry1: Signal<Local, Bits<12>>,
        w_ry0s: Signal<Local, Bits<12>>,
        w_ry1s: Signal<Local, Bits<12>>,
        w_wx: Signal<Local, Bits<12>>,
        w_wy: Signal<Local, Bits<12>>,
        w_wys: Signal<Local, Bits<12>>,
        w_cs: [Signal<Local, Bits<7>>; 3],
        w_rs: [Signal<Local, Bits<7>>; 3],
        // stage 3: the four words side by side (bank n at bit 32n) and each height's word shifted down to it
        w_b: [Signal<Local, Bits<128>>; 4],
        w_bs: [Signal<Local, Bits<128>>; 4],
        w_cat: Signal<Local, Bits<128>>,
        w_sel: [Signal<Local, Bits<128>>; 9],
    }
}

impl Logic for HeightFetch {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s0_um, s0_vm, s0_uwrap, s0_vwrap, s0_rd, s0_we, s0_waddr, s0_wdata, s1_rd, wr_en, wr_addr,
            wr_data, s2_rd, s3_rd
        );
        clock!(self, clock, valid);
        for n in 0..3 {
            self.s0_x[n].clock.next = self.clock.val();
            self.s0_y[n].clock.next = self.clock.val();
            self.s1_x[n].clock.next = self.clock.val();
            self.s1_y[n].clock.next = self.clock.val();
        }
        for n in 0..9 {
            self.s2_sh[n].clock.next = self.clock.val();
            self.s3_sh[n].clock.next = self.clock.val();
            self.s4_out[n].clock.next = self.clock.val();
        }
        for n in 0..4 {
            self.s3_word[n].clock.next = self.clock.val();
            self.bank[n].read_clock.next = self.clock.val();
            self.bank[n].write_clock.next = self.clock.val();
        }
        self.valid.d.next = self.valid_in.val();

        // stage 0: the axes. The last texel 2^s − 1, s = min(log2, 8) (saturate)
        self.w_one.next = 1.into();
        self.w_ul.next = bit_cast::<10, 4>(self.ulog2.val()); // U4 in 10, widening
        self.w_upow.next = self.w_one.val() << self.w_ul.val(); // 2^log2 for log2 ≤ 7: U8 in 10, exact
        if self.ulog2.val().get_bit(3) {
            self.w_um.next = 255.into(); // log2 ≥ 8: 256 texels (saturate)
        } else {
            self.w_um.next = self.w_upow.val() - 1; // U7, exact
        }
        self.w_vl.next = bit_cast::<10, 4>(self.vlog2.val()); // U4 in 10, widening
        self.w_vpow.next = self.w_one.val() << self.w_vl.val(); // U8 in 10, exact
        if self.vlog2.val().get_bit(3) {
            self.w_vm.next = 255.into(); // saturate
        } else {
            self.w_vm.next = self.w_vpow.val() - 1; // U7, exact
        }
        // the three columns i − 1, i, i + 1 (S10: −1..256, two's complement) and rows likewise
        self.w_ic.next = bit_cast::<10, 8>(self.i.val()); // U8 in 10, widening
        self.w_x[0].next = self.w_ic.val() - 1; // S10, exact
        self.w_x[1].next = self.w_ic.val(); // U8
        self.w_x[2].next = self.w_ic.val() + 1; // U9, exact
        self.w_jc.next = bit_cast::<10, 8>(self.j.val()); // U8 in 10, widening
        self.w_y[0].next = self.w_jc.val() - 1; // S10, exact
        self.w_y[1].next = self.w_jc.val(); // U8
        self.w_y[2].next = self.w_jc.val() + 1; // U9, exact
        for n in 0..3 {
            self.s0_x[n].d.next = self.w_x[n].val();
            self.s0_y[n].d.next = self.w_y[n].val();
        }
        self.s0_um.d.next = self.w_um.val();
        self.s0_vm.d.next = self.w_vm.val();
        self.s0_uwrap.d.next = self.uwrap.val().any();
        self.s0_vwrap.d.next = self.vwrap.val().any();
        self.s0_rd.d.next = !self.we.val().any();
        self.s0_we.d.next = self.we.val().any() & self.valid_in.val();
        self.s0_waddr.d.next = self.waddr.val();
        self.s0_wdata.d.next = self.wdata.val();
        // stage 0 → 1: wrap (the AND of the two's complement value: modulo 2^s) or clamp (saturate to 0..2^s − 1)
        for n in 0..3 {
            self.w_xm[n].next = self.s0_x[n].q.val() & self.s0_um.q.val(); // modulo 2^s: U8
            self.w_ym[n].next = self.s0_y[n].q.val() & self.s0_vm.q.val(); // modulo 2^s: U8
            if self.s0_uwrap.q.val() {
                self.s1_x[n].d.next = self.w_xm[n].val().get_bits::<8>(0); // wrap: U8, exact
            } else if self.s0_x[n].q.val().get_bit(9) {
                self.s1_x[n].d.next = 0.into(); // clamp below 0
            } else if self.s0_x[n].q.val() > self.s0_um.q.val() {
                self.s1_x[n].d.next = self.s0_um.q.val().get_bits::<8>(0); // clamp to the last texel
            } else {
                self.s1_x[n].d.next = self.s0_x[n].q.val().get_bits::<8>(0); // inside: U8, exact
            }
            if self.s0_vwrap.q.val() {
                self.s1_y[n].d.next = self.w_ym[n].val().get_bits::<8>(0); // wrap: U8, exact
            } else if self.s0_y[n].q.val().get_bit(9) {
                self.s1_y[n].d.next = 0.into(); // clamp below 0
            } else if self.s0_y[n].q.val() > self.s0_vm.q.val() {
                self.s1_y[n].d.next = self.s0_vm.q.val().get_bits::<8>(0); // clamp to the last texel
            } else {
                self.s1_y[n].d.next = self.s0_y[n].q.val().get_bits::<8>(0); // inside: U8, exact
            }
        }
        self.s1_rd.d.next = self.s0_rd.q.val();
        self.wr_en.d.next = self.s0_we.q.val();
        self.wr_addr.d.next = self.s0_waddr.q.val();
        self.wr_data.d.next = self.s0_wdata.q.val();

        // stage 1: each bank's word. Parity p along x reads the first column's word (x0 >> 1) if it has parity p,
        // else the last column's (x2 >> 1); the bank address takes the word's column and row halved (x >> 2)
        if self.s1_x[0].q.val().get_bit(1) {
            // U6 in 12 each, a slice widened
            self.w_cx0.next = bit_cast::<12, 6>(self.s1_x[2].q.val().get_bits::<6>(2));
            self.w_cx1.next = bit_cast::<12, 6>(self.s1_x[0].q.val().get_bits::<6>(2));
        } else {
            // U6 in 12 each, a slice widened
            self.w_cx0.next = bit_cast::<12, 6>(self.s1_x[0].q.val().get_bits::<6>(2));
            self.w_cx1.next = bit_cast::<12, 6>(self.s1_x[2].q.val().get_bits::<6>(2));
        }
        if self.s1_y[0].q.val().get_bit(1) {
            // U6 in 12 each, a slice widened
            self.w_ry0.next = bit_cast::<12, 6>(self.s1_y[2].q.val().get_bits::<6>(2));
            self.w_ry1.next = bit_cast::<12, 6>(self.s1_y[0].q.val().get_bits::<6>(2));
        } else {
            // U6 in 12 each, a slice widened
            self.w_ry0.next = bit_cast::<12, 6>(self.s1_y[0].q.val().get_bits::<6>(2));
            self.w_ry1.next = bit_cast::<12, 6>(self.s1_y[2].q.val().get_bits::<6>(2));
        }
        self.w_ry0s.next = self.w_ry0.val() << 6; // row · 64: U12, exact
        self.w_ry1s.next = self.w_ry1.val() << 6; // U12, exact
        self.bank[0].read_address.next = self.w_ry0s.val() | self.w_cx0.val(); // (even X, even Y): U12, fields side by side
        self.bank[1].read_address.next = self.w_ry0s.val() | self.w_cx1.val(); // (odd X, even Y)
        self.bank[2].read_address.next = self.w_ry1s.val() | self.w_cx0.val(); // (even X, odd Y)
        self.bank[3].read_address.next = self.w_ry1s.val() | self.w_cx1.val(); // (odd X, odd Y)

        // the write: word (X, Y) = (waddr[6:0], waddr[13:7]) goes to bank (X mod 2, Y mod 2) at (Y >> 1)·64 + (X >> 1)
        self.w_wx.next = bit_cast::<12, 6>(self.wr_addr.q.val().get_bits::<6>(1)); // X >> 1: U6 in 12
        self.w_wy.next = bit_cast::<12, 6>(self.wr_addr.q.val().get_bits::<6>(8)); // Y >> 1: U6 in 12
        self.w_wys.next = self.w_wy.val() << 6; // U12, exact
        for n in 0..4 {
            self.bank[n].write_address.next = self.w_wys.val() | self.w_wx.val(); // U12, fields side by side
            self.bank[n].write_data.next = self.wr_data.q.val();
        }
        self.bank[0].write_enable.next =
            self.wr_en.q.val() & !self.wr_addr.q.val().get_bit(0) & !self.wr_addr.q.val().get_bit(7);
        self.bank[1].write_enable.next =
            self.wr_en.q.val() & self.wr_addr.q.val().get_bit(0) & !self.wr_addr.q.val().get_bit(7);
        self.bank[2].write_enable.next =
            self.wr_en.q.val() & !self.wr_addr.q.val().get_bit(0) & self.wr_addr.q.val().get_bit(7);
        self.bank[3].write_enable.next =
            self.wr_en.q.val() & self.wr_addr.q.val().get_bit(0) & self.wr_addr.q.val().get_bit(7);
        // each height's place in the four words: 8·(x mod 2) + 32·((x >> 1) mod 2) by column, 16·(y mod 2) +
        // 64·((y >> 1) mod 2) by row
        for n in 0..3 {
            if self.s1_x[n].q.val().get_bit(1) {
                if self.s1_x[n].q.val().get_bit(0) {
                    self.w_cs[n].next = 40.into();
                } else {
                    self.w_cs[n].next = 32.into();
                }
            } else if self.s1_x[n].q.val().get_bit(0) {
                self.w_cs[n].next = 8.into();
            } else {
                self.w_cs[n].next = 0.into();
            }
            if self.s1_y[n].q.val().get_bit(1) {
                if self.s1_y[n].q.val().get_bit(0) {
                    self.w_rs[n].next = 80.into();
                } else {
                    self.w_rs[n].next = 64.into();
                }
            } else if self.s1_y[n].q.val().get_bit(0) {
                self.w_rs[n].next = 16.into();
            } else {
                self.w_rs[n].next = 0.into();
            }
        }
        // a b c / d e f / g h k: row r, column c at 3r + c; the two offsets share no bit, so OR adds them
        self.s2_sh[0].d.next = self.w_rs[0].val() | self.w_cs[0].val(); // U7
        self.s2_sh[1].d.next = self.w_rs[0].val() | self.w_cs[1].val(); // U7
        self.s2_sh[2].d.next = self.w_rs[0].val() | self.w_cs[2].val(); // U7
        self.s2_sh[3].d.next = self.w_rs[1].val() | self.w_cs[0].val(); // U7
        self.s2_sh[4].d.next = self.w_rs[1].val() | self.w_cs[1].val(); // U7
        self.s2_sh[5].d.next = self.w_rs[1].val() | self.w_cs[2].val(); // U7
        self.s2_sh[6].d.next = self.w_rs[2].val() | self.w_cs[0].val(); // U7
        self.s2_sh[7].d.next = self.w_rs[2].val() | self.w_cs[1].val(); // U7
        self.s2_sh[8].d.next = self.w_rs[2].val() | self.w_cs[2].val(); // U7
        self.s2_rd.d.next = self.s1_rd.q.val();

        // stage 2: the banks' words registered, the offsets beside them
        for n in 0..4 {
            self.s3_word[n].d.next = self.bank[n].read_data.val();
        }
        for n in 0..9 {
            self.s3_sh[n].d.next = self.s2_sh[n].q.val();
        }
        self.s3_rd.d.next = self.s2_rd.q.val();

        // stage 3: the four words side by side; each height shifted down from its place
        self.w_b[0].next = bit_cast::<128, 32>(self.s3_word[0].q.val()); // U32 in 128, widening
        self.w_b[1].next = bit_cast::<128, 32>(self.s3_word[1].q.val()); // U32 in 128, widening
        self.w_b[2].next = bit_cast::<128, 32>(self.s3_word[2].q.val()); // U32 in 128, widening
        self.w_b[3].next = bit_cast::<128, 32>(self.s3_word[3].q.val()); // U32 in 128, widening
        self.w_bs[0].next = self.w_b[0].val(); // bits 0..31
        self.w_bs[1].next = self.w_b[1].val() << 32; // bits 32..63, exact
        self.w_bs[2].next = self.w_b[2].val() << 64; // bits 64..95, exact
        self.w_bs[3].next = self.w_b[3].val() << 96; // bits 96..127, exact
        self.w_cat.next = self.w_bs[0].val() | self.w_bs[1].val() | self.w_bs[2].val() | self.w_bs[3].val(); // U128, side by side
        for n in 0..9 {
            self.w_sel[n].next = self.w_cat.val() >> self.s3_sh[n].q.val(); // the height in the low byte: exact
            if self.s3_rd.q.val() {
                self.s4_out[n].d.next = self.w_sel[n].val().get_bits::<8>(0); // U8, a slice
            } else {
                self.s4_out[n].d.next = 0.into(); // a write reads nothing
            }
        }
        self.a.next = self.s4_out[0].q.val();
        self.b.next = self.s4_out[1].q.val();
        self.c.next = self.s4_out[2].q.val();
        self.d.next = self.s4_out[3].q.val();
        self.e.next = self.s4_out[4].q.val();
        self.f.next = self.s4_out[5].q.val();
        self.g.next = self.s4_out[6].q.val();
        self.h.next = self.s4_out[7].q.val();
        self.k.next = self.s4_out[8].q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
