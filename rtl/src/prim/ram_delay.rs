//! `RamDelay`: an N-clock delay line held in a block RAM (a circular buffer of 2^A words) instead of N registers.
//! The pipeline's long side-band lines (the six blend colours, 35 clocks; C, 27 clocks) cost ~1,900 flip-flops as
//! DFF chains; yosys maps this memory to SB_RAM40_4K blocks instead (16 bits wide each on the iCE40).
//!
//! Timing: every clock the word `d` is written at `wp` and the word written N − 2 clocks earlier is read from
//! `wp − (N − 2)` (mod 2^A) into the RAM's read register, then into an output register of its own, so `q` is `d`
//! delayed by N clocks. The output register keeps the block RAM's clock-to-out (5.6 ns on an ECP5 DP16KD whose own
//! output register yosys leaves off) out of the next stage's logic: the light word read straight into dot3's first
//! stage was the one-light pipelines' critical path on the ECP5. The read address is a register too (`rp`, made a
//! clock ahead from the write pointer), not the sum `wp − (N − 2)`: that sum in front of a LUT RAM's read and its
//! fan-out to every LUT RAM cell was `cart_pipeline`'s critical path on the ECP5 (C's line, 2.29 ns of logic and
//! 4.70 of route). N ≥ 3, so from the first clock edge on the read never hits the address written on the same edge,
//! and N − 2 < 2^A; before that edge `rp` is 0, the address written. Until N clocks have passed `q` is whatever the
//! RAM held (zero in rust-hdl, undefined in Verilog); the valid flag travelling beside it is low then.
//!
//! The RAM is the field `ring`, and the Verilog export marks the memory of every module `…$ring` `(* no_rw_check
//! *)`: its read never meets its write after the first edge, and without the mark yosys keeps the old word on such a
//! collision with a comparator and a bypass multiplexer behind the block RAM (the ECP5's 36-bit mode promises
//! nothing there), logic between the block's read and the output register that the ECP5 register pass would
//! otherwise move into the DP16KD.

use rust_hdl::prelude::*;

crate::block! {
    pub struct RamDelay<const W: usize, const A: usize, const N: usize> {
        pub clock: Signal<In, Clock>,
        pub d: Signal<In, Bits<W>>,
        pub q: Signal<Out, Bits<W>>,
        ring: RAM<Bits<W>, A>,
        wp: DFF<Bits<A>>,
        /// the read address, `wp − (N − 2)` (mod 2^A) from the first clock edge on
        rp: DFF<Bits<A>>,
        /// the word read, a clock after the RAM's own read register
        out: DFF<Bits<W>>,
        /// 2^A − (N − 3) (mod 2^A): added to the write pointer, the next clock's read address, wp + 1 − (N − 2)
        ahead: Constant<Bits<A>>,
    }
}

/// The address bits of an N-clock line: at least `least` (a pipeline's lines keep one size where they fit it), more
/// where N − 2 ≥ 2^least (the long lines behind the trilinear front).
pub const fn addr_bits(n: usize, least: usize) -> usize {
    let mut a = least;
    while n >= 2 + (1 << a) {
        a += 1;
    }
    a
}

impl<const W: usize, const A: usize, const N: usize> Default for RamDelay<W, A, N> {
    fn default() -> Self {
        assert!(N >= 3 && N - 2 < (1 << A), "RamDelay needs 3 <= N <= 2^A + 1 (N = {N}, A = {A})");
        Self {
            clock: Default::default(),
            d: Default::default(),
            q: Default::default(),
            ring: Default::default(),
            wp: Default::default(),
            rp: Default::default(),
            out: Default::default(),
            ahead: Constant::new(Bits::<A>::from(((1u64 << A) - (N as u64 - 3)) & ((1u64 << A) - 1))),
        }
    }
}

impl<const W: usize, const A: usize, const N: usize> Logic for RamDelay<W, A, N> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, wp, rp, out);
        self.ring.read_clock.next = self.clock.val();
        self.ring.write_clock.next = self.clock.val();
        self.wp.d.next = self.wp.q.val() + 1; // wraps modulo 2^A: the assignment truncates in both simulators
        self.ring.write_enable.next = true;
        self.ring.write_address.next = self.wp.q.val();
        self.ring.write_data.next = self.d.val();
        self.rp.d.next = self.wp.q.val() + self.ahead.val(); // (wp + 1) − (N − 2) modulo 2^A: wraps on purpose
        self.ring.read_address.next = self.rp.q.val();
        self.out.d.next = self.ring.read_data.val(); // W, as stored
        self.q.next = self.out.q.val();
    }
}
