//! The wiring every Cartesian pipeline shares, written once: the texel (filtered or the nearest one) → the decode →
//! the bump's normaliser ─┐ the light ─┴→ dot3 → [gloss] → α = P >> 2 → blend, with the side-band values (the
//! light, C, the blend's mode and colours, P) riding beside the stages they skip.
//!
//! `cartesian_pipeline!` writes one block, every argument named: the module, the block and the unit, then the
//! decode (`decode: { block, module, u, v }`: its block, its module, its two texel ports). Its optional groups add
//! what a variant holds, each naming the fields and ports it brings (the group's presence alone sets the filter's
//! latency in front of the decode and the gloss unit's before the blend):
//! - `filter:` two bilinear units (TexelX or U, TexelZ or V), their valid chain and the blend factors' ports;
//! - `nearest:` the two ports the nearest texel comes in on (no filter);
//! - `vertex:` the three vertex lights and the barycentric weights (the ports the group names are the weights),
//!   interpolated per pixel by `light_iter`, waiting for the bump path in three DFF chains, then normalised;
//! - `surface:` one light per surface, already a unit vector (Sq1.10), packed into one 36-bit word that waits in
//!   block RAM for the bump path (no light_iter, no light normaliser);
//! - `gloss:` the gloss unit, C's port and C's block-RAM delay line;
//! - `interval:` (after `texture:`) the clocks a pixel takes, for a front that takes more than one
//!   (`StreamUnit::INTERVAL`); the stages after the front take its texels as they come;
//! - `colour:` (first, and with a front that has a colour map) the blend's destination colour from the front's
//!   colour map in place of the `dst_r`, `dst_g`, `dst_b` ports: the memory select's port, and the delay line that
//!   holds the pixel's mode and lit colour until the front has read its colour; the blend's own line then holds
//!   the three colours for the rest of the way.
//!
//! `cart_pipeline.rs`, `cart_surface.rs` and `cart_tex.rs` invoke it for their blocks.

/// The host-fed filter's two bilinear units (`filter:`), read rounded.
pub const HOST_FILTER: &[crate::stream::Waiver] = &[
    ("filter$0$wide", "the texel's components are read rounded, as the colour filter reads them"),
    ("filter$1$wide", "as filter$0$wide"),
];
/// The per-vertex light path (`vertex:`), whose valid chain the bump path's stands for.
pub const PER_VERTEX: &[crate::stream::Waiver] = &[
    ("light$valid_out", "the light path runs in lockstep with the bump path, whose valid is used"),
    ("light_norm$valid_out", "as light$valid_out"),
];

macro_rules! cartesian_pipeline {
    (colour: { $($c:tt)* }, $($rest:tt)*) => {
        cartesian_pipeline! { @spine colour: { $($c)* }, $($rest)* }
    };
    (
        @spine
        $(dst: { $dr:ident, $dg:ident, $db:ident },)?
        $(colour: { select: $wsel:ident, delay: $sd:ident },)?
        module: $m:ident,
        block: $t:ident,
        unit: $name:literal,
        decode: { block: $dec:ident, module: $dec_mod:ident, u: $tu:ident, v: $tv:ident }
        $(, filter: { units: $fl:ident, valid: $flv:ident, u: $ub:ident, v: $vb:ident })?
        $(, nearest: { x: $nx:ident, z: $nz:ident })?
        $(, texture: { block: $txb:ident, module: $txm:ident, u: $pu:ident, v: $pv:ident })?
        $(, interval: $iv:tt)?
        $(, mip: { derivatives: [$($dd:ident),*], bias: $lb:ident })?
        $(, vertex: { iter: $li:ident, norm: $ln:ident, delay: $lvd:ident, w1: $w1:ident, w2: $w2:ident })?
        $(, surface: { x: $lx:ident, y: $ly:ident, z: $lz:ident, word: $lw:ident, delay: $lsd:ident, addr_bits: $lab:tt })?
        $(, gloss: { unit: $gl:ident, c: $conc:ident, delay: $cd:ident })?
        $(,)?
    ) => {
pub mod $m {
use super::*; // the decode the invocation names
#[allow(unused_imports)] // each variant holds some of these
use crate::{bilinear::BilinearUnit, dot3::Dot3, gloss::Gloss, light_iter::LightIter, normalise::Normalise};
#[allow(unused_imports)]
use crate::texture::front::{
    TexBilinear, TexBilinearColour, TexNearest, TexNearestColour, TexNearestMip, TexNearestMipColour, TexTrilinear,
    TexTrilinearColour, TexTrilinearTwoPass,
};
#[allow(unused_imports)]
use crate::{delayed_blend::DelayedBlend, prim::{delay::Delay, q::{S8, Sq1_10, Sq11_8, Sq3_8, Sq7_2, Sq8_8, Sq9_0, U16, U8}, ram_delay::RamDelay}};

/// Cycles from the pipeline's input to each unit's input.
// a group's term below is there when the invocation names the group (`0 * stringify!(..).len()` only ties it to it)
pub const AT_NORMALISE: usize = $(crate::bilinear::LATENCY + 0 * stringify!($fl).len() +)?
    $(crate::texture::front::$txm::LATENCY + 0 * stringify!($txb).len() +)? crate::$dec_mod::LATENCY;
pub const AT_DOT: usize = AT_NORMALISE + crate::normalise::LATENCY;
pub const AT_GLOSS: usize = AT_DOT + crate::dot3::LATENCY;
pub const AT_BLEND: usize = AT_GLOSS $(+ crate::gloss::LATENCY + 0 * stringify!($gl).len())?;
pub const LATENCY: usize = AT_BLEND + crate::blend::LATENCY;
$(#[doc = concat!("Cycles the light from ", stringify!($li), " waits for the bump path before its normaliser.")]
pub const LIGHT_DELAY: usize = AT_NORMALISE - crate::light_iter::LATENCY;)?
/// Cycles from the pipeline's input to the blend's colour line: 0, or with a colour map the front's latency (the
/// pixel's mode and lit colour wait that long beside the front).
pub const AT_COLOUR: usize = 0 $(+ AT_NORMALISE - crate::$dec_mod::LATENCY + 0 * stringify!($sd).len())?;
/// Address bits of C's line and of the blend's colour line: 2^6 words, more behind the trilinear front.
#[allow(dead_code)] // a matte pipeline has no C line
const CONC_LINE_BITS: usize = crate::prim::ram_delay::addr_bits(AT_GLOSS, 6);
const BLEND_LINE_BITS: usize = crate::prim::ram_delay::addr_bits(AT_BLEND - AT_COLOUR, 6);
/// The map stream's ports: the front's write port, with a colour map its memory select too.
#[allow(dead_code)] // a pipeline without the texture unit has no map stream
const MAP_PORTS: &[&str] = {
    #[allow(unused_variables)] // a colour map's pipeline shadows it
    let m = crate::texture::tex_fetch::MAP;
    $(let _ = stringify!($wsel);
    let m = crate::texture::front::COLOUR_MAP;)?
    m
};

crate::stream_block! {
    #[derive(Default)]
    // with the texture unit, its memory's write port is the map stream (the block only ties the group to it)
    pub struct $t: unit(
        $name,
        LATENCY
        $(, map = { let _ = stringify!($pu); MAP_PORTS })?
        $(, interval = $iv)?,
        // the signals its Verilog leaves unused on purpose: the parts' lists (`StreamUnit::waivers`)
        waivers = crate::stream::waivers(&[
            $({ let _ = stringify!($fl); crate::cartesian::wiring::HOST_FILTER },)?
            $(&$txb::waivers()[..],)?
            $({ let _ = stringify!($li); crate::cartesian::wiring::PER_VERTEX },)?
        ])
    ) {
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
            $($pu: Sq11_8,
            $pv: Sq11_8,
            log_side: Bits<4>,
            uwrap: Bits<1>,
            vwrap: Bits<1>,
            we: Bits<1>,
            w_log2: Bits<4>,
            wx: U8,
            wy: U8,
            wdata: U16,)?
            $($wsel: Bits<1>,)?
            $($($dd: Sq8_8,)* $lb: Sq3_8,)?
            $(l0_x: S8,
            l0_y: S8,
            l0_z: S8,
            l1_x: S8,
            l1_y: S8,
            l1_z: S8,
            l2_x: S8,
            l2_y: S8,
            l2_z: S8,
            $w1: Bits<9>,
            $w2: Bits<9>,)?
            $($lx: Sq1_10,
            $ly: Sq1_10,
            $lz: Sq1_10,)?
            $($conc: U8,)?
            mode: Bits<1>,
            src_r: U8,
            src_g: U8,
            src_b: U8,
            $($dr: U8,
            $dg: U8,
            $db: U8,)?
        }
        out {
            p: Bits<10>,
            out_r: U8,
            out_g: U8,
            out_b: U8,
        }
        $(pub $fl: [BilinearUnit<8, 8>; 2], // TexelX (or U), TexelZ (or V)
        $flv: Delay<Bit, { crate::bilinear::LATENCY }>,)?
        $(pub texture: $txb,)?
        pub decode: $dec,
        pub bump_norm: Normalise,
        $(pub $li: LightIter,
        pub $ln: Normalise,
        $lvd: [Delay<Sq7_2, LIGHT_DELAY>; 3],)?
        pub dot: Dot3,
        $(pub $gl: Gloss,
        $cd: RamDelay<8, CONC_LINE_BITS, AT_GLOSS>,)?
        // (l_x, l_y, l_z) packed low to high, its last clock a register in the fabric: the line's own output register
        // becomes the block RAM's on the ECP5, and its read straight into dot3's first stage was a trilinear
        // pipeline's critical path there (2.62 ns of logic, 3.92 ns of routing)
        $($lsd: RamDelay<36, $lab, { AT_DOT - 1 }>,
        light_q: DFF<Bits<36>>,
        $lw: Signal<Local, Bits<36>>,)?
        $($sd: RamDelay<25, 6, AT_COLOUR>, // (src_r, src_g, src_b, mode) packed low to high
        colour_word: Signal<Local, Bits<25>>,)?
        pub blend: DelayedBlend<BLEND_LINE_BITS, { AT_BLEND - AT_COLOUR }>,
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
        clock!(self, clock, decode, bump_norm, dot, blend, p_dly);
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
        // or the texture unit's: the position, the map's modes and its write port in; the texel's two bytes out
        $(self.texture.clock.next = self.clock.val();
        self.texture.valid_in.next = self.valid_in.val();
        self.texture.u.next = self.$pu.val();
        self.texture.v.next = self.$pv.val();
        self.texture.log_side.next = self.log_side.val();
        self.texture.uwrap.next = self.uwrap.val();
        self.texture.vwrap.next = self.vwrap.val();
        self.texture.we.next = self.we.val();
        self.texture.w_log2.next = self.w_log2.val();
        self.texture.wx.next = self.wx.val();
        self.texture.wy.next = self.wy.val();
        self.texture.wdata.next = self.wdata.val();
        self.decode.valid_in.next = self.texture.valid_out.val();
        self.decode.$tu.next = self.texture.lo.val();
        self.decode.$tv.next = self.texture.hi.val();)?
        $($(self.texture.$dd.next = self.$dd.val();)* self.texture.lod_bias.next = self.$lb.val();)?
        $(self.texture.wcolour.next = self.$wsel.val();)? // the memory a write goes to
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
        // the vertex lights: interpolate, wait for the bump path, normalise
        $(self.$li.clock.next = self.clock.val();
        self.$ln.clock.next = self.clock.val();
        for i in 0..3 {
            self.$lvd[i].clock.next = self.clock.val();
        }
        self.$li.valid_in.next = self.valid_in.val();
        self.$li.l0_x.next = self.l0_x.val();
        self.$li.l0_y.next = self.l0_y.val();
        self.$li.l0_z.next = self.l0_z.val();
        self.$li.l1_x.next = self.l1_x.val();
        self.$li.l1_y.next = self.l1_y.val();
        self.$li.l1_z.next = self.l1_z.val();
        self.$li.l2_x.next = self.l2_x.val();
        self.$li.l2_y.next = self.l2_y.val();
        self.$li.l2_z.next = self.l2_z.val();
        self.$li.w1.next = self.$w1.val();
        self.$li.w2.next = self.$w2.val();
        self.$lvd[0].d.next = self.$li.light_x.val();
        self.$lvd[1].d.next = self.$li.light_y.val();
        self.$lvd[2].d.next = self.$li.light_z.val();
        self.$ln.valid_in.next = self.decode.valid_out.val();
        self.$ln.vec_x.next = self.$lvd[0].q.val();
        self.$ln.vec_y.next = self.$lvd[1].q.val();
        self.$ln.vec_z.next = self.$lvd[2].q.val();
        self.dot.l_x.next = self.$ln.norm_x.val();
        self.dot.l_y.next = self.$ln.norm_y.val();
        self.dot.l_z.next = self.$ln.norm_z.val();)?
        // or the surface's light waits for the bump path (three Sq1.10 in one 36-bit word: bit copies, no arithmetic)
        $(self.$lsd.clock.next = self.clock.val();
        self.light_q.clock.next = self.clock.val();
        self.$lw.next = bit_cast::<36, 12>(self.$lx.val());
        self.$lw.next = self.$lw.val() | (bit_cast::<36, 12>(self.$ly.val()) << 12);
        self.$lw.next = self.$lw.val() | (bit_cast::<36, 12>(self.$lz.val()) << 24);
        self.$lsd.d.next = self.$lw.val();
        self.light_q.d.next = self.$lsd.q.val();
        self.dot.l_x.next = self.light_q.q.val().get_bits::<12>(0);
        self.dot.l_y.next = self.light_q.q.val().get_bits::<12>(12);
        self.dot.l_z.next = self.light_q.q.val().get_bits::<12>(24);)?
        // N·L
        self.dot.valid_in.next = self.bump_norm.valid_out.val();
        self.dot.n_x.next = self.bump_norm.norm_x.val();
        self.dot.n_y.next = self.bump_norm.norm_y.val();
        self.dot.n_z.next = self.bump_norm.norm_z.val();
        // glossiness, where the material has it; without, P = X (the gloss unit's own C = 0)
        self.shade.next = self.dot.x.val();
        self.shade_valid.next = self.dot.valid_out.val();
        $(self.$cd.d.next = self.$conc.val();
        self.$gl.valid_in.next = self.dot.valid_out.val();
        self.$gl.conc.next = self.$cd.q.val();
        self.$gl.x.next = self.dot.x.val();
        self.shade.next = self.$gl.p.val();
        self.shade_valid.next = self.$gl.valid_out.val();)?
        // blend: α = P >> 2 (U10 → U8, truncate); the colours and mode as they come
        $(self.blend.mode.next = self.mode.val();
        self.blend.src_r.next = self.src_r.val();
        self.blend.src_g.next = self.src_g.val();
        self.blend.src_b.next = self.src_b.val();
        self.blend.dst_r.next = self.$dr.val();
        self.blend.dst_g.next = self.$dg.val();
        self.blend.dst_b.next = self.$db.val();)?
        // or the mode and lit colour after waiting for the front, the destination the front's colour (bit copies)
        $(self.$sd.clock.next = self.clock.val();
        self.colour_word.next = bit_cast::<25, 8>(self.src_r.val());
        self.colour_word.next = self.colour_word.val() | (bit_cast::<25, 8>(self.src_g.val()) << 8);
        self.colour_word.next = self.colour_word.val() | (bit_cast::<25, 8>(self.src_b.val()) << 16);
        self.colour_word.next = self.colour_word.val() | (bit_cast::<25, 1>(self.mode.val()) << 24);
        self.$sd.d.next = self.colour_word.val();
        self.blend.src_r.next = self.$sd.q.val().get_bits::<8>(0);
        self.blend.src_g.next = self.$sd.q.val().get_bits::<8>(8);
        self.blend.src_b.next = self.$sd.q.val().get_bits::<8>(16);
        self.blend.mode.next = self.$sd.q.val().get_bits::<1>(24);
        self.blend.dst_r.next = self.texture.c_r.val();
        self.blend.dst_g.next = self.texture.c_g.val();
        self.blend.dst_b.next = self.texture.c_b.val();)?
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
    ($($rest:tt)*) => {
        cartesian_pipeline! { @spine dst: { dst_r, dst_g, dst_b }, $($rest)* }
    };
}

pub(crate) use cartesian_pipeline;
