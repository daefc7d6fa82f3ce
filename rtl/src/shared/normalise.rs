//! `normalise`: three S10 components → a unit vector in Sq1.10 (S12), by a seed table of 1/√m (`Normalise<T>`: 2^T
//! entries of 13 bits, a ROM; the unit `normalise` and every pipeline have T = `TABLE_BITS` = 10, the other sizes
//! are the width sweep's) and no Newton step; see `vectors::normalise` for the exact recipe and the zero
//! vector (zero in, zero out). Latency 11: magnitudes; the squarers' operand register (it feeds nothing else, so it
//! can sit beside the DSP); squares; their sum; the leading-zero pairs; the shifts and
//! the table address; the table (the block RAM's own read register); a register after the block RAM, so that its
//! slow clock-to-output (5.6 ns on an ECP5-6) does not add to the multiplier's delay; the products; the rounding;
//! the signs.

use crate::delay::Delay;
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::ROM;
use crate::q::{Sq1_10, Sq9_0, Uq1_12};

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 11;

pub const TABLE_BITS: u32 = 10;

/// The seed table at `TABLE_BITS`.
pub fn table() -> Vec<u64> {
    table_of(TABLE_BITS)
}

/// A seed table of 2^t entries, entry `idx` = round(2^12/√m) at the midpoint m of its bin; bins below m = 1 are
/// unused (0). The model's `vectors::normalise::table_entry` is the same formula; a test compares the two entry by
/// entry.
pub fn table_of(t: u32) -> Vec<u64> {
    (0..1u64 << t)
        .map(|idx| {
            if idx < 1 << (t - 2) {
                0
            } else {
                let m = (idx as f64 + 0.5) / (1u64 << (t - 2)) as f64;
                (4096.0 / m.sqrt()).round() as u64
            }
        })
        .collect()
}

crate::stream_block! {
    pub struct Normalise<const T: usize = 10>: unit("normalise", LATENCY) {
        in {
            vec_x: Sq9_0,
            vec_y: Sq9_0,
            vec_z: Sq9_0,
        }
        out {
            norm_x: Sq1_10,
            norm_y: Sq1_10,
            norm_z: Sq1_10,
        }
        rsqrt: ROM<Uq1_12, T>,
        addr_at: Constant<Bits<5>>, // 20 − T: the address is the top T bits of s·4^e
        // stage 1: magnitudes ≤ 512 (U10) and signs
        s1_m: [DFF<Bits<10>>; 3],
        s1_neg: [DFF<Bit>; 3],
        s1b_m: [DFF<Bits<10>>; 3], // the squarers' operands again
        s1b_neg: [DFF<Bit>; 3],
        // stage 2: squares ≤ 2^18 (U19)
        s2_sq: [DFF<Bits<19>>; 3],
        s2_m: [DFF<Bits<10>>; 3],
        s2_neg: [DFF<Bit>; 3],
        // stage 3: s = x² + y² + z² < 2^20
        s3_s: DFF<Bits<20>>,
        s3_m: [DFF<Bits<10>>; 3],
        s3_neg: [DFF<Bit>; 3],
        // stage 4: e, the leading zero pairs of s (0..9)
        s4_e: DFF<Bits<4>>,
        s4_s: DFF<Bits<20>>,
        s4_m: [DFF<Bits<10>>; 3],
        s4_neg: [DFF<Bit>; 3],
        // stage 5: table address = top bits of s·4^e; |c|·2^e ≤ √(s·4^e) < 1024 (U10)
        s5_addr: DFF<Bits<T>>,
        s5_c: [DFF<Bits<10>>; 3],
        s5_neg: [DFF<Bit>; 3],
        // stage 6: the table entry
        s6_r: DFF<Uq1_12>,
        s6_c: [DFF<Bits<10>>; 3],
        s6_neg: [DFF<Bit>; 3],
        // stage 6b: the table entry and the shifted components, registered again after the block RAM
        mop_r: [DFF<Uq1_12>; 3], // the table value once per multiplier (`mop_`: see `rtl/README.md`)
        s6b_c: [DFF<Bits<10>>; 3],
        s6b_neg: [DFF<Bit>; 3],
        // stage 7: |c|·2^e·r ≤ 1023·4096 (U23)
        s7_p: [DFF<Bits<23>>; 3],
        s7_neg: [DFF<Bit>; 3],
        // stage 8: round half up on the magnitude, 11 bits dropped (so half away from zero on the value)
        s8_n: [DFF<Bits<12>>; 3],
        s8_neg: [DFF<Bit>; 3],
        // stage 9: the signs back
        s9_out: [DFF<Sq1_10>; 3],
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
        w_m: [Signal<Local, Bits<16>>; 3],
        w_sq: [Signal<Local, Bits<32>>; 3],
        w_part: Signal<Local, Bits<20>>,
        w_e2: Signal<Local, Bits<5>>,
        w_sn: Signal<Local, Bits<20>>,
        w_c: [Signal<Local, Bits<16>>; 3],
        w_r: [Signal<Local, Bits<16>>; 3],
        w_p: [Signal<Local, Bits<32>>; 3],
        w_u: [Signal<Local, Bits<23>>; 3],
    }
}

impl<const T: usize> Default for Normalise<T> {
    fn default() -> Self {
        assert!((4..=14).contains(&T), "Normalise<T>: a table of 2^4 to 2^14 entries (T = {T})");
        let rom: std::collections::BTreeMap<Bits<T>, Uq1_12> =
            table_of(T as u32).into_iter().enumerate().map(|(k, v)| (Bits::<T>::from(k as u64), Uq1_12::from(v))).collect();
        Self {
            clock: Default::default(),
            valid_in: Default::default(),
            vec_x: Default::default(),
            vec_y: Default::default(),
            vec_z: Default::default(),
            valid_out: Default::default(),
            norm_x: Default::default(),
            norm_y: Default::default(),
            norm_z: Default::default(),
            rsqrt: ROM::new(rom),
            addr_at: Constant::new(Bits::from(20 - T as u64)),
            s1_m: Default::default(),
            s1_neg: Default::default(),
            s1b_m: Default::default(),
            s1b_neg: Default::default(),
            s2_sq: Default::default(),
            s2_m: Default::default(),
            s2_neg: Default::default(),
            s3_s: Default::default(),
            s3_m: Default::default(),
            s3_neg: Default::default(),
            s4_e: Default::default(),
            s4_s: Default::default(),
            s4_m: Default::default(),
            s4_neg: Default::default(),
            s5_addr: Default::default(),
            s5_c: Default::default(),
            s5_neg: Default::default(),
            s6_r: Default::default(),
            s6_c: Default::default(),
            s6_neg: Default::default(),
            mop_r: Default::default(),
            s6b_c: Default::default(),
            s6b_neg: Default::default(),
            s7_p: Default::default(),
            s7_neg: Default::default(),
            s8_n: Default::default(),
            s8_neg: Default::default(),
            s9_out: Default::default(),
            valid: Default::default(),
            w_m: Default::default(),
            w_sq: Default::default(),
            w_part: Default::default(),
            w_e2: Default::default(),
            w_sn: Default::default(),
            w_c: Default::default(),
            w_r: Default::default(),
            w_p: Default::default(),
            w_u: Default::default(),
        }
    }
}

impl<const T: usize> Logic for Normalise<T> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s3_s, s4_e, s4_s, s5_addr, s6_r);
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        for i in 0..3 {
            self.s1_m[i].clock.next = self.clock.val();
            self.s1_neg[i].clock.next = self.clock.val();
            self.s1b_m[i].clock.next = self.clock.val();
            self.s1b_neg[i].clock.next = self.clock.val();
            self.s2_sq[i].clock.next = self.clock.val();
            self.s2_m[i].clock.next = self.clock.val();
            self.s2_neg[i].clock.next = self.clock.val();
            self.s3_m[i].clock.next = self.clock.val();
            self.s3_neg[i].clock.next = self.clock.val();
            self.s4_m[i].clock.next = self.clock.val();
            self.s4_neg[i].clock.next = self.clock.val();
            self.s5_c[i].clock.next = self.clock.val();
            self.s5_neg[i].clock.next = self.clock.val();
            self.s6_c[i].clock.next = self.clock.val();
            self.s6_neg[i].clock.next = self.clock.val();
            self.s6b_c[i].clock.next = self.clock.val();
            self.mop_r[i].clock.next = self.clock.val();
            self.s6b_neg[i].clock.next = self.clock.val();
            self.s7_p[i].clock.next = self.clock.val();
            self.s7_neg[i].clock.next = self.clock.val();
            self.s8_n[i].clock.next = self.clock.val();
            self.s8_neg[i].clock.next = self.clock.val();
            self.s9_out[i].clock.next = self.clock.val();
        }
        // ---- component x: magnitude and sign (stage 1), widened for the multipliers
        self.s1_m[0].d.next = self.vec_x.val();
        if self.vec_x.val().get_bit(9) {
            self.s1_m[0].d.next = !self.vec_x.val() + 1;
        }
        self.s1_neg[0].d.next = self.vec_x.val().get_bit(9);
        self.w_m[0].next = bit_cast::<16, 10>(self.s1b_m[0].q.val());
        self.w_c[0].next = bit_cast::<16, 10>(self.s6b_c[0].q.val());
        // ---- component y: magnitude and sign (stage 1), widened for the multipliers
        self.s1_m[1].d.next = self.vec_y.val();
        if self.vec_y.val().get_bit(9) {
            self.s1_m[1].d.next = !self.vec_y.val() + 1;
        }
        self.s1_neg[1].d.next = self.vec_y.val().get_bit(9);
        self.w_m[1].next = bit_cast::<16, 10>(self.s1b_m[1].q.val());
        self.w_c[1].next = bit_cast::<16, 10>(self.s6b_c[1].q.val());
        // ---- component z: magnitude and sign (stage 1), widened for the multipliers
        self.s1_m[2].d.next = self.vec_z.val();
        if self.vec_z.val().get_bit(9) {
            self.s1_m[2].d.next = !self.vec_z.val() + 1;
        }
        self.s1_neg[2].d.next = self.vec_z.val().get_bit(9);
        self.w_m[2].next = bit_cast::<16, 10>(self.s1b_m[2].q.val());
        self.w_c[2].next = bit_cast::<16, 10>(self.s6b_c[2].q.val());
        // stage 6 reads the table at the stage-5 address
        self.rsqrt.address.next = self.s5_addr.q.val();
        self.w_r[0].next = bit_cast::<16, 13>(self.mop_r[0].q.val());
        self.w_r[1].next = bit_cast::<16, 13>(self.mop_r[1].q.val());
        self.w_r[2].next = bit_cast::<16, 13>(self.mop_r[2].q.val());
        for i in 0..3 {
            // stage 1b: carried
            self.s1b_m[i].d.next = self.s1_m[i].q.val();
            self.s1b_neg[i].d.next = self.s1_neg[i].q.val();
            // stage 2
            self.w_sq[i].next = self.w_m[i].val() * self.w_m[i].val();
            self.s2_sq[i].d.next = self.w_sq[i].val().get_bits::<19>(0);
            self.s2_m[i].d.next = self.s1b_m[i].q.val();
            self.s2_neg[i].d.next = self.s1b_neg[i].q.val();
            // stages 3, 4: carried
            self.s3_m[i].d.next = self.s2_m[i].q.val();
            self.s3_neg[i].d.next = self.s2_neg[i].q.val();
            self.s4_m[i].d.next = self.s3_m[i].q.val();
            self.s4_neg[i].d.next = self.s3_neg[i].q.val();
            // stage 5: |c|·2^e
            self.s5_c[i].d.next = self.s4_m[i].q.val() << self.s4_e.q.val();
            self.s5_neg[i].d.next = self.s4_neg[i].q.val();
            // stage 6: carried
            self.s6_c[i].d.next = self.s5_c[i].q.val();
            self.s6_neg[i].d.next = self.s5_neg[i].q.val();
            // stage 6b: carried
            self.s6b_c[i].d.next = self.s6_c[i].q.val();
            self.mop_r[i].d.next = self.s6_r.q.val();
            self.s6b_neg[i].d.next = self.s6_neg[i].q.val();
            // stage 7: 10 × 13 → 23 bits
            self.w_p[i].next = self.w_c[i].val() * self.w_r[i].val();
            self.s7_p[i].d.next = self.w_p[i].val().get_bits::<23>(0);
            self.s7_neg[i].d.next = self.s6b_neg[i].q.val();
            // stage 8: (p + 2^10) >> 11
            self.w_u[i].next = self.s7_p[i].q.val() + 1024; // < 2^23
            self.s8_n[i].d.next = self.w_u[i].val().get_bits::<12>(11); // U23 >> 11 (floor of the + 2^10: round half up), ≤ 1024: U12
            self.s8_neg[i].d.next = self.s7_neg[i].q.val();
            // stage 9
            if self.s8_neg[i].q.val() {
                self.s9_out[i].d.next = !self.s8_n[i].q.val() + 1;
            } else {
                self.s9_out[i].d.next = self.s8_n[i].q.val();
            }
        }
        // stage 3: the sum of squares
        self.w_part.next = bit_cast::<20, 19>(self.s2_sq[0].q.val()) + bit_cast::<20, 19>(self.s2_sq[1].q.val());
        self.s3_s.d.next = self.w_part.val() + bit_cast::<20, 19>(self.s2_sq[2].q.val());
        // stage 4: the largest e with s·4^e < 2^20 (a zero s gives e = 0, and zero products later)
        if self.s3_s.q.val().get_bits::<2>(18).any() {
            self.s4_e.d.next = 0.into();
        } else if self.s3_s.q.val().get_bits::<2>(16).any() {
            self.s4_e.d.next = 1.into();
        } else if self.s3_s.q.val().get_bits::<2>(14).any() {
            self.s4_e.d.next = 2.into();
        } else if self.s3_s.q.val().get_bits::<2>(12).any() {
            self.s4_e.d.next = 3.into();
        } else if self.s3_s.q.val().get_bits::<2>(10).any() {
            self.s4_e.d.next = 4.into();
        } else if self.s3_s.q.val().get_bits::<2>(8).any() {
            self.s4_e.d.next = 5.into();
        } else if self.s3_s.q.val().get_bits::<2>(6).any() {
            self.s4_e.d.next = 6.into();
        } else if self.s3_s.q.val().get_bits::<2>(4).any() {
            self.s4_e.d.next = 7.into();
        } else if self.s3_s.q.val().get_bits::<2>(2).any() {
            self.s4_e.d.next = 8.into();
        } else if self.s3_s.q.val().get_bits::<2>(0).any() {
            self.s4_e.d.next = 9.into();
        } else {
            self.s4_e.d.next = 0.into();
        }
        self.s4_s.d.next = self.s3_s.q.val();
        // stage 5: the table address, the top T bits of s·4^e (floor)
        self.w_e2.next = bit_cast::<5, 4>(self.s4_e.q.val()) << 1;
        self.w_sn.next = self.s4_s.q.val() << self.w_e2.val();
        self.s5_addr.d.next = self.w_sn.val().get_bits::<T>(self.addr_at.val().index());
        // stage 6
        self.s6_r.d.next = self.rsqrt.data.val();
        self.norm_x.next = self.s9_out[0].q.val();
        self.norm_y.next = self.s9_out[1].q.val();
        self.norm_z.next = self.s9_out[2].q.val();
        self.valid_out.next = self.valid.q.val();
    }
}

