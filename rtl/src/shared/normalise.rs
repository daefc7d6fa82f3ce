//! `normalise`: three S10 components → a unit vector in Sq1.10 (S12), by a seed table of 1/√m (`Normalise<T, N>`:
//! 2^T entries of 13 bits, a ROM, then N Newton steps; the unit `normalise` and every pipeline have T =
//! `TABLE_BITS` = 10 and N = 0, the other settings are the width sweep's); see `vectors::normalise` for the exact
//! recipe and the zero vector (zero in, zero out). Each Newton step (`NewtonStep`) sits between the table and the
//! products and adds `NEWTON_LATENCY` clocks. Latency 14 without one: magnitudes; the squarers' operand register (it
//! feeds nothing else, so it can sit beside the DSP); squares; the squares again (on the ECP5 the first is the
//! MULT18X18D's output register, and its route to the sum's carry chain was `cart_pipeline`'s critical path: the
//! copy takes the route alone); their sum; the leading-zero pairs; the shifts and the table address; the table (the
//! block RAM's own read register); the entry registered once after the block RAM (on the ECP5 the DP16KD's output
//! register, where the register pass puts a flip-flop that is a read port's only load: the block's 5.6 ns
//! clock-to-output on an ECP5-6 becomes 0.97 ns); the entry once per multiplier (`mop_r`, each its multiplier's
//! input register); the products; the products again (the same reason, before the rounding's carry chain); the
//! rounding; the signs.

use crate::prim::delay::Delay;
use crate::prim::q::{Sq1_10, Sq9_0, Uq1_12};
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::ROM;

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 14;

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
    pub struct Normalise<const T: usize = 10, const N: usize = 0>: unit("normalise", LATENCY + N * NEWTON_LATENCY) {
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
        // stage 2b: the squares again, each in two registers (bits 0..9, 10..18: see `dot3` for why two)
        s2b_lo: [DFF<Bits<10>>; 3],
        s2b_hi: [DFF<Bits<9>>; 3],
        s2b_m: [DFF<Bits<10>>; 3],
        s2b_neg: [DFF<Bit>; 3],
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
        // stage 6c: the table entry registered after the block RAM, once (the read port's only load)
        s6c_r: DFF<Uq1_12>,
        s6c_c: [DFF<Bits<10>>; 3],
        s6c_neg: [DFF<Bit>; 3],
        // stage 6b: the table entry once per multiplier (`mop_`: see `rtl/README.md`), the components carried
        mop_r: [DFF<Uq1_12>; 3],
        s6b_c: [DFF<Bits<10>>; 3],
        s6b_neg: [DFF<Bit>; 3],
        // stage 7: |c|·2^e·r ≤ 1023·4096 (U23)
        s7_p: [DFF<Bits<23>>; 3],
        s7_neg: [DFF<Bit>; 3],
        // stage 7b: the products again, each in two registers (bits 0..11, 12..22)
        s7b_lo: [DFF<Bits<12>>; 3],
        s7b_hi: [DFF<Bits<11>>; 3],
        s7b_neg: [DFF<Bit>; 3],
        // stage 8: round half up on the magnitude, 11 bits dropped (so half away from zero on the value)
        s8_n: [DFF<Bits<12>>; 3],
        s8_neg: [DFF<Bit>; 3],
        // stage 9: the signs back
        s9_out: [DFF<Sq1_10>; 3],
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
        // the Newton steps, m beside the table address and the table entry for the first, the valid flag beside them
        newton: [NewtonStep; N],
        nw_s5_m: [DFF<Bits<12>>; N],
        nw_s6_m: [DFF<Bits<12>>; N],
        nw_s6c_m: [DFF<Bits<12>>; N],
        nw_valid: [Delay<Bit, NEWTON_LATENCY>; N],
        w_m: [Signal<Local, Bits<16>>; 3],
        w_sq: [Signal<Local, Bits<32>>; 3],
        w_sq2: [Signal<Local, Bits<20>>; 3], // a square out of its two stage-2b registers
        w_part: Signal<Local, Bits<20>>,
        w_e2: Signal<Local, Bits<5>>,
        w_sn: Signal<Local, Bits<20>>,
        w_c: [Signal<Local, Bits<16>>; 3],
        w_r: [Signal<Local, Bits<16>>; 3],
        w_p: [Signal<Local, Bits<32>>; 3],
        w_p7: [Signal<Local, Bits<23>>; 3], // a product out of its two stage-7b registers
        w_u: [Signal<Local, Bits<23>>; 3],
    }
}

impl<const T: usize, const N: usize> Default for Normalise<T, N> {
    fn default() -> Self {
        assert!((4..=14).contains(&T), "Normalise<T, N>: a table of 2^4 to 2^14 entries (T = {T})");
        assert!(N <= 2, "Normalise<T, N>: at most 2 Newton steps (N = {N}); a third cannot improve a Uq1.12 seed");
        let rom: std::collections::BTreeMap<Bits<T>, Uq1_12> = table_of(T as u32)
            .into_iter()
            .enumerate()
            .map(|(k, v)| (Bits::<T>::from(k as u64), Uq1_12::from(v)))
            .collect();
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
            s2b_lo: Default::default(),
            s2b_hi: Default::default(),
            s2b_m: Default::default(),
            s2b_neg: Default::default(),
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
            s6c_r: Default::default(),
            s6c_c: Default::default(),
            s6c_neg: Default::default(),
            mop_r: Default::default(),
            s6b_c: Default::default(),
            s6b_neg: Default::default(),
            s7_p: Default::default(),
            s7_neg: Default::default(),
            s7b_lo: Default::default(),
            s7b_hi: Default::default(),
            s7b_neg: Default::default(),
            s8_n: Default::default(),
            s8_neg: Default::default(),
            s9_out: Default::default(),
            valid: Default::default(),
            newton: std::array::from_fn(|_| NewtonStep::default()),
            nw_s5_m: std::array::from_fn(|_| DFF::default()),
            nw_s6_m: std::array::from_fn(|_| DFF::default()),
            nw_s6c_m: std::array::from_fn(|_| DFF::default()),
            nw_valid: std::array::from_fn(|_| Delay::default()),
            w_m: Default::default(),
            w_sq: Default::default(),
            w_sq2: Default::default(),
            w_part: Default::default(),
            w_e2: Default::default(),
            w_sn: Default::default(),
            w_c: Default::default(),
            w_r: Default::default(),
            w_p: Default::default(),
            w_p7: Default::default(),
            w_u: Default::default(),
        }
    }
}

impl<const T: usize, const N: usize> Logic for Normalise<T, N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s3_s, s4_e, s4_s, s5_addr, s6_r, s6c_r);
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
            self.s2b_lo[i].clock.next = self.clock.val();
            self.s2b_hi[i].clock.next = self.clock.val();
            self.s2b_m[i].clock.next = self.clock.val();
            self.s2b_neg[i].clock.next = self.clock.val();
            self.s3_m[i].clock.next = self.clock.val();
            self.s3_neg[i].clock.next = self.clock.val();
            self.s4_m[i].clock.next = self.clock.val();
            self.s4_neg[i].clock.next = self.clock.val();
            self.s5_c[i].clock.next = self.clock.val();
            self.s5_neg[i].clock.next = self.clock.val();
            self.s6_c[i].clock.next = self.clock.val();
            self.s6_neg[i].clock.next = self.clock.val();
            self.s6c_c[i].clock.next = self.clock.val();
            self.s6c_neg[i].clock.next = self.clock.val();
            self.s6b_c[i].clock.next = self.clock.val();
            self.mop_r[i].clock.next = self.clock.val();
            self.s6b_neg[i].clock.next = self.clock.val();
            self.s7_p[i].clock.next = self.clock.val();
            self.s7_neg[i].clock.next = self.clock.val();
            self.s7b_lo[i].clock.next = self.clock.val();
            self.s7b_hi[i].clock.next = self.clock.val();
            self.s7b_neg[i].clock.next = self.clock.val();
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
        self.w_sq2[0].next =
            (bit_cast::<20, 9>(self.s2b_hi[0].q.val()) << 10) | bit_cast::<20, 10>(self.s2b_lo[0].q.val());
        self.w_sq2[1].next =
            (bit_cast::<20, 9>(self.s2b_hi[1].q.val()) << 10) | bit_cast::<20, 10>(self.s2b_lo[1].q.val());
        self.w_sq2[2].next =
            (bit_cast::<20, 9>(self.s2b_hi[2].q.val()) << 10) | bit_cast::<20, 10>(self.s2b_lo[2].q.val());
        self.w_p7[0].next =
            (bit_cast::<23, 11>(self.s7b_hi[0].q.val()) << 12) | bit_cast::<23, 12>(self.s7b_lo[0].q.val());
        self.w_p7[1].next =
            (bit_cast::<23, 11>(self.s7b_hi[1].q.val()) << 12) | bit_cast::<23, 12>(self.s7b_lo[1].q.val());
        self.w_p7[2].next =
            (bit_cast::<23, 11>(self.s7b_hi[2].q.val()) << 12) | bit_cast::<23, 12>(self.s7b_lo[2].q.val());
        for i in 0..3 {
            // stage 1b: carried
            self.s1b_m[i].d.next = self.s1_m[i].q.val();
            self.s1b_neg[i].d.next = self.s1_neg[i].q.val();
            // stage 2
            self.w_sq[i].next = self.w_m[i].val() * self.w_m[i].val();
            self.s2_sq[i].d.next = self.w_sq[i].val().get_bits::<19>(0);
            self.s2_m[i].d.next = self.s1b_m[i].q.val();
            self.s2_neg[i].d.next = self.s1b_neg[i].q.val();
            // stage 2b: carried
            self.s2b_lo[i].d.next = self.s2_sq[i].q.val().get_bits::<10>(0);
            self.s2b_hi[i].d.next = self.s2_sq[i].q.val().get_bits::<9>(10);
            self.s2b_m[i].d.next = self.s2_m[i].q.val();
            self.s2b_neg[i].d.next = self.s2_neg[i].q.val();
            // stages 3, 4: carried
            self.s3_m[i].d.next = self.s2b_m[i].q.val();
            self.s3_neg[i].d.next = self.s2b_neg[i].q.val();
            self.s4_m[i].d.next = self.s3_m[i].q.val();
            self.s4_neg[i].d.next = self.s3_neg[i].q.val();
            // stage 5: |c|·2^e
            self.s5_c[i].d.next = self.s4_m[i].q.val() << self.s4_e.q.val();
            self.s5_neg[i].d.next = self.s4_neg[i].q.val();
            // stage 6: carried
            self.s6_c[i].d.next = self.s5_c[i].q.val();
            self.s6_neg[i].d.next = self.s5_neg[i].q.val();
            // stages 6c, 6b: carried
            self.s6c_c[i].d.next = self.s6_c[i].q.val();
            self.s6c_neg[i].d.next = self.s6_neg[i].q.val();
            self.s6b_c[i].d.next = self.s6c_c[i].q.val();
            self.mop_r[i].d.next = self.s6c_r.q.val();
            self.s6b_neg[i].d.next = self.s6c_neg[i].q.val();
            // stage 7: 10 × 13 → 23 bits
            self.w_p[i].next = self.w_c[i].val() * self.w_r[i].val();
            self.s7_p[i].d.next = self.w_p[i].val().get_bits::<23>(0);
            self.s7_neg[i].d.next = self.s6b_neg[i].q.val();
            // stage 7b: carried
            self.s7b_lo[i].d.next = self.s7_p[i].q.val().get_bits::<12>(0);
            self.s7b_hi[i].d.next = self.s7_p[i].q.val().get_bits::<11>(12);
            self.s7b_neg[i].d.next = self.s7_neg[i].q.val();
            // stage 8: (p + 2^10) >> 11
            self.w_u[i].next = self.w_p7[i].val() + 1024; // < 2^23
            self.s8_n[i].d.next = self.w_u[i].val().get_bits::<12>(11); // U23 >> 11 (floor of the + 2^10: round half up), ≤ 1024: U12
            self.s8_neg[i].d.next = self.s7b_neg[i].q.val();
            // stage 9
            if self.s8_neg[i].q.val() {
                self.s9_out[i].d.next = !self.s8_n[i].q.val() + 1;
            } else {
                self.s9_out[i].d.next = self.s8_n[i].q.val();
            }
        }
        // stage 3: the sum of squares
        self.w_part.next = self.w_sq2[0].val() + self.w_sq2[1].val();
        self.s3_s.d.next = self.w_part.val() + self.w_sq2[2].val();
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
        // stage 6c
        self.s6c_r.d.next = self.s6_r.q.val();
        self.norm_x.next = self.s9_out[0].q.val();
        self.norm_y.next = self.s9_out[1].q.val();
        self.norm_z.next = self.s9_out[2].q.val();
        self.valid_out.next = self.valid.q.val();
        // The Newton steps (none when N = 0: these loops are empty, and so is the Verilog they export). Each takes
        // the table entry, m = s·4^e/2^8 (Uq2.10, floor) and the waiting components from the stage or step before;
        // the last step's outputs replace stage 6c's at stage 6b (the last assignment wins, in rust-hdl and Verilog).
        for k in 0..N {
            self.newton[k].clock.next = self.clock.val();
            self.nw_s5_m[k].clock.next = self.clock.val();
            self.nw_s6_m[k].clock.next = self.clock.val();
            self.nw_s6c_m[k].clock.next = self.clock.val();
            self.nw_valid[k].clock.next = self.clock.val();
            self.nw_s5_m[k].d.next = self.w_sn.val().get_bits::<12>(8); // U20 → Uq2.10 (floor)
            self.nw_s6_m[k].d.next = self.nw_s5_m[k].q.val();
            self.nw_s6c_m[k].d.next = self.nw_s6_m[k].q.val();
            self.newton[k].r.next = self.s6c_r.q.val();
            self.newton[k].m.next = self.nw_s6c_m[k].q.val();
            self.newton[k].c_x.next = self.s6c_c[0].q.val();
            self.newton[k].c_y.next = self.s6c_c[1].q.val();
            self.newton[k].c_z.next = self.s6c_c[2].q.val();
            self.newton[k].neg_x.next = self.s6c_neg[0].q.val();
            self.newton[k].neg_y.next = self.s6c_neg[1].q.val();
            self.newton[k].neg_z.next = self.s6c_neg[2].q.val();
            self.nw_valid[k].d.next = self.valid.q.val();
        }
        for k in 1..N {
            self.newton[k].r.next = self.newton[k - 1].r_out.val();
            self.newton[k].m.next = self.newton[k - 1].m_out.val();
            self.newton[k].c_x.next = self.newton[k - 1].c_x_out.val();
            self.newton[k].c_y.next = self.newton[k - 1].c_y_out.val();
            self.newton[k].c_z.next = self.newton[k - 1].c_z_out.val();
            self.newton[k].neg_x.next = self.newton[k - 1].neg_x_out.val();
            self.newton[k].neg_y.next = self.newton[k - 1].neg_y_out.val();
            self.newton[k].neg_z.next = self.newton[k - 1].neg_z_out.val();
            self.nw_valid[k].d.next = self.nw_valid[k - 1].q.val();
        }
        for k in 0..N {
            self.mop_r[0].d.next = self.newton[k].r_out.val();
            self.mop_r[1].d.next = self.newton[k].r_out.val();
            self.mop_r[2].d.next = self.newton[k].r_out.val();
            self.s6b_c[0].d.next = self.newton[k].c_x_out.val();
            self.s6b_c[1].d.next = self.newton[k].c_y_out.val();
            self.s6b_c[2].d.next = self.newton[k].c_z_out.val();
            self.s6b_neg[0].d.next = self.newton[k].neg_x_out.val();
            self.s6b_neg[1].d.next = self.newton[k].neg_y_out.val();
            self.s6b_neg[2].d.next = self.newton[k].neg_z_out.val();
            self.valid_out.next = self.nw_valid[k].q.val();
        }
    }
}

/// Clock edges through one `NewtonStep`.
pub const NEWTON_LATENCY: usize = 5;

crate::block! {
    /// `NewtonStep`: one Newton step on the seed, `r ← r·(3 − m·r²)/2` (`vectors::normalise::newton_step`: three
    /// 16 × 16 products, each truncated (floor) to the next one's operand), with m, the shifted components and their
    /// signs waiting beside it. Five stages: the squarer's operands; q = r² (Uq2.14); t = m·q (Uq2.14); the last
    /// product's operands, d = 3 − t and r; r' = r·d/2 (Uq1.12).
    pub struct NewtonStep {
        pub clock: Signal<In, Clock>,
        /// The seed, Uq1.12 (U13).
        pub r: Signal<In, Uq1_12>,
        /// The mantissa s·4^e / 2^8, Uq2.10 ∈ [1, 4) (U12).
        pub m: Signal<In, Bits<12>>,
        /// |c|·2^e (U10) and the signs, waiting.
        pub c_x: Signal<In, Bits<10>>,
        pub c_y: Signal<In, Bits<10>>,
        pub c_z: Signal<In, Bits<10>>,
        pub neg_x: Signal<In, Bit>,
        pub neg_y: Signal<In, Bit>,
        pub neg_z: Signal<In, Bit>,
        /// The refined r, m, the components and signs, NEWTON_LATENCY clocks later.
        pub r_out: Signal<Out, Uq1_12>,
        pub m_out: Signal<Out, Bits<12>>,
        pub c_x_out: Signal<Out, Bits<10>>,
        pub c_y_out: Signal<Out, Bits<10>>,
        pub c_z_out: Signal<Out, Bits<10>>,
        pub neg_x_out: Signal<Out, Bit>,
        pub neg_y_out: Signal<Out, Bit>,
        pub neg_z_out: Signal<Out, Bit>,
        three: Constant<Bits<16>>, // 3 in Uq2.14
        // (rust-hdl's Verilog export cannot reach into a port array of a sub-block: one port per component)
        c_wait: [Delay<Bits<10>, NEWTON_LATENCY>; 3],
        neg_wait: [Delay<Bit, NEWTON_LATENCY>; 3],
        m_wait: Delay<Bits<12>, NEWTON_LATENCY>,
        // stage 1: the squarer's operands (`mop_`: they feed the DSP alone), m and r carried
        mop_ra: DFF<Bits<16>>,
        mop_rb: DFF<Bits<16>>,
        s1_m: DFF<Bits<16>>,
        s1_r: DFF<Uq1_12>,
        // stage 2: q = r²/2^10 ≤ 2^14 (Uq2.14, U15); m as the next product's operand
        s2_q: DFF<Bits<15>>,
        mop_m: DFF<Bits<16>>,
        s2_r: DFF<Uq1_12>,
        // stage 3: t = m·q/2^10 < 2^16 (Uq2.14)
        s3_t: DFF<Bits<16>>,
        s3_r: DFF<Uq1_12>,
        // stage 4: the last product's operands, d = 3 − t ≥ 0 (Uq2.14) and r
        mop_d: DFF<Bits<16>>,
        mop_r: DFF<Bits<16>>,
        // stage 5: r·d/2^15 ≤ 4096·3·2^14/2^15 < 2^13 (Uq1.12)
        s5_r: DFF<Uq1_12>,
        w_q: Signal<Local, Bits<32>>,
        w_t: Signal<Local, Bits<32>>,
        w_p: Signal<Local, Bits<32>>,
    }
}

impl Default for NewtonStep {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            r: Default::default(),
            m: Default::default(),
            c_x: Default::default(),
            c_y: Default::default(),
            c_z: Default::default(),
            neg_x: Default::default(),
            neg_y: Default::default(),
            neg_z: Default::default(),
            r_out: Default::default(),
            m_out: Default::default(),
            c_x_out: Default::default(),
            c_y_out: Default::default(),
            c_z_out: Default::default(),
            neg_x_out: Default::default(),
            neg_y_out: Default::default(),
            neg_z_out: Default::default(),
            three: Constant::new(Bits::from(NEWTON_THREE)),
            c_wait: Default::default(),
            neg_wait: Default::default(),
            m_wait: Default::default(),
            mop_ra: Default::default(),
            mop_rb: Default::default(),
            s1_m: Default::default(),
            s1_r: Default::default(),
            s2_q: Default::default(),
            mop_m: Default::default(),
            s2_r: Default::default(),
            s3_t: Default::default(),
            s3_r: Default::default(),
            mop_d: Default::default(),
            mop_r: Default::default(),
            s5_r: Default::default(),
            w_q: Default::default(),
            w_t: Default::default(),
            w_p: Default::default(),
        }
    }
}

/// 3 in Uq2.14 (`vectors::normalise::NEWTON_THREE`, compared in a test).
pub const NEWTON_THREE: u64 = 3 << 14;

impl Logic for NewtonStep {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, m_wait, mop_ra, mop_rb, s1_m, s1_r, s2_q, mop_m, s2_r, s3_t, s3_r, mop_d, mop_r, s5_r);
        for i in 0..3 {
            self.c_wait[i].clock.next = self.clock.val();
            self.neg_wait[i].clock.next = self.clock.val();
        }
        // the components and signs wait
        self.c_wait[0].d.next = self.c_x.val();
        self.c_wait[1].d.next = self.c_y.val();
        self.c_wait[2].d.next = self.c_z.val();
        self.neg_wait[0].d.next = self.neg_x.val();
        self.neg_wait[1].d.next = self.neg_y.val();
        self.neg_wait[2].d.next = self.neg_z.val();
        self.c_x_out.next = self.c_wait[0].q.val();
        self.c_y_out.next = self.c_wait[1].q.val();
        self.c_z_out.next = self.c_wait[2].q.val();
        self.neg_x_out.next = self.neg_wait[0].q.val();
        self.neg_y_out.next = self.neg_wait[1].q.val();
        self.neg_z_out.next = self.neg_wait[2].q.val();
        self.m_wait.d.next = self.m.val();
        self.m_out.next = self.m_wait.q.val();
        // stage 1: U13 → U16 operands, exact
        self.mop_ra.d.next = bit_cast::<16, 13>(self.r.val());
        self.mop_rb.d.next = bit_cast::<16, 13>(self.r.val());
        self.s1_m.d.next = bit_cast::<16, 12>(self.m.val());
        self.s1_r.d.next = self.r.val();
        // stage 2: Uq1.12² = Uq2.24 → Uq2.14 (floor), ≤ 2^14
        self.w_q.next = self.mop_ra.q.val() * self.mop_rb.q.val();
        self.s2_q.d.next = self.w_q.val().get_bits::<15>(10);
        self.mop_m.d.next = self.s1_m.q.val();
        self.s2_r.d.next = self.s1_r.q.val();
        // stage 3: Uq2.10 × Uq2.14 = Uq4.24 → Uq2.14 (floor), < 2^16
        self.w_t.next = self.mop_m.q.val() * bit_cast::<16, 15>(self.s2_q.q.val());
        self.s3_t.d.next = self.w_t.val().get_bits::<16>(10);
        self.s3_r.d.next = self.s2_r.q.val();
        // stage 4: 3 − m·r² (Uq2.14; m·r² ≤ 3 for every seed: `vectors::normalise` tests every mantissa), r widened
        self.mop_d.d.next = self.three.val() - self.s3_t.q.val();
        self.mop_r.d.next = bit_cast::<16, 13>(self.s3_r.q.val());
        // stage 5: Uq1.12 × Uq2.14 = Uq3.26 → Uq1.12 (floor, the halving included), < 2^13
        self.w_p.next = self.mop_r.q.val() * self.mop_d.q.val();
        self.s5_r.d.next = self.w_p.val().get_bits::<13>(15);
        self.r_out.next = self.s5_r.q.val();
    }
}
