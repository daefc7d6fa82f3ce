//! `height_pipeline`: US 2004/0207631's normal generation (FIG. 7) from the fetched 3×3 heights, one normal per clock,
//! built from the unit blocks themselves: replicate [152] and blend adjust [153] side by side → the four bilinear
//! units [65–68] (`BilinearUnit<8, 9, 1>`, the colour filter's own) → tangent [155] → height_normal [156] →
//! the shared `normalise`. The unadjusted blend factors ride beside the bilinear units to the tangent unit, the
//! scale factor to the normal unit.
//! Latency 48 = replicate 1 + bilinear 13 + tangent 8 + height_normal 12 + normalise 14.

use crate::bilinear::{self, BilinearUnit};
use crate::blend_adjust::{self, BlendAdjust};
use crate::prim::delay::Delay;
use crate::prim::q::{Sq1_10, U8};
use crate::replicate::{self, Replicate};
use crate::tangent_to_normal::{self, TangentToNormal};
use rust_hdl::prelude::*;

/// Clocks from the pipeline's input to the tangent unit's.
pub const AT_TANGENT: usize = replicate::LATENCY + bilinear::LATENCY;
pub const LATENCY: usize = AT_TANGENT + tangent_to_normal::LATENCY;
// replicate and blend adjust run side by side
const _: () = assert!(replicate::LATENCY == blend_adjust::LATENCY);

/// The signals the block's Verilog leaves unused on purpose (`StreamUnit::waivers`).
const WAIVERS: &[crate::stream::Waiver] = &[
    ("unit$0$out", "the height path reads each bilinear unit's exact result; the rounded one is the colour filter's"),
    ("unit$1$out", "as unit$0$out"),
    ("unit$2$out", "as unit$0$out"),
    ("unit$3$out", "as unit$0$out"),
];

crate::stream_block! {
    #[derive(Default)]
    pub struct HeightPipeline: unit("height_pipeline", LATENCY, waivers = WAIVERS) {
        in {
            a: U8,
            b: U8,
            c: U8,
            d: U8,
            e: U8,
            f: U8,
            g: U8,
            h: U8,
            k: U8,
            ublend: U8,
            vblend: U8,
            scale: U8,
        }
        out {
            norm_x: Sq1_10,
            norm_y: Sq1_10,
            norm_z: Sq1_10,
        }
        pub replicate: Replicate,
        pub adjust: BlendAdjust,
        pub unit: [BilinearUnit<8, 9, 1>; 4], // red, green, blue, alpha
        pub back: TangentToNormal,
        unit_valid: Delay<Bit, { bilinear::LATENCY }>,
        u_dly: Delay<U8, AT_TANGENT>,
        v_dly: Delay<U8, AT_TANGENT>,
        scale_dly: Delay<U8, AT_TANGENT>,
    }
}

impl Logic for HeightPipeline {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, replicate, adjust, back, unit_valid, u_dly, v_dly, scale_dly);
        for i in 0..4 {
            self.unit[i].clock.next = self.clock.val();
        }
        // replicate [152] and blend adjust [153]
        self.replicate.valid_in.next = self.valid_in.val();
        self.replicate.a.next = self.a.val();
        self.replicate.b.next = self.b.val();
        self.replicate.c.next = self.c.val();
        self.replicate.d.next = self.d.val();
        self.replicate.e.next = self.e.val();
        self.replicate.f.next = self.f.val();
        self.replicate.g.next = self.g.val();
        self.replicate.h.next = self.h.val();
        self.replicate.k.next = self.k.val();
        self.adjust.valid_in.next = self.valid_in.val();
        self.adjust.ublend.next = self.ublend.val();
        self.adjust.vblend.next = self.vblend.val();
        // the four bilinear units [65–68]: red (U0, V0), green (U1, V0), blue (U0, V1), alpha (U1, V1) [60]
        self.unit[0].t00.next = self.replicate.r00.val();
        self.unit[0].t10.next = self.replicate.r10.val();
        self.unit[0].t01.next = self.replicate.r01.val();
        self.unit[0].t11.next = self.replicate.r11.val();
        self.unit[0].ublend.next = self.adjust.u0.val();
        self.unit[0].vblend.next = self.adjust.v0.val();
        self.unit[1].t00.next = self.replicate.g00.val();
        self.unit[1].t10.next = self.replicate.g10.val();
        self.unit[1].t01.next = self.replicate.g01.val();
        self.unit[1].t11.next = self.replicate.g11.val();
        self.unit[1].ublend.next = self.adjust.u1.val();
        self.unit[1].vblend.next = self.adjust.v0.val();
        self.unit[2].t00.next = self.replicate.b00.val();
        self.unit[2].t10.next = self.replicate.b10.val();
        self.unit[2].t01.next = self.replicate.b01.val();
        self.unit[2].t11.next = self.replicate.b11.val();
        self.unit[2].ublend.next = self.adjust.u0.val();
        self.unit[2].vblend.next = self.adjust.v1.val();
        self.unit[3].t00.next = self.replicate.a00.val();
        self.unit[3].t10.next = self.replicate.a10.val();
        self.unit[3].t01.next = self.replicate.a01.val();
        self.unit[3].t11.next = self.replicate.a11.val();
        self.unit[3].ublend.next = self.adjust.u1.val();
        self.unit[3].vblend.next = self.adjust.v1.val();
        // both front units carry the same valid flag; it rides beside the bilinear units
        self.unit_valid.d.next = self.replicate.valid_out.val() & self.adjust.valid_out.val();
        // tangent [155], normal [156] and the normaliser, on the units' exact results (U25 of the 32-bit wide
        // outputs: their range, exact)
        self.u_dly.d.next = self.ublend.val();
        self.v_dly.d.next = self.vblend.val();
        self.scale_dly.d.next = self.scale.val();
        self.back.valid_in.next = self.unit_valid.q.val();
        self.back.red.next = self.unit[0].wide.val().get_bits::<25>(0); // U25, exact
        self.back.green.next = self.unit[1].wide.val().get_bits::<25>(0); // U25, exact
        self.back.blue.next = self.unit[2].wide.val().get_bits::<25>(0); // U25, exact
        self.back.alpha.next = self.unit[3].wide.val().get_bits::<25>(0); // U25, exact
        self.back.ublend.next = self.u_dly.q.val();
        self.back.vblend.next = self.v_dly.q.val();
        self.back.scale.next = self.scale_dly.q.val();
        self.norm_x.next = self.back.norm_x.val();
        self.norm_y.next = self.back.norm_y.val();
        self.norm_z.next = self.back.norm_z.val();
        self.valid_out.next = self.back.valid_out.val();
    }
}
