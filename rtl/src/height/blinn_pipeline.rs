//! `blinn_pipeline`: Blinn's height-map function (US 2004/0207631 ¶31, ¶85) on the colour filter's own bilinear units:
//! the red, green and blue units (`BilinearUnit<8, 9, 1>`) blend the top-left, top-right and bottom-left grids of
//! a..h at the plain factors doubled to 9 bits (no blend adjust, no alpha unit, no texel k); the tangent unit shrinks
//! to G − R and B − R, each shifted down to the normal unit's half derivative; then height_normal [156] and the
//! shared normaliser. See `vectors::blinn_pipeline`.
//! Latency 41 = the grids 1 + bilinear 13 + the differences 1 + height_normal 12 + normalise 14.

use crate::bilinear::{self, BilinearUnit};
use crate::height_normal::{self, HeightNormal};
use crate::normalise::{self, Normalise};
use crate::prim::delay::Delay;
use crate::prim::q::{SBits, Sq1_10, U8};
use rust_hdl::prelude::*;

/// Clocks from the input to the normal unit's.
pub const AT_NORMAL: usize = 1 + bilinear::LATENCY + 1;
pub const LATENCY: usize = AT_NORMAL + height_normal::LATENCY + normalise::LATENCY;

/// The signals the block's Verilog leaves unused on purpose (`StreamUnit::waivers`).
const WAIVERS: &[crate::stream::Waiver] = &[
    ("unit$0$out", "Blinn's function reads each bilinear unit's exact result; the rounded one is the colour filter's"),
    ("unit$1$out", "as unit$0$out"),
    ("unit$2$out", "as unit$0$out"),
];

crate::stream_block! {
    #[derive(Default)]
    pub struct BlinnPipeline: unit("blinn_pipeline", LATENCY, waivers = WAIVERS) {
        in {
            a: U8,
            b: U8,
            c: U8,
            d: U8,
            e: U8,
            f: U8,
            g: U8,
            h: U8,
            ublend: U8,
            vblend: U8,
            scale: U8,
        }
        out {
            norm_x: Sq1_10,
            norm_y: Sq1_10,
            norm_z: Sq1_10,
        }
        // stage 1: the three grids (t00, t10, t01, t11 of red, green, blue) and the factors doubled (U9, exact)
        s1_t: [DFF<U8>; 12],
        s1_u: DFF<Bits<9>>,
        s1_v: DFF<Bits<9>>,
        pub unit: [BilinearUnit<8, 9, 1>; 3], // red, green, blue
        // G − R and B − R shifted down by 6, floor (S20 in 21)
        s2_t1: DFF<SBits<21>>,
        s2_t2: DFF<SBits<21>>,
        pub normal: HeightNormal,
        pub norm: Normalise,
        valid: Delay<Bit, AT_NORMAL>,
        scale_dly: Delay<U8, AT_NORMAL>,
        w_u: Signal<Local, Bits<9>>,
        w_v: Signal<Local, Bits<9>>,
        w_d1: Signal<Local, SBits<32>>,
        w_d2: Signal<Local, SBits<32>>,
    }
}

impl Logic for BlinnPipeline {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_u, s1_v, s2_t1, s2_t2);
        clock!(self, clock, normal, norm, valid, scale_dly);
        for i in 0..12 {
            self.s1_t[i].clock.next = self.clock.val();
        }
        for i in 0..3 {
            self.unit[i].clock.next = self.clock.val();
            self.unit[i].t00.next = self.s1_t[4 * i].q.val();
            self.unit[i].t10.next = self.s1_t[4 * i + 1].q.val();
            self.unit[i].t01.next = self.s1_t[4 * i + 2].q.val();
            self.unit[i].t11.next = self.s1_t[4 * i + 3].q.val();
            self.unit[i].ublend.next = self.s1_u.q.val();
            self.unit[i].vblend.next = self.s1_v.q.val();
        }
        self.valid.d.next = self.valid_in.val();
        self.scale_dly.d.next = self.scale.val();
        // stage 1: red [a b; d e], green [b c; e f], blue [d e; g h] (the replicate unit without alpha)
        self.s1_t[0].d.next = self.a.val();
        self.s1_t[1].d.next = self.b.val();
        self.s1_t[2].d.next = self.d.val();
        self.s1_t[3].d.next = self.e.val();
        self.s1_t[4].d.next = self.b.val();
        self.s1_t[5].d.next = self.c.val();
        self.s1_t[6].d.next = self.e.val();
        self.s1_t[7].d.next = self.f.val();
        self.s1_t[8].d.next = self.d.val();
        self.s1_t[9].d.next = self.e.val();
        self.s1_t[10].d.next = self.g.val();
        self.s1_t[11].d.next = self.h.val();
        self.w_u.next = bit_cast::<9, 8>(self.ublend.val()); // U8 in 9, widening
        self.w_v.next = bit_cast::<9, 8>(self.vblend.val()); // U8 in 9, widening
        self.s1_u.d.next = self.w_u.val() << 1; // 2U in 1/512: U9, exact
        self.s1_v.d.next = self.w_v.val() << 1; // 2V in 1/512: U9, exact

        // the units' exact results (U25 of 32) → G − R and B − R (S26, two's complement in 32, exact)
        self.w_d1.next = self.unit[1].wide.val() - self.unit[0].wide.val(); // S26 in 32, exact
        self.w_d2.next = self.unit[2].wide.val() - self.unit[0].wide.val(); // S26 in 32, exact
                                                                            // bits 6..26 of the two's complement S26:
                                                                            // >> 6, floor, S20 in 21 (as the tangent
                                                                            // unit's last stage)
        self.s2_t1.d.next = self.w_d1.val().get_bits::<21>(6);
        self.s2_t2.d.next = self.w_d2.val().get_bits::<21>(6);
        // normal [156] and the shared normaliser
        self.normal.valid_in.next = self.valid.q.val();
        self.normal.t1.next = self.s2_t1.q.val();
        self.normal.t2.next = self.s2_t2.q.val();
        self.normal.scale.next = self.scale_dly.q.val();
        self.norm.valid_in.next = self.normal.valid_out.val();
        self.norm.vec_x.next = self.normal.n_x.val();
        self.norm.vec_y.next = self.normal.n_y.val();
        self.norm.vec_z.next = self.normal.n_z.val();
        self.norm_x.next = self.norm.norm_x.val();
        self.norm_y.next = self.norm.norm_y.val();
        self.norm_z.next = self.norm.norm_z.val();
        self.valid_out.next = self.norm.valid_out.val();
    }
}
