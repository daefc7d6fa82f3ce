//! `tex_addr`: the texture unit's address unit, both axes: the sample position (u, v: Sq11.8, texels of level 0)
//! and the MIP level to read → the level's side (log2), the bilinear footprint's two columns and two rows, and its
//! two blend factors, each axis repeating or clamping on its own; `linear` = 0 gives the nearest texel instead. See
//! `vectors::tex_addr` for the exact recipe.
//!
//! Latency 5: the level read and its side; the position shifted to the level, the level's mask and the clamp's
//! limit; half a texel back, beside the clamp's top and comparison; the repeat or the clamp; the footprint's second
//! texel. (With the shift and the subtraction in one stage the ECP5-45F placed the unit at 116.2 MHz, that path the
//! critical one.)
//!
//! Every figure of the level (the repeat's mask 256·2^m − 1, the clamp's top and limit, the last texel) is the mask
//! with its low bits cleared or a slice of it, and the mask is the complement of a constant shifted by m: no carry
//! chain. (As 256·2^m − 256 and − 128, the shift and the subtraction in a row were the trilinear pipelines' path on
//! the ECP5, 1.99 ns of logic and 3.96 ns of routing.)

use crate::prim::delay::Delay;
use crate::prim::q::{SBits, Sq11_8, U16, U8};
use rust_hdl::prelude::*;

pub const LATENCY: usize = 5;

crate::stream_block! {
    #[derive(Default)]
    pub struct TexAddr: unit("tex_addr", LATENCY) {
        in {
            u: Sq11_8,
            v: Sq11_8,
            level: Bits<4>,
            log_side: Bits<4>,
            uwrap: Bits<1>,
            vwrap: Bits<1>,
            linear: Bits<1>,
        }
        out {
            level_log2: Bits<4>,
            x0: U8,
            x1: U8,
            y0: U8,
            y1: U8,
            ublend: U8,
            vblend: U8,
        }
        // stage 1: the level read n' = min(level, s) and its side's log2 m = s − n' (s = min(log_side, 8)); the
        // position and the modes beside them
        s1_n: DFF<Bits<4>>,
        s1_m: DFF<Bits<4>>,
        s1_u: DFF<Sq11_8>,
        s1_v: DFF<Sq11_8>,
        s1_uwrap: DFF<Bit>,
        s1_vwrap: DFF<Bit>,
        s1_lin: DFF<Bit>,
        // stage 1b: a = floor(u / 2^n') per axis (S20 in 22), the level's side and the modes beside it
        s1b_au: DFF<SBits<22>>,
        s1b_av: DFF<SBits<22>>,
        s1b_m: DFF<Bits<4>>,
        s1b_lin: DFF<Bit>,
        s1b_uwrap: DFF<Bit>,
        s1b_vwrap: DFF<Bit>,
        // the level's last coordinate 256·2^m − 1 (the repeat's mask, U16 in 22), and the clamp's limit on a: past
        // it, c is past the top (bilinear top + 128, as c = a − 128; nearest the top: U16 in 22)
        s1b_mask: DFF<Bits<22>>,
        s1b_lim: DFF<Bits<22>>,
        // stage 2: c per axis (S21 in 22: the position at the level, half a texel back for bilinear), the mask, the
        // clamp's top (U16 in 22), the level's last texel
        s2_cu: DFF<SBits<22>>,
        s2_cv: DFF<SBits<22>>,
        s2_mask: DFF<Bits<22>>,
        s2_top: DFF<Bits<22>>,
        s2_last: DFF<U8>,
        s2_m: DFF<Bits<4>>,
        s2_uwrap: DFF<Bit>,
        s2_vwrap: DFF<Bit>,
        s2_lin: DFF<Bit>,
        // whether a is past the limit, per axis: the clamp's comparison a clock before its choice (in stage 3, the
        // comparison of c with the top in front of the choice was the trilinear pipelines' critical path on the
        // ECP5, 2.60 ns of logic and 3.59 ns of routing)
        s2_ou: DFF<Bit>,
        s2_ov: DFF<Bit>,
        // stage 3: r per axis, repeated or clamped (U16)
        s3_ru: DFF<U16>,
        s3_rv: DFF<U16>,
        s3_last: DFF<U8>,
        s3_m: DFF<Bits<4>>,
        s3_uwrap: DFF<Bit>,
        s3_vwrap: DFF<Bit>,
        s3_lin: DFF<Bit>,
        // stage 4: the outputs
        s4_m: DFF<Bits<4>>,
        s4_x0: DFF<U8>,
        s4_x1: DFF<U8>,
        s4_y0: DFF<U8>,
        s4_y1: DFF<U8>,
        s4_ub: DFF<U8>,
        s4_vb: DFF<U8>,
        valid: Delay<Bit, LATENCY>,
        w_s: Signal<Local, Bits<4>>,
        w_n: Signal<Local, Bits<4>>,
        w_ux: Signal<Local, SBits<30>>,
        w_vx: Signal<Local, SBits<30>>,
        w_sign: Signal<Local, Bits<30>>,
        w_ua: Signal<Local, Bits<30>>,
        w_va: Signal<Local, Bits<30>>,
        w_ua22: Signal<Local, SBits<22>>,
        w_va22: Signal<Local, SBits<22>>,
        w_above: Signal<Local, Bits<22>>,
        w_lm22: Signal<Local, Bits<22>>,
        w_lmask: Signal<Local, Bits<22>>,
        w_ru: Signal<Local, Bits<22>>,
        w_rv: Signal<Local, Bits<22>>,
        w_tu: Signal<Local, U8>,
        w_tv: Signal<Local, U8>,
        w_tu1: Signal<Local, U8>,
        w_tv1: Signal<Local, U8>,
    }
}

impl Logic for TexAddr {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s1_n, s1_m, s1_u, s1_v, s1_uwrap, s1_vwrap, s1_lin, s1b_au, s1b_av, s1b_m, s1b_lin, s1b_uwrap,
            s1b_vwrap, s1b_mask, s1b_lim, s2_ou, s2_ov, s2_cu, s2_cv, s2_mask, s2_top, s2_last, s2_m, s2_uwrap,
            s2_vwrap, s2_lin, s3_ru, s3_rv, s3_last, s3_m, s3_uwrap, s3_vwrap, s3_lin, s4_m, s4_x0, s4_x1, s4_y0,
            s4_y1, s4_ub, s4_vb
        );
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();

        // stage 1: s = min(log_side, 8) (saturate), n' = min(level, s), m = s − n' (U4, exact: n' ≤ s)
        if self.log_side.val().get_bit(3) {
            self.w_s.next = 8.into();
        } else {
            self.w_s.next = self.log_side.val();
        }
        if self.level.val() > self.w_s.val() {
            self.w_n.next = self.w_s.val();
        } else {
            self.w_n.next = self.level.val();
        }
        self.s1_n.d.next = self.w_n.val();
        self.s1_m.d.next = self.w_s.val() - self.w_n.val();
        self.s1_u.d.next = self.u.val();
        self.s1_v.d.next = self.v.val();
        self.s1_uwrap.d.next = self.uwrap.val().any();
        self.s1_vwrap.d.next = self.vwrap.val().any();
        self.s1_lin.d.next = self.linear.val().any();

        // stage 1b: a = u >> n' (an arithmetic shift, the floor: u sign-extended to 30 bits by hand, shifted
        // logically by at most 8, so bits 0..21 of the result are the shifted value's, sign included)
        self.w_sign.next = 0x3ff0_0000.into(); // bits 20..29
        self.w_ux.next = bit_cast::<30, 20>(self.s1_u.q.val()); // U20 in 30, widening
        if self.s1_u.q.val().get_bit(19) {
            // the sign extended into bits 20..29
            self.w_ux.next = bit_cast::<30, 20>(self.s1_u.q.val()) | self.w_sign.val();
        }
        self.w_vx.next = bit_cast::<30, 20>(self.s1_v.q.val()); // U20 in 30, widening
        if self.s1_v.q.val().get_bit(19) {
            // the sign extended into bits 20..29
            self.w_vx.next = bit_cast::<30, 20>(self.s1_v.q.val()) | self.w_sign.val();
        }
        self.w_ua.next = self.w_ux.val() >> self.s1_n.q.val(); // floor(u / 2^n'), in bits 0..21 (S20)
        self.w_va.next = self.w_vx.val() >> self.s1_n.q.val(); // floor(v / 2^n'), in bits 0..21 (S20)
        self.w_ua22.next = self.w_ua.val().get_bits::<22>(0); // S20 in 22, a slice of a sign-extended value
        self.w_va22.next = self.w_va.val().get_bits::<22>(0); // S20 in 22, a slice of a sign-extended value
        self.s1b_au.d.next = self.w_ua22.val();
        self.s1b_av.d.next = self.w_va22.val();
        self.s1b_m.d.next = self.s1_m.q.val();
        self.s1b_lin.d.next = self.s1_lin.q.val();
        self.s1b_uwrap.d.next = self.s1_uwrap.q.val();
        self.s1b_vwrap.d.next = self.s1_vwrap.q.val();
        // the mask 256·2^m − 1 (bits 0 .. m + 7 set): the complement of bits 8..21 shifted up by m ≤ 8 (exact)
        self.w_above.next = 0x3f_ff00.into(); // bits 8..21
        self.w_lm22.next = bit_cast::<22, 4>(self.s1_m.q.val()); // U4 in 22, widening
        self.w_lmask.next = !(self.w_above.val() << self.w_lm22.val()); // bits 8 + m .. 21 cleared: U16 in 22
        self.s1b_mask.d.next = self.w_lmask.val();
        // the limit: 256·2^m − 128 (bilinear: the mask with bits 0..6 cleared) or 256·2^m − 1 (nearest: the mask)
        if self.s1_lin.q.val() {
            self.s1b_lim.d.next = self.w_lmask.val() & 0x3f_ff80; // exact
        } else {
            self.s1b_lim.d.next = self.w_lmask.val();
        }

        // stage 2: c = a − 128 (bilinear) or a (nearest)
        if self.s1b_lin.q.val() {
            self.s2_cu.d.next = self.s1b_au.q.val() - 128; // half a texel back: S21 in 22, two's complement, exact
            self.s2_cv.d.next = self.s1b_av.q.val() - 128; // S21 in 22, exact
        } else {
            self.s2_cu.d.next = self.s1b_au.q.val(); // nearest: the position itself
            self.s2_cv.d.next = self.s1b_av.q.val();
        }
        // the clamp's top and the last texel 2^m − 1, both from the mask
        self.s2_mask.d.next = self.s1b_mask.q.val();
        if self.s1b_lin.q.val() {
            // bilinear: up to the last texel's centre, 256·2^m − 256 (the mask with bits 0..7 cleared), exact
            self.s2_top.d.next = self.s1b_mask.q.val() & 0x3f_ff00;
        } else {
            self.s2_top.d.next = self.s1b_mask.q.val(); // nearest: up to the last texel's end, 256·2^m − 1
        }
        self.s2_last.d.next = self.s1b_mask.q.val().get_bits::<8>(8); // 2^m − 1: U8, a slice of a U16 value
        self.s2_m.d.next = self.s1b_m.q.val();
        self.s2_uwrap.d.next = self.s1b_uwrap.q.val();
        self.s2_vwrap.d.next = self.s1b_vwrap.q.val();
        self.s2_lin.d.next = self.s1b_lin.q.val();
        // a past the limit (read only where c ≥ 0, so a ≥ 0 and the unsigned comparison is the signed one)
        self.s2_ou.d.next = self.s1b_au.q.val() > self.s1b_lim.q.val();
        self.s2_ov.d.next = self.s1b_av.q.val() > self.s1b_lim.q.val();

        // stage 3: repeat (modulo the span: the AND of the two's complement value) or clamp (saturate to 0..top)
        if self.s2_uwrap.q.val() {
            self.w_ru.next = self.s2_cu.q.val() & self.s2_mask.q.val(); // U16, exact modulo
        } else if self.s2_cu.q.val().get_bit(21) {
            self.w_ru.next = 0.into(); // below 0: clamp
        } else if self.s2_ou.q.val() {
            self.w_ru.next = self.s2_top.q.val(); // past the top: clamp
        } else {
            self.w_ru.next = self.s2_cu.q.val();
        }
        if self.s2_vwrap.q.val() {
            self.w_rv.next = self.s2_cv.q.val() & self.s2_mask.q.val(); // U16, exact modulo
        } else if self.s2_cv.q.val().get_bit(21) {
            self.w_rv.next = 0.into(); // below 0: clamp
        } else if self.s2_ov.q.val() {
            self.w_rv.next = self.s2_top.q.val(); // past the top: clamp
        } else {
            self.w_rv.next = self.s2_cv.q.val();
        }
        self.s3_ru.d.next = self.w_ru.val().get_bits::<16>(0); // U16, a slice of a U16 value
        self.s3_rv.d.next = self.w_rv.val().get_bits::<16>(0); // U16, a slice of a U16 value
        self.s3_last.d.next = self.s2_last.q.val();
        self.s3_m.d.next = self.s2_m.q.val();
        self.s3_uwrap.d.next = self.s2_uwrap.q.val();
        self.s3_vwrap.d.next = self.s2_vwrap.q.val();
        self.s3_lin.d.next = self.s2_lin.q.val();

        // stage 4: the first texel and the blend (a split of r), the second texel: t0 + 1 modulo 2^m (repeat: the
        // AND with the last texel) or at most the last (clamp); nearest repeats the first and blends nothing
        self.w_tu.next = self.s3_ru.q.val().get_bits::<8>(8); // the integer part: U8, a split
        self.w_tv.next = self.s3_rv.q.val().get_bits::<8>(8); // the integer part: U8, a split
        self.w_tu1.next = self.w_tu.val() + 1; // U8, wraps at 256 (where the AND with 255 wants 0)
        self.w_tv1.next = self.w_tv.val() + 1; // U8, wraps at 256
        self.s4_x0.d.next = self.w_tu.val();
        self.s4_y0.d.next = self.w_tv.val();
        self.s4_x1.d.next = self.w_tu.val();
        self.s4_y1.d.next = self.w_tv.val();
        self.s4_ub.d.next = 0.into();
        self.s4_vb.d.next = 0.into();
        if self.s3_lin.q.val() {
            self.s4_ub.d.next = self.s3_ru.q.val().get_bits::<8>(0); // the fraction: U8, a split
            self.s4_vb.d.next = self.s3_rv.q.val().get_bits::<8>(0); // the fraction: U8, a split
            if self.s3_uwrap.q.val() {
                self.s4_x1.d.next = self.w_tu1.val() & self.s3_last.q.val(); // modulo 2^m
            } else if self.w_tu.val() != self.s3_last.q.val() {
                self.s4_x1.d.next = self.w_tu1.val(); // below the last texel: no clamp
            }
            if self.s3_vwrap.q.val() {
                self.s4_y1.d.next = self.w_tv1.val() & self.s3_last.q.val(); // modulo 2^m
            } else if self.w_tv.val() != self.s3_last.q.val() {
                self.s4_y1.d.next = self.w_tv1.val(); // below the last texel: no clamp
            }
        }
        self.s4_m.d.next = self.s3_m.q.val();
        self.level_log2.next = self.s4_m.q.val();
        self.x0.next = self.s4_x0.q.val();
        self.x1.next = self.s4_x1.q.val();
        self.y0.next = self.s4_y0.q.val();
        self.y1.next = self.s4_y1.q.val();
        self.ublend.next = self.s4_ub.q.val();
        self.vblend.next = self.s4_vb.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
