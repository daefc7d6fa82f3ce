//! `height_addr`: US 2004/0207631's address unit [150], one axis: a UQ8.8 texel coordinate → the integer texel (U8) and
//! the blend factor (U8) on a 2^size_log2-texel axis (size_log2 ≥ 8 read as 8), wrapping or clamping at the
//! border; colour mode subtracts half a texel [51], height mode bypasses it. See `vectors::height_addr`.
//! Latency 2: the shifted coordinate and the axis's span; the wrap or the clamp, and the split.

use crate::prim::delay::Delay;
use crate::prim::q::{SBits, U8};
use rust_hdl::prelude::*;

pub const LATENCY: usize = 2;

crate::stream_block! {
    #[derive(Default)]
    pub struct HeightAddr: unit("height_addr", LATENCY) {
        in {
            coord: Bits<16>,
            size_log2: Bits<4>,
            wrap: Bits<1>,
            height: Bits<1>,
        }
        out {
            texel: U8,
            blend: U8,
        }
        // stage 1: c = coord − ½ texel, or coord (S17, two's complement in 18 bits); the span's last coordinate
        // (U17) and the clamp's top (U17)
        s1_c: DFF<SBits<18>>,
        s1_mask: DFF<Bits<18>>,
        s1_top: DFF<Bits<18>>,
        s1_wrap: DFF<Bit>,
        // stage 2: the coordinate wrapped or clamped (U16), split
        s2_texel: DFF<U8>,
        s2_blend: DFF<U8>,
        valid: Delay<Bit, LATENCY>,
        w_coord: Signal<Local, Bits<18>>,
        w_s: Signal<Local, Bits<18>>,
        w_256: Signal<Local, Bits<18>>,
        w_span: Signal<Local, Bits<18>>,
        w_r: Signal<Local, Bits<18>>,
    }
}

impl Logic for HeightAddr {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_c, s1_mask, s1_top, s1_wrap, s2_texel, s2_blend);
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1
        self.w_coord.next = bit_cast::<18, 16>(self.coord.val()); // U16 in 18, widening
        if self.height.val().any() {
            self.s1_c.d.next = self.w_coord.val(); // height mode: the coordinate itself [51 bypassed]
        } else {
            self.s1_c.d.next = self.w_coord.val() - 128; // − ½ texel: S17, two's complement in 18 bits, exact
        }
        // the axis: 2^s texels with s = min(size_log2, 8) (saturate), 256·2^s coordinates
        if self.size_log2.val().get_bit(3) {
            self.w_s.next = 8.into();
        } else {
            self.w_s.next = bit_cast::<18, 4>(self.size_log2.val()); // 0..7, widening
        }
        self.w_256.next = 256.into();
        self.w_span.next = self.w_256.val() << self.w_s.val(); // 256·2^s ≤ 65,536: U17 in 18, exact
        self.s1_mask.d.next = self.w_span.val() - 1; // the last coordinate, U16, exact
        if self.height.val().any() {
            self.s1_top.d.next = self.w_span.val() - 1; // height mode: up to the last segment's end
        } else {
            self.s1_top.d.next = self.w_span.val() - 256; // colour mode: up to the last texel's centre
        }
        self.s1_wrap.d.next = self.wrap.val().any();
        // stage 2: wrap (modulo 256·2^s, the AND of a two's complement value) or clamp (saturate to 0..top)
        if self.s1_wrap.q.val() {
            self.w_r.next = self.s1_c.q.val() & self.s1_mask.q.val(); // U16, exact modulo
        } else if self.s1_c.q.val().get_bit(17) {
            self.w_r.next = 0.into(); // below 0: clamp
        } else if self.s1_c.q.val() > self.s1_top.q.val() {
            self.w_r.next = self.s1_top.q.val(); // beyond the top: clamp
        } else {
            self.w_r.next = self.s1_c.q.val();
        }
        self.s2_texel.d.next = self.w_r.val().get_bits::<8>(8); // the integer part: U8, a split
        self.s2_blend.d.next = self.w_r.val().get_bits::<8>(0); // the fraction: U8, a split
        self.texel.next = self.s2_texel.q.val();
        self.blend.next = self.s2_blend.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
