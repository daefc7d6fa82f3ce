//! Tarini et al.'s palette pipeline on the texture unit: `palette_pipeline` with the index map (and, for the MIP
//! filter, its §5.2 levels: each texel the index nearest the average of the four normals below it) in the unit's
//! memory, fed by what a rasteriser gives (u, v, and for the MIP filter their screen derivatives) in place of the
//! index the host fetched: front (`texture::front`, nearest or nearest-MIP: an index is never filtered) → the
//! texel's low byte is the index → palette_pipeline (the table builder and the two colour tables) whole. The
//! pixel's frame and the builder's vector (the normal, L, H, C and the specular colour, 144 bits) wait beside the
//! front in two block-RAM lines, then enter the palette pipeline with the index, so a vector's build and its read
//! still reach the table RAM together. Named `palette_tex_<filter>` (`vectors::palette_tex`).

use crate::palette_pipeline::PalettePipeline;
use crate::prim::q::{Sq11_8, Sq1_10, Sq3_8, Sq8_8, Sq9_0, U16, U8};
use crate::prim::ram_delay::RamDelay;
#[allow(unused_imports)] // each pipeline holds one
use crate::texture::front::{TexNearest, TexNearestMip};
use rust_hdl::prelude::*;

/// The texel's high byte, unused: an 8-bit index is the low byte (the front's module's own name for it).
const INDEX: &[crate::stream::Waiver] =
    &[("texture$hi", "an 8-bit index is the texel's low byte; the high byte is read from the memory and not used")];

/// The side band's two words, 72 bits each (two block-RAM lines of 36-bit words; each word within the width
/// analysis' 128 bits): A holds frame, build (a bit each), b_idx (8), the normal (3 × 10), l_x, l_y (12 each) and C
/// (8); B holds l_z, H (4 × 12) and the specular colour (3 × 8).
const SIDE_BITS: usize = 72;

macro_rules! palette_tex_pipeline {
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

/// Cycles from the pipeline's input to the palette pipeline's (the front's latency), and to the output.
pub const AT_PALETTE: usize = crate::texture::front::$txm::LATENCY;
pub const LATENCY: usize = AT_PALETTE + crate::palette_pipeline::LATENCY;
const SIDE_LINE_BITS: usize = crate::prim::ram_delay::addr_bits(AT_PALETTE, 5);

crate::stream_block! {
    #[derive(Default)]
    // the front's memory's write port is the map stream
    pub struct $t: unit(
        $name,
        LATENCY,
        map = crate::texture::tex_fetch::MAP,
        waivers = crate::stream::waivers(&[&$txb::waivers()[..], crate::table_builder::WAIVERS, INDEX])
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
            frame: Bits<1>,
            build: Bits<1>,
            b_idx: Bits<8>,
            n_x: Sq9_0,
            n_y: Sq9_0,
            n_z: Sq9_0,
            l_x: Sq1_10,
            l_y: Sq1_10,
            l_z: Sq1_10,
            h_x: Sq1_10,
            h_y: Sq1_10,
            h_z: Sq1_10,
            conc: U8,
            spec_r: U8,
            spec_g: U8,
            spec_b: U8,
        }
        out {
            out_r: U8,
            out_g: U8,
            out_b: U8,
            out_a: U8,
        }
        pub texture: $txb,
        // A: (frame, build, b_idx, n_x, n_y, n_z, l_x, l_y, conc) packed low to high; B: (l_z, h_x, h_y, h_z,
        // spec_r, spec_g, spec_b)
        side_a_dly: RamDelay<SIDE_BITS, SIDE_LINE_BITS, AT_PALETTE>,
        side_b_dly: RamDelay<SIDE_BITS, SIDE_LINE_BITS, AT_PALETTE>,
        side_a: Signal<Local, Bits<SIDE_BITS>>,
        side_b: Signal<Local, Bits<SIDE_BITS>>,
        pub palette: PalettePipeline<8, 9>,
    }
}

impl Logic for $t {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, texture, side_a_dly, side_b_dly, palette);
        // the front: the position, the map's modes and its write port in; the texel out
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
        self.side_a.next = bit_cast::<SIDE_BITS, 1>(self.frame.val());
        self.side_a.next = self.side_a.val() | (bit_cast::<SIDE_BITS, 1>(self.build.val()) << 1);
        self.side_a.next = self.side_a.val() | (bit_cast::<SIDE_BITS, 8>(self.b_idx.val()) << 2);
        self.side_a.next = self.side_a.val() | (bit_cast::<SIDE_BITS, 10>(self.n_x.val()) << 10);
        self.side_a.next = self.side_a.val() | (bit_cast::<SIDE_BITS, 10>(self.n_y.val()) << 20);
        self.side_a.next = self.side_a.val() | (bit_cast::<SIDE_BITS, 10>(self.n_z.val()) << 30);
        self.side_a.next = self.side_a.val() | (bit_cast::<SIDE_BITS, 12>(self.l_x.val()) << 40);
        self.side_a.next = self.side_a.val() | (bit_cast::<SIDE_BITS, 12>(self.l_y.val()) << 52);
        self.side_a.next = self.side_a.val() | (bit_cast::<SIDE_BITS, 8>(self.conc.val()) << 64);
        self.side_b.next = bit_cast::<SIDE_BITS, 12>(self.l_z.val());
        self.side_b.next = self.side_b.val() | (bit_cast::<SIDE_BITS, 12>(self.h_x.val()) << 12);
        self.side_b.next = self.side_b.val() | (bit_cast::<SIDE_BITS, 12>(self.h_y.val()) << 24);
        self.side_b.next = self.side_b.val() | (bit_cast::<SIDE_BITS, 12>(self.h_z.val()) << 36);
        self.side_b.next = self.side_b.val() | (bit_cast::<SIDE_BITS, 8>(self.spec_r.val()) << 48);
        self.side_b.next = self.side_b.val() | (bit_cast::<SIDE_BITS, 8>(self.spec_g.val()) << 56);
        self.side_b.next = self.side_b.val() | (bit_cast::<SIDE_BITS, 8>(self.spec_b.val()) << 64);
        self.side_a_dly.d.next = self.side_a.val();
        self.side_b_dly.d.next = self.side_b.val();
        // the palette pipeline: the index the texel's low byte, the rest from the two lines
        self.palette.valid_in.next = self.texture.valid_out.val();
        self.palette.idx.next = self.texture.lo.val();
        self.palette.frame.next = self.side_a_dly.q.val().get_bits::<1>(0);
        self.palette.build.next = self.side_a_dly.q.val().get_bits::<1>(1);
        self.palette.b_idx.next = self.side_a_dly.q.val().get_bits::<8>(2);
        self.palette.n_x.next = self.side_a_dly.q.val().get_bits::<10>(10);
        self.palette.n_y.next = self.side_a_dly.q.val().get_bits::<10>(20);
        self.palette.n_z.next = self.side_a_dly.q.val().get_bits::<10>(30);
        self.palette.l_x.next = self.side_a_dly.q.val().get_bits::<12>(40);
        self.palette.l_y.next = self.side_a_dly.q.val().get_bits::<12>(52);
        self.palette.conc.next = self.side_a_dly.q.val().get_bits::<8>(64);
        self.palette.l_z.next = self.side_b_dly.q.val().get_bits::<12>(0);
        self.palette.h_x.next = self.side_b_dly.q.val().get_bits::<12>(12);
        self.palette.h_y.next = self.side_b_dly.q.val().get_bits::<12>(24);
        self.palette.h_z.next = self.side_b_dly.q.val().get_bits::<12>(36);
        self.palette.spec_r.next = self.side_b_dly.q.val().get_bits::<8>(48);
        self.palette.spec_g.next = self.side_b_dly.q.val().get_bits::<8>(56);
        self.palette.spec_b.next = self.side_b_dly.q.val().get_bits::<8>(64);
        self.valid_out.next = self.palette.valid_out.val();
        self.out_r.next = self.palette.out_r.val();
        self.out_g.next = self.palette.out_g.val();
        self.out_b.next = self.palette.out_b.val();
        self.out_a.next = self.palette.out_a.val();
    }
}
}
pub use $m::$t;
    };
}

palette_tex_pipeline! {
    module: nearest,
    block: PaletteTexNearest,
    unit: "palette_tex_nearest",
    texture: { block: TexNearest, module: nearest },
}

palette_tex_pipeline! {
    module: nearest_mip,
    block: PaletteTexNearestMip,
    unit: "palette_tex_nearest_mip",
    texture: { block: TexNearestMip, module: nearest_mip },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
}
