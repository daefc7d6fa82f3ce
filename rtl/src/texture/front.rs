//! The texture unit's fronts: what sits between a rasteriser's (u, v) and a family's texel, wired once from the unit
//! blocks so that every family's pipeline holds the same blocks (the polar, height and palette ones next):
//! [lod →] tex_addr → tex_fetch [→ two bilinear units, one a byte of the 16-bit texel].
//!
//! `texture_front!` writes one block. Its optional groups add what a front holds, each naming its fields:
//! - `lod:` the level-of-detail unit (the derivative ports, and the delay lines that keep the position and the
//!   write beside it); its `pick` names the output the address unit reads (`nearest` for the nearest level,
//!   `level` for ⌊λ⌋); without it the front reads level 0;
//! - `filter:` the two bilinear units (the low byte and the high byte), the blend factors' delay line beside the
//!   fetch, and their valid chain; without it the address unit takes the nearest texel (`linear` = 0) and the
//!   texel leaves as it is read;
//! - `colour_map:` the colour map's memory: a second fetch (RGB565 texels, the same layout) read at the same
//!   footprint; the port `wcolour` beside the write port picks the memory a write goes to, its delay line keeping
//!   it beside the write; outputs `c_r`, `c_g`, `c_b`, in step with `lo` and `hi` (`vectors::front`); `written`,
//!   the front's clocks from the fetch to its output. A write leaves as zeros on every output, as on a front
//!   without one: the fetch a write does not go to reads as for a read, so its path's outputs are cleared at the
//!   end. Its four texels reach the channel path (one of the next two groups) as `colour_t`;
//! - `colour:` (with `filter:`) each colour texel's channels widened to 8 bits by repeating their top bits, and
//!   three more bilinear units (R, G, B) on the bump texel's blend factors;
//! - `colour_texel:` (with `unfiltered:`) the colour texel at the bump texel's place, widened, not filtered.
//!
//! `trilinear_front!` writes the one-clock trilinear front, two sets of the blocks (`TexTrilinear`), and with its
//! `colour:` group the same with a colour map (`TexTrilinearColour`); `TexTrilinearTwoPass` is written out.
//!
//! Ports (every front): the position u, v (Sq11.8, texels of level 0), the map's side log2 and the two wrap modes
//! (per frame), and the memory's write port (we, w_log2, wx, wy, wdata: `tex_fetch`'s). Outputs: `lo` and `hi`, the
//! texel's two bytes (filtered, or the nearest texel's). A write is a vector of its own, in order with the reads:
//! its delay line keeps it beside the position, so it reaches the fetch with its own vector and a read sees every
//! write before it (`vectors::front`); it leaves as a texel of zero.

/// A colour front's map stream: the write port and the memory select (`vectors::front::COLOUR`).
pub const COLOUR_MAP: &[&str] = &["we", "wcolour", "w_log2", "wx", "wy", "wdata"];

use crate::prim::q::U16;
use crate::stream::Waiver;
use rust_hdl::prelude::*;

// The signals a front's Verilog leaves unused on purpose, a list a part: each front's `waivers()` joins its parts',
// and the pipeline holding the front waives them (`StreamUnit::waivers`).

/// The bilinear units (`filter:`).
const BILINEAR: &[Waiver] = &[
    ("filter$0$wide", "the front's bilinear units, read rounded as in cart_pipeline"),
    ("filter$1$wide", "as filter$0$wide"),
];
/// The colour map's bilinear units (`colour:`).
const COLOUR: &[Waiver] = &[
    ("colour_filter$0$wide", "as filter$0$wide: the front reads each colour unit's rounded byte"),
    ("colour_filter$1$wide", "as colour_filter$0$wide"),
    ("colour_filter$2$wide", "as colour_filter$0$wide"),
    ("colour_fetch$valid_out", "the two fetches run in step: the valid chain follows the bump map's"),
];
/// The nearest texel (`unfiltered:`).
const NEAREST: &[Waiver] = &[
    ("addr$ublend", "the nearest texel needs no blend factors (tex_addr gives 0 for linear = 0)"),
    ("addr$vblend", "as addr$ublend"),
    ("fetch$t10", "the nearest texel is the footprint's first, t00; the other three are the bilinear fronts'"),
    ("fetch$t01", "as fetch$t10"),
    ("fetch$t11", "as fetch$t10"),
];
/// The nearest colour texel (`colour_texel:`): the footprint's first, as the bump texel is.
const NEAREST_COLOUR: &[Waiver] = &[
    ("colour_t$1", "the nearest colour texel is the footprint's first, colour_t[0]; the fetch reads four, as fetch"),
    ("colour_t$2", "as colour_t$1"),
    ("colour_t$3", "as colour_t$1"),
    ("colour_fetch$valid_out", "the two fetches run in step: the valid chain follows the bump map's"),
];
/// The LOD unit read for the nearest level (`lod:`).
const NEAREST_MIP: &[Waiver] = &[
    (
        "lod$level",
        "the nearest level is the LOD unit's `nearest`; the floor of lambda and its fraction are trilinear's",
    ),
    ("lod$frac", "as lod$level"),
];
/// The one-clock trilinear front.
const TRILINEAR: &[Waiver] = &[
    ("lod$nearest", "trilinear reads the floor of lambda and its fraction; the nearest level is nearest_mip's"),
    ("filter$0$wide", "as in cart_tex_bilinear: the front reads each unit's rounded byte"),
    ("filter$1$wide", "as filter$0$wide"),
    ("filter$2$wide", "as filter$0$wide"),
    ("filter$3$wide", "as filter$0$wide"),
    ("fetch_odd$valid_out", "the two fetches run in step: the valid chain follows the even one's"),
];
/// The one-clock trilinear front's colour map.
const TRILINEAR_COLOUR: &[Waiver] = &[
    ("colour_filter$0$wide", "as filter$0$wide: the front reads each colour unit's rounded byte"),
    ("colour_filter$1$wide", "as colour_filter$0$wide"),
    ("colour_filter$2$wide", "as colour_filter$0$wide"),
    ("colour_filter$3$wide", "as colour_filter$0$wide"),
    ("colour_filter$4$wide", "as colour_filter$0$wide"),
    ("colour_filter$5$wide", "as colour_filter$0$wide"),
    ("colour_even$valid_out", "the fetches run in step: the valid chain follows the bump map's even one"),
    ("colour_odd$valid_out", "as colour_even$valid_out"),
];
/// The two-pass trilinear front.
const TRILINEAR_TWO_PASS: &[Waiver] = &[
    ("lod$nearest", "as in a one-clock trilinear front"),
    ("fetch$valid_out", "the front's valid follows each vector's second pass from the address unit, not the fetch's"),
    ("filter$0$wide", "as in cart_tex_bilinear: the front reads each unit's rounded byte"),
    ("filter$1$wide", "as filter$0$wide"),
];

crate::block! {
    /// An RGB565 texel widened to three bytes, R in bits 0..7, G in 8..15, B in 16..23 of `c`, each channel's top
    /// bits repeated below it: `(r << 3) | (r >> 2)`, `(g << 2) | (g >> 4)`, `(b << 3) | (b >> 2)`
    /// (`vectors::front::expand565`). Wiring only.
    #[derive(Default)]
    pub struct Rgb565 {
        pub t: Signal<In, U16>,
        pub c: Signal<Out, Bits<24>>,
    }
}

impl Logic for Rgb565 {
    #[hdl_gen]
    fn update(&mut self) {
        // bit copies throughout, each field of t into its place (r << 3, g << 2, b << 3) and its top bits again
        // below it (r >> 2, g >> 4, b >> 2)
        self.c.next = bit_cast::<24, 5>(self.t.val().get_bits::<5>(11)) << 3;
        self.c.next = self.c.val() | bit_cast::<24, 3>(self.t.val().get_bits::<3>(13));
        self.c.next = self.c.val() | (bit_cast::<24, 6>(self.t.val().get_bits::<6>(5)) << 10);
        self.c.next = self.c.val() | (bit_cast::<24, 2>(self.t.val().get_bits::<2>(9)) << 8);
        self.c.next = self.c.val() | (bit_cast::<24, 5>(self.t.val().get_bits::<5>(0)) << 19);
        self.c.next = self.c.val() | (bit_cast::<24, 3>(self.t.val().get_bits::<3>(2)) << 16);
    }
}

macro_rules! texture_front {
    (
        module: $m:ident,
        block: $t:ident,
        linear: $lin:tt,
        write_delay: $wd:ty
        $(, level: $lv:tt)?
        $(, lod: { unit: $lod:ident, pick: $pick:ident, position: $pd:ident })?
        $(, filter: { units: $fl:ident, blend: $bd:ident, valid: $flv:ident })?
        $(, unfiltered: { texel: $tx:ident })?
        $(, colour_map: { fetch: $cf:ident, select: $cs:ident, written: $cw:expr })?
        $(, colour: { widen: $cx:ident, units: $cu:ident, blend: $cbd:ident })?
        $(, colour_texel: { widen: $nx:ident })?
        $(,)?
    ) => {
pub mod $m {
#[allow(unused_imports)] // each front holds some of these
use crate::prim::{delay::Delay, q::{Sq11_8, Sq3_8, Sq8_8, U16, U8}, ram_delay::RamDelay};
#[allow(unused_imports)]
use crate::{bilinear::BilinearUnit, lod::Lod, tex_addr::TexAddr, tex_fetch::TexFetch};
#[allow(unused_imports)]
use super::Rgb565;
use rust_hdl::prelude::*;

/// Cycles from the front's input to the address unit's, to the fetch's, and to its output.
// a group's term below is there when the invocation names the group (`0 * stringify!(..).len()` only ties it to it)
pub const AT_ADDR: usize = 0 $(+ crate::lod::LATENCY + 0 * stringify!($lod).len())?;
pub const AT_FETCH: usize = AT_ADDR + crate::tex_addr::LATENCY;
pub const AT_FILTER: usize = AT_FETCH + crate::tex_fetch::LATENCY;
pub const LATENCY: usize = AT_FILTER $(+ crate::bilinear::LATENCY + 0 * stringify!($fl).len())?;

impl $t {
    /// The signals the front's Verilog leaves unused on purpose, its parts' lists joined.
    pub fn waivers() -> Vec<crate::stream::Waiver> {
        crate::stream::waivers(&[
            $({ let _ = stringify!($fl); super::BILINEAR },)?
            $({ let _ = stringify!($tx); super::NEAREST },)?
            $({ let _ = stringify!($lod); super::NEAREST_MIP },)?
            $({ let _ = stringify!($cu); super::COLOUR },)?
            $({ let _ = stringify!($nx); super::NEAREST_COLOUR },)?
        ])
    }
}

crate::block! {
    #[derive(Default)]
    pub struct $t {
        pub clock: Signal<In, Clock>,
        pub valid_in: Signal<In, Bit>,
        pub u: Signal<In, Sq11_8>,
        pub v: Signal<In, Sq11_8>,
        $(pub du_dx: Signal<In, Sq8_8>,
        pub dv_dx: Signal<In, Sq8_8>,
        pub du_dy: Signal<In, Sq8_8>,
        pub dv_dy: Signal<In, Sq8_8>,
        pub lod_bias: Signal<In, Sq3_8>,
        $pd: RamDelay<46, 4, { crate::lod::LATENCY }>, // (u, v, log_side, uwrap, vwrap) packed low to high
        pos_word: Signal<Local, Bits<46>>,
        pub $lod: Lod,)?
        pub log_side: Signal<In, Bits<4>>,
        pub uwrap: Signal<In, Bits<1>>,
        pub vwrap: Signal<In, Bits<1>>,
        pub we: Signal<In, Bits<1>>,
        pub w_log2: Signal<In, Bits<4>>,
        pub wx: Signal<In, U8>,
        pub wy: Signal<In, U8>,
        pub wdata: Signal<In, U16>,
        $(pub wcolour: Signal<In, Bits<1>>,
        pub $cf: TexFetch, // the colour map's memory
        $cs: Delay<Bits<1>, AT_FETCH>, // wcolour, beside the write
        // the colour memory's four texels as the channel paths read them (bit copies)
        colour_t: [Signal<Local, U16>; 4],
        // (a write to the colour map, a write to the bump map) from the fetch to the front's output
        written: Delay<Bits<2>, { $cw }>,
        wrote_colour: Signal<Local, Bits<1>>,
        wrote_bump: Signal<Local, Bits<1>>,
        pub c_r: Signal<Out, U8>,
        pub c_g: Signal<Out, U8>,
        pub c_b: Signal<Out, U8>,)?
        $($cx: [Rgb565; 4], // the four texels widened
        pub $cu: [BilinearUnit<8, 8>; 3],)? // R, G, B
        $($nx: Rgb565,)? // the nearest texel widened
        pub valid_out: Signal<Out, Bit>,
        pub lo: Signal<Out, U8>,
        pub hi: Signal<Out, U8>,
        pub addr: TexAddr,
        pub fetch: TexFetch,
        $(pub $fl: [BilinearUnit<8, 8>; 2], // the low byte, the high byte
        $bd: Delay<U16, { crate::tex_fetch::LATENCY }>, // (ublend, vblend) packed low to high
        $flv: Delay<Bit, { crate::bilinear::LATENCY }>,
        blend_word: Signal<Local, U16>,)?
        write_dly: $wd, // (we, w_log2, wx, wy, wdata) packed low to high
        write_word: Signal<Local, Bits<37>>,
    }
}

impl Logic for $t {
    #[hdl_gen]
    fn update(&mut self) {
        self.addr.clock.next = self.clock.val();
        self.fetch.clock.next = self.clock.val();
        self.write_dly.clock.next = self.clock.val();
        // the write, packed (bit copies), waits for its vector's address
        self.write_word.next = bit_cast::<37, 1>(self.we.val());
        self.write_word.next = self.write_word.val() | (bit_cast::<37, 4>(self.w_log2.val()) << 1);
        self.write_word.next = self.write_word.val() | (bit_cast::<37, 8>(self.wx.val()) << 5);
        self.write_word.next = self.write_word.val() | (bit_cast::<37, 8>(self.wy.val()) << 13);
        self.write_word.next = self.write_word.val() | (bit_cast::<37, 16>(self.wdata.val()) << 21);
        self.write_dly.d.next = self.write_word.val();
        // the level: from the derivatives, the position waiting beside the LOD unit (bit copies)
        $(self.$lod.clock.next = self.clock.val();
        self.$pd.clock.next = self.clock.val();
        self.$lod.valid_in.next = self.valid_in.val();
        self.$lod.du_dx.next = self.du_dx.val();
        self.$lod.dv_dx.next = self.dv_dx.val();
        self.$lod.du_dy.next = self.du_dy.val();
        self.$lod.dv_dy.next = self.dv_dy.val();
        self.$lod.log_side.next = self.log_side.val();
        self.$lod.bias.next = self.lod_bias.val();
        self.pos_word.next = bit_cast::<46, 20>(self.u.val());
        self.pos_word.next = self.pos_word.val() | (bit_cast::<46, 20>(self.v.val()) << 20);
        self.pos_word.next = self.pos_word.val() | (bit_cast::<46, 4>(self.log_side.val()) << 40);
        self.pos_word.next = self.pos_word.val() | (bit_cast::<46, 1>(self.uwrap.val()) << 44);
        self.pos_word.next = self.pos_word.val() | (bit_cast::<46, 1>(self.vwrap.val()) << 45);
        self.$pd.d.next = self.pos_word.val();
        self.addr.valid_in.next = self.$lod.valid_out.val();
        self.addr.level.next = self.$lod.$pick.val();
        self.addr.u.next = self.$pd.q.val().get_bits::<20>(0);
        self.addr.v.next = self.$pd.q.val().get_bits::<20>(20);
        self.addr.log_side.next = self.$pd.q.val().get_bits::<4>(40);
        self.addr.uwrap.next = self.$pd.q.val().get_bits::<1>(44);
        self.addr.vwrap.next = self.$pd.q.val().get_bits::<1>(45);
        )?
        // or one level, the position as it comes
        $(self.addr.valid_in.next = self.valid_in.val();
        self.addr.level.next = $lv.into();
        self.addr.u.next = self.u.val();
        self.addr.v.next = self.v.val();
        self.addr.log_side.next = self.log_side.val();
        self.addr.uwrap.next = self.uwrap.val();
        self.addr.vwrap.next = self.vwrap.val();)?
        self.addr.linear.next = $lin.into(); // 1: the bilinear footprint, 0: the nearest texel
        // the fetch: the footprint the address unit gives, and the write that waited beside it (bit copies)
        self.fetch.valid_in.next = self.addr.valid_out.val();
        self.fetch.level_log2.next = self.addr.level_log2.val();
        self.fetch.x0.next = self.addr.x0.val();
        self.fetch.x1.next = self.addr.x1.val();
        self.fetch.y0.next = self.addr.y0.val();
        self.fetch.y1.next = self.addr.y1.val();
        self.fetch.we.next = self.write_dly.q.val().get_bits::<1>(0);
        self.fetch.w_log2.next = self.write_dly.q.val().get_bits::<4>(1);
        self.fetch.wx.next = self.write_dly.q.val().get_bits::<8>(5);
        self.fetch.wy.next = self.write_dly.q.val().get_bits::<8>(13);
        self.fetch.wdata.next = self.write_dly.q.val().get_bits::<16>(21);
        // the filter: each byte of the four texels, blended by the factors that waited beside the fetch
        $(self.$bd.clock.next = self.clock.val();
        self.$flv.clock.next = self.clock.val();
        // (ublend, vblend) packed and unpacked: bit copies
        self.blend_word.next = bit_cast::<16, 8>(self.addr.ublend.val());
        self.blend_word.next = self.blend_word.val() | (bit_cast::<16, 8>(self.addr.vblend.val()) << 8);
        self.$bd.d.next = self.blend_word.val();
        for i in 0..2 {
            self.$fl[i].clock.next = self.clock.val();
            self.$fl[i].ublend.next = self.$bd.q.val().get_bits::<8>(0); // bit copies
            self.$fl[i].vblend.next = self.$bd.q.val().get_bits::<8>(8); // bit copies
        }
        // each texel's low byte to the first unit, its high byte to the second: bit copies
        self.$fl[0].t00.next = self.fetch.t00.val().get_bits::<8>(0);
        self.$fl[0].t10.next = self.fetch.t10.val().get_bits::<8>(0);
        self.$fl[0].t01.next = self.fetch.t01.val().get_bits::<8>(0);
        self.$fl[0].t11.next = self.fetch.t11.val().get_bits::<8>(0);
        self.$fl[1].t00.next = self.fetch.t00.val().get_bits::<8>(8);
        self.$fl[1].t10.next = self.fetch.t10.val().get_bits::<8>(8);
        self.$fl[1].t01.next = self.fetch.t01.val().get_bits::<8>(8);
        self.$fl[1].t11.next = self.fetch.t11.val().get_bits::<8>(8);
        self.$flv.d.next = self.fetch.valid_out.val();
        self.valid_out.next = self.$flv.q.val();
        self.lo.next = self.$fl[0].out.val();
        self.hi.next = self.$fl[1].out.val();
        )?
        // the colour map: its own memory read at the same footprint, the write it takes picked by wcolour (and the
        // bump map's fetch takes the others)
        $(self.$cf.clock.next = self.clock.val();
        self.$cs.clock.next = self.clock.val();
        self.$cs.d.next = self.wcolour.val();
        self.$cf.valid_in.next = self.addr.valid_out.val();
        self.$cf.level_log2.next = self.addr.level_log2.val();
        self.$cf.x0.next = self.addr.x0.val();
        self.$cf.x1.next = self.addr.x1.val();
        self.$cf.y0.next = self.addr.y0.val();
        self.$cf.y1.next = self.addr.y1.val();
        self.$cf.we.next = self.write_dly.q.val().get_bits::<1>(0) & self.$cs.q.val();
        self.fetch.we.next = self.write_dly.q.val().get_bits::<1>(0) & !self.$cs.q.val();
        self.$cf.w_log2.next = self.write_dly.q.val().get_bits::<4>(1);
        self.$cf.wx.next = self.write_dly.q.val().get_bits::<8>(5);
        self.$cf.wy.next = self.write_dly.q.val().get_bits::<8>(13);
        self.$cf.wdata.next = self.write_dly.q.val().get_bits::<16>(21);
        self.colour_t[0].next = self.$cf.t00.val();
        self.colour_t[1].next = self.$cf.t10.val();
        self.colour_t[2].next = self.$cf.t01.val();
        self.colour_t[3].next = self.$cf.t11.val();)?
        // filtered: each texel's RGB565 widened to three bytes by repeating the top bits (`(c << 3) | (c >> 2)`,
        // `(c << 2) | (c >> 4)`: bit copies), filtered on the bump texel's blend factors
        $(for i in 0..3 {
            self.$cu[i].clock.next = self.clock.val();
            self.$cu[i].ublend.next = self.$cbd.q.val().get_bits::<8>(0); // bit copies
            self.$cu[i].vblend.next = self.$cbd.q.val().get_bits::<8>(8); // bit copies
        }
        for k in 0..4 {
            self.$cx[k].t.next = self.colour_t[k].val();
        }
        for i in 0..3 {
            self.$cu[i].t00.next = self.$cx[0].c.val().get_bits::<8>(8 * i); // channel i of the widened texel: bit copies
            self.$cu[i].t10.next = self.$cx[1].c.val().get_bits::<8>(8 * i); // likewise
            self.$cu[i].t01.next = self.$cx[2].c.val().get_bits::<8>(8 * i); // likewise
            self.$cu[i].t11.next = self.$cx[3].c.val().get_bits::<8>(8 * i); // likewise
        }
        self.c_r.next = self.$cu[0].out.val();
        self.c_g.next = self.$cu[1].out.val();
        self.c_b.next = self.$cu[2].out.val();)?
        // or the nearest texel as it is read (bit copies)
        $(self.valid_out.next = self.fetch.valid_out.val();
        self.lo.next = self.fetch.$tx.val().get_bits::<8>(0);
        self.hi.next = self.fetch.$tx.val().get_bits::<8>(8);)?
        // beside the nearest texel: the colour texel at the same place (the footprint's first, t00), widened
        $(self.$nx.t.next = self.colour_t[0].val();
        self.c_r.next = self.$nx.c.val().get_bits::<8>(0); // bit copies: R, G, B of the widened texel
        self.c_g.next = self.$nx.c.val().get_bits::<8>(8); // likewise
        self.c_b.next = self.$nx.c.val().get_bits::<8>(16);)? // likewise
        // a write leaves as zeros: the path it did not write read a texel, so clear it (the one it wrote gave zeros)
        $(self.written.clock.next = self.clock.val();
        self.wrote_colour.next = self.write_dly.q.val().get_bits::<1>(0) & self.$cs.q.val();
        self.wrote_bump.next = self.write_dly.q.val().get_bits::<1>(0) & !self.$cs.q.val();
        self.written.d.next = bit_cast::<2, 1>(self.wrote_colour.val()) | (bit_cast::<2, 1>(self.wrote_bump.val()) << 1);
        if self.written.q.val().get_bit(0) {
            self.lo.next = 0.into();
            self.hi.next = 0.into();
        }
        if self.written.q.val().get_bit(1) {
            self.c_r.next = 0.into();
            self.c_g.next = 0.into();
            self.c_b.next = 0.into();
        })?
    }
}
}
pub use $m::$t;
    };
}

texture_front! {
    module: nearest,
    block: TexNearest,
    linear: 0,
    write_delay: Delay<Bits<37>, { crate::tex_addr::LATENCY }>,
    level: 0,
    unfiltered: { texel: t00 },
}

texture_front! {
    module: bilinear,
    block: TexBilinear,
    linear: 1,
    write_delay: Delay<Bits<37>, { crate::tex_addr::LATENCY }>,
    level: 0,
    filter: { units: filter, blend: blend_dly, valid: filter_valid },
}

texture_front! {
    module: nearest_colour,
    block: TexNearestColour,
    linear: 0,
    write_delay: Delay<Bits<37>, { crate::tex_addr::LATENCY }>,
    level: 0,
    unfiltered: { texel: t00 },
    colour_map: { fetch: colour_fetch, select: wcolour_dly, written: crate::tex_fetch::LATENCY },
    colour_texel: { widen: colour_widen },
}

texture_front! {
    module: nearest_mip_colour,
    block: TexNearestMipColour,
    linear: 0,
    write_delay: RamDelay<37, 5, { crate::lod::LATENCY + crate::tex_addr::LATENCY }>,
    lod: { unit: lod, pick: nearest, position: pos_dly },
    unfiltered: { texel: t00 },
    colour_map: { fetch: colour_fetch, select: wcolour_dly, written: crate::tex_fetch::LATENCY },
    colour_texel: { widen: colour_widen },
}

texture_front! {
    module: bilinear_colour,
    block: TexBilinearColour,
    linear: 1,
    write_delay: Delay<Bits<37>, { crate::tex_addr::LATENCY }>,
    level: 0,
    filter: { units: filter, blend: blend_dly, valid: filter_valid },
    colour_map: {
        fetch: colour_fetch,
        select: wcolour_dly,
        written: crate::tex_fetch::LATENCY + crate::bilinear::LATENCY
    },
    colour: { widen: colour_widen, units: colour_filter, blend: blend_dly },
}

texture_front! {
    module: nearest_mip,
    block: TexNearestMip,
    linear: 0,
    write_delay: RamDelay<37, 5, { crate::lod::LATENCY + crate::tex_addr::LATENCY }>,
    lod: { unit: lod, pick: nearest, position: pos_dly },
    unfiltered: { texel: t00 },
}

/// Both trilinear fronts' block of their own: the blend of the two levels.
pub mod level {
    use crate::prim::delay::Delay;
    use crate::prim::q::{SBits, U8};
    use crate::prim::sm_mul::{self, SmMul};
    use rust_hdl::prelude::*;

    /// `LevelLerp`'s clocks: the difference (f registered beside it); the product; the rounded sum.
    pub const LERP_LATENCY: usize = 1 + sm_mul::LATENCY + 1;

    crate::block! {
        /// One byte of the blend of two levels by frac(λ): `round_half_up(b₀·2^8 + (b₁ − b₀)·f, 8)` (U8,
        /// `vectors::front::lerp`), b₀ the level ⌊λ⌋'s byte, b₁ the second level's, f = frac(λ) (U0.8), the three
        /// on one clock; `out` LERP_LATENCY clocks later.
        #[derive(Default)]
        pub struct LevelLerp {
            pub clock: Signal<In, Clock>,
            pub b0: Signal<In, U8>,
            pub b1: Signal<In, U8>,
            pub f: Signal<In, U8>,
            pub out: Signal<Out, U8>,
            // stage 1: b₁ − b₀ (S9 in 16, two's complement), b₀·2^8 + 2^7 (the rounding's half: U16 in 17), f beside
            // them
            s1_d: DFF<SBits<16>>,
            s1_base: DFF<Bits<17>>,
            s1_f: DFF<U8>,
            w_b0: Signal<Local, Bits<16>>,   // b₀ widened (U8 in 16)
            w_b1: Signal<Local, Bits<16>>,   // b₁ widened (U8 in 16)
            w_base: Signal<Local, Bits<17>>, // b₀ widened (U8 in 17)
            w_frac: Signal<Local, Bits<16>>, // f widened (U8 in 16)
            // stages 2–5: |b₁ − b₀|·f ≤ 255·255 (U16), the base beside it
            mul: SmMul<16>,
            base: Delay<Bits<17>, { sm_mul::LATENCY }>,
            w_prod: Signal<Local, Bits<17>>, // the product's low 17 bits: exact (< 2^16)
            w_sum: Signal<Local, Bits<17>>, // b₀·2^8 + 2^7 ± |b₁ − b₀|·f ∈ 128..=65408, exact (a mean of b₀, b₁ times 2^8, + 2^7)
            // the last stage: bits 8.. of the rounded sum (truncation of it: round half up overall). The half is in
            // the base from stage 1 on, so this stage is one add or subtract: the sum then its + 2^7, two adders in a
            // row, was one of the trilinear pipelines' critical paths on the ECP5
            s5_out: DFF<U8>,
        }
    }

    impl Logic for LevelLerp {
        #[hdl_gen]
        fn update(&mut self) {
            dff_setup!(self, clock, s1_d, s1_base, s1_f, s5_out);
            self.mul.clock.next = self.clock.val();
            self.base.clock.next = self.clock.val();
            // stage 1: b₁ − b₀, wrapping in 16 bits to its two's complement; b₀·2^8 + 2^7 (an OR: the low byte is
            // zero; exact in 17)
            self.w_b0.next = bit_cast::<16, 8>(self.b0.val());
            self.w_b1.next = bit_cast::<16, 8>(self.b1.val());
            self.w_base.next = bit_cast::<17, 8>(self.b0.val());
            self.s1_d.d.next = self.w_b1.val() - self.w_b0.val();
            self.s1_base.d.next = (self.w_base.val() << 8) | 128;
            self.s1_f.d.next = self.f.val();
            // stages 2–5: |b₁ − b₀|·f, the base beside it
            self.w_frac.next = bit_cast::<16, 8>(self.s1_f.q.val());
            self.mul.x.next = self.s1_d.q.val();
            self.mul.w.next = self.w_frac.val();
            self.base.d.next = self.s1_base.q.val();
            // the last stage: (b₀·2^8 + 2^7) ± |b₁ − b₀|·f, then bits 8..
            self.w_prod.next = self.mul.p.val().get_bits::<17>(0);
            if self.mul.neg.val() {
                self.w_sum.next = self.base.q.val() - self.w_prod.val();
            } else {
                self.w_sum.next = self.base.q.val() + self.w_prod.val();
            }
            self.s5_out.d.next = self.w_sum.val().get_bits::<8>(8); // truncation of the rounded sum
            self.out.next = self.s5_out.q.val();
        }
    }
}
pub use level::LevelLerp;

macro_rules! trilinear_front {
    (
        $(#[$attr:meta])*
        module: $m:ident,
        block: $t:ident
        $(, colour: {
            select: $cs:ident,
            fetches: [$ce:ident, $co:ident],
            widen: $cx:ident,
            units: $cu:ident,
            lerp: $cl:ident
        })?
        $(,)?
    ) => {
$(#[$attr])*
pub mod $m {
    use super::level::{LevelLerp, LERP_LATENCY};
    #[allow(unused_imports)] // a front with a colour map widens its texels
    use super::Rgb565;
    use crate::prim::delay::Delay;
    use crate::prim::q::{Sq11_8, Sq3_8, Sq8_8, U16, U8};
    use crate::prim::ram_delay::RamDelay;
    use crate::tex_fetch::{TexFetch, EVEN, EVEN_ADDR_BITS, ODD};
    use crate::{bilinear::BilinearUnit, lod::Lod, tex_addr::TexAddr};
    use rust_hdl::prelude::*;

    /// Cycles from the front's input to the address units' (the LOD unit, then the choice of the second level
    /// registered), to the fetches', to the bilinear units', to the blend of the two levels and to its output (the
    /// difference; the product; the rounded sum). The choice has its clock: straight from the LOD unit's level
    /// register into the address units' first stage it was the trilinear pipelines' critical path on the ECP5
    /// (2.93 ns of logic and 4.06 ns of routing, 143 MHz).
    pub const AT_ADDR: usize = crate::lod::LATENCY + 1;
    pub const AT_FETCH: usize = AT_ADDR + crate::tex_addr::LATENCY;
    pub const AT_FILTER: usize = AT_FETCH + crate::tex_fetch::LATENCY;
    pub const AT_LERP: usize = AT_FILTER + crate::bilinear::LATENCY;
    pub const LATENCY: usize = AT_LERP + LERP_LATENCY;

    crate::block! {
        #[derive(Default)]
        pub struct $t {
            pub clock: Signal<In, Clock>,
            pub valid_in: Signal<In, Bit>,
            pub u: Signal<In, Sq11_8>,
            pub v: Signal<In, Sq11_8>,
            pub du_dx: Signal<In, Sq8_8>,
            pub dv_dx: Signal<In, Sq8_8>,
            pub du_dy: Signal<In, Sq8_8>,
            pub dv_dy: Signal<In, Sq8_8>,
            pub lod_bias: Signal<In, Sq3_8>,
            pub log_side: Signal<In, Bits<4>>,
            pub uwrap: Signal<In, Bits<1>>,
            pub vwrap: Signal<In, Bits<1>>,
            pub we: Signal<In, Bits<1>>,
            pub w_log2: Signal<In, Bits<4>>,
            pub wx: Signal<In, U8>,
            pub wy: Signal<In, U8>,
            pub wdata: Signal<In, U16>,
            pub valid_out: Signal<Out, Bit>,
            pub lo: Signal<Out, U8>,
            pub hi: Signal<Out, U8>,
            pub lod: Lod,
            pos_dly: RamDelay<46, 4, { crate::lod::LATENCY }>, // (u, v, log_side, uwrap, vwrap) packed low to high
            pos_word: Signal<Local, Bits<46>>,
            next_level: Signal<Local, Bits<4>>, // ⌊λ⌋ + 1 ≤ 9 (λ ≤ 8)
            prev_level: Signal<Local, Bits<4>>, // ⌊λ⌋ − 1 (wraps at 0, unused there)
            second: Signal<Local, Bits<4>>,     // the level ⌊λ⌋ is blended with
            side_log2: Signal<Local, Bits<4>>,  // the map's side log2, waited beside the LOD unit
            odd_first: Signal<Local, Bit>,      // ⌊λ⌋'s side log2, log_side − ⌊λ⌋, is odd: ⌊λ⌋ from the odd fetch
            // the choice registered: each address unit's level (the even fetch's, the odd one's), odd_first, the
            // position and the valid flag
            ch_level: [DFF<Bits<4>>; 2],
            ch_odd: DFF<Bit>,
            ch_pos: DFF<Bits<46>>,
            ch_valid: DFF<Bit>,
            odd_first_dly: Delay<Bit, { AT_LERP - AT_ADDR }>,
            pub addr: [TexAddr; 2], // the level of even side log2, the odd one
            pub fetch_even: TexFetch<EVEN, EVEN_ADDR_BITS>, // the levels of even side log2
            pub fetch_odd: TexFetch<ODD, 13>,               // the odd ones
            write_dly: RamDelay<37, 5, { AT_FETCH }>, // (we, w_log2, wx, wy, wdata)
            write_word: Signal<Local, Bits<37>>,
            pub filter: [BilinearUnit<8, 8>; 4], // level ⌊λ⌋ low byte, high byte; level ⌊λ⌋ + 1 low byte, high byte
            blend_dly: [Delay<U16, { crate::tex_fetch::LATENCY }>; 2], // each level's (ublend, vblend) packed low to high
            blend_word: [Signal<Local, U16>; 2],
            filter_valid: Delay<Bit, { crate::bilinear::LATENCY }>,
            // frac(λ), from the LOD unit to the blend of the two levels
            frac_dly: RamDelay<8, 5, { AT_LERP - crate::lod::LATENCY }>,
            // the blend of the two levels, a byte each (low, high)
            lerp: [LevelLerp; 2],
            lerp_valid: Delay<Bit, LERP_LATENCY>,
            // the colour map: its memory split by level parity as the bump map's, read at the same footprints
            $(pub wcolour: Signal<In, Bits<1>>,
            $cs: Delay<Bits<1>, AT_FETCH>, // wcolour, beside the write
            pub $ce: TexFetch<EVEN, EVEN_ADDR_BITS>, // the colour levels of even side log2
            pub $co: TexFetch<ODD, 13>,               // the odd ones
            $cx: [Rgb565; 8], // the even fetch's four texels widened, then the odd one's
            pub $cu: [BilinearUnit<8, 8>; 6], // the even level's R, G, B, then the odd level's
            $cl: [LevelLerp; 3], // R, G, B: the blend of the two levels
            // (a write to the colour map, a write to the bump map) from the fetches to the front's output
            written: Delay<Bits<2>, { LATENCY - AT_FETCH }>,
            wrote_colour: Signal<Local, Bits<1>>,
            wrote_bump: Signal<Local, Bits<1>>,
            pub c_r: Signal<Out, U8>,
            pub c_g: Signal<Out, U8>,
            pub c_b: Signal<Out, U8>,)?
        }
    }

    impl Logic for $t {
        #[hdl_gen]
        fn update(&mut self) {
            dff_setup!(self, clock, ch_odd, ch_pos, ch_valid);
            self.lod.clock.next = self.clock.val();
            self.pos_dly.clock.next = self.clock.val();
            self.write_dly.clock.next = self.clock.val();
            self.filter_valid.clock.next = self.clock.val();
            self.frac_dly.clock.next = self.clock.val();
            self.lerp_valid.clock.next = self.clock.val();
            // the write, packed (bit copies), waits for its vector's address
            self.write_word.next = bit_cast::<37, 1>(self.we.val());
            self.write_word.next = self.write_word.val() | (bit_cast::<37, 4>(self.w_log2.val()) << 1);
            self.write_word.next = self.write_word.val() | (bit_cast::<37, 8>(self.wx.val()) << 5);
            self.write_word.next = self.write_word.val() | (bit_cast::<37, 8>(self.wy.val()) << 13);
            self.write_word.next = self.write_word.val() | (bit_cast::<37, 16>(self.wdata.val()) << 21);
            self.write_dly.d.next = self.write_word.val();
            // the level: from the derivatives, the position waiting beside the LOD unit (bit copies)
            self.lod.valid_in.next = self.valid_in.val();
            self.lod.du_dx.next = self.du_dx.val();
            self.lod.dv_dx.next = self.dv_dx.val();
            self.lod.du_dy.next = self.du_dy.val();
            self.lod.dv_dy.next = self.dv_dy.val();
            self.lod.log_side.next = self.log_side.val();
            self.lod.bias.next = self.lod_bias.val();
            self.pos_word.next = bit_cast::<46, 20>(self.u.val());
            self.pos_word.next = self.pos_word.val() | (bit_cast::<46, 20>(self.v.val()) << 20);
            self.pos_word.next = self.pos_word.val() | (bit_cast::<46, 4>(self.log_side.val()) << 40);
            self.pos_word.next = self.pos_word.val() | (bit_cast::<46, 1>(self.uwrap.val()) << 44);
            self.pos_word.next = self.pos_word.val() | (bit_cast::<46, 1>(self.vwrap.val()) << 45);
            self.pos_dly.d.next = self.pos_word.val();
            // the second level: ⌊λ⌋ + 1 below the last level, else ⌊λ⌋ − 1, else (a 1 × 1 map) 1
            self.next_level.next = self.lod.level.val() + 1; // ≤ 9 in 4 bits: exact
            self.prev_level.next = self.lod.level.val() - 1; // wraps at 0 on purpose: not read there
            self.side_log2.next = self.pos_dly.q.val().get_bits::<4>(40); // bit copies: the U4 it was
            self.second.next = 1.into();
            if self.lod.level.val().any() {
                self.second.next = self.prev_level.val();
            }
            if self.lod.level.val() < self.side_log2.val() {
                self.second.next = self.next_level.val();
            }
            self.odd_first.next = self.side_log2.val().get_bit(0) ^ self.lod.level.val().get_bit(0);
            self.ch_odd.d.next = self.odd_first.val();
            self.ch_pos.d.next = self.pos_dly.q.val();
            self.ch_valid.d.next = self.lod.valid_out.val();
            self.odd_first_dly.clock.next = self.clock.val();
            self.odd_first_dly.d.next = self.ch_odd.q.val();
            // each level's blend factors wait beside its fetch: packed and unpacked, bit copies (a loop's index
            // cannot reach into a cast's argument under `hdl_gen`)
            // (one assignment each, before the loop reads them: an element read before it is written, or written from
            // itself, reads to Verilator as a combinational loop)
            self.blend_word[0].next =
                bit_cast::<16, 8>(self.addr[0].ublend.val()) | (bit_cast::<16, 8>(self.addr[0].vblend.val()) << 8);
            self.blend_word[1].next =
                bit_cast::<16, 8>(self.addr[1].ublend.val()) | (bit_cast::<16, 8>(self.addr[1].vblend.val()) << 8);
            // each address unit the level its fetch holds, registered
            if self.odd_first.val() {
                self.ch_level[0].d.next = self.second.val();
                self.ch_level[1].d.next = self.lod.level.val();
            } else {
                self.ch_level[0].d.next = self.lod.level.val();
                self.ch_level[1].d.next = self.second.val();
            }
            for k in 0..2 {
                self.ch_level[k].clock.next = self.clock.val();
                self.addr[k].clock.next = self.clock.val();
                self.blend_dly[k].clock.next = self.clock.val();
                self.addr[k].valid_in.next = self.ch_valid.q.val();
                self.addr[k].level.next = self.ch_level[k].q.val();
                // the position that waited beside the LOD unit and the choice, unpacked: bit copies
                self.addr[k].u.next = self.ch_pos.q.val().get_bits::<20>(0);
                self.addr[k].v.next = self.ch_pos.q.val().get_bits::<20>(20);
                self.addr[k].log_side.next = self.ch_pos.q.val().get_bits::<4>(40);
                self.addr[k].uwrap.next = self.ch_pos.q.val().get_bits::<1>(44);
                self.addr[k].vwrap.next = self.ch_pos.q.val().get_bits::<1>(45);
                self.addr[k].linear.next = true.into(); // the bilinear footprint
                self.blend_dly[k].d.next = self.blend_word[k].val();
            }
            // the fetches: the footprint its address unit gives, and the write that waited beside it (bit copies);
            // both take every write and keep those of the levels they hold
            self.fetch_even.clock.next = self.clock.val();
            self.fetch_odd.clock.next = self.clock.val();
            self.fetch_even.valid_in.next = self.addr[0].valid_out.val();
            self.fetch_even.level_log2.next = self.addr[0].level_log2.val();
            self.fetch_even.x0.next = self.addr[0].x0.val();
            self.fetch_even.x1.next = self.addr[0].x1.val();
            self.fetch_even.y0.next = self.addr[0].y0.val();
            self.fetch_even.y1.next = self.addr[0].y1.val();
            self.fetch_odd.valid_in.next = self.addr[1].valid_out.val();
            self.fetch_odd.level_log2.next = self.addr[1].level_log2.val();
            self.fetch_odd.x0.next = self.addr[1].x0.val();
            self.fetch_odd.x1.next = self.addr[1].x1.val();
            self.fetch_odd.y0.next = self.addr[1].y0.val();
            self.fetch_odd.y1.next = self.addr[1].y1.val();
            self.fetch_even.we.next = self.write_dly.q.val().get_bits::<1>(0);
            self.fetch_even.w_log2.next = self.write_dly.q.val().get_bits::<4>(1);
            self.fetch_even.wx.next = self.write_dly.q.val().get_bits::<8>(5);
            self.fetch_even.wy.next = self.write_dly.q.val().get_bits::<8>(13);
            self.fetch_even.wdata.next = self.write_dly.q.val().get_bits::<16>(21);
            self.fetch_odd.we.next = self.write_dly.q.val().get_bits::<1>(0);
            self.fetch_odd.w_log2.next = self.write_dly.q.val().get_bits::<4>(1);
            self.fetch_odd.wx.next = self.write_dly.q.val().get_bits::<8>(5);
            self.fetch_odd.wy.next = self.write_dly.q.val().get_bits::<8>(13);
            self.fetch_odd.wdata.next = self.write_dly.q.val().get_bits::<16>(21);
            // the filters: unit 2k + c takes byte c of the four texels of fetch k (even, odd): bit copies
            for i in 0..4 {
                self.filter[i].clock.next = self.clock.val();
            }
            // each unit's blend factors (its level's, unpacked) and its byte of the four texels: bit copies
            self.filter[0].ublend.next = self.blend_dly[0].q.val().get_bits::<8>(0);
            self.filter[0].vblend.next = self.blend_dly[0].q.val().get_bits::<8>(8);
            self.filter[1].ublend.next = self.blend_dly[0].q.val().get_bits::<8>(0);
            self.filter[1].vblend.next = self.blend_dly[0].q.val().get_bits::<8>(8);
            self.filter[2].ublend.next = self.blend_dly[1].q.val().get_bits::<8>(0);
            self.filter[2].vblend.next = self.blend_dly[1].q.val().get_bits::<8>(8);
            self.filter[3].ublend.next = self.blend_dly[1].q.val().get_bits::<8>(0);
            self.filter[3].vblend.next = self.blend_dly[1].q.val().get_bits::<8>(8);
            self.filter[0].t00.next = self.fetch_even.t00.val().get_bits::<8>(0);
            self.filter[0].t10.next = self.fetch_even.t10.val().get_bits::<8>(0);
            self.filter[0].t01.next = self.fetch_even.t01.val().get_bits::<8>(0);
            self.filter[0].t11.next = self.fetch_even.t11.val().get_bits::<8>(0);
            self.filter[1].t00.next = self.fetch_even.t00.val().get_bits::<8>(8);
            self.filter[1].t10.next = self.fetch_even.t10.val().get_bits::<8>(8);
            self.filter[1].t01.next = self.fetch_even.t01.val().get_bits::<8>(8);
            self.filter[1].t11.next = self.fetch_even.t11.val().get_bits::<8>(8);
            self.filter[2].t00.next = self.fetch_odd.t00.val().get_bits::<8>(0);
            self.filter[2].t10.next = self.fetch_odd.t10.val().get_bits::<8>(0);
            self.filter[2].t01.next = self.fetch_odd.t01.val().get_bits::<8>(0);
            self.filter[2].t11.next = self.fetch_odd.t11.val().get_bits::<8>(0);
            self.filter[3].t00.next = self.fetch_odd.t00.val().get_bits::<8>(8);
            self.filter[3].t10.next = self.fetch_odd.t10.val().get_bits::<8>(8);
            self.filter[3].t01.next = self.fetch_odd.t01.val().get_bits::<8>(8);
            self.filter[3].t11.next = self.fetch_odd.t11.val().get_bits::<8>(8);
            self.filter_valid.d.next = self.fetch_even.valid_out.val();
            // frac(λ) waits for the two levels' bytes
            self.frac_dly.d.next = self.lod.frac.val();
            // the blend of the two levels, per byte c: b₀ from ⌊λ⌋'s fetch's units (the odd one's, 2 + c, where its
            // side log2 is odd), b₁ from the other's
            if self.odd_first_dly.q.val() {
                self.lerp[0].b0.next = self.filter[2].out.val();
                self.lerp[1].b0.next = self.filter[3].out.val();
                self.lerp[0].b1.next = self.filter[0].out.val();
                self.lerp[1].b1.next = self.filter[1].out.val();
            } else {
                self.lerp[0].b0.next = self.filter[0].out.val();
                self.lerp[1].b0.next = self.filter[1].out.val();
                self.lerp[0].b1.next = self.filter[2].out.val();
                self.lerp[1].b1.next = self.filter[3].out.val();
            }
            for c in 0..2 {
                self.lerp[c].clock.next = self.clock.val();
                self.lerp[c].f.next = self.frac_dly.q.val();
            }
            self.lerp_valid.d.next = self.filter_valid.q.val();
            self.valid_out.next = self.lerp_valid.q.val();
            self.lo.next = self.lerp[0].out.val();
            self.hi.next = self.lerp[1].out.val();
            // the colour map: a write goes to its memories where wcolour is set, else to the bump map's; its two fetches
            // read at the bump map's footprints, each feeding three bilinear units (R, G, B) on that level's blend factors
            $(self.$cs.clock.next = self.clock.val();
            self.$cs.d.next = self.wcolour.val();
            self.fetch_even.we.next = self.write_dly.q.val().get_bits::<1>(0) & !self.$cs.q.val(); // 1 bit: the bump map's
            self.fetch_odd.we.next = self.write_dly.q.val().get_bits::<1>(0) & !self.$cs.q.val(); // 1 bit: the bump map's
            self.$ce.clock.next = self.clock.val();
            self.$ce.valid_in.next = self.addr[0].valid_out.val();
            self.$ce.level_log2.next = self.addr[0].level_log2.val();
            self.$ce.x0.next = self.addr[0].x0.val();
            self.$ce.x1.next = self.addr[0].x1.val();
            self.$ce.y0.next = self.addr[0].y0.val();
            self.$ce.y1.next = self.addr[0].y1.val();
            self.$ce.we.next = self.write_dly.q.val().get_bits::<1>(0) & self.$cs.q.val(); // 1 bit: the colour map's
            self.$ce.w_log2.next = self.write_dly.q.val().get_bits::<4>(1); // bit copies
            self.$ce.wx.next = self.write_dly.q.val().get_bits::<8>(5); // bit copies
            self.$ce.wy.next = self.write_dly.q.val().get_bits::<8>(13); // bit copies
            self.$ce.wdata.next = self.write_dly.q.val().get_bits::<16>(21); // bit copies
            self.$co.clock.next = self.clock.val();
            self.$co.valid_in.next = self.addr[1].valid_out.val();
            self.$co.level_log2.next = self.addr[1].level_log2.val();
            self.$co.x0.next = self.addr[1].x0.val();
            self.$co.x1.next = self.addr[1].x1.val();
            self.$co.y0.next = self.addr[1].y0.val();
            self.$co.y1.next = self.addr[1].y1.val();
            self.$co.we.next = self.write_dly.q.val().get_bits::<1>(0) & self.$cs.q.val(); // 1 bit: the colour map's
            self.$co.w_log2.next = self.write_dly.q.val().get_bits::<4>(1); // bit copies
            self.$co.wx.next = self.write_dly.q.val().get_bits::<8>(5); // bit copies
            self.$co.wy.next = self.write_dly.q.val().get_bits::<8>(13); // bit copies
            self.$co.wdata.next = self.write_dly.q.val().get_bits::<16>(21); // bit copies
            // each texel's RGB565 widened to three bytes (bit copies), even fetch's first
            self.$cx[0].t.next = self.$ce.t00.val();
            self.$cx[1].t.next = self.$ce.t10.val();
            self.$cx[2].t.next = self.$ce.t01.val();
            self.$cx[3].t.next = self.$ce.t11.val();
            self.$cx[4].t.next = self.$co.t00.val();
            self.$cx[5].t.next = self.$co.t10.val();
            self.$cx[6].t.next = self.$co.t01.val();
            self.$cx[7].t.next = self.$co.t11.val();
            for i in 0..6 {
                self.$cu[i].clock.next = self.clock.val();
            }
            // unit 3k + c: channel c of fetch k's four widened texels (bit copies), on level k's blend factors (bit copies)
            self.$cu[0].ublend.next = self.blend_dly[0].q.val().get_bits::<8>(0);
            self.$cu[0].vblend.next = self.blend_dly[0].q.val().get_bits::<8>(8);
            self.$cu[0].t00.next = self.$cx[0].c.val().get_bits::<8>(0);
            self.$cu[0].t10.next = self.$cx[1].c.val().get_bits::<8>(0);
            self.$cu[0].t01.next = self.$cx[2].c.val().get_bits::<8>(0);
            self.$cu[0].t11.next = self.$cx[3].c.val().get_bits::<8>(0);
            self.$cu[1].ublend.next = self.blend_dly[0].q.val().get_bits::<8>(0);
            self.$cu[1].vblend.next = self.blend_dly[0].q.val().get_bits::<8>(8);
            self.$cu[1].t00.next = self.$cx[0].c.val().get_bits::<8>(8);
            self.$cu[1].t10.next = self.$cx[1].c.val().get_bits::<8>(8);
            self.$cu[1].t01.next = self.$cx[2].c.val().get_bits::<8>(8);
            self.$cu[1].t11.next = self.$cx[3].c.val().get_bits::<8>(8);
            self.$cu[2].ublend.next = self.blend_dly[0].q.val().get_bits::<8>(0);
            self.$cu[2].vblend.next = self.blend_dly[0].q.val().get_bits::<8>(8);
            self.$cu[2].t00.next = self.$cx[0].c.val().get_bits::<8>(16);
            self.$cu[2].t10.next = self.$cx[1].c.val().get_bits::<8>(16);
            self.$cu[2].t01.next = self.$cx[2].c.val().get_bits::<8>(16);
            self.$cu[2].t11.next = self.$cx[3].c.val().get_bits::<8>(16);
            self.$cu[3].ublend.next = self.blend_dly[1].q.val().get_bits::<8>(0);
            self.$cu[3].vblend.next = self.blend_dly[1].q.val().get_bits::<8>(8);
            self.$cu[3].t00.next = self.$cx[4].c.val().get_bits::<8>(0);
            self.$cu[3].t10.next = self.$cx[5].c.val().get_bits::<8>(0);
            self.$cu[3].t01.next = self.$cx[6].c.val().get_bits::<8>(0);
            self.$cu[3].t11.next = self.$cx[7].c.val().get_bits::<8>(0);
            self.$cu[4].ublend.next = self.blend_dly[1].q.val().get_bits::<8>(0);
            self.$cu[4].vblend.next = self.blend_dly[1].q.val().get_bits::<8>(8);
            self.$cu[4].t00.next = self.$cx[4].c.val().get_bits::<8>(8);
            self.$cu[4].t10.next = self.$cx[5].c.val().get_bits::<8>(8);
            self.$cu[4].t01.next = self.$cx[6].c.val().get_bits::<8>(8);
            self.$cu[4].t11.next = self.$cx[7].c.val().get_bits::<8>(8);
            self.$cu[5].ublend.next = self.blend_dly[1].q.val().get_bits::<8>(0);
            self.$cu[5].vblend.next = self.blend_dly[1].q.val().get_bits::<8>(8);
            self.$cu[5].t00.next = self.$cx[4].c.val().get_bits::<8>(16);
            self.$cu[5].t10.next = self.$cx[5].c.val().get_bits::<8>(16);
            self.$cu[5].t01.next = self.$cx[6].c.val().get_bits::<8>(16);
            self.$cu[5].t11.next = self.$cx[7].c.val().get_bits::<8>(16);
            // the blend of the two levels per channel, ⌊λ⌋'s from the fetch of its parity, as the bump texel's bytes
            if self.odd_first_dly.q.val() {
                self.$cl[0].b0.next = self.$cu[3].out.val();
                self.$cl[0].b1.next = self.$cu[0].out.val();
                self.$cl[1].b0.next = self.$cu[4].out.val();
                self.$cl[1].b1.next = self.$cu[1].out.val();
                self.$cl[2].b0.next = self.$cu[5].out.val();
                self.$cl[2].b1.next = self.$cu[2].out.val();
            } else {
                self.$cl[0].b0.next = self.$cu[0].out.val();
                self.$cl[0].b1.next = self.$cu[3].out.val();
                self.$cl[1].b0.next = self.$cu[1].out.val();
                self.$cl[1].b1.next = self.$cu[4].out.val();
                self.$cl[2].b0.next = self.$cu[2].out.val();
                self.$cl[2].b1.next = self.$cu[5].out.val();
            }
            for c in 0..3 {
                self.$cl[c].clock.next = self.clock.val();
                self.$cl[c].f.next = self.frac_dly.q.val();
            }
            self.c_r.next = self.$cl[0].out.val();
            self.c_g.next = self.$cl[1].out.val();
            self.c_b.next = self.$cl[2].out.val();
            // a write leaves as zeros: the path it did not write read a texel, so clear it (the one it wrote gave zeros)
            self.written.clock.next = self.clock.val();
            self.wrote_colour.next = self.write_dly.q.val().get_bits::<1>(0) & self.$cs.q.val();
            self.wrote_bump.next = self.write_dly.q.val().get_bits::<1>(0) & !self.$cs.q.val();
            self.written.d.next = bit_cast::<2, 1>(self.wrote_colour.val()) | (bit_cast::<2, 1>(self.wrote_bump.val()) << 1);
            if self.written.q.val().get_bit(0) {
                self.lo.next = 0.into();
                self.hi.next = 0.into();
            }
            if self.written.q.val().get_bit(1) {
                self.c_r.next = 0.into();
                self.c_g.next = 0.into();
                self.c_b.next = 0.into();
            })?
        }
    }
}
pub use $m::$t;

impl $t {
    /// The signals the front's Verilog leaves unused on purpose.
    pub fn waivers() -> Vec<Waiver> {
        crate::stream::waivers(&[TRILINEAR $(, { let _ = stringify!($cu); TRILINEAR_COLOUR })?])
    }
}
    };
}

trilinear_front! {
    /// `TexTrilinear`: the trilinear front, two sets of the unit blocks side by side, one a level: the LOD unit gives
    /// ⌊λ⌋ and frac(λ); the second level is ⌊λ⌋ + 1, or at the last level (where frac(λ) is 0) ⌊λ⌋ − 1
    /// (`vectors::front::neighbour`). Two levels a step apart have sides of different parity (log2), so the map is
    /// split by it (the parity split: a bank has one read port, and two footprints a clock would otherwise need two
    /// copies of the memory): one fetch holds the levels of even side log2 (`TexFetch<EVEN, 11>`) and the other the
    /// odd ones (`TexFetch<ODD, 13>`), each taking the writes of its own levels from the one write port; each address
    /// unit reads the level its fetch holds, and each fetch feeds two bilinear units; then each byte of the two levels
    /// (⌊λ⌋'s picked by the parity it had) is blended by frac(λ): `round_half_up(b₀·2^8 + (b₁ − b₀)·f, 8)` (U8,
    /// `vectors::front::lerp`). Ports as `TexNearestMip`'s.
    module: trilinear,
    block: TexTrilinear,
}

trilinear_front! {
    /// `TexTrilinearColour`: `TexTrilinear` with a colour map (as `TexBilinearColour` beside `TexBilinear`): its
    /// RGB565 memory split by level parity as the bump map's (two more fetches, `wcolour` picking the memories a
    /// write goes to), read at the same two footprints, each texel widened to three bytes, six more bilinear units
    /// (R, G, B a level) on the levels' blend factors, and the two levels' channels blended by frac(λ) as the bump
    /// texel's bytes are. Outputs `c_r`, `c_g`, `c_b` in step with `lo` and `hi` (`vectors::front`); a write leaves
    /// as zeros on every output.
    module: trilinear_colour,
    block: TexTrilinearColour,
    colour: {
        select: wcolour_dly,
        fetches: [colour_even, colour_odd],
        widen: colour_widen,
        units: colour_filter,
        lerp: colour_lerp
    },
}

/// `TexTrilinearTwoPass`: trilinear in two passes of one set of the unit blocks, a pixel taking two clocks (the
/// k-clock variant beside `TexTrilinear`, which reads both levels in one clock with two sets). The LOD unit gives
/// ⌊λ⌋, frac(λ) and the second level (`vectors::front::neighbour`), as there. On the clock the LOD unit gives a
/// vector, the address unit reads level ⌊λ⌋ (the first pass); on the next it reads the second level (the second
/// pass) at the position and level kept in registers for it; so the one fetch (`TexFetch`, every level of the
/// chain) and the two bilinear units (low byte, high byte) give ⌊λ⌋'s bytes and then, a clock later, the second
/// level's, and the first are held a clock for the blend by frac(λ), as `TexTrilinear`'s. Ports and outputs as
/// `TexTrilinear`'s, the same values (the same model, one memory holding the chain).
///
/// A vector (a read or a write) may come at most every other clock: the clock after one is the second pass's and
/// carries no vector (`valid_in` low; a valid vector there would be lost to the second pass), and its data (a
/// write enable among them) are not read; the AXI4-Stream wrapper takes a beat every other clock
/// (`StreamUnit::INTERVAL`). A write's second pass reads nothing (its texel leaves as zero).
pub mod trilinear_two_pass {
    use super::level::{LevelLerp, LERP_LATENCY};
    use crate::prim::delay::Delay;
    use crate::prim::q::{Sq11_8, Sq3_8, Sq8_8, U16, U8};
    use crate::prim::ram_delay::RamDelay;
    use crate::tex_fetch::TexFetch;
    use crate::{bilinear::BilinearUnit, lod::Lod, tex_addr::TexAddr};
    use rust_hdl::prelude::*;

    /// Cycles from the front's input to the address unit's first pass, to the fetch's, to the bilinear units', to
    /// the blend of the two levels (on the second pass's bytes, a clock after the first's) and to its output (the
    /// difference; the product; the rounded sum).
    pub const AT_ADDR: usize = crate::lod::LATENCY;
    pub const AT_FETCH: usize = AT_ADDR + crate::tex_addr::LATENCY;
    pub const AT_FILTER: usize = AT_FETCH + crate::tex_fetch::LATENCY;
    pub const AT_LERP: usize = AT_FILTER + crate::bilinear::LATENCY + 1;
    pub const LATENCY: usize = AT_LERP + LERP_LATENCY;
    /// Clocks a vector takes: the two passes.
    pub const INTERVAL: usize = 2;

    crate::block! {
        #[derive(Default)]
        pub struct TexTrilinearTwoPass {
            pub clock: Signal<In, Clock>,
            pub valid_in: Signal<In, Bit>,
            pub u: Signal<In, Sq11_8>,
            pub v: Signal<In, Sq11_8>,
            pub du_dx: Signal<In, Sq8_8>,
            pub dv_dx: Signal<In, Sq8_8>,
            pub du_dy: Signal<In, Sq8_8>,
            pub dv_dy: Signal<In, Sq8_8>,
            pub lod_bias: Signal<In, Sq3_8>,
            pub log_side: Signal<In, Bits<4>>,
            pub uwrap: Signal<In, Bits<1>>,
            pub vwrap: Signal<In, Bits<1>>,
            pub we: Signal<In, Bits<1>>,
            pub w_log2: Signal<In, Bits<4>>,
            pub wx: Signal<In, U8>,
            pub wy: Signal<In, U8>,
            pub wdata: Signal<In, U16>,
            pub valid_out: Signal<Out, Bit>,
            pub lo: Signal<Out, U8>,
            pub hi: Signal<Out, U8>,
            pub lod: Lod,
            pos_dly: RamDelay<46, 4, { crate::lod::LATENCY }>, // (u, v, log_side, uwrap, vwrap) packed low to high
            pos_word: Signal<Local, Bits<46>>,
            next_level: Signal<Local, Bits<4>>, // ⌊λ⌋ + 1 ≤ 9 (λ ≤ 8)
            prev_level: Signal<Local, Bits<4>>, // ⌊λ⌋ − 1 (wraps at 0, unused there)
            second: Signal<Local, Bits<4>>,     // the level ⌊λ⌋ is blended with
            side_log2: Signal<Local, Bits<4>>,  // the map's side log2, waited beside the LOD unit
            // the second pass: on the clock after the first, its position, its level and that it is one
            p2_pos: DFF<Bits<46>>,
            p2_level: DFF<Bits<4>>,
            p2_valid: DFF<Bit>,
            pub addr: TexAddr,
            pub fetch: TexFetch, // the whole chain: the two passes read it on two clocks
            write_dly: RamDelay<37, 5, { crate::lod::LATENCY + crate::tex_addr::LATENCY }>, // (we, w_log2, wx, wy, wdata)
            write_word: Signal<Local, Bits<37>>,
            // at the fetch: the second pass, and whether its vector (the first pass's, a clock before) was a write
            p2_at_fetch: Delay<Bit, { crate::tex_addr::LATENCY }>,
            was_write: DFF<Bit>,
            pub filter: [BilinearUnit<8, 8>; 2], // low byte, high byte: ⌊λ⌋'s on the first pass, the second's after
            blend_dly: Delay<U16, { crate::tex_fetch::LATENCY }>, // each pass's (ublend, vblend) packed low to high
            blend_word: Signal<Local, U16>,
            // ⌊λ⌋'s two bytes, held a clock for the second level's
            first: [DFF<U8>; 2],
            // frac(λ), from the LOD unit to the blend of the two levels
            frac_dly: RamDelay<8, 5, { AT_LERP - crate::lod::LATENCY }>,
            // the blend of the two levels, a byte each (low, high)
            lerp: [LevelLerp; 2],
            // a vector's second pass, from the address unit to the output
            out_valid: Delay<Bit, { LATENCY - AT_ADDR - 1 }>,
        }
    }

    impl Logic for TexTrilinearTwoPass {
        #[hdl_gen]
        fn update(&mut self) {
            dff_setup!(self, clock, p2_pos, p2_level, p2_valid, was_write);
            self.lod.clock.next = self.clock.val();
            self.pos_dly.clock.next = self.clock.val();
            self.write_dly.clock.next = self.clock.val();
            self.addr.clock.next = self.clock.val();
            self.fetch.clock.next = self.clock.val();
            self.p2_at_fetch.clock.next = self.clock.val();
            self.blend_dly.clock.next = self.clock.val();
            self.frac_dly.clock.next = self.clock.val();
            self.out_valid.clock.next = self.clock.val();
            // the write, packed (bit copies), waits for its vector's address
            self.write_word.next = bit_cast::<37, 1>(self.we.val());
            self.write_word.next = self.write_word.val() | (bit_cast::<37, 4>(self.w_log2.val()) << 1);
            self.write_word.next = self.write_word.val() | (bit_cast::<37, 8>(self.wx.val()) << 5);
            self.write_word.next = self.write_word.val() | (bit_cast::<37, 8>(self.wy.val()) << 13);
            self.write_word.next = self.write_word.val() | (bit_cast::<37, 16>(self.wdata.val()) << 21);
            self.write_dly.d.next = self.write_word.val();
            // the level: from the derivatives, the position waiting beside the LOD unit (bit copies)
            self.lod.valid_in.next = self.valid_in.val();
            self.lod.du_dx.next = self.du_dx.val();
            self.lod.dv_dx.next = self.dv_dx.val();
            self.lod.du_dy.next = self.du_dy.val();
            self.lod.dv_dy.next = self.dv_dy.val();
            self.lod.log_side.next = self.log_side.val();
            self.lod.bias.next = self.lod_bias.val();
            self.pos_word.next = bit_cast::<46, 20>(self.u.val());
            self.pos_word.next = self.pos_word.val() | (bit_cast::<46, 20>(self.v.val()) << 20);
            self.pos_word.next = self.pos_word.val() | (bit_cast::<46, 4>(self.log_side.val()) << 40);
            self.pos_word.next = self.pos_word.val() | (bit_cast::<46, 1>(self.uwrap.val()) << 44);
            self.pos_word.next = self.pos_word.val() | (bit_cast::<46, 1>(self.vwrap.val()) << 45);
            self.pos_dly.d.next = self.pos_word.val();
            // the second level: ⌊λ⌋ + 1 below the last level, else ⌊λ⌋ − 1, else (a 1 × 1 map) 1
            self.next_level.next = self.lod.level.val() + 1; // ≤ 9 in 4 bits: exact
            self.prev_level.next = self.lod.level.val() - 1; // wraps at 0 on purpose: not read there
            self.side_log2.next = self.pos_dly.q.val().get_bits::<4>(40); // bit copies: the U4 it was
            self.second.next = 1.into();
            if self.lod.level.val().any() {
                self.second.next = self.prev_level.val();
            }
            if self.lod.level.val() < self.side_log2.val() {
                self.second.next = self.next_level.val();
            }
            // kept for the second pass
            self.p2_pos.d.next = self.pos_dly.q.val();
            self.p2_level.d.next = self.second.val();
            self.p2_valid.d.next = self.lod.valid_out.val();
            // the address unit: the first pass, ⌊λ⌋ at the position that waited beside the LOD unit; or on the clock
            // after, the second (bit copies throughout)
            self.addr.valid_in.next = self.lod.valid_out.val();
            self.addr.level.next = self.lod.level.val();
            self.addr.u.next = self.pos_dly.q.val().get_bits::<20>(0);
            self.addr.v.next = self.pos_dly.q.val().get_bits::<20>(20);
            self.addr.log_side.next = self.pos_dly.q.val().get_bits::<4>(40);
            self.addr.uwrap.next = self.pos_dly.q.val().get_bits::<1>(44);
            self.addr.vwrap.next = self.pos_dly.q.val().get_bits::<1>(45);
            if self.p2_valid.q.val() {
                self.addr.valid_in.next = true;
                self.addr.level.next = self.p2_level.q.val();
                self.addr.u.next = self.p2_pos.q.val().get_bits::<20>(0);
                self.addr.v.next = self.p2_pos.q.val().get_bits::<20>(20);
                self.addr.log_side.next = self.p2_pos.q.val().get_bits::<4>(40);
                self.addr.uwrap.next = self.p2_pos.q.val().get_bits::<1>(44);
                self.addr.vwrap.next = self.p2_pos.q.val().get_bits::<1>(45);
            }
            self.addr.linear.next = true.into(); // the bilinear footprint
            self.p2_at_fetch.d.next = self.p2_valid.q.val();
            // the fetch: the footprint the address unit gives, and the write that waited beside it (bit copies);
            // on a second pass no write, and a write's second pass no read either (it reads as a write: zeros)
            self.fetch.valid_in.next = self.addr.valid_out.val();
            self.fetch.level_log2.next = self.addr.level_log2.val();
            self.fetch.x0.next = self.addr.x0.val();
            self.fetch.x1.next = self.addr.x1.val();
            self.fetch.y0.next = self.addr.y0.val();
            self.fetch.y1.next = self.addr.y1.val();
            self.fetch.we.next = self.write_dly.q.val().get_bits::<1>(0);
            self.fetch.w_log2.next = self.write_dly.q.val().get_bits::<4>(1);
            self.fetch.wx.next = self.write_dly.q.val().get_bits::<8>(5);
            self.fetch.wy.next = self.write_dly.q.val().get_bits::<8>(13);
            self.fetch.wdata.next = self.write_dly.q.val().get_bits::<16>(21);
            self.was_write.d.next = self.write_dly.q.val().get_bit(0) & self.addr.valid_out.val();
            if self.p2_at_fetch.q.val() {
                self.fetch.we.next = 0.into();
                self.fetch.valid_in.next = true;
                if self.was_write.q.val() {
                    self.fetch.we.next = 1.into(); // a write's second pass: no read
                    self.fetch.valid_in.next = false; // and no write
                }
            }
            // the filter: each pass's four texels, blended by its factors that waited beside the fetch
            // ((ublend, vblend) packed and unpacked: bit copies)
            self.blend_word.next = bit_cast::<16, 8>(self.addr.ublend.val());
            self.blend_word.next = self.blend_word.val() | (bit_cast::<16, 8>(self.addr.vblend.val()) << 8);
            self.blend_dly.d.next = self.blend_word.val();
            for i in 0..2 {
                self.filter[i].clock.next = self.clock.val();
                // the pass's (ublend, vblend), unpacked: bit copies
                self.filter[i].ublend.next = self.blend_dly.q.val().get_bits::<8>(0);
                self.filter[i].vblend.next = self.blend_dly.q.val().get_bits::<8>(8);
            }
            // each texel's low byte to the first unit, its high byte to the second: bit copies
            self.filter[0].t00.next = self.fetch.t00.val().get_bits::<8>(0);
            self.filter[0].t10.next = self.fetch.t10.val().get_bits::<8>(0);
            self.filter[0].t01.next = self.fetch.t01.val().get_bits::<8>(0);
            self.filter[0].t11.next = self.fetch.t11.val().get_bits::<8>(0);
            self.filter[1].t00.next = self.fetch.t00.val().get_bits::<8>(8);
            self.filter[1].t10.next = self.fetch.t10.val().get_bits::<8>(8);
            self.filter[1].t01.next = self.fetch.t01.val().get_bits::<8>(8);
            self.filter[1].t11.next = self.fetch.t11.val().get_bits::<8>(8);
            // frac(λ) waits for the second level's bytes
            self.frac_dly.d.next = self.lod.frac.val();
            self.out_valid.d.next = self.p2_valid.q.val();
            // the blend of the two levels, per byte c: b₀ ⌊λ⌋'s, held a clock from the first pass; b₁ the second
            // level's, as it leaves its unit
            for c in 0..2 {
                self.first[c].clock.next = self.clock.val();
                self.first[c].d.next = self.filter[c].out.val();
                self.lerp[c].clock.next = self.clock.val();
                self.lerp[c].b0.next = self.first[c].q.val();
                self.lerp[c].b1.next = self.filter[c].out.val();
                self.lerp[c].f.next = self.frac_dly.q.val();
            }
            self.valid_out.next = self.out_valid.q.val();
            self.lo.next = self.lerp[0].out.val();
            self.hi.next = self.lerp[1].out.val();
        }
    }
}
pub use trilinear_two_pass::TexTrilinearTwoPass;

impl TexTrilinearTwoPass {
    /// The signals the front's Verilog leaves unused on purpose.
    pub fn waivers() -> Vec<Waiver> {
        TRILINEAR_TWO_PASS.to_vec()
    }
}
