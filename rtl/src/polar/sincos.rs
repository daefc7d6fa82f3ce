//! `sincos`: the sine/cosine unit [10] of US 6,819,319's FIG. 3 on its own, with its table size and output width as
//! parameters: a 10-bit elevation angle (1024 = 90°) → sin and cos as UNORM_W, from two 2^TB-entry tables (the
//! ROM widget) addressed by the angle's top TB bits (truncation). Latency 2: the address; the tables.
//! The unit `sincos` is `SinCos<8, 8>`, the block the polar shade unit holds (there `SinCos<8, 8, DC>`, fed S·4,
//! with the Dreamcast scale's contents when `DC`); `bumprtl accuracy --lut-cost` synthesises the other sizes of the
//! LUT-size table from this same block. Contents: `crate::tables::elevation`.

use crate::prim::delay::Delay;
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::ROM;

pub const LATENCY: usize = 2;
pub const ANGLE_BITS: usize = 10;

crate::stream_block! {
    pub struct SinCos<const TB: usize, const W: usize, const DC: bool = false>: unit("sincos", LATENCY) {
        in {
            angle: Bits<ANGLE_BITS>,
        }
        out {
            sin: Bits<W>,
            cos: Bits<W>,
        }
        sin_rom: ROM<Bits<W>, TB>,
        cos_rom: ROM<Bits<W>, TB>,
        /// 10 − TB: the angle bits below the table's resolution
        low_bits: Constant<Bits<4>>,
        s1_addr: DFF<Bits<TB>>,
        s2_sin: DFF<Bits<W>>,
        s2_cos: DFF<Bits<W>>,
        valid: Delay<Bit, LATENCY>,
        w_top: Signal<Local, Bits<ANGLE_BITS>>,
    }
}

impl<const TB: usize, const W: usize, const DC: bool> Default for SinCos<TB, W, DC> {
    fn default() -> Self {
        assert!(TB <= ANGLE_BITS && W <= 16, "SinCos<{TB}, {W}>: at most 2^10 entries of 16 bits");
        let e = crate::tables::elevation(DC, TB, W);
        Self {
            clock: Default::default(),
            valid_in: Default::default(),
            angle: Default::default(),
            valid_out: Default::default(),
            sin: Default::default(),
            cos: Default::default(),
            sin_rom: ROM::from(e.iter().map(|x| Bits::<W>::from(x.0))),
            cos_rom: ROM::from(e.iter().map(|x| Bits::<W>::from(x.1))),
            low_bits: Constant::new(Bits::<4>::from((ANGLE_BITS - TB) as u64)),
            s1_addr: Default::default(),
            s2_sin: Default::default(),
            s2_cos: Default::default(),
            valid: Default::default(),
            w_top: Default::default(),
        }
    }
}

impl<const TB: usize, const W: usize, const DC: bool> Logic for SinCos<TB, W, DC> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_addr, s2_sin, s2_cos);
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1: the top TB bits (truncate)
        self.w_top.next = self.angle.val() >> self.low_bits.val();
        self.s1_addr.d.next = bit_cast::<TB, ANGLE_BITS>(self.w_top.val());
        // stage 2: the tables
        self.sin_rom.address.next = self.s1_addr.q.val();
        self.cos_rom.address.next = self.s1_addr.q.val();
        self.s2_sin.d.next = self.sin_rom.data.val();
        self.s2_cos.d.next = self.cos_rom.data.val();
        self.sin.next = self.s2_sin.q.val();
        self.cos.next = self.s2_cos.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}

/// The unit `sincos`: the size the polar shade unit uses.
pub type SinCosUnit = SinCos<8, 8>;
