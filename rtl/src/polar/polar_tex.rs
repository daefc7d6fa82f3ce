//! The polar pipeline on the texture unit: `polar_pipeline` (US 6,819,319's first embodiment) with the map in the
//! unit's memory, fed by what a rasteriser gives (u, v, and for a MIP filter their screen derivatives) in place of
//! the S and R the host filtered: front (`texture::front`) → S = the texel's low byte, R = its high byte →
//! polar_shade → power → blend, the polar pipeline's own block whole. The front filters S and R as plain numbers
//! (the seed's shortcoming 2 across R's wrap, now made by the hardware). The light's bytes (Q, k1, k2, k3), p, the
//! blend's mode and colours wait beside the front in one block-RAM line (89 bits), then enter the polar pipeline
//! with the texel. Named `polar_tex_<filter>` (`vectors::polar_tex`).

use crate::polar_pipeline::PolarPipeline;
use crate::prim::q::{Sq11_8, Sq3_8, Sq8_8, U16, U8};
use crate::prim::ram_delay::RamDelay;
#[allow(unused_imports)] // each pipeline holds one
use crate::texture::front::{TexBilinear, TexTrilinear};
use rust_hdl::prelude::*;

/// The polar pipeline's signal its Verilog leaves unused on purpose (its module's own name for it).
const POLAR: &[crate::stream::Waiver] = &[(
    "shader$sum",
    "polar_shade's S11 before the clamp is an output for tests and waveforms; the pipeline uses the clamped shade",
)];

/// The side-band word's width: Q, k1, k2, k3, p (five bytes), the mode bit, the source and destination colours.
const SIDE_BITS: usize = 5 * 8 + 1 + 6 * 8;

macro_rules! polar_tex_pipeline {
    (
        module: $m:ident,
        block: $t:ident,
        unit: $name:literal,
        texture: { block: $txb:ident, module: $txm:ident }
        $(, mip: { derivatives: [$($dd:ident),*], bias: $lb:ident })?
        $(,)?
    ) => {
pub mod $m {
use super::*;

/// Cycles from the pipeline's input to the polar pipeline's (the front's latency), and to the output.
pub const AT_POLAR: usize = crate::texture::front::$txm::LATENCY;
pub const LATENCY: usize = AT_POLAR + crate::polar_pipeline::LATENCY;
const SIDE_LINE_BITS: usize = crate::prim::ram_delay::addr_bits(AT_POLAR, 5);

crate::stream_block! {
    #[derive(Default)]
    // the front's memory's write port is the map stream
    pub struct $t: unit(
        $name,
        LATENCY,
        map = crate::texture::tex_fetch::MAP,
        waivers = crate::stream::waivers(&[&$txb::waivers()[..], POLAR])
    ) {
        in {
            u: Sq11_8,
            v: Sq11_8,
            log_side: Bits<4>,
            uwrap: Bits<1>,
            vwrap: Bits<1>,
            we: Bits<1>,
            w_log2: Bits<4>,
            wx: U8,
            wy: U8,
            wdata: U16,
            $($($dd: Sq8_8,)* $lb: Sq3_8,)?
            q: U8,
            k1: U8,
            k2: U8,
            k3: U8,
            pw: U8,
            mode: Bits<1>,
            src_r: U8,
            src_g: U8,
            src_b: U8,
            dst_r: U8,
            dst_g: U8,
            dst_b: U8,
        }
        out {
            alpha: U8,
            out_r: U8,
            out_g: U8,
            out_b: U8,
        }
        pub texture: $txb,
        // (q, k1, k2, k3, pw, mode, src_r, src_g, src_b, dst_r, dst_g, dst_b) packed low to high
        side_dly: RamDelay<SIDE_BITS, SIDE_LINE_BITS, AT_POLAR>,
        side_word: Signal<Local, Bits<SIDE_BITS>>,
        pub polar: PolarPipeline<false>,
    }
}

impl Logic for $t {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, texture, side_dly, polar);
        // the front: the position, the map's modes and its write port in; the texel's two bytes out
        self.texture.valid_in.next = self.valid_in.val();
        self.texture.u.next = self.u.val();
        self.texture.v.next = self.v.val();
        self.texture.log_side.next = self.log_side.val();
        self.texture.uwrap.next = self.uwrap.val();
        self.texture.vwrap.next = self.vwrap.val();
        self.texture.we.next = self.we.val();
        self.texture.w_log2.next = self.w_log2.val();
        self.texture.wx.next = self.wx.val();
        self.texture.wy.next = self.wy.val();
        self.texture.wdata.next = self.wdata.val();
        $($(self.texture.$dd.next = self.$dd.val();)* self.texture.lod_bias.next = self.$lb.val();)?
        // the side band waits for the front (bit copies, no arithmetic)
        self.side_word.next = bit_cast::<SIDE_BITS, 8>(self.q.val());
        self.side_word.next = self.side_word.val() | (bit_cast::<SIDE_BITS, 8>(self.k1.val()) << 8);
        self.side_word.next = self.side_word.val() | (bit_cast::<SIDE_BITS, 8>(self.k2.val()) << 16);
        self.side_word.next = self.side_word.val() | (bit_cast::<SIDE_BITS, 8>(self.k3.val()) << 24);
        self.side_word.next = self.side_word.val() | (bit_cast::<SIDE_BITS, 8>(self.pw.val()) << 32);
        self.side_word.next = self.side_word.val() | (bit_cast::<SIDE_BITS, 1>(self.mode.val()) << 40);
        self.side_word.next = self.side_word.val() | (bit_cast::<SIDE_BITS, 8>(self.src_r.val()) << 41);
        self.side_word.next = self.side_word.val() | (bit_cast::<SIDE_BITS, 8>(self.src_g.val()) << 49);
        self.side_word.next = self.side_word.val() | (bit_cast::<SIDE_BITS, 8>(self.src_b.val()) << 57);
        self.side_word.next = self.side_word.val() | (bit_cast::<SIDE_BITS, 8>(self.dst_r.val()) << 65);
        self.side_word.next = self.side_word.val() | (bit_cast::<SIDE_BITS, 8>(self.dst_g.val()) << 73);
        self.side_word.next = self.side_word.val() | (bit_cast::<SIDE_BITS, 8>(self.dst_b.val()) << 81);
        self.side_dly.d.next = self.side_word.val();
        // the polar pipeline: S the texel's low byte, R its high byte, the rest from the line
        self.polar.valid_in.next = self.texture.valid_out.val();
        self.polar.s.next = self.texture.lo.val();
        self.polar.r.next = self.texture.hi.val();
        self.polar.q.next = self.side_dly.q.val().get_bits::<8>(0);
        self.polar.k1.next = self.side_dly.q.val().get_bits::<8>(8);
        self.polar.k2.next = self.side_dly.q.val().get_bits::<8>(16);
        self.polar.k3.next = self.side_dly.q.val().get_bits::<8>(24);
        self.polar.pw.next = self.side_dly.q.val().get_bits::<8>(32);
        self.polar.mode.next = self.side_dly.q.val().get_bits::<1>(40);
        self.polar.src_r.next = self.side_dly.q.val().get_bits::<8>(41);
        self.polar.src_g.next = self.side_dly.q.val().get_bits::<8>(49);
        self.polar.src_b.next = self.side_dly.q.val().get_bits::<8>(57);
        self.polar.dst_r.next = self.side_dly.q.val().get_bits::<8>(65);
        self.polar.dst_g.next = self.side_dly.q.val().get_bits::<8>(73);
        self.polar.dst_b.next = self.side_dly.q.val().get_bits::<8>(81);
        self.valid_out.next = self.polar.valid_out.val();
        self.alpha.next = self.polar.alpha.val();
        self.out_r.next = self.polar.out_r.val();
        self.out_g.next = self.polar.out_g.val();
        self.out_b.next = self.polar.out_b.val();
    }
}
}
pub use $m::$t;
    };
}

polar_tex_pipeline! {
    module: bilinear,
    block: PolarTexBilinear,
    unit: "polar_tex_bilinear",
    texture: { block: TexBilinear, module: bilinear },
}

polar_tex_pipeline! {
    module: trilinear,
    block: PolarTexTrilinear,
    unit: "polar_tex_trilinear",
    texture: { block: TexTrilinear, module: trilinear },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
}
