//! `SmMul`: the one sign-magnitude multiplier every block uses for a signed value times an unsigned weight.
//!
//! rust-hdl multiplies only `Bits<16> × Bits<16> → Bits<32>`, unsigned, so a signed product is taken as
//! |x| · w with the sign of x kept beside it; the block that reads the product folds the sign into its next add or
//! subtract, where it costs nothing. Four stages:
//! 1. |x| and the sign of x; w carried;
//! 2. the operand registers `mop_m` and `mop_w`, which feed the DSP and nothing else;
//! 3. the product |x|·w (U32; < 2^32 since both operands are U16);
//! 4. the product again, `s4_p`, which feeds whatever reads it.
//!
//! On the ECP5 stages 2 and 3 become the MULT18X18D's own input and output registers (`synth::regpack`), so the
//! product costs the block's 0.74 ns from the clock rather than 3.93 ns of logic, and stage 4 takes the route from
//! the DSP to the logic that reads it on a path of its own: with three stages that route and the reader's add were
//! one path, 8.3 ns in `cart_pipeline`'s bilinear units.
//!
//! `x` is two's complement in `N` bits (`N` ≤ 32). Its magnitude must fit 16 bits: the caller states why, and
//! `magnitude_fits_16_bits` in the tests checks the edge. Truncation to 16 bits of a magnitude that fits is exact.

use crate::prim::q::SBits;
use rust_hdl::prelude::*;

/// Clock edges from x and w to the product.
pub const LATENCY: usize = 4;

crate::block! {
    pub struct SmMul<const N: usize> {
        pub clock: Signal<In, Clock>,
        /// Two's complement, N bits.
        pub x: Signal<In, SBits<N>>,
        /// Unsigned weight.
        pub w: Signal<In, Bits<16>>,
        /// |x|·w, LATENCY clocks later (U32).
        pub p: Signal<Out, Bits<32>>,
        /// The sign of x beside it.
        pub neg: Signal<Out, Bit>,
        sign_bit: Constant<Bits<N>>, // 2^(N−1), the sign bit alone: x & sign_bit ≠ 0 is x < 0
        w_abs: Signal<Local, Bits<N>>,
        s1_m: DFF<Bits<16>>,
        s1_w: DFF<Bits<16>>,
        s1_n: DFF<Bit>,
        mop_m: DFF<Bits<16>>,
        mop_w: DFF<Bits<16>>,
        s2_n: DFF<Bit>,
        s3_p: DFF<Bits<32>>,
        s3_n: DFF<Bit>,
        s4_p: DFF<Bits<32>>,
        s4_n: DFF<Bit>,
    }
}

impl<const N: usize> Default for SmMul<N> {
    fn default() -> Self {
        assert!((2..=32).contains(&N), "SmMul: x is 2 to 32 bits, not {N}");
        Self {
            clock: Default::default(),
            x: Default::default(),
            w: Default::default(),
            p: Default::default(),
            neg: Default::default(),
            sign_bit: Constant::new(Bits::from(1u64 << (N - 1))),
            w_abs: Default::default(),
            s1_m: Default::default(),
            s1_w: Default::default(),
            s1_n: Default::default(),
            mop_m: Default::default(),
            mop_w: Default::default(),
            s2_n: Default::default(),
            s3_p: Default::default(),
            s3_n: Default::default(),
            s4_p: Default::default(),
            s4_n: Default::default(),
        }
    }
}

impl<const N: usize> Logic for SmMul<N> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, s1_m, s1_w, s1_n, mop_m, mop_w, s2_n, s3_p, s3_n, s4_p, s4_n);
        // stage 1: |x| (N bits; −2^(N−1) stays itself, read unsigned it is 2^(N−1), still right), sign of x
        if (self.x.val() & self.sign_bit.val()).any() {
            self.w_abs.next = !self.x.val() + 1;
        } else {
            self.w_abs.next = self.x.val();
        }
        self.s1_m.d.next = bit_cast::<16, N>(self.w_abs.val()); // U16: the caller's bound on |x|, exact
        self.s1_n.d.next = (self.x.val() & self.sign_bit.val()).any();
        self.s1_w.d.next = self.w.val();
        // stage 2: the DSP's operands, registered alone
        self.mop_m.d.next = self.s1_m.q.val();
        self.mop_w.d.next = self.s1_w.q.val();
        self.s2_n.d.next = self.s1_n.q.val();
        // stage 3: U16 × U16 → U32, exact
        self.s3_p.d.next = self.mop_m.q.val() * self.mop_w.q.val();
        self.s3_n.d.next = self.s2_n.q.val();
        // stage 4: the product carried
        self.s4_p.d.next = self.s3_p.q.val();
        self.s4_n.d.next = self.s3_n.q.val();
        self.p.next = self.s4_p.q.val();
        self.neg.next = self.s4_n.q.val();
    }
}

/// Clock edges from x and w to the product of `SmMulWide`.
pub const WIDE_LATENCY: usize = 4;

crate::block! {
    /// `SmMulWide`: the same for a magnitude wider than 16 bits, |x| < 2^32, as two 16 × 16 products: |x| = hi·2^16 + lo,
    /// |x|·w = lo·w + (hi·w)·2^16. The caller bounds |x|·w < 2^32. Four stages: |x| split; the operand registers;
    /// both products; their sum.
    pub struct SmMulWide<const N: usize> {
        pub clock: Signal<In, Clock>,
        /// Two's complement, N bits (N ≤ 33).
        pub x: Signal<In, SBits<N>>,
        /// Unsigned weight.
        pub w: Signal<In, Bits<16>>,
        /// |x|·w, WIDE_LATENCY clocks later (U32).
        pub p: Signal<Out, Bits<32>>,
        /// The sign of x beside it.
        pub neg: Signal<Out, Bit>,
        sign_bit: Constant<Bits<N>>, // 2^(N−1)
        w_abs: Signal<Local, Bits<N>>,
        w_abs32: Signal<Local, Bits<32>>,
        w_hi16: Signal<Local, Bits<32>>,
        s1_lo: DFF<Bits<16>>,
        s1_hi: DFF<Bits<16>>,
        s1_w: DFF<Bits<16>>,
        s1_n: DFF<Bit>,
        mop_lo: DFF<Bits<16>>,
        mop_hi: DFF<Bits<16>>,
        mop_wl: DFF<Bits<16>>,
        mop_wh: DFF<Bits<16>>,
        s2_n: DFF<Bit>,
        s3_pl: DFF<Bits<32>>,
        s3_ph: DFF<Bits<32>>,
        s3_n: DFF<Bit>,
        s4_p: DFF<Bits<32>>,
        s4_n: DFF<Bit>,
    }
}

impl<const N: usize> Default for SmMulWide<N> {
    fn default() -> Self {
        assert!((2..=33).contains(&N), "SmMulWide: x is 2 to 33 bits, not {N}");
        Self {
            clock: Default::default(),
            x: Default::default(),
            w: Default::default(),
            p: Default::default(),
            neg: Default::default(),
            sign_bit: Constant::new(Bits::from(1u64 << (N - 1))),
            w_abs: Default::default(),
            w_abs32: Default::default(),
            w_hi16: Default::default(),
            s1_lo: Default::default(),
            s1_hi: Default::default(),
            s1_w: Default::default(),
            s1_n: Default::default(),
            mop_lo: Default::default(),
            mop_hi: Default::default(),
            mop_wl: Default::default(),
            mop_wh: Default::default(),
            s2_n: Default::default(),
            s3_pl: Default::default(),
            s3_ph: Default::default(),
            s3_n: Default::default(),
            s4_p: Default::default(),
            s4_n: Default::default(),
        }
    }
}

impl<const N: usize> Logic for SmMulWide<N> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, s1_lo, s1_hi, s1_w, s1_n, mop_lo, mop_hi, mop_wl, mop_wh);
        clock!(self, clock, s2_n, s3_pl, s3_ph, s3_n, s4_p, s4_n);
        // stage 1: |x| (N bits), split into two 16-bit halves; the sign
        if (self.x.val() & self.sign_bit.val()).any() {
            self.w_abs.next = !self.x.val() + 1;
        } else {
            self.w_abs.next = self.x.val();
        }
        self.w_abs32.next = bit_cast::<32, N>(self.w_abs.val()); // |x| < 2^32: U32, exact
        self.s1_lo.d.next = self.w_abs32.val().get_bits::<16>(0); // the low half, a split
        self.s1_hi.d.next = self.w_abs32.val().get_bits::<16>(16); // the high half, a split
        self.s1_w.d.next = self.w.val();
        self.s1_n.d.next = (self.x.val() & self.sign_bit.val()).any();
        // stage 2: each DSP's operands, registered alone (the weight once per multiplier)
        self.mop_lo.d.next = self.s1_lo.q.val();
        self.mop_hi.d.next = self.s1_hi.q.val();
        self.mop_wl.d.next = self.s1_w.q.val();
        self.mop_wh.d.next = self.s1_w.q.val();
        self.s2_n.d.next = self.s1_n.q.val();
        // stage 3: U16 × U16 → U32, both exact
        self.s3_pl.d.next = self.mop_lo.q.val() * self.mop_wl.q.val();
        self.s3_ph.d.next = self.mop_hi.q.val() * self.mop_wh.q.val();
        self.s3_n.d.next = self.s2_n.q.val();
        // stage 4: lo·w + hi·w·2^16 (U32: the caller's bound |x|·w < 2^32 makes the bits shifted out zero)
        self.w_hi16.next = self.s3_ph.q.val() << 16;
        self.s4_p.d.next = self.s3_pl.q.val() + self.w_hi16.val(); // U32, exact under the bound
        self.s4_n.d.next = self.s3_n.q.val();
        self.p.next = self.s4_p.q.val();
        self.neg.next = self.s4_n.q.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Drive `SmMul<N>` with (x, w) pairs, one per clock, and return (p, neg) as they leave.
    fn run<const N: usize>(pairs: &[(i64, u64)]) -> Vec<(u64, bool)> {
        let mut uut = SmMul::<N>::default();
        uut.connect_all();
        let mut out = vec![];
        for k in 0..pairs.len() + LATENCY - 1 {
            let (x, w) = pairs.get(k).copied().unwrap_or((0, 0));
            uut.x.next = Bits::from((x as u64) & ((1u64 << N) - 1));
            uut.w.next = Bits::from(w);
            uut.clock.next = Clock { clk: false };
            assert!(simulate(&mut uut, 1000));
            uut.clock.next = Clock { clk: true };
            assert!(simulate(&mut uut, 1000));
            if k + 1 >= LATENCY {
                out.push((uut.p.val().to_u64(), uut.neg.val()));
            }
        }
        out
    }

    #[test]
    fn signed_times_unsigned_at_the_edges() {
        // S9 (bilinear's texel differences) and S17 in 32 bits (its b − a) at their extremes
        let pairs: Vec<(i64, u64)> = vec![(-255, 255), (255, 255), (0, 65_535), (-1, 1), (1, 0), (-255, 0)];
        let got = run::<16>(&pairs);
        for ((x, w), (p, n)) in pairs.iter().zip(got) {
            assert_eq!((p, n), ((x.unsigned_abs() * w), *x < 0), "x {x} w {w}");
        }
        let pairs: Vec<(i64, u64)> = vec![(-65_280, 255), (65_280, 255), (-65_535, 65_535), (0, 7)];
        let got = run::<32>(&pairs);
        for ((x, w), (p, n)) in pairs.iter().zip(got) {
            assert_eq!((p, n), ((x.unsigned_abs() * w), *x < 0), "x {x} w {w}");
        }
    }

    #[test]
    fn the_wide_multiplier_takes_magnitudes_beyond_16_bits() {
        let pairs: Vec<(i64, u64)> =
            vec![(-(1 << 21) + 1, 255), ((1 << 21) - 1, 255), (-1_048_576, 1785), (65_536, 1), (0, 9), (-7, 3)];
        let mut uut = SmMulWide::<22>::default();
        uut.connect_all();
        let mut got = vec![];
        for k in 0..pairs.len() + WIDE_LATENCY - 1 {
            let (x, w) = pairs.get(k).copied().unwrap_or((0, 0));
            uut.x.next = Bits::from((x as u64) & ((1u64 << 22) - 1));
            uut.w.next = Bits::from(w);
            uut.clock.next = Clock { clk: false };
            assert!(simulate(&mut uut, 1000));
            uut.clock.next = Clock { clk: true };
            assert!(simulate(&mut uut, 1000));
            if k + 1 >= WIDE_LATENCY {
                got.push((uut.p.val().to_u64(), uut.neg.val()));
            }
        }
        for ((x, w), (p, n)) in pairs.iter().zip(got) {
            assert_eq!((p, n), ((x.unsigned_abs() * w), *x < 0), "x {x} w {w}");
        }
    }

    #[test]
    fn magnitude_fits_16_bits() {
        // the most negative N-bit value's magnitude is 2^(N−1): for N = 17 that is 65,536, which does not fit, and
        // the truncation shows it; callers bound |x| ≤ 65,535
        let got = run::<17>(&[(-65_536, 1), (-65_535, 1)]);
        assert_eq!(got, vec![(0, true), (65_535, true)]);
    }
}
