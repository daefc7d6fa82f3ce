//! `cos_sign`: the cosine unit [18] of US 6,819,319's FIG. 3 on its own, table size and output width as parameters:
//! d = (R − Q) mod 256 → |cos d| as UNORM_W and the sign bit [26], from 2^TB-entry tables over the full turn (the
//! ROM widget) addressed by d's top TB bits (truncation). Latency 2: the address; the tables. The unit `cos_sign`
//! is `CosSign<8, 8>`, the block the polar shade unit holds (there `CosSign<8, 8, DC>`, with the Dreamcast scale's
//! contents when `DC`). Contents: `crate::tables::cos_sign`.

use crate::prim::delay::Delay;
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::ROM;

pub const LATENCY: usize = 2;

crate::stream_block! {
    pub struct CosSign<const TB: usize, const W: usize, const DC: bool = false>: unit("cos_sign", LATENCY) {
        in {
            d: Bits<8>,
        }
        out {
            mag: Bits<W>,
            neg: Bits<1>,
        }
        mag_rom: ROM<Bits<W>, TB>,
        neg_rom: ROM<Bits<1>, TB>,
        /// 8 − TB: the bits of d below the table's resolution
        low_bits: Constant<Bits<4>>,
        s1_addr: DFF<Bits<TB>>,
        s2_mag: DFF<Bits<W>>,
        s2_neg: DFF<Bits<1>>,
        valid: Delay<Bit, LATENCY>,
        w_top: Signal<Local, Bits<8>>,
    }
}

impl<const TB: usize, const W: usize, const DC: bool> Default for CosSign<TB, W, DC> {
    fn default() -> Self {
        assert!(TB <= 8 && W <= 16, "CosSign<{TB}, {W}>: at most 2^8 entries of 16 bits");
        let e = crate::tables::cos_sign(DC, TB, W);
        Self {
            clock: Default::default(),
            valid_in: Default::default(),
            d: Default::default(),
            valid_out: Default::default(),
            mag: Default::default(),
            neg: Default::default(),
            mag_rom: ROM::from(e.iter().map(|x| Bits::<W>::from(x.0))),
            neg_rom: ROM::from(e.iter().map(|x| Bits::<1>::from(x.1 as u64))),
            low_bits: Constant::new(Bits::<4>::from((8 - TB) as u64)),
            s1_addr: Default::default(),
            s2_mag: Default::default(),
            s2_neg: Default::default(),
            valid: Default::default(),
            w_top: Default::default(),
        }
    }
}

impl<const TB: usize, const W: usize, const DC: bool> Logic for CosSign<TB, W, DC> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_addr, s2_mag, s2_neg);
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1: the top TB bits of d (truncate)
        self.w_top.next = self.d.val() >> self.low_bits.val();
        self.s1_addr.d.next = bit_cast::<TB, 8>(self.w_top.val());
        // stage 2: the tables
        self.mag_rom.address.next = self.s1_addr.q.val();
        self.neg_rom.address.next = self.s1_addr.q.val();
        self.s2_mag.d.next = self.mag_rom.data.val();
        self.s2_neg.d.next = self.neg_rom.data.val();
        self.mag.next = self.s2_mag.q.val();
        self.neg.next = self.s2_neg.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}

/// The unit `cos_sign`: the size the polar shade unit uses.
pub type CosSignUnit = CosSign<8, 8>;
