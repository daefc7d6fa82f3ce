//! `bilinear`: the colour filter's bilinear unit, four 8-bit channels, 8 blend-factor bits. Per channel:
//! `a = t00·256 + (t10 − t00)·u`, `b = t01·256 + (t11 − t01)·u` (exact, U16), then
//! `out = (a·256 + (b − a)·v + 2^15) >> 16` — the model's `a·(256 − v) + b·v` rounded half up, same value.
//! Latency 11: widen; differences; magnitudes; the operand register; ·u; a and b; b − a; its magnitude; the operand
//! register; ·v; the rounded sum. An operand register feeds nothing but its multiplier, so the placer can put it
//! beside the DSP and the long route lands on a register-to-register path.
//! Intermediates are carried in 16/32-bit registers (hdl_gen cannot bit_cast inside a loop); their real widths
//! are in the comments, and yosys removes the constant upper bits.

use crate::delay::Delay;
use crate::stream_unit;
use rust_hdl::prelude::*;
use crate::q::U8;

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 11;


#[derive(LogicBlock, Default)]
pub struct Bilinear {
    pub clock: Signal<In, Clock>,
    pub valid_in: Signal<In, Bit>,
    pub t00_r: Signal<In, U8>,
    pub t00_g: Signal<In, U8>,
    pub t00_b: Signal<In, U8>,
    pub t00_a: Signal<In, U8>,
    pub t10_r: Signal<In, U8>,
    pub t10_g: Signal<In, U8>,
    pub t10_b: Signal<In, U8>,
    pub t10_a: Signal<In, U8>,
    pub t01_r: Signal<In, U8>,
    pub t01_g: Signal<In, U8>,
    pub t01_b: Signal<In, U8>,
    pub t01_a: Signal<In, U8>,
    pub t11_r: Signal<In, U8>,
    pub t11_g: Signal<In, U8>,
    pub t11_b: Signal<In, U8>,
    pub t11_a: Signal<In, U8>,
    pub ublend: Signal<In, U8>,
    pub vblend: Signal<In, U8>,
    pub valid_out: Signal<Out, Bit>,
    pub out_r: Signal<Out, U8>,
    pub out_g: Signal<Out, U8>,
    pub out_b: Signal<Out, U8>,
    pub out_a: Signal<Out, U8>,
    // stage 1: texels widened (U8 in 16 bits; the two bases in 32)
    s1_t00: [DFF<Bits<16>>; 4],
    s1_t10: [DFF<Bits<16>>; 4],
    s1_t01: [DFF<Bits<16>>; 4],
    s1_t11: [DFF<Bits<16>>; 4],
    s1_b0: [DFF<Bits<32>>; 4],
    s1_b1: [DFF<Bits<32>>; 4],
    u: [DFF<Bits<16>>; 3], // u carried to stage 3
    v: [DFF<Bits<16>>; 8], // v carried to stage 7
    mop_u0: [DFF<Bits<16>>; 4], // stage 3b: u once per multiplier (`mop_`: see `rtl/README.md`)
    mop_u1: [DFF<Bits<16>>; 4],
    mop_v: [DFF<Bits<16>>; 4], // stage 7b: v once per multiplier
    // stage 2: t10 − t00, t11 − t01 (S9 in 16 bits)
    s2_d0: [DFF<Bits<16>>; 4],
    s2_d1: [DFF<Bits<16>>; 4],
    s2_b0: [DFF<Bits<32>>; 4],
    s2_b1: [DFF<Bits<32>>; 4],
    // stage 3: magnitudes ≤ 255, signs
    s3_m0: [DFF<Bits<16>>; 4],
    s3_m1: [DFF<Bits<16>>; 4],
    s3_n0: [DFF<Bit>; 4],
    s3_n1: [DFF<Bit>; 4],
    s3_b0: [DFF<Bits<32>>; 4],
    s3_b1: [DFF<Bits<32>>; 4],
    // stage 3b: the multipliers' operands again, and what travels beside them
    s3b_m0: [DFF<Bits<16>>; 4],
    s3b_m1: [DFF<Bits<16>>; 4],
    s3b_n0: [DFF<Bit>; 4],
    s3b_n1: [DFF<Bit>; 4],
    s3b_b0: [DFF<Bits<32>>; 4],
    s3b_b1: [DFF<Bits<32>>; 4],
    // stage 4: |d|·u ≤ 255·255 (U16)
    s4_p0: [DFF<Bits<32>>; 4],
    s4_p1: [DFF<Bits<32>>; 4],
    s4_n0: [DFF<Bit>; 4],
    s4_n1: [DFF<Bit>; 4],
    s4_b0: [DFF<Bits<32>>; 4],
    s4_b1: [DFF<Bits<32>>; 4],
    // stage 5: a, b ∈ 0..65,280 (U16)
    s5_a: [DFF<Bits<32>>; 4],
    s5_b: [DFF<Bits<32>>; 4],
    // stage 6: b − a (S17, two's complement in 32 bits)
    s6_e: [DFF<Bits<32>>; 4],
    s6_a: [DFF<Bits<32>>; 4],
    // stage 7: |b − a| ≤ 65,280 (U16), sign
    s7_m: [DFF<Bits<16>>; 4],
    s7_n: [DFF<Bit>; 4],
    s7_a: [DFF<Bits<32>>; 4],
    // stage 7b: the multiplier's operand again, and what travels beside it
    s7b_m: [DFF<Bits<16>>; 4],
    s7b_n: [DFF<Bit>; 4],
    s7b_a: [DFF<Bits<32>>; 4],
    // stage 8: |b − a|·v < 2^24
    s8_q: [DFF<Bits<32>>; 4],
    s8_n: [DFF<Bit>; 4],
    s8_a: [DFF<Bits<32>>; 4],
    // stage 9: (a·256 + 2^15 ± q) >> 16
    s9_out: [DFF<U8>; 4],
    valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
    w_base0: [Signal<Local, Bits<32>>; 4],
    w_base1: [Signal<Local, Bits<32>>; 4],
    w_em: [Signal<Local, Bits<32>>; 4],
    w_a256: [Signal<Local, Bits<32>>; 4],
    w_r: [Signal<Local, Bits<32>>; 4],
}

impl Logic for Bilinear {
    #[hdl_gen]
    fn update(&mut self) {
        self.valid.clock.next = self.clock.val();
        self.valid.d.next = self.valid_in.val();
        for i in 0..3 {
            self.u[i].clock.next = self.clock.val();
        }
        for i in 0..8 {
            self.v[i].clock.next = self.clock.val();
        }
        self.u[0].d.next = bit_cast::<16, 8>(self.ublend.val());
        self.v[0].d.next = bit_cast::<16, 8>(self.vblend.val());
        for i in 1..3 {
            self.u[i].d.next = self.u[i - 1].q.val();
        }
        for i in 1..8 {
            self.v[i].d.next = self.v[i - 1].q.val();
        }
        self.s1_t00[0].d.next = bit_cast::<16, 8>(self.t00_r.val());
        self.s1_t10[0].d.next = bit_cast::<16, 8>(self.t10_r.val());
        self.s1_t01[0].d.next = bit_cast::<16, 8>(self.t01_r.val());
        self.s1_t11[0].d.next = bit_cast::<16, 8>(self.t11_r.val());
        self.s1_b0[0].d.next = bit_cast::<32, 8>(self.t00_r.val());
        self.s1_b1[0].d.next = bit_cast::<32, 8>(self.t01_r.val());
        self.s1_t00[1].d.next = bit_cast::<16, 8>(self.t00_g.val());
        self.s1_t10[1].d.next = bit_cast::<16, 8>(self.t10_g.val());
        self.s1_t01[1].d.next = bit_cast::<16, 8>(self.t01_g.val());
        self.s1_t11[1].d.next = bit_cast::<16, 8>(self.t11_g.val());
        self.s1_b0[1].d.next = bit_cast::<32, 8>(self.t00_g.val());
        self.s1_b1[1].d.next = bit_cast::<32, 8>(self.t01_g.val());
        self.s1_t00[2].d.next = bit_cast::<16, 8>(self.t00_b.val());
        self.s1_t10[2].d.next = bit_cast::<16, 8>(self.t10_b.val());
        self.s1_t01[2].d.next = bit_cast::<16, 8>(self.t01_b.val());
        self.s1_t11[2].d.next = bit_cast::<16, 8>(self.t11_b.val());
        self.s1_b0[2].d.next = bit_cast::<32, 8>(self.t00_b.val());
        self.s1_b1[2].d.next = bit_cast::<32, 8>(self.t01_b.val());
        self.s1_t00[3].d.next = bit_cast::<16, 8>(self.t00_a.val());
        self.s1_t10[3].d.next = bit_cast::<16, 8>(self.t10_a.val());
        self.s1_t01[3].d.next = bit_cast::<16, 8>(self.t01_a.val());
        self.s1_t11[3].d.next = bit_cast::<16, 8>(self.t11_a.val());
        self.s1_b0[3].d.next = bit_cast::<32, 8>(self.t00_a.val());
        self.s1_b1[3].d.next = bit_cast::<32, 8>(self.t01_a.val());
        for i in 0..4 {
            self.s1_t00[i].clock.next = self.clock.val();
            self.s1_t10[i].clock.next = self.clock.val();
            self.s1_t01[i].clock.next = self.clock.val();
            self.s1_t11[i].clock.next = self.clock.val();
            self.s1_b0[i].clock.next = self.clock.val();
            self.s1_b1[i].clock.next = self.clock.val();
            self.s2_d0[i].clock.next = self.clock.val();
            self.s2_d1[i].clock.next = self.clock.val();
            self.s2_b0[i].clock.next = self.clock.val();
            self.s2_b1[i].clock.next = self.clock.val();
            self.s3_m0[i].clock.next = self.clock.val();
            self.s3_m1[i].clock.next = self.clock.val();
            self.s3_n0[i].clock.next = self.clock.val();
            self.s3_n1[i].clock.next = self.clock.val();
            self.s3_b0[i].clock.next = self.clock.val();
            self.s3_b1[i].clock.next = self.clock.val();
            self.mop_u0[i].clock.next = self.clock.val();
            self.mop_u1[i].clock.next = self.clock.val();
            self.mop_v[i].clock.next = self.clock.val();
            self.s3b_m0[i].clock.next = self.clock.val();
            self.s3b_m1[i].clock.next = self.clock.val();
            self.s3b_n0[i].clock.next = self.clock.val();
            self.s3b_n1[i].clock.next = self.clock.val();
            self.s3b_b0[i].clock.next = self.clock.val();
            self.s3b_b1[i].clock.next = self.clock.val();
            self.s4_p0[i].clock.next = self.clock.val();
            self.s4_p1[i].clock.next = self.clock.val();
            self.s4_n0[i].clock.next = self.clock.val();
            self.s4_n1[i].clock.next = self.clock.val();
            self.s4_b0[i].clock.next = self.clock.val();
            self.s4_b1[i].clock.next = self.clock.val();
            self.s5_a[i].clock.next = self.clock.val();
            self.s5_b[i].clock.next = self.clock.val();
            self.s6_e[i].clock.next = self.clock.val();
            self.s6_a[i].clock.next = self.clock.val();
            self.s7_m[i].clock.next = self.clock.val();
            self.s7_n[i].clock.next = self.clock.val();
            self.s7_a[i].clock.next = self.clock.val();
            self.s7b_m[i].clock.next = self.clock.val();
            self.s7b_n[i].clock.next = self.clock.val();
            self.s7b_a[i].clock.next = self.clock.val();
            self.s8_q[i].clock.next = self.clock.val();
            self.s8_n[i].clock.next = self.clock.val();
            self.s8_a[i].clock.next = self.clock.val();
            self.s9_out[i].clock.next = self.clock.val();
            // stage 2
            self.s2_d0[i].d.next = self.s1_t10[i].q.val() - self.s1_t00[i].q.val();
            self.s2_d1[i].d.next = self.s1_t11[i].q.val() - self.s1_t01[i].q.val();
            self.s2_b0[i].d.next = self.s1_b0[i].q.val();
            self.s2_b1[i].d.next = self.s1_b1[i].q.val();
            // stage 3
            if self.s2_d0[i].q.val().get_bit(15) {
                self.s3_m0[i].d.next = !self.s2_d0[i].q.val() + 1;
            } else {
                self.s3_m0[i].d.next = self.s2_d0[i].q.val();
            }
            if self.s2_d1[i].q.val().get_bit(15) {
                self.s3_m1[i].d.next = !self.s2_d1[i].q.val() + 1;
            } else {
                self.s3_m1[i].d.next = self.s2_d1[i].q.val();
            }
            self.s3_n0[i].d.next = self.s2_d0[i].q.val().get_bit(15);
            self.s3_n1[i].d.next = self.s2_d1[i].q.val().get_bit(15);
            self.s3_b0[i].d.next = self.s2_b0[i].q.val();
            self.s3_b1[i].d.next = self.s2_b1[i].q.val();
            // stage 3b: carried
            self.s3b_m0[i].d.next = self.s3_m0[i].q.val();
            self.s3b_m1[i].d.next = self.s3_m1[i].q.val();
            self.s3b_n0[i].d.next = self.s3_n0[i].q.val();
            self.s3b_n1[i].d.next = self.s3_n1[i].q.val();
            self.s3b_b0[i].d.next = self.s3_b0[i].q.val();
            self.s3b_b1[i].d.next = self.s3_b1[i].q.val();
            self.mop_u0[i].d.next = self.u[2].q.val();
            self.mop_u1[i].d.next = self.u[2].q.val();
            // stage 4: 16 × 16 → 32
            self.s4_p0[i].d.next = self.s3b_m0[i].q.val() * self.mop_u0[i].q.val();
            self.s4_p1[i].d.next = self.s3b_m1[i].q.val() * self.mop_u1[i].q.val();
            self.s4_n0[i].d.next = self.s3b_n0[i].q.val();
            self.s4_n1[i].d.next = self.s3b_n1[i].q.val();
            self.s4_b0[i].d.next = self.s3b_b0[i].q.val();
            self.s4_b1[i].d.next = self.s3b_b1[i].q.val();
            // stage 5: t·256 ± |d|·u
            self.w_base0[i].next = self.s4_b0[i].q.val() << 8;
            self.w_base1[i].next = self.s4_b1[i].q.val() << 8;
            if self.s4_n0[i].q.val() {
                self.s5_a[i].d.next = self.w_base0[i].val() - self.s4_p0[i].q.val();
            } else {
                self.s5_a[i].d.next = self.w_base0[i].val() + self.s4_p0[i].q.val();
            }
            if self.s4_n1[i].q.val() {
                self.s5_b[i].d.next = self.w_base1[i].val() - self.s4_p1[i].q.val();
            } else {
                self.s5_b[i].d.next = self.w_base1[i].val() + self.s4_p1[i].q.val();
            }
            // stage 6
            self.s6_e[i].d.next = self.s5_b[i].q.val() - self.s5_a[i].q.val();
            self.s6_a[i].d.next = self.s5_a[i].q.val();
            // stage 7
            if self.s6_e[i].q.val().get_bit(31) {
                self.w_em[i].next = !self.s6_e[i].q.val() + 1;
            } else {
                self.w_em[i].next = self.s6_e[i].q.val();
            }
            self.s7_m[i].d.next = self.w_em[i].val().get_bits::<16>(0);
            self.s7_n[i].d.next = self.s6_e[i].q.val().get_bit(31);
            self.s7_a[i].d.next = self.s6_a[i].q.val();
            // stage 7b: carried
            self.s7b_m[i].d.next = self.s7_m[i].q.val();
            self.s7b_n[i].d.next = self.s7_n[i].q.val();
            self.s7b_a[i].d.next = self.s7_a[i].q.val();
            self.mop_v[i].d.next = self.v[7].q.val();
            // stage 8: 16 × 16 → 32
            self.s8_q[i].d.next = self.s7b_m[i].q.val() * self.mop_v[i].q.val();
            self.s8_n[i].d.next = self.s7b_n[i].q.val();
            self.s8_a[i].d.next = self.s7b_a[i].q.val();
            // stage 9: a·256 + 2^15 ± q, then the top byte of 24
            self.w_a256[i].next = self.s8_a[i].q.val() << 8;
            if self.s8_n[i].q.val() {
                self.w_r[i].next = self.w_a256[i].val() + 32768 - self.s8_q[i].q.val();
            } else {
                self.w_r[i].next = self.w_a256[i].val() + 32768 + self.s8_q[i].q.val();
            }
            self.s9_out[i].d.next = self.w_r[i].val().get_bits::<8>(16);
        }
        self.out_r.next = self.s9_out[0].q.val();
        self.out_g.next = self.s9_out[1].q.val();
        self.out_b.next = self.s9_out[2].q.val();
        self.out_a.next = self.s9_out[3].q.val();
        self.valid_out.next = self.valid.q.val();
    }
}

stream_unit!(Bilinear, "bilinear", LATENCY,
    inputs: [t00_r: 8, t00_g: 8, t00_b: 8, t00_a: 8, t10_r: 8, t10_g: 8, t10_b: 8, t10_a: 8,
             t01_r: 8, t01_g: 8, t01_b: 8, t01_a: 8, t11_r: 8, t11_g: 8, t11_b: 8, t11_a: 8, ublend: 8, vblend: 8],
    outputs: [out_r: 8, out_g: 8, out_b: 8, out_a: 8]);
