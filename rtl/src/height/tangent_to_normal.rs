//! The height path after the four bilinear units, as one block both tops hold: tangent [155] → normal [156] → the
//! shared normaliser, the scale factor waiting beside the tangent unit. Latency 34 = tangent 8 + height_normal 12 +
//! normalise 14.

use crate::height_normal::{self, HeightNormal};
use crate::normalise::{self, Normalise};
use crate::prim::delay::Delay;
use crate::prim::q::{Sq1_10, U8};
use crate::tangent::{self, Tangent};
use rust_hdl::prelude::*;

pub const LATENCY: usize = tangent::LATENCY + height_normal::LATENCY + normalise::LATENCY;

crate::block! {
    #[derive(Default)]
    pub struct TangentToNormal {
        pub clock: Signal<In, Clock>,
        pub valid_in: Signal<In, Bit>,
        /// The four units' exact results (U25, 17 fraction bits of a height LSB), the unadjusted blend factors and the
        /// scale factor, all of one pixel on the same clock.
        pub red: Signal<In, Bits<25>>,
        pub green: Signal<In, Bits<25>>,
        pub blue: Signal<In, Bits<25>>,
        pub alpha: Signal<In, Bits<25>>,
        pub ublend: Signal<In, U8>,
        pub vblend: Signal<In, U8>,
        pub scale: Signal<In, U8>,
        pub valid_out: Signal<Out, Bit>,
        pub norm_x: Signal<Out, Sq1_10>,
        pub norm_y: Signal<Out, Sq1_10>,
        pub norm_z: Signal<Out, Sq1_10>,
        pub tangent: Tangent,
        pub normal: HeightNormal,
        pub norm: Normalise,
        scale_dly: Delay<U8, { tangent::LATENCY }>,
    }
}

impl Logic for TangentToNormal {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, tangent, normal, norm, scale_dly);
        // tangent [155]
        self.tangent.valid_in.next = self.valid_in.val();
        self.tangent.red.next = self.red.val();
        self.tangent.green.next = self.green.val();
        self.tangent.blue.next = self.blue.val();
        self.tangent.alpha.next = self.alpha.val();
        self.tangent.ublend.next = self.ublend.val();
        self.tangent.vblend.next = self.vblend.val();
        // normal [156], then the shared normaliser
        self.scale_dly.d.next = self.scale.val();
        self.normal.valid_in.next = self.tangent.valid_out.val();
        self.normal.t1.next = self.tangent.t1.val();
        self.normal.t2.next = self.tangent.t2.val();
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
