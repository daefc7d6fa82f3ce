//! `DelayedBlend`: the blend unit at the end of a pipeline, fed from the pixel's colours and mode as they entered
//! it, delayed in block RAM (`prim::ram_delay`) until the α computed from the same pixel arrives.

use crate::blend::Blend;
use crate::prim::delay::Delay;
use crate::prim::ram_delay::RamDelay;
use rust_hdl::prelude::*;

crate::block! {
    /// The blend unit fed from a pixel's colours and mode delayed N clocks, the six colours in one 48-bit `RamDelay`
    /// (three SB_RAM40_4K instead of 48·N flip-flops) and the mode in a DFF chain, so that they meet the α computed
    /// from the same pixel N clocks later. Both pipelines end in one. Latency from α to the colour: `blend::LATENCY`.
    #[derive(Default)]
    pub struct DelayedBlend<const A: usize, const N: usize> {
        pub clock: Signal<In, Clock>,
        /// the pixel's mode and colours, as it enters the pipeline
        pub mode: Signal<In, Bits<1>>,
        pub src_r: Signal<In, Bits<8>>,
        pub src_g: Signal<In, Bits<8>>,
        pub src_b: Signal<In, Bits<8>>,
        pub dst_r: Signal<In, Bits<8>>,
        pub dst_g: Signal<In, Bits<8>>,
        pub dst_b: Signal<In, Bits<8>>,
        /// its α, N clocks later
        pub valid_in: Signal<In, Bit>,
        pub alpha: Signal<In, Bits<8>>,
        pub valid_out: Signal<Out, Bit>,
        pub out_r: Signal<Out, Bits<8>>,
        pub out_g: Signal<Out, Bits<8>>,
        pub out_b: Signal<Out, Bits<8>>,
        pub blend: Blend,
        colours: RamDelay<48, A, N>,
        mode_dly: Delay<Bits<1>, N>,
        word: Signal<Local, Bits<48>>,
    }
}

impl<const A: usize, const N: usize> Logic for DelayedBlend<A, N> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, colours, mode_dly, blend);
        // packed low to high: src r, g, b, dst r, g, b
        self.word.next = bit_cast::<48, 8>(self.src_r.val());
        self.word.next = self.word.val() | (bit_cast::<48, 8>(self.src_g.val()) << 8);
        self.word.next = self.word.val() | (bit_cast::<48, 8>(self.src_b.val()) << 16);
        self.word.next = self.word.val() | (bit_cast::<48, 8>(self.dst_r.val()) << 24);
        self.word.next = self.word.val() | (bit_cast::<48, 8>(self.dst_g.val()) << 32);
        self.word.next = self.word.val() | (bit_cast::<48, 8>(self.dst_b.val()) << 40);
        self.colours.d.next = self.word.val();
        self.mode_dly.d.next = self.mode.val();
        self.blend.valid_in.next = self.valid_in.val();
        self.blend.alpha.next = self.alpha.val();
        self.blend.mode.next = self.mode_dly.q.val();
        self.blend.src_r.next = self.colours.q.val().get_bits::<8>(0);
        self.blend.src_g.next = self.colours.q.val().get_bits::<8>(8);
        self.blend.src_b.next = self.colours.q.val().get_bits::<8>(16);
        self.blend.dst_r.next = self.colours.q.val().get_bits::<8>(24);
        self.blend.dst_g.next = self.colours.q.val().get_bits::<8>(32);
        self.blend.dst_b.next = self.colours.q.val().get_bits::<8>(40);
        self.valid_out.next = self.blend.valid_out.val();
        self.out_r.next = self.blend.out_r.val();
        self.out_g.next = self.blend.out_g.val();
        self.out_b.next = self.blend.out_b.val();
    }
}
