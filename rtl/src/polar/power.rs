//! `power`: the power unit [30] of US 6,819,319's FIG. 3, `y = 255·(x/255)^p` with p = pw/4 (U6.2), by a log table,
//! one multiplier and an exp table; see `vectors::power` for the recipe and why. Latency 10:
//! 1 inputs registered; 2 L(x) (table); 2b L again; 3 e = pw·L; 4 g = round(e >> 6), n = min(g >> 8, 9),
//! f = g mod 256; 5 E(f) (table); 5b E again; 6 and 6c the barrel shift w = E >> (n + 6) in two steps, by the
//! shift's multiple of 4, then by the rest (a floor twice is the floor of the whole shift); 7 y = (w + 1) >> 1, which
//! makes (E + 2^(n+6)) >> (n + 7), and x = 0 overrides. (With the shift and the rounding in one stage, the UP5K
//! placed the unit at 43.7 MHz; with the shift in one stage, polar_pipeline's critical path on the UP5K was the
//! shift, 14 ns.) Stages 2b and 5b compute nothing: on the ECP5 each is a table's DP16KD output register, so
//! neither the product nor the shift waits on a block RAM read (5.6 ns from the clock without it, 0.97 with it;
//! polar_pipeline's critical path, 9.1 ns, was that read into the multiplier).
//!
//! `Power<LF, EB>`: L with LF fraction bits and an exp table of 2^EB entries (`vectors::power::exact_with`); the
//! unit and the polar pipeline have the defaults, LF = 12 and EB = 8, the other sizes are the width sweep's. The
//! registers keep the default's widths, which hold every smaller setting.

use crate::prim::delay::Delay;
use crate::prim::q::U8;
use crate::tables::{ExpTable, LogTable};
use rust_hdl::prelude::*;

pub const LATENCY: usize = 10;

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
        half: Constant<Bits<8>>, // 2^(k − 1) ≤ 2^7, k = 2 + LF − EB the fraction bits g drops from e
        f_at: Constant<Bits<5>>, // k: f is g's EB bits from bit k of e + half
        n_at: Constant<Bits<5>>, // k + EB = 2 + LF: n is the bits above
        s1_x: DFF<U8>,
        s1_pw: DFF<U8>,
        // stage 2: L(x), Uq3.12
        s2_l: DFF<Bits<15>>,
        s2_pw: DFF<U8>,
        // stage 2b: L again (a DP16KD's output register on the ECP5)
        s2b_l: DFF<Bits<15>>,
        s2b_pw: DFF<U8>,
        // stage 3: e = pw·L, Uq9.14 (U23)
        s3_e: DFF<Bits<23>>,
        // stage 4: n (0..9) and f (U(EB))
        s4_n: DFF<Bits<4>>,
        s4_f: DFF<Bits<EB>>,
        // stage 5: E(f) (U15) and the shift n + 6
        s5_e: DFF<Bits<15>>,
        s5_sh: DFF<Bits<4>>,
        // stage 5b: E again (a DP16KD's output register on the ECP5)
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
        zero_dly: Delay<Bit, 8>,
        pw0_dly: Delay<Bit, 8>,
        valid: Delay<Bit, LATENCY>,
        w_l: Signal<Local, Bits<16>>,
        w_p: Signal<Local, Bits<16>>,
        w_e: Signal<Local, Bits<32>>,
        w_g: Signal<Local, Bits<23>>,
        w_n: Signal<Local, Bits<9>>,
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
            half: Constant::new(Bits::from(1u64 << (k - 1))),
            f_at: Constant::new(Bits::from(k as u64)),
            n_at: Constant::new(Bits::from((k + EB) as u64)),
            s1_x: Default::default(),
            s1_pw: Default::default(),
            s2_l: Default::default(),
            s2_pw: Default::default(),
            s2b_l: Default::default(),
            s2b_pw: Default::default(),
            s3_e: Default::default(),
            s4_n: Default::default(),
            s4_f: Default::default(),
            s5_e: Default::default(),
            s5_sh: Default::default(),
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
            w_g: Default::default(),
            w_n: Default::default(),
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
            self, clock, s1_x, s1_pw, s2_l, s2_pw, s2b_l, s2b_pw, s3_e, s4_n, s4_f, s5_e, s5_sh, s5b_e, s5b_sh, s6_t,
            s6_lo, s6_w, s7_y
        );
        clock!(self, clock, zero_dly, pw0_dly, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1 (x = 0 and pw = 0 are flagged from the registered inputs, so their delay lines are 8 long)
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
        // stage 3: pw·L, U8 × U15 → U23
        self.w_l.next = bit_cast::<16, 15>(self.s2b_l.q.val());
        self.w_p.next = bit_cast::<16, 8>(self.s2b_pw.q.val());
        self.w_e.next = self.w_l.val() * self.w_p.val();
        self.s3_e.d.next = self.w_e.val().get_bits::<23>(0);
        // stage 4: g = (e + 2^(k−1)) >> k (round half up; e ≤ 255·32,745 = 8,349,975 and 2^(k−1) ≤ 128: U23), split
        self.w_g.next = self.s3_e.q.val() + bit_cast::<23, 8>(self.half.val()); // U8 widened to U23, exact
        self.s4_f.d.next = self.w_g.val().get_bits::<EB>(self.f_at.val().index()); // g mod 2^EB: U(EB), the split
        self.w_n.next = self.w_g.val().get_bits::<9>(self.n_at.val().index()); // g >> EB ≤ 509 (U9)
        if self.w_n.val() > 9 {
            self.s4_n.d.next = 9.into();
        } else {
            self.s4_n.d.next = self.w_n.val().get_bits::<4>(0); // n ≤ 9: U4, exact
        }
        // stage 5: the exp table; shift = n + 6 ≤ 15
        self.exp.address.next = self.s4_f.q.val();
        self.s5_e.d.next = self.exp.data.val();
        self.s5_sh.d.next = self.s4_n.q.val() + 6;
        // stage 5b
        self.s5b_e.d.next = self.s5_e.q.val();
        self.s5b_sh.d.next = self.s5_sh.q.val();
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
