//! `texture_filter`: US 2004/0207631's texture filter with its mode input: one set of four bilinear units
//! (`BilinearUnit<8, 9, 1>`) filters RGBA colour (`mode` = 0) or, fed by the fetch's select [151], replicate [152]
//! and blend adjust [153], generates a normal from a 2×2-interleaved height map (`mode` = 1) through tangent [155],
//! normal [156] and the shared normaliser. See `vectors::texture_filter`. Both results leave every clock, the
//! colour held in a block-RAM delay line until the normal is ready.
//! Latency 48 = the front 1 + bilinear 13 + tangent 8 + height_normal 12 + normalise 14.

use crate::bilinear::{self, BilinearUnit};
use crate::prim::delay::Delay;
use crate::prim::q::{Sq1_10, U8};
use crate::prim::ram_delay::RamDelay;
use crate::tangent_to_normal::{self, TangentToNormal};
use rust_hdl::prelude::*;

pub const AT_TANGENT: usize = 1 + bilinear::LATENCY;
pub const LATENCY: usize = AT_TANGENT + tangent_to_normal::LATENCY;
/// The colour's delay line's address bits: 5, or more where its LATENCY − AT_TANGENT clocks need a longer ring.
const COLOUR_LINE_BITS: usize = crate::prim::ram_delay::addr_bits(LATENCY - AT_TANGENT, 5);

crate::stream_block! {
    #[derive(Default)]
    pub struct TextureFilter: unit("texture_filter", LATENCY) {
        in {
            t00_r: U8,
            t00_g: U8,
            t00_b: U8,
            t00_a: U8,
            t10_r: U8,
            t10_g: U8,
            t10_b: U8,
            t10_a: U8,
            t01_r: U8,
            t01_g: U8,
            t01_b: U8,
            t01_a: U8,
            t11_r: U8,
            t11_g: U8,
            t11_b: U8,
            t11_a: U8,
            ublend: U8,
            vblend: U8,
            mode: Bits<1>,
            ox: Bits<1>,
            oy: Bits<1>,
            scale: U8,
        }
        out {
            out_r: U8,
            out_g: U8,
            out_b: U8,
            out_a: U8,
            norm_x: Sq1_10,
            norm_y: Sq1_10,
            norm_z: Sq1_10,
        }
        // stage 1: each unit's four texels and two factors, for the mode: colour channel c of the four texels at
        // 2U, 2V; or its 2×2 grid of the 3×3 window at (ox, oy) in the 4 × 4 block, at ½ + U/2 or U/2 (U9)
        s1_t: [DFF<U8>; 16],
        s1_u: [DFF<Bits<9>>; 4],
        s1_v: [DFF<Bits<9>>; 4],
        pub unit: [BilinearUnit<8, 9, 1>; 4], // red, green, blue, alpha
        colour: RamDelay<32, COLOUR_LINE_BITS, { LATENCY - AT_TANGENT }>, // the rounded colour, waiting for the normal
        pub back: TangentToNormal,
        valid: Delay<Bit, AT_TANGENT>,
        u_dly: Delay<U8, AT_TANGENT>,
        v_dly: Delay<U8, AT_TANGENT>,
        scale_dly: Delay<U8, AT_TANGENT>,
        w_u9: Signal<Local, Bits<9>>,
        w_v9: Signal<Local, Bits<9>>,
        w_pack: Signal<Local, Bits<32>>,
        w_r: Signal<Local, Bits<32>>,
        w_g: Signal<Local, Bits<32>>,
        w_b: Signal<Local, Bits<32>>,
        w_a: Signal<Local, Bits<32>>,
    }
}

impl Logic for TextureFilter {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, colour, back, valid, u_dly, v_dly, scale_dly);
        for i in 0..16 {
            self.s1_t[i].clock.next = self.clock.val();
        }
        for i in 0..4 {
            self.s1_u[i].clock.next = self.clock.val();
            self.s1_v[i].clock.next = self.clock.val();
            self.unit[i].clock.next = self.clock.val();
            self.unit[i].t00.next = self.s1_t[4 * i].q.val();
            self.unit[i].t10.next = self.s1_t[4 * i + 1].q.val();
            self.unit[i].t01.next = self.s1_t[4 * i + 2].q.val();
            self.unit[i].t11.next = self.s1_t[4 * i + 3].q.val();
            self.unit[i].ublend.next = self.s1_u[i].q.val();
            self.unit[i].vblend.next = self.s1_v[i].q.val();
        }
        self.valid.d.next = self.valid_in.val();
        // stage 1: the texels (the fetch's select [151] and replicate [152] in height mode: wiring and muxes)
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[0].d.next = self.t00_a.val();
                } else {
                    self.s1_t[0].d.next = self.t00_b.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[0].d.next = self.t00_g.val();
            } else {
                self.s1_t[0].d.next = self.t00_r.val();
            }
        } else {
            self.s1_t[0].d.next = self.t00_r.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[1].d.next = self.t10_b.val();
                } else {
                    self.s1_t[1].d.next = self.t00_a.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[1].d.next = self.t10_r.val();
            } else {
                self.s1_t[1].d.next = self.t00_g.val();
            }
        } else {
            self.s1_t[1].d.next = self.t10_r.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[2].d.next = self.t01_g.val();
                } else {
                    self.s1_t[2].d.next = self.t01_r.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[2].d.next = self.t00_a.val();
            } else {
                self.s1_t[2].d.next = self.t00_b.val();
            }
        } else {
            self.s1_t[2].d.next = self.t01_r.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[3].d.next = self.t11_r.val();
                } else {
                    self.s1_t[3].d.next = self.t01_g.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[3].d.next = self.t10_b.val();
            } else {
                self.s1_t[3].d.next = self.t00_a.val();
            }
        } else {
            self.s1_t[3].d.next = self.t11_r.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[4].d.next = self.t10_b.val();
                } else {
                    self.s1_t[4].d.next = self.t00_a.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[4].d.next = self.t10_r.val();
            } else {
                self.s1_t[4].d.next = self.t00_g.val();
            }
        } else {
            self.s1_t[4].d.next = self.t00_g.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[5].d.next = self.t10_a.val();
                } else {
                    self.s1_t[5].d.next = self.t10_b.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[5].d.next = self.t10_g.val();
            } else {
                self.s1_t[5].d.next = self.t10_r.val();
            }
        } else {
            self.s1_t[5].d.next = self.t10_g.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[6].d.next = self.t11_r.val();
                } else {
                    self.s1_t[6].d.next = self.t01_g.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[6].d.next = self.t10_b.val();
            } else {
                self.s1_t[6].d.next = self.t00_a.val();
            }
        } else {
            self.s1_t[6].d.next = self.t01_g.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[7].d.next = self.t11_g.val();
                } else {
                    self.s1_t[7].d.next = self.t11_r.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[7].d.next = self.t10_a.val();
            } else {
                self.s1_t[7].d.next = self.t10_b.val();
            }
        } else {
            self.s1_t[7].d.next = self.t11_g.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[8].d.next = self.t01_g.val();
                } else {
                    self.s1_t[8].d.next = self.t01_r.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[8].d.next = self.t00_a.val();
            } else {
                self.s1_t[8].d.next = self.t00_b.val();
            }
        } else {
            self.s1_t[8].d.next = self.t00_b.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[9].d.next = self.t11_r.val();
                } else {
                    self.s1_t[9].d.next = self.t01_g.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[9].d.next = self.t10_b.val();
            } else {
                self.s1_t[9].d.next = self.t00_a.val();
            }
        } else {
            self.s1_t[9].d.next = self.t10_b.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[10].d.next = self.t01_a.val();
                } else {
                    self.s1_t[10].d.next = self.t01_b.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[10].d.next = self.t01_g.val();
            } else {
                self.s1_t[10].d.next = self.t01_r.val();
            }
        } else {
            self.s1_t[10].d.next = self.t01_b.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[11].d.next = self.t11_b.val();
                } else {
                    self.s1_t[11].d.next = self.t01_a.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[11].d.next = self.t11_r.val();
            } else {
                self.s1_t[11].d.next = self.t01_g.val();
            }
        } else {
            self.s1_t[11].d.next = self.t11_b.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[12].d.next = self.t11_r.val();
                } else {
                    self.s1_t[12].d.next = self.t01_g.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[12].d.next = self.t10_b.val();
            } else {
                self.s1_t[12].d.next = self.t00_a.val();
            }
        } else {
            self.s1_t[12].d.next = self.t00_a.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[13].d.next = self.t11_g.val();
                } else {
                    self.s1_t[13].d.next = self.t11_r.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[13].d.next = self.t10_a.val();
            } else {
                self.s1_t[13].d.next = self.t10_b.val();
            }
        } else {
            self.s1_t[13].d.next = self.t10_a.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[14].d.next = self.t11_b.val();
                } else {
                    self.s1_t[14].d.next = self.t01_a.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[14].d.next = self.t11_r.val();
            } else {
                self.s1_t[14].d.next = self.t01_g.val();
            }
        } else {
            self.s1_t[14].d.next = self.t01_a.val();
        }
        if self.mode.val().any() {
            if self.oy.val().any() {
                if self.ox.val().any() {
                    self.s1_t[15].d.next = self.t11_a.val();
                } else {
                    self.s1_t[15].d.next = self.t11_b.val();
                }
            } else if self.ox.val().any() {
                self.s1_t[15].d.next = self.t11_g.val();
            } else {
                self.s1_t[15].d.next = self.t11_r.val();
            }
        } else {
            self.s1_t[15].d.next = self.t11_a.val();
        }
        // stage 1: the factors: 2U, 2V in colour mode; blend adjust [153] in height mode (½ + U/2 = 256 + U, U/2 = U)
        self.w_u9.next = bit_cast::<9, 8>(self.ublend.val()); // U8 in 9, widening
        self.w_v9.next = bit_cast::<9, 8>(self.vblend.val()); // U8 in 9, widening
        if self.mode.val().any() {
            self.s1_u[0].d.next = self.w_u9.val() | 0x100; // red: ½ + U/2 in 1/512, exact
            self.s1_u[1].d.next = self.w_u9.val(); // green: U/2
            self.s1_u[2].d.next = self.w_u9.val() | 0x100; // blue: ½ + U/2
            self.s1_u[3].d.next = self.w_u9.val(); // alpha: U/2
            self.s1_v[0].d.next = self.w_v9.val() | 0x100; // red: ½ + V/2
            self.s1_v[1].d.next = self.w_v9.val() | 0x100; // green: ½ + V/2
            self.s1_v[2].d.next = self.w_v9.val(); // blue: V/2
            self.s1_v[3].d.next = self.w_v9.val(); // alpha: V/2
        } else {
            for i in 0..4 {
                self.s1_u[i].d.next = self.w_u9.val() << 1; // 2U in 1/512: U9, exact
                self.s1_v[i].d.next = self.w_v9.val() << 1; // 2V in 1/512: U9, exact
            }
        }
        // the colour, packed (r in the low byte), waits for the normal in block RAM
        self.w_g.next = bit_cast::<32, 8>(self.unit[1].out.val()) << 8; // g in bits 8..15
        self.w_b.next = bit_cast::<32, 8>(self.unit[2].out.val()) << 16; // b in bits 16..23
        self.w_a.next = bit_cast::<32, 8>(self.unit[3].out.val()) << 24; // a in bits 24..31
        self.w_r.next = bit_cast::<32, 8>(self.unit[0].out.val()); // r in bits 0..7
        self.w_pack.next = self.w_r.val() | self.w_g.val() | self.w_b.val() | self.w_a.val(); // four U8 side by side, exact
        self.colour.d.next = self.w_pack.val();
        self.out_r.next = self.colour.q.val().get_bits::<8>(0); // a split
        self.out_g.next = self.colour.q.val().get_bits::<8>(8); // a split
        self.out_b.next = self.colour.q.val().get_bits::<8>(16); // a split
        self.out_a.next = self.colour.q.val().get_bits::<8>(24); // a split

        // tangent [155], normal [156] and the normaliser, on the units' exact results (U25 of the 32-bit wide
        // outputs: their range, exact)
        self.u_dly.d.next = self.ublend.val();
        self.v_dly.d.next = self.vblend.val();
        self.scale_dly.d.next = self.scale.val();
        self.back.valid_in.next = self.valid.q.val();
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
