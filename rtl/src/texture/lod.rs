//! `lod`: the texture unit's level of detail, OpenGL's isotropic rule with a LOD bias: from the four screen
//! derivatives of u and v (Sq8.8, texels of level 0 a pixel), the map's side 2^n and the bias (Sq3.8, levels), the
//! level ⌊λ⌋, frac(λ) in 8 bits and the nearest level ⌊λ + ½⌋, λ = log2 ρ + bias clamped to [0, n]; see
//! `vectors::lod` for the exact recipe. ρ² comes from four squarers, log2 from the leading one of ρ² and a 256-entry
//! table of its next 8 bits. Latency 15: magnitudes; their saturation to U16; the squarers' operand register; the
//! squares; the squares again, in the fabric; the two sums; their comparison; the larger; the leading one within each group of five bits; the first
//! group with one, and the shift by whole groups; the rest of the normalising shift; the table (its read register)
//! beside the exponent plus the bias; the table's output register; λ; the clamps. (With the comparison and the
//! choice in one stage on 33-bit sums, the UP5K placed the unit at 41.5 MHz, that path the critical one; with the
//! negation and the saturation in one stage, 44.6 MHz. With the leading one of all 25 bits found in one stage, the
//! trilinear pipelines' critical path on the ECP5 was that stage: 3.56 ns of logic, 3.58 ns of routing, 140 MHz.)

use crate::prim::delay::Delay;
use crate::prim::q::{Sq3_8, Sq5_10, Sq8_8, Uq0_9, U16, U8};
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::ROM;

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 15;

/// The table: entry f = round(log2(1 + (f + ½)/256)·2^9), the log of the midpoint of the mantissa's bin. The
/// model's `vectors::lod::table_entry` is the same formula written apart; a test compares the two entry by entry.
pub fn table() -> Vec<u64> {
    (0..256u64).map(|f| ((1.0 + (f as f64 + 0.5) / 256.0).log2() * 512.0).round() as u64).collect()
}

crate::block! {
    /// The log table as a block of its own (a ROM, the block RAM's read register after it in the unit).
    pub struct LogMantissa {
        pub address: Signal<In, U8>,
        pub data: Signal<Out, Uq0_9>,
        rom: ROM<Uq0_9, 8>,
    }
}

impl Default for LogMantissa {
    fn default() -> Self {
        let rom = ROM::from(table().into_iter().map(Uq0_9::from));
        Self { address: Default::default(), data: Default::default(), rom }
    }
}

impl Logic for LogMantissa {
    #[hdl_gen]
    fn update(&mut self) {
        self.rom.address.next = self.address.val();
        self.data.next = self.rom.data.val();
    }
}

crate::stream_block! {
    #[derive(Default)]
    pub struct Lod: unit("lod", LATENCY) {
        in {
            du_dx: Sq8_8,
            dv_dx: Sq8_8,
            du_dy: Sq8_8,
            dv_dy: Sq8_8,
            log_side: Bits<4>,
            bias: Sq3_8,
        }
        out {
            level: Bits<4>,
            frac: U8,
            nearest: Bits<4>,
        }
        log2: LogMantissa,
        // stage 1: |d| ≤ 2^16 (U17)
        s1_m: [DFF<Bits<17>>; 4],
        // stage 1s: |d| saturated to U16 (Uq8.8)
        s1_a: [DFF<U16>; 4],
        // stage 1b: the squarers' operands again (they feed nothing else: the placer can put them by the DSPs)
        s1b_a: [DFF<U16>; 4],
        // stage 2: the squares, Uq16.8 (truncated)
        s2_q: [DFF<Bits<24>>; 4],
        // stage 2b: the squares again, the adders' operands. On the ECP5 each square is the MULT18X18D's own output
        // register, and its route to the adder was the colour pipelines' critical path
        // (cart_tex_nearest_mip_hemi_oct_colour at 166.4 MHz: 2.34 ns of logic, 3.68 ns of routing); a fabric
        // register the placer can put by the adder takes that route into a clock of its own
        s2b_q: [DFF<Bits<24>>; 4],
        // stage 3: L_x and L_y, Uq17.8
        s3_lx: DFF<Bits<25>>,
        s3_ly: DFF<Bits<25>>,
        // stage 4: the comparison of L_x and L_y in two halves (the top 13 bits: greater, equal; the low 12:
        // greater), and both. As one 25-bit compare it was cart_tex_trilinear_colour's critical path (164.9 MHz:
        // 2.69 ns of logic, 3.38 ns of routing); stage 4b joins the halves in the select of its choice
        s4_gth: DFF<Bit>,
        s4_eqh: DFF<Bit>,
        s4_gtl: DFF<Bit>,
        s4_lx: DFF<Bits<25>>,
        s4_ly: DFF<Bits<25>>,
        // stage 4b: m = max(L_x, L_y) ≈ ρ²·2^8
        s4b_m: DFF<Bits<25>>,
        // stage 5: m, and for each group of five bits (g = 4: bits 24..20, … g = 0: bits 4..0) whether it holds a one
        // and the leading one's place below the group's top (0..4)
        s5_m: DFF<Bits<25>>,
        s5_any: [DFF<Bit>; 5],
        s5_lp: [DFF<Bits<3>>; 5],
        // stage 5c: m shifted by the first such group's 5·(4 − g) (U25, the bits shifted out are zeros above its
        // leading one), the rest of the shift (0..4), e = p − 8 (−8..16, two's complement: the integer part of 2λ
        // before the bias), and whether m ≠ 0 (λ > −∞)
        s5c_mc: DFF<Bits<25>>,
        s5c_fine: DFF<Bits<3>>,
        s5c_e: DFF<Bits<6>>,
        s5c_big: DFF<Bit>,
        // stage 6: the table's address (the 8 bits below the leading one), e and e + 1
        s6_addr: DFF<U8>,
        s6_e: DFF<Bits<6>>,
        s6_e1: DFF<Bits<6>>,
        s6_big: DFF<Bit>,
        // stage 7: the table entry (log2 of the mantissa, Uq0.9), (e << 9) + (bias << 2) (Sq5.10), and the same
        // plus ½ ((e + 1) << 9 + (bias << 2)), so that ⌊λ + ½⌋ needs no adder after λ
        s7_t: DFF<Uq0_9>,
        s7_eb: DFF<Sq5_10>,
        s7_ebh: DFF<Sq5_10>,
        s7_big: DFF<Bit>,
        // the table word registered again (the block RAM's output register on the ECP5: its read alone is 5.6 ns
        // clock-to-out, the critical path of every MIP front without it), the others beside it
        s7r_t: DFF<Uq0_9>,
        s7r_eb: DFF<Sq5_10>,
        s7r_ebh: DFF<Sq5_10>,
        s7r_big: DFF<Bit>,
        // stage 8: λ·2^10 = (e << 9) + T + (bias << 2) and (λ + ½)·2^10 (Sq5.10). (With λ + ½ added after λ in
        // stage 9, its carry chain before the clamp was the critical path of cart_tex_nearest_mip on the ECP5: 2.61 ns
        // of logic, 3.30 ns of routing, 169.1 MHz, the median of 5 placements.)
        s8_l: DFF<Sq5_10>,
        s8_lh: DFF<Sq5_10>,
        s8_big: DFF<Bit>,
        // stage 9: the clamped outputs
        s9_level: DFF<Bits<4>>,
        s9_frac: DFF<U8>,
        s9_near: DFF<Bits<4>>,
        n_dly: Delay<Bits<4>, 14>, // log_side beside the stages up to λ
        b_dly: Delay<Sq3_8, 11>, // the bias beside the stages up to the table's address
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
        w_mag: [Signal<Local, Bits<17>>; 4],
        w_lxh: Signal<Local, Bits<13>>,
        w_lyh: Signal<Local, Bits<13>>,
        w_lxl: Signal<Local, Bits<12>>,
        w_lyl: Signal<Local, Bits<12>>,
        w_gt: Signal<Local, Bit>,
        w_sq: [Signal<Local, Bits<32>>; 4],
        w_grp: [Signal<Local, Bits<5>>; 5],
        w_lp6: Signal<Local, Bits<6>>,
        w_norm: Signal<Local, Bits<25>>,
        w_e16: Signal<Local, Sq5_10>,
        w_es: Signal<Local, Sq5_10>,
        w_e16h: Signal<Local, Sq5_10>,
        w_esh: Signal<Local, Sq5_10>,
        w_b16: Signal<Local, Sq5_10>,
        w_bs: Signal<Local, Sq5_10>,
        w_t16: Signal<Local, Sq5_10>,
        w_n5: Signal<Local, Bits<5>>,
        w_int: Signal<Local, Bits<5>>,
        w_frac: Signal<Local, U8>,
        w_near: Signal<Local, Bits<5>>,
    }
}

impl Logic for Lod {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s3_lx, s3_ly, s4_gth, s4_eqh, s4_gtl, s4_lx, s4_ly, s4b_m, s5_m, s5c_mc, s5c_fine, s5c_e,
            s5c_big, s6_addr, s6_e, s6_e1, s6_big, s7_t, s7_eb, s7_ebh, s7_big, s7r_t, s7r_eb, s7r_ebh, s7r_big, s8_l,
            s8_lh, s8_big, s9_level, s9_frac, s9_near
        );
        clock!(self, clock, n_dly, b_dly, valid);
        self.valid.d.next = self.valid_in.val();
        self.n_dly.d.next = self.log_side.val();
        self.b_dly.d.next = self.bias.val();
        for i in 0..4 {
            self.s1_m[i].clock.next = self.clock.val();
            self.s1_a[i].clock.next = self.clock.val();
            self.s1b_a[i].clock.next = self.clock.val();
            self.s2_q[i].clock.next = self.clock.val();
            self.s2b_q[i].clock.next = self.clock.val();
        }
        // stage 1: the magnitudes, −d = !d + 1 on 17 bits (−(−256) = 2^16 is still right there, read unsigned)
        self.w_mag[0].next = self.du_dx.val();
        if self.du_dx.val().get_bit(16) {
            self.w_mag[0].next = !self.du_dx.val() + 1; // U17: |d| ≤ 2^16, no wrap read unsigned
        }
        self.w_mag[1].next = self.dv_dx.val();
        if self.dv_dx.val().get_bit(16) {
            self.w_mag[1].next = !self.dv_dx.val() + 1; // U17, as above
        }
        self.w_mag[2].next = self.du_dy.val();
        if self.du_dy.val().get_bit(16) {
            self.w_mag[2].next = !self.du_dy.val() + 1; // U17, as above
        }
        self.w_mag[3].next = self.dv_dy.val();
        if self.dv_dy.val().get_bit(16) {
            self.w_mag[3].next = !self.dv_dy.val() + 1; // U17, as above
        }
        for i in 0..4 {
            self.s1_m[i].d.next = self.w_mag[i].val();
            // stage 1s: U17 → U16, saturated: only 2^16 (d = −256) is above 2^16 − 1
            if self.s1_m[i].q.val().get_bit(16) {
                self.s1_a[i].d.next = 0xffff.into();
            } else {
                self.s1_a[i].d.next = self.s1_m[i].q.val().get_bits::<16>(0);
            }
            // stage 1b: carried
            self.s1b_a[i].d.next = self.s1_a[i].q.val();
            // stage 2: a², 16 × 16 → 32 bits, exact, then >> 8 (floor): Uq16.8
            self.w_sq[i].next = self.s1b_a[i].q.val() * self.s1b_a[i].q.val();
            self.s2_q[i].d.next = self.w_sq[i].val().get_bits::<24>(8); // U32 >> 8: U24, truncated
            self.s2b_q[i].d.next = self.s2_q[i].q.val(); // stage 2b: carried
        }
        // stage 3: L_x = q(u_x) + q(v_x), L_y = q(u_y) + q(v_y): U24 + U24 → U25, exact
        self.s3_lx.d.next = bit_cast::<25, 24>(self.s2b_q[0].q.val()) + bit_cast::<25, 24>(self.s2b_q[1].q.val());
        self.s3_ly.d.next = bit_cast::<25, 24>(self.s2b_q[2].q.val()) + bit_cast::<25, 24>(self.s2b_q[3].q.val());
        // stage 4: which edge is the longer, half by half: L_x > L_y if its top 13 bits are greater, or equal and
        // its low 12 greater (slices, each compared as a whole signal)
        self.w_lxh.next = self.s3_lx.q.val().get_bits::<13>(12);
        self.w_lyh.next = self.s3_ly.q.val().get_bits::<13>(12);
        self.w_lxl.next = self.s3_lx.q.val().get_bits::<12>(0);
        self.w_lyl.next = self.s3_ly.q.val().get_bits::<12>(0);
        self.s4_gth.d.next = self.w_lxh.val() > self.w_lyh.val();
        self.s4_eqh.d.next = self.w_lxh.val() == self.w_lyh.val();
        self.s4_gtl.d.next = self.w_lxl.val() > self.w_lyl.val();
        self.s4_lx.d.next = self.s3_lx.q.val();
        self.s4_ly.d.next = self.s3_ly.q.val();
        // stage 4b: the larger, U25
        self.w_gt.next = self.s4_gth.q.val() | (self.s4_eqh.q.val() & self.s4_gtl.q.val()); // L_x > L_y
        if self.w_gt.val() {
            self.s4b_m.d.next = self.s4_lx.q.val();
        } else {
            self.s4b_m.d.next = self.s4_ly.q.val();
        }
        // stage 5: m's 25 bits as five groups of five, g = 4 (bits 24..20) down to 0 (bits 4..0): whether each holds a
        // one, and its leading one's place below the group's top (0..4)
        self.s5_m.d.next = self.s4b_m.q.val();
        for g in 0..5 {
            self.s5_lp[g].clock.next = self.clock.val();
            self.s5_any[g].clock.next = self.clock.val();
            self.w_grp[g].next = self.s4b_m.q.val().get_bits::<5>(5 * g); // m's bits 5g .. 5g + 4: U5, a slice
            self.s5_any[g].d.next = self.w_grp[g].val().any();
            if self.w_grp[g].val().get_bit(4) {
                self.s5_lp[g].d.next = 0.into();
            } else if self.w_grp[g].val().get_bit(3) {
                self.s5_lp[g].d.next = 1.into();
            } else if self.w_grp[g].val().get_bit(2) {
                self.s5_lp[g].d.next = 2.into();
            } else if self.w_grp[g].val().get_bit(1) {
                self.s5_lp[g].d.next = 3.into();
            } else {
                self.s5_lp[g].d.next = 4.into(); // bit 0, or no one (the any flag says which)
            }
        }
        // stage 5c: the first group with a one gives the coarse shift 5·(4 − g) (m << it), the fine shift (its place)
        // and e = p − 8 = 16 − shift (−8..16, two's complement in 6 bits: −8 is 56); none: m = 0, λ = −∞
        self.s5c_big.d.next = true;
        if self.s5_any[4].q.val() {
            self.s5c_mc.d.next = self.s5_m.q.val();
            self.s5c_fine.d.next = self.s5_lp[4].q.val();
            self.w_lp6.next = bit_cast::<6, 3>(self.s5_lp[4].q.val()); // U3 widened to U6, exact
            self.s5c_e.d.next = 16 - self.w_lp6.val(); // 12..16
        } else if self.s5_any[3].q.val() {
            self.s5c_mc.d.next = self.s5_m.q.val() << 5; // m < 2^20 here: U25, exact
            self.s5c_fine.d.next = self.s5_lp[3].q.val();
            self.w_lp6.next = bit_cast::<6, 3>(self.s5_lp[3].q.val()); // U3 widened to U6, exact
            self.s5c_e.d.next = 11 - self.w_lp6.val(); // 7..11
        } else if self.s5_any[2].q.val() {
            self.s5c_mc.d.next = self.s5_m.q.val() << 10; // m < 2^15 here: U25, exact
            self.s5c_fine.d.next = self.s5_lp[2].q.val();
            self.w_lp6.next = bit_cast::<6, 3>(self.s5_lp[2].q.val()); // U3 widened to U6, exact
            self.s5c_e.d.next = 6 - self.w_lp6.val(); // 2..6
        } else if self.s5_any[1].q.val() {
            self.s5c_mc.d.next = self.s5_m.q.val() << 15; // m < 2^10 here: U25, exact
            self.s5c_fine.d.next = self.s5_lp[1].q.val();
            self.w_lp6.next = bit_cast::<6, 3>(self.s5_lp[1].q.val()); // U3 widened to U6, exact
            self.s5c_e.d.next = 1 - self.w_lp6.val(); // 1 − lp: −3..1 (61..63, 0, 1), wrapping on purpose to S6
        } else {
            self.s5c_mc.d.next = self.s5_m.q.val() << 20; // m < 2^5 here: U25, exact
            self.s5c_fine.d.next = self.s5_lp[0].q.val();
            self.w_lp6.next = bit_cast::<6, 3>(self.s5_lp[0].q.val()); // U3 widened to U6, exact
            self.s5c_e.d.next = 60 - self.w_lp6.val(); // −4 − lp: −8..−4 (56..60)
            if !self.s5_any[0].q.val() {
                self.s5c_big.d.next = false;
            }
        }
        // stage 6: m << shift puts the leading one at bit 24 (U25, the bits shifted out are zeros above it); the
        // table address is the 8 bits below it (truncating the rest)
        self.w_norm.next = self.s5c_mc.q.val() << self.s5c_fine.q.val();
        self.s6_addr.d.next = self.w_norm.val().get_bits::<8>(16); // bits 23..16: the mantissa, truncated to 8 bits
        self.s6_e.d.next = self.s5c_e.q.val();
        self.s6_e1.d.next = self.s5c_e.q.val() + 1; // e + 1, −7..17: S6, exact
        self.s6_big.d.next = self.s5c_big.q.val();
        // stage 7: the table; beside it (e << 9) + (bias << 2), each sign-extended to 16 bits by an OR on its sign
        self.log2.address.next = self.s6_addr.q.val();
        self.s7_t.d.next = self.log2.data.val();
        self.w_e16.next = bit_cast::<16, 6>(self.s6_e.q.val()); // e's six bits, the sign extended below
        if self.s6_e.q.val().get_bit(5) {
            self.w_e16.next = bit_cast::<16, 6>(self.s6_e.q.val()) | 0xffc0; // S6 → S16, exact
        }
        self.w_es.next = self.w_e16.val() << 9; // e·512, −4,096 ..= 8,192: S16, exact
        self.w_e16h.next = bit_cast::<16, 6>(self.s6_e1.q.val()); // e + 1, the sign extended below
        if self.s6_e1.q.val().get_bit(5) {
            self.w_e16h.next = bit_cast::<16, 6>(self.s6_e1.q.val()) | 0xffc0; // S6 → S16, exact
        }
        self.w_esh.next = self.w_e16h.val() << 9; // e·512 + 512, −3,584 ..= 8,704: S16, exact
        self.w_b16.next = bit_cast::<16, 12>(self.b_dly.q.val()); // the bias's twelve bits, the sign extended below
        if self.b_dly.q.val().get_bit(11) {
            self.w_b16.next = bit_cast::<16, 12>(self.b_dly.q.val()) | 0xf000; // S12 → S16, exact
        }
        self.w_bs.next = self.w_b16.val() << 2; // bias·4, −8,192 ..= 8,188: S16, exact
        self.s7_eb.d.next = self.w_es.val() + self.w_bs.val(); // −12,288 ..= 16,380: S16, exact (modulo 2^16)
        self.s7_ebh.d.next = self.w_esh.val() + self.w_bs.val(); // the same plus 512: S16, exact (modulo 2^16)
        self.s7_big.d.next = self.s6_big.q.val();
        // the table's output register, nothing between it and the read
        self.s7r_t.d.next = self.s7_t.q.val();
        self.s7r_eb.d.next = self.s7_eb.q.val();
        self.s7r_ebh.d.next = self.s7_ebh.q.val();
        self.s7r_big.d.next = self.s7_big.q.val();
        // stage 8: λ·2^10 = (e << 9) + (bias << 2) + T, −12,288 ..= 16,891: S16, exact (modulo 2^16)
        self.w_t16.next = bit_cast::<16, 9>(self.s7r_t.q.val()); // U9 widened to S16, exact
        self.s8_l.d.next = self.s7r_eb.q.val() + self.w_t16.val(); // Sq5.10, exact (see above)
        self.s8_lh.d.next = self.s7r_ebh.q.val() + self.w_t16.val(); // λ + 512, ≤ 17,403: S16, no wrap for λ ≥ 0
        self.s8_big.d.next = self.s7r_big.q.val();
        // stage 9: λ < 0 (its sign, bit 15) or m = 0 reads level 0; else ⌊λ⌋ (bits 14..10, ≤ 16), frac(λ) to 8 bits
        // (bits 9..2, truncated), ⌊λ + ½⌋ (rounded half up: ≤ 17,403, no wrap), each clamped to the last level n
        self.w_n5.next = bit_cast::<5, 4>(self.n_dly.q.val()); // U4 widened to U5, exact
        self.w_int.next = self.s8_l.q.val().get_bits::<5>(10); // λ >> 10 for λ ≥ 0: the integer part, ≤ 16
        self.w_frac.next = self.s8_l.q.val().get_bits::<8>(2); // (λ mod 2^10) >> 2: truncated to 8 bits
        self.w_near.next = self.s8_lh.q.val().get_bits::<5>(10); // (λ + 2^9) >> 10, ≤ 16
        if !self.s8_big.q.val() | self.s8_l.q.val().get_bit(15) {
            self.s9_level.d.next = 0.into();
            self.s9_frac.d.next = 0.into();
            self.s9_near.d.next = 0.into();
        } else {
            if self.w_int.val() >= self.w_n5.val() {
                self.s9_level.d.next = self.n_dly.q.val();
                self.s9_frac.d.next = 0.into();
            } else {
                self.s9_level.d.next = self.w_int.val().get_bits::<4>(0); // < n ≤ 15: U4, exact
                self.s9_frac.d.next = self.w_frac.val();
            }
            if self.w_near.val() > self.w_n5.val() {
                self.s9_near.d.next = self.n_dly.q.val();
            } else {
                self.s9_near.d.next = self.w_near.val().get_bits::<4>(0); // ≤ n ≤ 15: U4, exact
            }
        }
        self.level.next = self.s9_level.q.val();
        self.frac.next = self.s9_frac.q.val();
        self.nearest.next = self.s9_near.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
