//! `sincos`: the sine/cosine unit [10] of seed 000's FIG. 3 on its own: a 10-bit elevation angle (1024 = 90°)
//! → sin and cos as UNORM8, from a 256-entry table (the ROM widget) addressed by the angle's top 8 bits
//! (truncation). Latency 2: the address; the table.

use crate::delay::Delay;
use crate::stream_unit;
use crate::tables::ElevationTable;
use rust_hdl::prelude::*;

pub const LATENCY: usize = 2;

#[derive(LogicBlock, Default)]
pub struct SinCos {
    pub clock: Signal<In, Clock>,
    pub valid_in: Signal<In, Bit>,
    pub angle: Signal<In, Bits<10>>,
    pub valid_out: Signal<Out, Bit>,
    pub sin: Signal<Out, Bits<8>>,
    pub cos: Signal<Out, Bits<8>>,
    lut: ElevationTable<false>,
    s1_addr: DFF<Bits<8>>,
    s2_e: DFF<Bits<16>>,
    valid: Delay<Bit, LATENCY>,
}

impl Logic for SinCos {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_addr, s2_e);
        self.valid.clock.next = self.clock.val();
        self.valid.d.next = self.valid_in.val();
        self.s1_addr.d.next = self.angle.val().get_bits::<8>(2); // top 8 bits: truncate
        self.lut.address.next = self.s1_addr.q.val();
        self.s2_e.d.next = self.lut.data.val();
        self.sin.next = self.s2_e.q.val().get_bits::<8>(0);
        self.cos.next = self.s2_e.q.val().get_bits::<8>(8);
        self.valid_out.next = self.valid.q.val();
    }
}

stream_unit!(SinCos, "sincos", LATENCY, inputs: [angle: 10], outputs: [sin: 8, cos: 8]);
