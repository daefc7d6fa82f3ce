//! `cart_decode`: offset-8-bit TexelX, TexelZ → BumpX, BumpZ (INT9), BumpY (UINT8), with the guard documented in
//! `vectors::cart_decode`: texels saturate at 254; outside the diamond, `|BumpX| = 127 + ax − az`,
//! `|BumpZ| = 127 + az − ax`, `BumpY = 1`. Latency 4: |T − 127|; ax + az and ax − az; the guard mux; the signs.

use crate::prim::delay::Delay;
use crate::prim::q::{Sq8_0, U8};
use rust_hdl::prelude::*;

/// Clock edges from an input to its output: the length of the valid chain, and of the datapath's stages.
pub const LATENCY: usize = 4;

crate::stream_block! {
    #[derive(Default)]
    pub struct CartDecode: unit("cart_decode", LATENCY) {
        in {
            texel_x: U8,
            texel_z: U8,
        }
        out {
            bump_x: Sq8_0,
            bump_y: U8,
            bump_z: Sq8_0,
        }
        // stage 1: ax = |sat(T) − 127| (U7 in U8), sx = sat(T) < 127
        s1_ax: DFF<U8>,
        s1_az: DFF<U8>,
        s1_sx: DFF<Bit>,
        s1_sz: DFF<Bit>,
        // stage 2: ax + az (U8), ax − az (S9)
        s2_sum: DFF<U8>,
        s2_dxz: DFF<Sq8_0>,
        s2_ax: DFF<U8>,
        s2_az: DFF<U8>,
        s2_sx: DFF<Bit>,
        s2_sz: DFF<Bit>,
        // stage 3: magnitudes and BumpY, guarded or not
        s3_mx: DFF<U8>,
        s3_mz: DFF<U8>,
        s3_by: DFF<U8>,
        s3_sx: DFF<Bit>,
        s3_sz: DFF<Bit>,
        // stage 4: signs applied
        s4_bx: DFF<Sq8_0>,
        s4_by: DFF<U8>,
        s4_bz: DFF<Sq8_0>,
        valid: Delay<Bit, LATENCY>, // the valid flag, beside the stages
        lo_x: Signal<Local, Bits<7>>,
        lo_z: Signal<Local, Bits<7>>,
        inv_x: Signal<Local, Bits<7>>,
        inv_z: Signal<Local, Bits<7>>,
        w_ax: Signal<Local, Sq8_0>,
        w_az: Signal<Local, Sq8_0>,
        twice_sum: Signal<Local, U8>,
        g_mx: Signal<Local, Sq8_0>,
        g_mz: Signal<Local, Sq8_0>,
        w_mx: Signal<Local, Sq8_0>,
        w_mz: Signal<Local, Sq8_0>,
    }
}

impl Logic for CartDecode {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s1_ax, s1_az, s1_sx, s1_sz, s2_sum, s2_dxz, s2_ax, s2_az, s2_sx, s2_sz, s3_mx, s3_mz, s3_by,
            s3_sx, s3_sz, s4_bx, s4_by, s4_bz
        );
        clock!(self, clock, valid);
        self.valid.d.next = self.valid_in.val();
        // stage 1: the distance from 127 of T saturated to 254, and its side, with one 7-bit incrementer:
        // T < 128: 127 − T = !T[6:0] (texel 127 gives 0, and then the sign does not matter);
        // T ≥ 128: T − 127 = T[6:0] + 1, except T = 255, which saturates to 254 and gives 127
        self.lo_x.next = self.texel_x.val().get_bits::<7>(0);
        self.lo_z.next = self.texel_z.val().get_bits::<7>(0);
        self.inv_x.next = !self.lo_x.val(); // inverted at 7 bits: Verilog would widen first, then invert
        self.inv_z.next = !self.lo_z.val();
        if !self.texel_x.val().get_bit(7) {
            self.s1_ax.d.next = bit_cast::<8, 7>(self.inv_x.val()); // 127 − T ∈ 0..127 (U7 in U8), exact
        } else if self.texel_x.val().all() {
            self.s1_ax.d.next = 127.into();
        } else {
            self.s1_ax.d.next = bit_cast::<8, 7>(self.lo_x.val()) + 1; // T − 127 ∈ 1..127 (U8), exact
        }
        self.s1_sx.d.next = !self.texel_x.val().get_bit(7);
        if !self.texel_z.val().get_bit(7) {
            self.s1_az.d.next = bit_cast::<8, 7>(self.inv_z.val()); // 127 − T (U8), exact
        } else if self.texel_z.val().all() {
            self.s1_az.d.next = 127.into();
        } else {
            self.s1_az.d.next = bit_cast::<8, 7>(self.lo_z.val()) + 1; // T − 127 (U8), exact
        }
        self.s1_sz.d.next = !self.texel_z.val().get_bit(7);
        // stage 2: ax + az ≤ 254 (U8); ax − az ∈ −127..127 (S9)
        self.s2_sum.d.next = self.s1_ax.q.val() + self.s1_az.q.val();
        self.w_ax.next = bit_cast::<9, 8>(self.s1_ax.q.val());
        self.w_az.next = bit_cast::<9, 8>(self.s1_az.q.val());
        self.s2_dxz.d.next = self.w_ax.val() - self.w_az.val();
        self.s2_ax.d.next = self.s1_ax.q.val();
        self.s2_az.d.next = self.s1_az.q.val();
        self.s2_sx.d.next = self.s1_sx.q.val();
        self.s2_sz.d.next = self.s1_sz.q.val();
        // stage 3: 2·(ax + az) > 255 ⟺ ax + az ≥ 128 ⟺ bit 7 of the sum
        self.g_mx.next = 127 + self.s2_dxz.q.val(); // 0..254
        self.g_mz.next = 127 - self.s2_dxz.q.val(); // 0..254
        self.twice_sum.next = self.s2_sum.q.val() << 1; // unguarded: sum ≤ 127, so ≤ 254
        if self.s2_sum.q.val().get_bit(7) {
            self.s3_mx.d.next = self.g_mx.val().get_bits::<8>(0); // 0..254 fits U8: exact
            self.s3_mz.d.next = self.g_mz.val().get_bits::<8>(0); // 0..254 fits U8: exact
            self.s3_by.d.next = 1.into();
        } else {
            self.s3_mx.d.next = self.s2_ax.q.val() << 1; // 2·ax ≤ 254 (sum < 128): U8, exact
            self.s3_mz.d.next = self.s2_az.q.val() << 1; // 2·az ≤ 254: U8, exact
            self.s3_by.d.next = 255 - self.twice_sum.val(); // 255 − 2·sum ∈ 1..255: U8, exact
        }
        self.s3_sx.d.next = self.s2_sx.q.val();
        self.s3_sz.d.next = self.s2_sz.q.val();
        // stage 4: restore the signs (INT9)
        self.w_mx.next = bit_cast::<9, 8>(self.s3_mx.q.val());
        self.w_mz.next = bit_cast::<9, 8>(self.s3_mz.q.val());
        if self.s3_sx.q.val() {
            self.s4_bx.d.next = !self.w_mx.val() + 1;
        } else {
            self.s4_bx.d.next = self.w_mx.val();
        }
        if self.s3_sz.q.val() {
            self.s4_bz.d.next = !self.w_mz.val() + 1;
        } else {
            self.s4_bz.d.next = self.w_mz.val();
        }
        self.s4_by.d.next = self.s3_by.q.val();
        self.bump_x.next = self.s4_bx.q.val();
        self.bump_y.next = self.s4_by.q.val();
        self.bump_z.next = self.s4_bz.q.val();
        self.valid_out.next = self.valid.q.val();
    }
}
