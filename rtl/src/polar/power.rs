//! `power`: the power unit [30] of US 6,819,319's FIG. 3, `y = 255·(x/255)^p` with p = pw/4 (U6.2), by a log table,
//! one multiplier and an exp table; see `vectors::power` for the recipe and why. Latency 12: 1 inputs registered; 2
//! L(x) (table); 2b L again; 2c the multiplier's operands; 3 e = pw·L; 3b e again; 4 the rounding's pieces of g =
//! round(e >> 6): e >> 6's low 8 bits, its rounding bit e₅, e >> 14's low 4 bits and whether e >> 14 > 9; 5 m =
//! min(e >> 14, 9); f = g mod 256 = ((e >> 6) + e₅) mod 256 into the exp table, E(f), and the carry out of that sum; 5b
//! E again, and n = min(g >> 8, 9) from the carry; 6 and 6c the barrel shift w = E >> (n + 6) in two steps, by the
//! shift's multiple of 4, then by the rest (a floor twice is the floor of the whole shift); 7 y = (w + 1) >> 1, which
//! makes (E + 2^(n+6)) >> (n + 7), and x = 0 overrides. (With the shift and the rounding in one stage, the UP5K placed
//! the unit at 43.7 MHz; with the shift in one stage, polar_pipeline's critical path on the UP5K was the shift, 14 ns.)
//! Stages 2b and 5b compute nothing: on the ECP5 each is a table's DP16KD output register, so neither the product nor
//! the shift waits on a block RAM read (5.6 ns from the clock without it, 0.97 with it; polar_pipeline's critical path,
//! 9.1 ns, was that read into the multiplier). Stage 2c is the MULT18X18D's own input register: without it that
//! register took stage 2b, and the table's read without its output register into the multiplier was the critical path
//! again (4.46 ns of logic, 1.77 ns of routing, 161 MHz). Stage 4 reads the product through slices and one comparison
//! only: with g's rounding add there (23 bits) and n's saturation behind it, the product's route into that add was
//! polar_pipeline's critical path on both parts (ECP5 3.56 ns logic + 3.99 ns routing, 132 MHz; UP5K 4.6 + 9.3 ns, 72
//! MHz). The add is 8 bits in stage 5, in front of the table's address; n's saturation waits for stage 5b (in stage 5,
//! behind the carry, it was the UP5K's critical path: 57.8 MHz), and m's for stage 5: in stage 4, yosys put the
//! comparison on the flip-flops' set and reset pins, the UP5K's critical path (5.9 ns of logic, 7.1 ns of routing, 77.0
//! MHz); stage 4 registers the comparison, stage 5 picks. Stage 3b copies the product: with stage 4 reading the
//! SB_MAC16's output, the UP5K's critical path was that route into n's saturation (4.6 ns of logic, 9.3 ns of routing,
//! 72.1 MHz).
//!
//! `Power<LF, EB>`: L with LF fraction bits and an exp table of 2^EB entries (`vectors::power::exact_with`); the
//! unit and the polar pipeline have the defaults, LF = 12 and EB = 8, the other sizes are the width sweep's. The
//! registers keep the default's widths, which hold every smaller setting.

use crate::prim::delay::Delay;
use crate::prim::q::U8;
use crate::tables::{ExpTable, LogTable};
use rust_hdl::prelude::*;

pub const LATENCY: usize = 12;

crate::stream_block! {
    pub struct Power<const LF: usize = 12, const EB: usize = 8>: unit("power", LATENCY) {
        in {
            x: U8,
            pw: U8,
        }
        out {
            y: U8,
        }
        log: LogTable<LF>,
        exp: ExpTable<EB>,
        r_at: Constant<Bits<5>>, // k − 1, k = 2 + LF − EB the fraction bits g drops from e: the rounding bit
        f_at: Constant<Bits<5>>, // k: g = (e >> k) + e_(k−1), and f its EB low bits
        n_at: Constant<Bits<5>>, // k + EB = 2 + LF: n is g's bits above
        s1_x: DFF<U8>,
        s1_pw: DFF<U8>,
        // stage 2: L(x), Uq3.12
        s2_l: DFF<Bits<15>>,
        s2_pw: DFF<U8>,
        // stage 2b: L again (a DP16KD's output register on the ECP5)
        s2b_l: DFF<Bits<15>>,
        s2b_pw: DFF<U8>,
        // stage 2c: the multiplier's operands, registered alone (`mop_`: see `rtl/README.md`)
        mop_l: DFF<Bits<16>>,
        mop_pw: DFF<Bits<16>>,
        // stage 3: e = pw·L, Uq9.14 (U23)
        s3_e: DFF<Bits<23>>,
        // stage 3b: e again, in two registers (bits 0..11, 12..22): yosys 0.23's iCE40 DSP pass crashes on a whole
        // second register behind a product's first (see `dot3`)
        s3b_lo: DFF<Bits<12>>,
        s3b_hi: DFF<Bits<11>>,
        // stage 4: e >> k's low EB bits (U(EB)), the rounding bit e_(k−1), e >> (k + EB)'s low 4 bits and whether
        // it is above 9
        s4_f: DFF<Bits<EB>>,
        s4_r: DFF<Bit>,
        s4_m: DFF<Bits<4>>,
        s4_big: DFF<Bit>,
        // stage 5: E(f) (U15), m = min(e >> (k + EB), 9) (U4) and the carry out of f's sum
        s5_e: DFF<Bits<15>>,
        s5_m: DFF<Bits<4>>,
        s5_c: DFF<Bit>,
        // stage 5b: E again (a DP16KD's output register on the ECP5) and the shift n + 6
        s5b_e: DFF<Bits<15>>,
        s5b_sh: DFF<Bits<4>>,
        // stage 6: E >> ((n + 6) & 12) (U15), and the rest of the shift, (n + 6) & 3
        s6_t: DFF<Bits<15>>,
        s6_lo: DFF<Bits<4>>,
        // stage 6c: E >> (n + 6) ≤ 510 (U9)
        s6_w: DFF<Bits<9>>,
        // stage 7
        s7_y: DFF<U8>,
        // x = 0 and pw = 0, beside the stages
        zero_dly: Delay<Bit, 10>,
        pw0_dly: Delay<Bit, 10>,
        valid: Delay<Bit, LATENCY>,
        w_l: Signal<Local, Bits<16>>,
        w_p: Signal<Local, Bits<16>>,
        w_e: Signal<Local, Bits<32>>,
        w_e3: Signal<Local, Bits<23>>, // the copy's halves side by side: e (U23)
        w_n: Signal<Local, Bits<9>>,  // e >> (k + EB) ≤ 509 (U9)
        w_f: Signal<Local, Bits<EB>>, // f = ((e >> k) + e_(k−1)) mod 2^EB, wrapping on purpose
        w_m: Signal<Local, Bits<4>>,  // m + carry ≤ 10 (U4)
        w_w: Signal<Local, Bits<15>>,
        w_w1: Signal<Local, Bits<9>>,
        w_y: Signal<Local, Bits<9>>,
    }
}

impl<const LF: usize, const EB: usize> Default for Power<LF, EB> {
    fn default() -> Self {
        assert!(
            LF <= 12 && EB < 2 + LF && EB <= 12,
            "Power<{LF}, {EB}>: L fits U15 for LF ≤ 12; g drops 2 + LF − EB ≥ 1 bits"
        );
        let k = 2 + LF - EB;
        Self {
            clock: Default::default(),
            valid_in: Default::default(),
            x: Default::default(),
            pw: Default::default(),
            valid_out: Default::default(),
            y: Default::default(),
            log: Default::default(),
            exp: Default::default(),
            r_at: Constant::new(Bits::from((k - 1) as u64)),
            f_at: Constant::new(Bits::from(k as u64)),
            n_at: Constant::new(Bits::from((k + EB) as u64)),
            s1_x: Default::default(),
            s1_pw: Default::default(),
            s2_l: Default::default(),
            s2_pw: Default::default(),
            s2b_l: Default::default(),
            s2b_pw: Default::default(),
            mop_l: Default::default(),
            mop_pw: Default::default(),
            s3_e: Default::default(),
            s3b_lo: Default::default(),
            s3b_hi: Default::default(),
            w_e3: Default::default(),
            s4_f: Default::default(),
            s4_r: Default::default(),
            s4_m: Default::default(),
            s4_big: Default::default(),
            s5_e: Default::default(),
            s5_m: Default::default(),
            s5_c: Default::default(),
            s5b_e: Default::default(),
            s5b_sh: Default::default(),
            s6_t: Default::default(),
            s6_lo: Default::default(),
            s6_w: Default::default(),
            s7_y: Default::default(),
            zero_dly: Default::default(),
            pw0_dly: Default::default(),
            valid: Default::default(),
            w_l: Default::default(),
            w_p: Default::default(),
            w_e: Default::default(),
            w_n: Default::default(),
            w_f: Default::default(),
            w_m: Default::default(),
            w_w: Default::default(),
            w_w1: Default::default(),
            w_y: Default::default(),
        }
    }
}

impl<const LF: usize, const EB: usize> Logic for Power<LF, EB> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s1_x, s1_pw, s2_l, s2_pw, s2b_l, s2b_pw, mop_l, mop_pw, s3_e, s3b_lo, s3b_hi, s4_f, s4_r,
            s4_m, s4_big, s5_e, s5_m, s5_c, s5b_e, s5b_sh, s6_t, s6_lo, s6_w, s7_y
        );
        clock!(self, clock, zero_dly, pw0_dly, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1 (x = 0 and pw = 0 are flagged from the registered inputs, so their delay lines are 10 long)
        self.s1_x.d.next = self.x.val();
        self.s1_pw.d.next = self.pw.val();
        self.zero_dly.d.next = !self.s1_x.q.val().any();
        self.pw0_dly.d.next = !self.s1_pw.q.val().any();
        // stage 2: the log table
        self.log.address.next = self.s1_x.q.val();
        self.s2_l.d.next = self.log.data.val();
        self.s2_pw.d.next = self.s1_pw.q.val();
        // stage 2b
        self.s2b_l.d.next = self.s2_l.q.val();
        self.s2b_pw.d.next = self.s2_pw.q.val();
        // stage 2c: the operands, widened to the multiplier's 16 bits
        self.w_l.next = bit_cast::<16, 15>(self.s2b_l.q.val());
        self.w_p.next = bit_cast::<16, 8>(self.s2b_pw.q.val());
        self.mop_l.d.next = self.w_l.val();
        self.mop_pw.d.next = self.w_p.val();
        // stage 3: pw·L, U8 × U15 → U23
        self.w_e.next = self.mop_l.q.val() * self.mop_pw.q.val();
        self.s3_e.d.next = self.w_e.val().get_bits::<23>(0);
        // stage 3b: the product copied (on the ECP5 s3_e is the MULT18X18D's output register, on the UP5K the
        // SB_MAC16's: the route from the block is a clock of its own)
        self.s3b_lo.d.next = self.s3_e.q.val().get_bits::<12>(0); // bits 0..11, a slice
        self.s3b_hi.d.next = self.s3_e.q.val().get_bits::<11>(12); // bits 12..22, a slice
        self.w_e3.next = (bit_cast::<23, 11>(self.s3b_hi.q.val()) << 12) | bit_cast::<23, 12>(self.s3b_lo.q.val()); // U23

        // stage 4: g = (e + 2^(k−1)) >> k (round half up) = (e >> k) + e_(k−1), taken apart: e >> k's low EB bits,
        // the rounding bit, and e >> (k + EB)'s low bits and whether it is above 9 (e ≤ 255·32,745 = 8,349,975: U23)
        self.s4_f.d.next = self.w_e3.val().get_bits::<EB>(self.f_at.val().index()); // (e >> k) mod 2^EB, the split
        self.s4_r.d.next = self.w_e3.val().get_bit(self.r_at.val().index());
        self.w_n.next = self.w_e3.val().get_bits::<9>(self.n_at.val().index()); // e >> (k + EB) ≤ 509 (U9)
        self.s4_m.d.next = self.w_n.val().get_bits::<4>(0); // the low 4 bits, a slice: read where e >> (k + EB) ≤ 9
        self.s4_big.d.next = self.w_n.val() > 9;
        // stage 5: f = g mod 2^EB into the exp table; the carry out of that sum, and m, beside it
        if self.s4_r.q.val() {
            self.w_f.next = self.s4_f.q.val() + 1; // mod 2^EB, wrapping on purpose: g's low bits
        } else {
            self.w_f.next = self.s4_f.q.val();
        }
        self.exp.address.next = self.w_f.val();
        self.s5_e.d.next = self.exp.data.val();
        self.s5_c.d.next = self.s4_r.q.val() & self.s4_f.q.val().all();
        if self.s4_big.q.val() {
            self.s5_m.d.next = 9.into();
        } else {
            self.s5_m.d.next = self.s4_m.q.val(); // ≤ 9 here: U4, exact
        }
        // stage 5b: n = min(g >> EB, 9) = min(m + carry, 9) (m = 9 stands for every e >> (k + EB) ≥ 9, where n is 9
        // with or without the carry); shift = n + 6 ≤ 15
        self.s5b_e.d.next = self.s5_e.q.val();
        if self.s5_c.q.val() {
            self.w_m.next = self.s5_m.q.val() + 1; // ≤ 10: U4, exact
        } else {
            self.w_m.next = self.s5_m.q.val();
        }
        if self.w_m.val() > 9 {
            self.s5b_sh.d.next = 15.into();
        } else {
            self.s5b_sh.d.next = self.w_m.val() + 6; // ≤ 15: U4, exact
        }
        // stages 6, 6c: the shift, E >> (n + 6) = (E >> ((n + 6) & 12)) >> ((n + 6) & 3) (each truncating, so the
        // whole too; the next stage rounds)
        self.s6_t.d.next = self.s5b_e.q.val() >> (self.s5b_sh.q.val() & 12);
        self.s6_lo.d.next = self.s5b_sh.q.val() & 3;
        self.w_w.next = self.s6_t.q.val() >> self.s6_lo.q.val();
        self.s6_w.d.next = self.w_w.val().get_bits::<9>(0);
        // stage 7: ((E >> (n + 6)) + 1) >> 1, the last bit rounded half up
        self.w_w1.next = self.s6_w.q.val() + 1; // ≤ 511: no wrap
        self.w_y.next = self.w_w1.val() >> 1; // ≤ 255 (U8 in 9), floor: with the + 1, round half up
        if self.zero_dly.q.val() {
            if self.pw0_dly.q.val() {
                self.s7_y.d.next = 255.into(); // 0^0 = 1
            } else {
                self.s7_y.d.next = 0.into();
            }
        } else {
            self.s7_y.d.next = self.w_y.val().get_bits::<8>(0); // ≤ 255: U8, exact
        }
        self.y.next = self.s7_y.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
