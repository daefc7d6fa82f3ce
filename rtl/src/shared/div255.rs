//! `Div255`: a U16 numerator (≤ 65,152 = 255·255 + 127) divided by 255 and rounded to nearest, in two stages:
//! `t = num + 128`, then `(t + (t >> 8)) >> 8` (truncating). The same arithmetic as `vectors::blend::div255`.
//! Latency 2. Used after every 8 × 8 product of the polar shade unit, where 255 stands for 1.0.

use rust_hdl::prelude::*;

pub const LATENCY: usize = 2;

crate::block! {
    #[derive(Default)]
    pub struct Div255 {
        pub clock: Signal<In, Clock>,
        pub num: Signal<In, Bits<16>>,
        pub quot: Signal<Out, Bits<8>>,
        s1_t: DFF<Bits<16>>,
        s2_q: DFF<Bits<8>>,
        w_th: Signal<Local, Bits<16>>,
        w_u: Signal<Local, Bits<16>>,
    }
}

impl Logic for Div255 {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_t, s2_q);
        self.s1_t.d.next = self.num.val() + 128; // ≤ 65,280: no wrap
        self.w_th.next = self.s1_t.q.val() >> 8; // t >> 8 ≤ 255 (U8 in 16), floor
        self.w_u.next = self.s1_t.q.val() + self.w_th.val(); // ≤ 65,534: no wrap
        self.s2_q.d.next = self.w_u.val().get_bits::<8>(8); // U16 >> 8 (floor): U8, num/255 rounded half up
        self.quot.next = self.s2_q.q.val();
    }
}
