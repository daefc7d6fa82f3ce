//! `cart_surface`: seed 000's Cartesian pipeline for a scene with one light per surface (a directional light, or
//! a point light taken at the surface's centre): the light arrives already a unit vector, once per surface, so the
//! pipeline holds no `light_iter` and no light normaliser. The light still travels with each pixel (a curved
//! surface's triangles each have their own), in one block-RAM delay line to the dot product.
//! bilinear(TexelX, TexelZ) → cart_decode → normalise ─┐
//! L (unit, Sq1.10) ─────────── (RAM delay 26) ────────┴→ dot3 → gloss(C) → α = P >> 2 → blend.
//! Latency 48 = bilinear 11 + cart_decode 4 + normalise 11 + dot3 6 + gloss 11 + blend 5.
//!
//! `cart_surface_matte` is the same pipeline for a material with C = 0, where the gloss unit's P = X: it holds no
//! gloss unit and has no C port, and α = X >> 2 (latency 37). The `_hemi_oct` variants read hemi-octahedral texels
//! through `cart_decode_hemi_oct` (one clock less). A macro writes all four, so each exported Verilog holds only
//! its own units.

use crate::bilinear::BilinearUnit;
use crate::cart_decode::CartDecode;
use crate::cart_decode_hemi_oct::CartDecodeHemiOct;
use crate::delay::Delay;
use crate::dot3::Dot3;
use crate::gloss::Gloss;
use crate::normalise::Normalise;
use crate::ram_delay::{DelayedBlend, RamDelay};
use rust_hdl::prelude::*;

// `$front` is the filter's latency. With `filter:`, the texel comes through two bilinear units (the group names
// them, their valid chain and the blend factors' ports); with `nearest:`, the nearest texel comes in on the two ports the group names. `$g`
// is 1 with a gloss unit, 0 without; with one, the `gloss:` group names its block, C's port and C's delay line.
macro_rules! cart_surface {
    ($m:ident, $t:ident, $name:literal, $dec:ident, $dec_mod:ident, $tu:ident, $tv:ident, $front:expr, $g:literal
        $(, filter: $fl:ident, $flv:ident, $ub:ident, $vb:ident)? $(, nearest: $nx:ident, $nz:ident)? $(, gloss: $gl:ident, $conc:ident, $cd:ident)?) => {
pub mod $m {
use super::*;
use crate::q::{Sq1_10, Sq9_0, U8};

/// Cycles from the pipeline's input to each unit's input.
pub const AT_NORMALISE: usize = $front + crate::$dec_mod::LATENCY;
pub const AT_DOT: usize = AT_NORMALISE + crate::normalise::LATENCY;
pub const AT_GLOSS: usize = AT_DOT + crate::dot3::LATENCY;
pub const AT_BLEND: usize = AT_GLOSS + $g * crate::gloss::LATENCY;
pub const LATENCY: usize = AT_BLEND + crate::blend::LATENCY;

crate::stream_block! {
    #[derive(Default)]
    pub struct $t: unit($name, LATENCY) {
        in {
            $(t00_x: U8,
            t00_z: U8,
            t10_x: U8,
            t10_z: U8,
            t01_x: U8,
            t01_z: U8,
            t11_x: U8,
            t11_z: U8,
            $ub: U8,
            $vb: U8,)?
            $($nx: U8,
            $nz: U8,)?
            l_x: Sq1_10,
            l_y: Sq1_10,
            l_z: Sq1_10,
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
        $(pub $fl: [BilinearUnit<8, 8>; 2], // TexelX (or U), TexelZ (or V)
        $flv: Delay<Bit, { crate::bilinear::LATENCY }>,)?
        pub decode: $dec,
        pub bump_norm: Normalise,
        pub dot: Dot3,
        $(pub $gl: Gloss,
        $cd: RamDelay<8, 6, AT_GLOSS>,)?
        light_dly: RamDelay<36, 5, AT_DOT>, // (l_x, l_y, l_z) packed low to high
        pub blend: DelayedBlend<6, AT_BLEND>,
        p_dly: Delay<Bits<10>, { crate::blend::LATENCY }>,
        bump_x10: Signal<Local, Sq9_0>,
        bump_z10: Signal<Local, Sq9_0>,
        light_word: Signal<Local, Bits<36>>,
        shade: Signal<Local, Bits<10>>, // P (U10): X when the pipeline has no gloss unit
        shade_valid: Signal<Local, Bit>,
    }
}

impl Logic for $t {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, decode, bump_norm, dot, light_dly, blend, p_dly);
        $(self.$gl.clock.next = self.clock.val();
        self.$cd.clock.next = self.clock.val();)?
        // filter: two bilinear units, TexelX (or U) and TexelZ (or V); then decode the filtered texel
        $(for i in 0..2 {
            self.$fl[i].clock.next = self.clock.val();
            self.$fl[i].ublend.next = self.$ub.val();
            self.$fl[i].vblend.next = self.$vb.val();
        }
        self.$flv.clock.next = self.clock.val();
        self.$flv.d.next = self.valid_in.val();
        self.$fl[0].t00.next = self.t00_x.val();
        self.$fl[0].t10.next = self.t10_x.val();
        self.$fl[0].t01.next = self.t01_x.val();
        self.$fl[0].t11.next = self.t11_x.val();
        self.$fl[1].t00.next = self.t00_z.val();
        self.$fl[1].t10.next = self.t10_z.val();
        self.$fl[1].t01.next = self.t01_z.val();
        self.$fl[1].t11.next = self.t11_z.val();
        self.decode.valid_in.next = self.$flv.q.val();
        self.decode.$tu.next = self.$fl[0].out.val();
        self.decode.$tv.next = self.$fl[1].out.val();)?
        // or decode the nearest texel as it comes
        $(self.decode.valid_in.next = self.valid_in.val();
        self.decode.$tu.next = self.$nx.val();
        self.decode.$tv.next = self.$nz.val();)?
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
        // the surface's light waits for the bump path (three Sq1.10 in one 36-bit word: bit copies, no arithmetic)
        self.light_word.next = bit_cast::<36, 12>(self.l_x.val());
        self.light_word.next = self.light_word.val() | (bit_cast::<36, 12>(self.l_y.val()) << 12);
        self.light_word.next = self.light_word.val() | (bit_cast::<36, 12>(self.l_z.val()) << 24);
        self.light_dly.d.next = self.light_word.val();
        // N·L
        self.dot.valid_in.next = self.bump_norm.valid_out.val();
        self.dot.n_x.next = self.bump_norm.norm_x.val();
        self.dot.n_y.next = self.bump_norm.norm_y.val();
        self.dot.n_z.next = self.bump_norm.norm_z.val();
        self.dot.l_x.next = self.light_dly.q.val().get_bits::<12>(0);
        self.dot.l_y.next = self.light_dly.q.val().get_bits::<12>(12);
        self.dot.l_z.next = self.light_dly.q.val().get_bits::<12>(24);
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

const BILINEAR: usize = crate::bilinear::LATENCY;

cart_surface!(seed, CartSurface, "cart_surface", CartDecode, cart_decode, texel_x, texel_z, BILINEAR, 1, filter: filter, filter_valid, ublend, vblend, gloss: gloss, conc, conc_dly);
cart_surface!(matte, CartSurfaceMatte, "cart_surface_matte", CartDecode, cart_decode, texel_x, texel_z, BILINEAR, 0, filter: filter, filter_valid, ublend, vblend);
cart_surface!(hemi_oct, CartSurfaceHemiOct, "cart_surface_hemi_oct", CartDecodeHemiOct, cart_decode_hemi_oct, texel_u, texel_v, BILINEAR, 1, filter: filter, filter_valid, ublend, vblend, gloss: gloss, conc, conc_dly);
cart_surface!(hemi_oct_matte, CartSurfaceHemiOctMatte, "cart_surface_hemi_oct_matte", CartDecodeHemiOct, cart_decode_hemi_oct, texel_u, texel_v, BILINEAR, 0, filter: filter, filter_valid, ublend, vblend);
cart_surface!(nearest, CartSurfaceNearest, "cart_surface_nearest", CartDecode, cart_decode, texel_x, texel_z, 0, 1, nearest: t_x, t_z, gloss: gloss, conc, conc_dly);
cart_surface!(nearest_matte, CartSurfaceNearestMatte, "cart_surface_nearest_matte", CartDecode, cart_decode, texel_x, texel_z, 0, 0, nearest: t_x, t_z);
cart_surface!(nearest_hemi_oct, CartSurfaceNearestHemiOct, "cart_surface_nearest_hemi_oct", CartDecodeHemiOct, cart_decode_hemi_oct, texel_u, texel_v, 0, 1, nearest: t_x, t_z, gloss: gloss, conc, conc_dly);
cart_surface!(nearest_hemi_oct_matte, CartSurfaceNearestHemiOctMatte, "cart_surface_nearest_hemi_oct_matte", CartDecodeHemiOct, cart_decode_hemi_oct, texel_u, texel_v, 0, 0, nearest: t_x, t_z);
