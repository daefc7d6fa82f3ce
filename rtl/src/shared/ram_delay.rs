//! `RamDelay`: an N-clock delay line held in a block RAM (a circular buffer of 2^A words) instead of N registers.
//! The pipeline's long side-band lines (the six blend colours, 35 clocks; C, 27 clocks) cost ~1,900 flip-flops as
//! DFF chains; yosys maps this memory to SB_RAM40_4K blocks instead (16 bits wide each on the iCE40).
//!
//! Timing: every clock the word `d` is written at `wp` and the word written N − 1 clocks earlier is read from
//! `wp − (N − 1)` (mod 2^A) into the RAM's read register, so `q` is `d` delayed by N clocks. N ≥ 2, so the read
//! never hits the address written on the same edge, and N − 1 < 2^A. Until N clocks have passed `q` is whatever
//! the RAM held (zero in rust-hdl, undefined in Verilog); the valid flag travelling beside it is low then.

use crate::blend::Blend;
use crate::delay::Delay;
use rust_hdl::prelude::*;

crate::block! {
    pub struct RamDelay<const W: usize, const A: usize, const N: usize> {
        pub clock: Signal<In, Clock>,
        pub d: Signal<In, Bits<W>>,
        pub q: Signal<Out, Bits<W>>,
        ram: RAM<Bits<W>, A>,
        wp: DFF<Bits<A>>,
        /// 2^A − (N − 1): added to the write pointer, modulo 2^A, it gives the read pointer
        back: Constant<Bits<A>>,
    }
}

impl<const W: usize, const A: usize, const N: usize> Default for RamDelay<W, A, N> {
    fn default() -> Self {
        assert!(N >= 2 && N - 1 < (1 << A), "RamDelay needs 2 <= N <= 2^A (N = {N}, A = {A})");
        Self {
            clock: Default::default(),
            d: Default::default(),
            q: Default::default(),
            ram: Default::default(),
            wp: Default::default(),
            back: Constant::new(Bits::<A>::from(((1u64 << A) - (N as u64 - 1)) & ((1u64 << A) - 1))),
        }
    }
}

impl<const W: usize, const A: usize, const N: usize> Logic for RamDelay<W, A, N> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, wp);
        self.ram.read_clock.next = self.clock.val();
        self.ram.write_clock.next = self.clock.val();
        self.wp.d.next = self.wp.q.val() + 1; // wraps modulo 2^A: the assignment truncates in both simulators
        self.ram.write_enable.next = true;
        self.ram.write_address.next = self.wp.q.val();
        self.ram.write_data.next = self.d.val();
        self.ram.read_address.next = self.wp.q.val() + self.back.val(); // wp − (N − 1) modulo 2^A (back = 2^A − N + 1): wraps on purpose
        self.q.next = self.ram.read_data.val();
    }
}

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
