//! `tex_fetch`: the texture unit's map memory and fetch: 16-bit texels with the whole MIP chain (levels up to
//! 128 × 128, or with `L` = 8 up to 256 × 256) in four 2×2-interleaved banks, one bilinear footprint read a clock,
//! written texel by texel through the same stream (`we`). See `vectors::tex_fetch` for the layout and the ports.
//!
//! Latency 7: the level's side, its base, and the coordinates taken modulo the side (and the write's); each bank's two
//! addends, its word column plus the level's base and its word row shifted to the level's row length (in the bank a
//! write writes, the write's); the bank addresses, each the sum of its bank's addends; the banks' read (their own
//! register); the four words registered (a block RAM's output straight into a select is slow: `height_fetch` measured
//! it); the four words again; each texel picked from the four words. (On the ECP5 the first register of the words is
//! the DP16KD's output register; with the select behind it, that read into the select was the nearest pipelines'
//! critical path, 1.61 ns of logic and 4.41 ns of routing, 166 MHz. The base joins the column a clock before the row:
//! base + row + column in one clock, two adders in a row, was the next one, 1.96 ns of logic and 3.94 ns of routing,
//! 170 MHz; and with the base's table behind the registered side log2, in stage 2, the trilinear pipelines' write
//! address was one of theirs, 6.4 ns.)
//!
//! The banks are single-port (`SpRam`): `synth_ice40 -spram` puts each in one of the UP5K's four SPRAMs, so a
//! 128 × 128 map and its chain (43.7 KB) fit a part whose 30 EBR hold 15 KB.

use crate::prim::delay::Delay;
use crate::prim::q::{U16, U8};
use crate::prim::sp_ram::SpRam;
use rust_hdl::prelude::*;

pub const LATENCY: usize = 7;
/// A bank's address bits: 8,192 words, of which a 128 × 128 map's chain takes 5,462 (`vectors::tex_fetch`).
pub const ADDR_BITS: usize = 13;
/// The levels a fetch's memory holds (its `P`): every level, the even sides' log2 (0, 2, 4, 6) or the odd ones
/// (1, 3, 5, 7): trilinear's two fetches hold one each (`vectors::tex_fetch::Levels`).
pub const ALL: usize = 0;
pub const EVEN: usize = 1;
pub const ODD: usize = 2;
/// A bank's address bits for the even levels: 1,093 words of 2,048.
pub const EVEN_ADDR_BITS: usize = 11;
/// The largest level's side log2 (the unit's `L`): 7, a 128 × 128 map. With `L` = 8 a bank holds a 256 × 256 map's
/// chain, 21,846 words (`A` = 15; 4 × 2^15 16-bit words, more block RAM than the ECP5-45F's 108 DP16KD give).
pub const MAX_LOG_SIDE: usize = 7;
/// A bank's address bits for a 256 × 256 map's chain (`L` = 8).
pub const ADDR_BITS_256: usize = 15;

/// Where each level starts in a bank of a memory holding the levels `p` (ALL, EVEN, ODD): the words of the held
/// levels below it (the 1 × 1 level one word, the side 2^m one 4^(m−1)); a level not held is never placed (its
/// writes are dropped and its reads give zeros). Entry 9 is where a chain of side 2^8 ends.
pub fn bases(p: usize) -> [u64; 10] {
    let size = |k: usize| if k == 0 { 1u64 } else { 1 << (2 * (k - 1)) };
    std::array::from_fn(|m| (0..m).filter(|&k| holds(p, k)).map(size).sum())
}

/// Whether a memory holding the levels `p` holds the level of side 2^m.
pub fn holds(p: usize, m: usize) -> bool {
    p == ALL || m.is_multiple_of(2) == (p == EVEN)
}

crate::block! {
    /// The level's base (U15: the largest, at side 2^8, is 5,462) and whether the memory holds it, for a memory
    /// holding the levels `P` (`bases`) whose largest side is 2^L: a table of nine constants read by the side log2
    /// as given, m_in, saturated to L in the table (entry k holds level min(k, L), entry 8 every m_in ≥ 8), so each
    /// bit is one function of m_in's four bits and the table sits in stage 1 beside the cap. Combinational.
    pub struct LevelBase<const P: usize, const L: usize> {
        pub m: Signal<In, Bits<4>>,
        pub base: Signal<Out, Bits<15>>,
        pub held: Signal<Out, Bit>,
        tab: [Constant<Bits<15>>; 9],
        holds: Constant<Bits<16>>,
    }
}

impl<const P: usize, const L: usize> Default for LevelBase<P, L> {
    fn default() -> Self {
        let b = bases(P);
        let mask: u64 = (0..16).filter(|&m: &usize| holds(P, m.min(L))).map(|m| 1 << m).sum();
        Self {
            m: Default::default(),
            base: Default::default(),
            held: Default::default(),
            tab: std::array::from_fn(|k| Constant::new(Bits::<15>::from(b[k.min(L)]))),
            holds: Constant::new(Bits::<16>::from(mask)),
        }
    }
}

impl<const P: usize, const L: usize> Logic for LevelBase<P, L> {
    #[hdl_gen]
    fn update(&mut self) {
        self.base.next = self.tab[8].val();
        if self.m.val() == 0 {
            self.base.next = self.tab[0].val();
        }
        if self.m.val() == 1 {
            self.base.next = self.tab[1].val();
        }
        if self.m.val() == 2 {
            self.base.next = self.tab[2].val();
        }
        if self.m.val() == 3 {
            self.base.next = self.tab[3].val();
        }
        if self.m.val() == 4 {
            self.base.next = self.tab[4].val();
        }
        if self.m.val() == 5 {
            self.base.next = self.tab[5].val();
        }
        if self.m.val() == 6 {
            self.base.next = self.tab[6].val();
        }
        if self.m.val() == 7 {
            self.base.next = self.tab[7].val();
        }
        self.held.next = self.holds.val().get_bit(self.m.val().index());
    }
}
crate::block! {
    /// A side log2 saturated to `L` (≤ 8), the largest level a memory of side 2^L holds, and that side's mask
    /// 2^m − 1 (U8), a table of nine constants read by the side log2 as given: each bit of the mask is then one
    /// function of its four bits, where 1 << m − 1 was a shift and a carry chain in front of the coordinates' AND
    /// (the write's, from its delay line, was the nearest pipelines' critical path on the ECP5: 2.22 ns of logic
    /// and 3.63 ns of routing). Combinational.
    pub struct LevelCap<const L: usize> {
        pub m_in: Signal<In, Bits<4>>,
        pub m: Signal<Out, Bits<4>>,
        pub mask: Signal<Out, U8>,
        top: Constant<Bits<4>>,
        masks: [Constant<U8>; 9],
    }
}

impl<const L: usize> Default for LevelCap<L> {
    fn default() -> Self {
        assert!(L <= 8, "LevelCap: the memory holds sides up to 2^8, not 2^{L}");
        Self {
            m_in: Default::default(),
            m: Default::default(),
            mask: Default::default(),
            top: Constant::new(Bits::<4>::from(L as u64)),
            masks: std::array::from_fn(|k| Constant::new(U8::from((1u64 << k.min(L)) - 1))),
        }
    }
}

impl<const L: usize> Logic for LevelCap<L> {
    #[hdl_gen]
    fn update(&mut self) {
        self.m.next = self.m_in.val();
        if self.m_in.val() > self.top.val() {
            self.m.next = self.top.val();
        }
        // 2^min(m_in, L) − 1: entry 8 for m_in ≥ 8
        self.mask.next = self.masks[8].val();
        if self.m_in.val() == 0 {
            self.mask.next = self.masks[0].val();
        }
        if self.m_in.val() == 1 {
            self.mask.next = self.masks[1].val();
        }
        if self.m_in.val() == 2 {
            self.mask.next = self.masks[2].val();
        }
        if self.m_in.val() == 3 {
            self.mask.next = self.masks[3].val();
        }
        if self.m_in.val() == 4 {
            self.mask.next = self.masks[4].val();
        }
        if self.m_in.val() == 5 {
            self.mask.next = self.masks[5].val();
        }
        if self.m_in.val() == 6 {
            self.mask.next = self.masks[6].val();
        }
        if self.m_in.val() == 7 {
            self.mask.next = self.masks[7].val();
        }
    }
}

/// The write port (`StreamUnit::MAP`): a write beat writes one texel and reads nothing.
pub const MAP: &[&str] = &["we", "w_log2", "wx", "wy", "wdata"];

crate::stream_block! {
    #[derive(Default)]
    pub struct TexFetch<const P: usize = 0, const A: usize = 13, const L: usize = 7>: unit("tex_fetch", LATENCY, map = MAP) {
        in {
            level_log2: Bits<4>,
            x0: U8,
            x1: U8,
            y0: U8,
            y1: U8,
            we: Bits<1>,
            w_log2: Bits<4>,
            wx: U8,
            wy: U8,
            wdata: U16,
        }
        out {
            t00: U16,
            t10: U16,
            t01: U16,
            t11: U16,
        }
        /// the four banks, (x mod 2) + 2·(y mod 2), each single-port: a clock reads it or writes it
        pub bank: [SpRam<U16, A>; 4],
        /// the read's and the write's level bases, for the levels the memory holds (`P`)
        read_base: LevelBase<P, L>,
        write_base: LevelBase<P, L>,
        /// the read's and the write's side log2, saturated to L
        read_cap: LevelCap<L>,
        write_cap: LevelCap<L>,
        // stage 1: the level's side log2 (saturated to L), its base (U15) and whether the memory holds it, the
        // coordinates modulo its side as the banks read them (the column bank column p reads, the row bank row q
        // reads) and the parities of x0, x1, y0, y1; the write's likewise
        s1_m: DFF<Bits<4>>,
        s1_base: DFF<Bits<15>>,
        s1_held: DFF<Bit>,
        s1_wbase: DFF<Bits<15>>,
        s1_wheld: DFF<Bit>,
        s1_cx: [DFF<U8>; 2],
        s1_ry: [DFF<U8>; 2],
        s1_px: [DFF<Bit>; 2],
        s1_py: [DFF<Bit>; 2],
        s1_rd: DFF<Bit>,
        s1_we: DFF<Bit>,
        s1_wm: DFF<Bits<4>>,
        s1_wx: DFF<U8>,
        s1_wy: DFF<U8>,
        s1_wdata: DFF<U16>,
        // stage 2: each bank's two addends, its own registers: bank p + 2q's the level's base plus the column that
        // bank column p reads, halved (base ≤ 5,462 at L = 8, the column < 2^7: U15), and the row bank row q reads,
        // halved and shifted to its place (row·2^(m−1) < 2^(2L−1), U15 at L = 8); in the bank a write writes, the
        // write's. The parities for the select. The addresses are 15 bits whatever the banks' A (a bank takes its A
        // low bits, all of the address where the level is held; yosys drops the rest)
        s2_col: [DFF<Bits<15>>; 4],
        s2_row: [DFF<Bits<15>>; 4],
        s2_px: [DFF<Bit>; 2],
        s2_py: [DFF<Bit>; 2],
        s2_rd: DFF<Bit>,
        s2_we: DFF<Bit>,
        s2_wpx: DFF<Bit>,
        s2_wpy: DFF<Bit>,
        s2_wdata: DFF<U16>,
        // stage 3: the four bank addresses, each the sum of its bank's two addends (registered: the banks read and
        // write them)
        s3_addr: [DFF<Bits<15>>; 4],
        s3_px: [DFF<Bit>; 2],
        s3_py: [DFF<Bit>; 2],
        s3_rd: DFF<Bit>,
        wr_en: [DFF<Bit>; 4],
        wr_data: DFF<U16>,
        // stage 4 is the banks' read; stage 5: the four words; stage 5b: the words again; stage 6: the four texels
        s4_px: [DFF<Bit>; 2],
        s4_py: [DFF<Bit>; 2],
        s4_rd: DFF<Bit>,
        s5_word: [DFF<U16>; 4],
        s5_px: [DFF<Bit>; 2],
        s5_py: [DFF<Bit>; 2],
        s5_rd: DFF<Bit>,
        s5b_word: [DFF<U16>; 4],
        s5b_px: [DFF<Bit>; 2],
        s5b_py: [DFF<Bit>; 2],
        s5b_rd: DFF<Bit>,
        s6_t: [DFF<U16>; 4],
        valid: Delay<Bit, LATENCY>,
        w_m: Signal<Local, Bits<4>>,
        w_wm: Signal<Local, Bits<4>>,
        w_mask: Signal<Local, U8>,
        w_wmask: Signal<Local, U8>,
        w_xm: [Signal<Local, U8>; 2],
        w_ym: [Signal<Local, U8>; 2],
        w_c15: [Signal<Local, Bits<15>>; 2],
        w_r15: [Signal<Local, Bits<15>>; 2],
        w_rm: [Signal<Local, Bits<15>>; 2],
        w_wc15: Signal<Local, Bits<15>>,
        w_wr15: Signal<Local, Bits<15>>,
        w_wrm: Signal<Local, Bits<15>>,
        w_base: Signal<Local, Bits<15>>,
        w_wbase: Signal<Local, Bits<15>>,
        w_bc: [Signal<Local, Bits<15>>; 2],
        w_row: [Signal<Local, Bits<15>>; 2],
        w_wbc: Signal<Local, Bits<15>>,
        w_wrow: Signal<Local, Bits<15>>,
        w_kx: [Signal<Local, Bit>; 4],
        w_ky: [Signal<Local, Bit>; 4],
    }
}

impl<const P: usize, const A: usize, const L: usize> Logic for TexFetch<P, A, L> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s1_m, s1_base, s1_held, s1_wbase, s1_wheld, s1_rd, s1_we, s1_wm, s1_wx, s1_wy, s1_wdata,
            s2_rd, s2_we, s2_wpx, s2_wpy, s2_wdata, s3_rd, wr_data, s4_rd, s5_rd, s5b_rd
        );
        clock!(self, clock, valid);
        for n in 0..2 {
            self.s1_cx[n].clock.next = self.clock.val();
            self.s1_ry[n].clock.next = self.clock.val();
            self.s1_px[n].clock.next = self.clock.val();
            self.s1_py[n].clock.next = self.clock.val();
            self.s2_px[n].clock.next = self.clock.val();
            self.s2_py[n].clock.next = self.clock.val();
            self.s3_px[n].clock.next = self.clock.val();
            self.s3_py[n].clock.next = self.clock.val();
            self.s4_px[n].clock.next = self.clock.val();
            self.s4_py[n].clock.next = self.clock.val();
            self.s5_px[n].clock.next = self.clock.val();
            self.s5_py[n].clock.next = self.clock.val();
            self.s5b_px[n].clock.next = self.clock.val();
            self.s5b_py[n].clock.next = self.clock.val();
        }
        for n in 0..4 {
            self.s2_col[n].clock.next = self.clock.val();
            self.s2_row[n].clock.next = self.clock.val();
            self.s3_addr[n].clock.next = self.clock.val();
            self.wr_en[n].clock.next = self.clock.val();
            self.s5_word[n].clock.next = self.clock.val();
            self.s5b_word[n].clock.next = self.clock.val();
            self.s6_t[n].clock.next = self.clock.val();
            self.bank[n].clock.next = self.clock.val();
        }
        self.valid.d.next = self.valid_in.val();

        // stage 1: m = min(level_log2, L) (saturate), the side's mask 2^m − 1, each coordinate modulo the side
        self.read_cap.m_in.next = self.level_log2.val();
        self.w_m.next = self.read_cap.m.val();
        self.write_cap.m_in.next = self.w_log2.val();
        self.w_wm.next = self.write_cap.m.val();
        self.w_mask.next = self.read_cap.mask.val(); // 2^m − 1, U8
        self.w_wmask.next = self.write_cap.mask.val(); // 2^m − 1, U8
        self.s1_m.d.next = self.w_m.val();
        // where the level starts in every bank, base(m) = 1 + (4^(m−1) − 1)/3 for the whole chain (`bases`), and
        // whether the memory holds it: tables read by the side log2 as given (they saturate it themselves)
        self.read_base.m.next = self.level_log2.val();
        self.s1_base.d.next = self.read_base.base.val(); // ≤ 5,462: U15
        self.s1_held.d.next = self.read_base.held.val();
        self.write_base.m.next = self.w_log2.val();
        self.s1_wbase.d.next = self.write_base.base.val(); // ≤ 5,462: U15
        self.s1_wheld.d.next = self.write_base.held.val();
        self.w_xm[0].next = self.x0.val() & self.w_mask.val(); // modulo 2^m
        self.w_xm[1].next = self.x1.val() & self.w_mask.val();
        self.w_ym[0].next = self.y0.val() & self.w_mask.val();
        self.w_ym[1].next = self.y1.val() & self.w_mask.val();
        // bank column p reads x0 if x0 has parity p, else x1; bank row q likewise. The choice is made on x0's own
        // bit 0: where the mask keeps bit 0 (m ≥ 1) it is the parity of x0 modulo 2^m, and where it does not
        // (m = 0) both columns are 0, so either order is right. Each bit one LUT4 (x0, x1, the mask's bit, x0's
        // bit 0). With the choice in stage 2, on the stage-1 registers, its select fanned out to every bank's
        // column: cart_tex_nearest_mip_hemi_oct_matte_colour's path ran from it to the colour fetch's s2_col
        // (2.06 ns of logic, 3.51 ns of routing)
        if self.x0.val().get_bit(0) {
            self.s1_cx[0].d.next = self.w_xm[1].val();
            self.s1_cx[1].d.next = self.w_xm[0].val();
        } else {
            self.s1_cx[0].d.next = self.w_xm[0].val();
            self.s1_cx[1].d.next = self.w_xm[1].val();
        }
        if self.y0.val().get_bit(0) {
            self.s1_ry[0].d.next = self.w_ym[1].val();
            self.s1_ry[1].d.next = self.w_ym[0].val();
        } else {
            self.s1_ry[0].d.next = self.w_ym[0].val();
            self.s1_ry[1].d.next = self.w_ym[1].val();
        }
        for n in 0..2 {
            self.s1_px[n].d.next = self.w_xm[n].val().get_bit(0);
            self.s1_py[n].d.next = self.w_ym[n].val().get_bit(0);
        }
        self.s1_rd.d.next = !self.we.val().any();
        self.s1_we.d.next = self.we.val().any() & self.valid_in.val();
        self.s1_wm.d.next = self.w_wm.val();
        self.s1_wx.d.next = self.wx.val() & self.w_wmask.val(); // modulo 2^m
        self.s1_wy.d.next = self.wy.val() & self.w_wmask.val();
        self.s1_wdata.d.next = self.wdata.val();

        // stage 2: the word column x >> 1 and row y >> 1 (U7 in 15, a slice widened; written out: the loop index does not
        // reach into a function's argument under #[hdl_gen])
        self.w_c15[0].next = bit_cast::<15, 7>(self.s1_cx[0].q.val().get_bits::<7>(1));
        self.w_c15[1].next = bit_cast::<15, 7>(self.s1_cx[1].q.val().get_bits::<7>(1));
        self.w_r15[0].next = bit_cast::<15, 7>(self.s1_ry[0].q.val().get_bits::<7>(1));
        self.w_r15[1].next = bit_cast::<15, 7>(self.s1_ry[1].q.val().get_bits::<7>(1));
        self.w_base.next = self.s1_base.q.val();
        for n in 0..2 {
            self.w_bc[n].next = self.w_base.val() + self.w_c15[n].val(); // ≤ 5,462 + 127: U15, exact
                                                                         // (y >> 1)·2^(m−1) as ((y >> 1) << m) >> 1, which is 0 for m = 0 with no case of its own: y >> 1 < 2^m−1
                                                                         // so (y >> 1) << m < 2^(2m−1) ≤ 2^15, U15, exact, and the last shift drops a zero
            self.w_rm[n].next = self.w_r15[n].val() << self.s1_m.q.val();
            self.w_row[n].next = self.w_rm[n].val() >> 1; // U14, exact
        }
        for n in 0..2 {
            self.s2_px[n].d.next = self.s1_px[n].q.val();
            self.s2_py[n].d.next = self.s1_py[n].q.val();
        }
        self.s2_rd.d.next = self.s1_rd.q.val() & self.s1_held.q.val(); // a level it does not hold reads as zeros

        // the write: bank (x mod 2) + 2·(y mod 2), at base + (y >> 1)·2^(m−1) + (x >> 1)
        self.w_wc15.next = bit_cast::<15, 7>(self.s1_wx.q.val().get_bits::<7>(1)); // x >> 1: U7 in 15
        self.w_wr15.next = bit_cast::<15, 7>(self.s1_wy.q.val().get_bits::<7>(1)); // y >> 1: U7 in 15
        self.w_wrm.next = self.w_wr15.val() << self.s1_wm.q.val(); // U15, exact, as the read's
        self.w_wrow.next = self.w_wrm.val() >> 1; // U14, exact
        self.w_wbase.next = self.s1_wbase.q.val();
        self.w_wbc.next = self.w_wbase.val() + self.w_wc15.val(); // ≤ 5,462 + 127: U15, exact
                                                                  // bank p + 2q's addends: column p's and row q's; one address a bank a clock, so in the bank a write writes,
                                                                  // the write's (a vector either reads or writes, so nothing is lost), as a single-port RAM (the UP5K's SPRAM)
                                                                  // needs it. Each bank has its own pair, chosen here, so that its address is one adder from its registers:
                                                                  // with the choice after the sum, the colour fetch's stage 3 (2.13 ns of logic, 4.38 ns of routing to banks
                                                                  // spread over the ECP5's block RAM) was cart_tex_nearest_mip_colour's critical path, 153.5 MHz
        self.s2_col[0].d.next = self.w_bc[0].val();
        self.s2_row[0].d.next = self.w_row[0].val();
        self.s2_col[1].d.next = self.w_bc[1].val();
        self.s2_row[1].d.next = self.w_row[0].val();
        self.s2_col[2].d.next = self.w_bc[0].val();
        self.s2_row[2].d.next = self.w_row[1].val();
        self.s2_col[3].d.next = self.w_bc[1].val();
        self.s2_row[3].d.next = self.w_row[1].val();
        if self.s1_we.q.val() & self.s1_wheld.q.val() {
            if self.s1_wy.q.val().get_bit(0) {
                if self.s1_wx.q.val().get_bit(0) {
                    self.s2_col[3].d.next = self.w_wbc.val();
                    self.s2_row[3].d.next = self.w_wrow.val();
                } else {
                    self.s2_col[2].d.next = self.w_wbc.val();
                    self.s2_row[2].d.next = self.w_wrow.val();
                }
            } else if self.s1_wx.q.val().get_bit(0) {
                self.s2_col[1].d.next = self.w_wbc.val();
                self.s2_row[1].d.next = self.w_wrow.val();
            } else {
                self.s2_col[0].d.next = self.w_wbc.val();
                self.s2_row[0].d.next = self.w_wrow.val();
            }
        }
        self.s2_wpx.d.next = self.s1_wx.q.val().get_bit(0);
        self.s2_wpy.d.next = self.s1_wy.q.val().get_bit(0);
        self.s2_we.d.next = self.s1_we.q.val() & self.s1_wheld.q.val(); // a level it does not hold: no write
        self.s2_wdata.d.next = self.s1_wdata.q.val();

        // stage 3: bank (p, q) = p + 2q at (base + column p) + row q, or the write's (< 5,462 at L = 7, < 21,846 at
        // L = 8: U15, exact)
        for n in 0..4 {
            // U15, exact (the bound above)
            self.s3_addr[n].d.next = self.s2_col[n].q.val() + self.s2_row[n].q.val();
        }
        // the write's bank (x mod 2) + 2·(y mod 2)
        self.wr_en[0].d.next = self.s2_we.q.val() & !self.s2_wpx.q.val() & !self.s2_wpy.q.val();
        self.wr_en[1].d.next = self.s2_we.q.val() & self.s2_wpx.q.val() & !self.s2_wpy.q.val();
        self.wr_en[2].d.next = self.s2_we.q.val() & !self.s2_wpx.q.val() & self.s2_wpy.q.val();
        self.wr_en[3].d.next = self.s2_we.q.val() & self.s2_wpx.q.val() & self.s2_wpy.q.val();
        self.wr_data.d.next = self.s2_wdata.q.val();
        for n in 0..2 {
            self.s3_px[n].d.next = self.s2_px[n].q.val();
            self.s3_py[n].d.next = self.s2_py[n].q.val();
        }
        self.s3_rd.d.next = self.s2_rd.q.val();

        // stage 4: each bank writes the write or reads its address (a read sees the writes of the clocks before;
        // the written bank's word is not read, and a writing vector's outputs are zero)
        for n in 0..4 {
            self.bank[n].address.next = self.s3_addr[n].q.val().get_bits::<A>(0); // < 2^A where the level is held
            self.bank[n].write_data.next = self.wr_data.q.val();
            self.bank[n].write_enable.next = self.wr_en[n].q.val();
        }
        for n in 0..2 {
            self.s4_px[n].d.next = self.s3_px[n].q.val();
            self.s4_py[n].d.next = self.s3_py[n].q.val();
        }
        self.s4_rd.d.next = self.s3_rd.q.val();

        // stage 5: the four words registered
        for n in 0..4 {
            self.s5_word[n].d.next = self.bank[n].read_data.val();
        }
        for n in 0..2 {
            self.s5_px[n].d.next = self.s4_px[n].q.val();
            self.s5_py[n].d.next = self.s4_py[n].q.val();
        }
        self.s5_rd.d.next = self.s4_rd.q.val();

        // stage 5b: carried
        for n in 0..4 {
            self.s5b_word[n].d.next = self.s5_word[n].q.val();
        }
        for n in 0..2 {
            self.s5b_px[n].d.next = self.s5_px[n].q.val();
            self.s5b_py[n].d.next = self.s5_py[n].q.val();
        }
        self.s5b_rd.d.next = self.s5_rd.q.val();

        // stage 6: texel (x_a, y_b) is the word of bank (x_a mod 2) + 2·(y_b mod 2); a write reads nothing
        // t00 = (x0, y0), t10 = (x1, y0), t01 = (x0, y1), t11 = (x1, y1): output k = a + 2b
        for k in 0..4 {
            self.s6_t[k].d.next = 0.into();
        }
        // each output's column parity, x_(k mod 2), and row parity, y_(k / 2)
        self.w_kx[0].next = self.s5b_px[0].q.val();
        self.w_kx[1].next = self.s5b_px[1].q.val();
        self.w_kx[2].next = self.s5b_px[0].q.val();
        self.w_kx[3].next = self.s5b_px[1].q.val();
        self.w_ky[0].next = self.s5b_py[0].q.val();
        self.w_ky[1].next = self.s5b_py[0].q.val();
        self.w_ky[2].next = self.s5b_py[1].q.val();
        self.w_ky[3].next = self.s5b_py[1].q.val();
        if self.s5b_rd.q.val() {
            for k in 0..4 {
                if self.w_ky[k].val() {
                    if self.w_kx[k].val() {
                        self.s6_t[k].d.next = self.s5b_word[3].q.val();
                    } else {
                        self.s6_t[k].d.next = self.s5b_word[2].q.val();
                    }
                } else if self.w_kx[k].val() {
                    self.s6_t[k].d.next = self.s5b_word[1].q.val();
                } else {
                    self.s6_t[k].d.next = self.s5b_word[0].q.val();
                }
            }
        }
        self.t00.next = self.s6_t[0].q.val();
        self.t10.next = self.s6_t[1].q.val();
        self.t01.next = self.s6_t[2].q.val();
        self.t11.next = self.s6_t[3].q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
