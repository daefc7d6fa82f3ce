//! `cart_pipeline`: seed 000's second embodiment, one pixel per clock, built from the unit blocks themselves:
//! bilinear(TexelX, TexelZ) → cart_decode → normalise ─────────────┐
//! light_iter → (delay 7) → normalise ─────────────────────────────┴→ dot3 → gloss → α = P >> 2 → blend.
//! Side-band values ride beside the stages they skip: C in a block-RAM delay line (`RamDelay`), the mode and the
//! colours in the `DelayedBlend`, the light and P in short DFF chains.
//! Latency 48 = bilinear 11 + cart_decode 4 + normalise 11 + dot3 6 + gloss 11 + blend 5.
//!
//! Four variants from one macro, so each exported Verilog holds only its own units:
//! - `CartPipeline` (`cart_pipeline`): the seed's offset-binary texels through `cart_decode`;
//! - `CartPipelineHemiOct` (`cart_pipeline_hemi_oct`): rotated hemi-octahedral texels (U on the red channel, V on
//!   green) through `cart_decode_hemi_oct`, latency 47. Bilinear filtering of (U, V) is filtering of (x, z): the
//!   map between them is linear.
//! - `CartPipelineMatte` (`cart_pipeline_matte`) and `CartPipelineHemiOctMatte` (`cart_pipeline_hemi_oct_matte`):
//!   the same for a material with C = 0, where the gloss unit's P = X: no gloss unit, no C port, no C delay line,
//!   α = X >> 2 (latency 37 and 36).

use crate::bilinear::BilinearUnit;
use crate::cart_decode::CartDecode;
use crate::cart_decode_hemi_oct::CartDecodeHemiOct;
use crate::delay::Delay;
use crate::dot3::Dot3;
use crate::gloss::Gloss;
use crate::light_iter::LightIter;
use crate::normalise::Normalise;
use crate::ram_delay::{DelayedBlend, RamDelay};
use rust_hdl::prelude::*;


macro_rules! cart_pipeline {
    ($m:ident, $t:ident, $name:literal, $dec:ident, $dec_mod:ident, $tu:ident, $tv:ident, $g:literal
        $(, gloss: $gl:ident, $conc:ident, $cd:ident)?) => {
pub mod $m {
use super::*;
use crate::q::{S8, Sq7_2, Sq9_0, U8};

/// Cycles from the pipeline's input to each unit's input (seed decode: 15, 8, 32, 43, 48; matte: 15, 8, 32, 32, 37).
pub const AT_NORMALISE: usize = crate::bilinear::LATENCY + crate::$dec_mod::LATENCY;
pub const LIGHT_DELAY: usize = AT_NORMALISE - crate::light_iter::LATENCY;
pub const AT_GLOSS: usize = AT_NORMALISE + crate::normalise::LATENCY + crate::dot3::LATENCY;
pub const AT_BLEND: usize = AT_GLOSS + $g * crate::gloss::LATENCY;
pub const LATENCY: usize = AT_BLEND + crate::blend::LATENCY;

crate::stream_block! {
    #[derive(Default)]
    pub struct $t: unit($name, LATENCY) {
        in {
            t00_x: U8,
            t00_z: U8,
            t10_x: U8,
            t10_z: U8,
            t01_x: U8,
            t01_z: U8,
            t11_x: U8,
            t11_z: U8,
            ublend: U8,
            vblend: U8,
            l0_x: S8,
            l0_y: S8,
            l0_z: S8,
            l1_x: S8,
            l1_y: S8,
            l1_z: S8,
            l2_x: S8,
            l2_y: S8,
            l2_z: S8,
            w1: Bits<9>,
            w2: Bits<9>,
            $($conc: U8,)?
            mode: Bits<1>,
            src_r: U8,
            src_g: U8,
            src_b: U8,
            dst_r: U8,
            dst_g: U8,
            dst_b: U8,
        }
        out {
            p: Bits<10>,
            out_r: U8,
            out_g: U8,
            out_b: U8,
        }
        pub filter: [BilinearUnit<8, 8>; 2], // TexelX (or U), TexelZ (or V)
        filter_valid: Delay<Bit, { crate::bilinear::LATENCY }>,
        pub decode: $dec,
        pub bump_norm: Normalise,
        pub light: LightIter,
        pub light_norm: Normalise,
        pub dot: Dot3,
        $(pub $gl: Gloss,
        $cd: RamDelay<8, 6, AT_GLOSS>,)?
        light_dly: [Delay<Sq7_2, LIGHT_DELAY>; 3],
        pub blend: DelayedBlend<6, AT_BLEND>,
        p_dly: Delay<Bits<10>, { crate::blend::LATENCY }>,
        bump_x10: Signal<Local, Sq9_0>,
        bump_z10: Signal<Local, Sq9_0>,
        shade: Signal<Local, Bits<10>>, // P (U10): X when the pipeline has no gloss unit
        shade_valid: Signal<Local, Bit>,
    }
}

impl Logic for $t {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, filter_valid, decode, bump_norm, light, light_norm, dot, blend, p_dly);
        $(self.$gl.clock.next = self.clock.val();
        self.$cd.clock.next = self.clock.val();)?
        for i in 0..3 {
            self.light_dly[i].clock.next = self.clock.val();
        }
        // filter: two bilinear units, TexelX (or U) and TexelZ (or V)
        for i in 0..2 {
            self.filter[i].clock.next = self.clock.val();
            self.filter[i].ublend.next = self.ublend.val();
            self.filter[i].vblend.next = self.vblend.val();
        }
        self.filter_valid.d.next = self.valid_in.val();
        self.filter[0].t00.next = self.t00_x.val();
        self.filter[0].t10.next = self.t10_x.val();
        self.filter[0].t01.next = self.t01_x.val();
        self.filter[0].t11.next = self.t11_x.val();
        self.filter[1].t00.next = self.t00_z.val();
        self.filter[1].t10.next = self.t10_z.val();
        self.filter[1].t01.next = self.t01_z.val();
        self.filter[1].t11.next = self.t11_z.val();
        // decode the filtered texel
        self.decode.valid_in.next = self.filter_valid.q.val();
        self.decode.$tu.next = self.filter[0].out.val();
        self.decode.$tv.next = self.filter[1].out.val();
        // normalise the bump: INT9 → S10 by sign extension, UINT8 → S10 by zero extension
        self.bump_x10.next = bit_cast::<10, 9>(self.decode.bump_x.val());
        if self.decode.bump_x.val().get_bit(8) {
            self.bump_x10.next = self.bump_x10.val() | 0x200;
        }
        self.bump_z10.next = bit_cast::<10, 9>(self.decode.bump_z.val());
        if self.decode.bump_z.val().get_bit(8) {
            self.bump_z10.next = self.bump_z10.val() | 0x200;
        }
        self.bump_norm.valid_in.next = self.decode.valid_out.val();
        self.bump_norm.vec_x.next = self.bump_x10.val();
        self.bump_norm.vec_y.next = bit_cast::<10, 8>(self.decode.bump_y.val());
        self.bump_norm.vec_z.next = self.bump_z10.val();
        // the light: interpolate, wait for the bump path, normalise
        self.light.valid_in.next = self.valid_in.val();
        self.light.l0_x.next = self.l0_x.val();
        self.light.l0_y.next = self.l0_y.val();
        self.light.l0_z.next = self.l0_z.val();
        self.light.l1_x.next = self.l1_x.val();
        self.light.l1_y.next = self.l1_y.val();
        self.light.l1_z.next = self.l1_z.val();
        self.light.l2_x.next = self.l2_x.val();
        self.light.l2_y.next = self.l2_y.val();
        self.light.l2_z.next = self.l2_z.val();
        self.light.w1.next = self.w1.val();
        self.light.w2.next = self.w2.val();
        self.light_dly[0].d.next = self.light.light_x.val();
        self.light_dly[1].d.next = self.light.light_y.val();
        self.light_dly[2].d.next = self.light.light_z.val();
        self.light_norm.valid_in.next = self.decode.valid_out.val();
        self.light_norm.vec_x.next = self.light_dly[0].q.val();
        self.light_norm.vec_y.next = self.light_dly[1].q.val();
        self.light_norm.vec_z.next = self.light_dly[2].q.val();
        // N·L
        self.dot.valid_in.next = self.bump_norm.valid_out.val();
        self.dot.n_x.next = self.bump_norm.norm_x.val();
        self.dot.n_y.next = self.bump_norm.norm_y.val();
        self.dot.n_z.next = self.bump_norm.norm_z.val();
        self.dot.l_x.next = self.light_norm.norm_x.val();
        self.dot.l_y.next = self.light_norm.norm_y.val();
        self.dot.l_z.next = self.light_norm.norm_z.val();
        // glossiness, where the material has it; without, P = X (the gloss unit's own C = 0)
        self.shade.next = self.dot.x.val();
        self.shade_valid.next = self.dot.valid_out.val();
        $(self.$cd.d.next = self.$conc.val();
        self.$gl.valid_in.next = self.dot.valid_out.val();
        self.$gl.conc.next = self.$cd.q.val();
        self.$gl.x.next = self.dot.x.val();
        self.shade.next = self.$gl.p.val();
        self.shade_valid.next = self.$gl.valid_out.val();)?
        // blend: α = P >> 2 (U10 → U8, truncate)
        self.blend.mode.next = self.mode.val();
        self.blend.src_r.next = self.src_r.val();
        self.blend.src_g.next = self.src_g.val();
        self.blend.src_b.next = self.src_b.val();
        self.blend.dst_r.next = self.dst_r.val();
        self.blend.dst_g.next = self.dst_g.val();
        self.blend.dst_b.next = self.dst_b.val();
        self.blend.valid_in.next = self.shade_valid.val();
        self.blend.alpha.next = self.shade.val().get_bits::<8>(2);
        self.p_dly.d.next = self.shade.val();
        self.valid_out.next = self.blend.valid_out.val();
        self.p.next = self.p_dly.q.val();
        self.out_r.next = self.blend.out_r.val();
        self.out_g.next = self.blend.out_g.val();
        self.out_b.next = self.blend.out_b.val();
    }
}

}
pub use $m::$t;
    };
}

cart_pipeline!(seed, CartPipeline, "cart_pipeline", CartDecode, cart_decode, texel_x, texel_z, 1, gloss: gloss, conc, conc_dly);
cart_pipeline!(matte, CartPipelineMatte, "cart_pipeline_matte", CartDecode, cart_decode, texel_x, texel_z, 0);
cart_pipeline!(hemi_oct, CartPipelineHemiOct, "cart_pipeline_hemi_oct", CartDecodeHemiOct, cart_decode_hemi_oct, texel_u, texel_v, 1, gloss: gloss, conc, conc_dly);
cart_pipeline!(hemi_oct_matte, CartPipelineHemiOctMatte, "cart_pipeline_hemi_oct_matte", CartDecodeHemiOct, cart_decode_hemi_oct, texel_u, texel_v, 0);
