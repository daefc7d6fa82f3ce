//! `cart_decode_hemi_oct`: the rotated hemi-octahedral decode of `vectors::cart_decode_hemi_oct`:
//! `BumpX = U + V − 255`, `BumpZ = U − V` (INT9), `BumpY = 255 − |BumpX| − |BumpZ|` (UINT8). Exact, no guard: every
//! texel is legal. Latency 3: the two sums; their magnitudes; BumpY.

use crate::prim::delay::Delay;
use crate::prim::q::{Sq8_0, U8};
use rust_hdl::prelude::*;

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 3;

crate::stream_block! {
    #[derive(Default)]
    pub struct CartDecodeHemiOct: unit("cart_decode_hemi_oct", LATENCY) {
        in {
            texel_u: U8,
            texel_v: U8,
        }
        out {
            bump_x: Sq8_0,
            bump_y: U8,
            bump_z: Sq8_0,
        }
        // stage 1: x = U + V − 255, z = U − V (INT9: both within ±255, so the 9-bit wrap is exact)
        s1_x: DFF<Sq8_0>,
        s1_z: DFF<Sq8_0>,
        // stage 2: |x|, |z| (U8, ≤ 255)
        s2_ax: DFF<U8>,
        s2_az: DFF<U8>,
        s2_x: DFF<Sq8_0>,
        s2_z: DFF<Sq8_0>,
        // stage 3: y = 255 − |x| − |z| (U8, 0..255 since |x| + |z| ≤ 255)
        s3_y: DFF<U8>,
        s3_x: DFF<Sq8_0>,
        s3_z: DFF<Sq8_0>,
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
        w_u: Signal<Local, Sq8_0>,
        w_v: Signal<Local, Sq8_0>,
        w_mx: Signal<Local, Sq8_0>,
        w_mz: Signal<Local, Sq8_0>,
    }
}

impl Logic for CartDecodeHemiOct {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_x, s1_z, s2_ax, s2_az, s2_x, s2_z, s3_y, s3_x, s3_z);
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1: U8 widened to 9 bits, added and subtracted with a 9-bit wrap (the true values fit INT9)
        self.w_u.next = bit_cast::<9, 8>(self.texel_u.val());
        self.w_v.next = bit_cast::<9, 8>(self.texel_v.val());
        self.s1_x.d.next = self.w_u.val() + self.w_v.val() - 255;
        self.s1_z.d.next = self.w_u.val() - self.w_v.val();
        // stage 2: magnitudes (|−255| = 255 fits U8)
        self.w_mx.next = self.s1_x.q.val();
        if self.s1_x.q.val().get_bit(8) {
            self.w_mx.next = !self.s1_x.q.val() + 1;
        }
        self.w_mz.next = self.s1_z.q.val();
        if self.s1_z.q.val().get_bit(8) {
            self.w_mz.next = !self.s1_z.q.val() + 1;
        }
        self.s2_ax.d.next = self.w_mx.val().get_bits::<8>(0);
        self.s2_az.d.next = self.w_mz.val().get_bits::<8>(0);
        self.s2_x.d.next = self.s1_x.q.val();
        self.s2_z.d.next = self.s1_z.q.val();
        // stage 3: BumpY, never below 0 (no wrap)
        self.s3_y.d.next = 255 - self.s2_ax.q.val() - self.s2_az.q.val();
        self.s3_x.d.next = self.s2_x.q.val();
        self.s3_z.d.next = self.s2_z.q.val();
        self.bump_x.next = self.s3_x.q.val();
        self.bump_y.next = self.s3_y.q.val();
        self.bump_z.next = self.s3_z.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
