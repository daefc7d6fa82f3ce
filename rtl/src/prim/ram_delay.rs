//! `RamDelay`: an N-clock delay line held in a block RAM (a circular buffer of 2^A words) instead of N registers.
//! The pipeline's long side-band lines (the six blend colours, 35 clocks; C, 27 clocks) cost ~1,900 flip-flops as
//! DFF chains; yosys maps this memory to SB_RAM40_4K blocks instead (16 bits wide each on the iCE40).
//!
//! Timing: every clock the word `d` is written at `wp` and the word written N − 1 clocks earlier is read from
//! `wp − (N − 1)` (mod 2^A) into the RAM's read register, so `q` is `d` delayed by N clocks. N ≥ 2, so the read
//! never hits the address written on the same edge, and N − 1 < 2^A. Until N clocks have passed `q` is whatever
//! the RAM held (zero in rust-hdl, undefined in Verilog); the valid flag travelling beside it is low then.

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
