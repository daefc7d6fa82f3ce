//! `polar_pipeline`: US 6,819,319's first embodiment, one pixel per clock, built from the unit blocks themselves:
//! polar_shade(S, R, Q, k1, k2, k3) → power(p) → α → blend(src, dst).
//! p rides beside the shade unit in a DFF chain; the mode and the colours wait in the `DelayedBlend`.
//! Latency 30 = polar_shade 11 + power 12 + blend 7.

use crate::delayed_blend::DelayedBlend;
use crate::polar_shade::PolarShade;
use crate::power::Power;
use crate::prim::delay::Delay;
use crate::prim::q::U8;
use rust_hdl::prelude::*;

pub const AT_POWER: usize = crate::polar_shade::LATENCY; // 11
pub const AT_BLEND: usize = AT_POWER + crate::power::LATENCY; // 23
pub const LATENCY: usize = AT_BLEND + crate::blend::LATENCY; // 30

/// The signals the block's Verilog leaves unused on purpose (`StreamUnit::waivers`).
const WAIVERS: &[crate::stream::Waiver] = &[(
    "shader$sum",
    "polar_shade's S11 before the clamp is an output for tests and waveforms; the pipeline uses the clamped shade",
)];

crate::stream_block! {
    /// `DC`: the Dreamcast toolchains' angle scale in the shade unit's tables (unit `polar_pipeline_dc`).
    #[derive(Default)]
    pub struct PolarPipeline<const DC: bool>: unit(if DC { "polar_pipeline_dc" } else { "polar_pipeline" }, LATENCY, waivers = WAIVERS) {
        in {
            s: U8,
            r: U8,
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
        pub shader: PolarShade<DC>,
        pub power: Power,
        pw_dly: Delay<U8, AT_POWER>,
        pub blend: DelayedBlend<5, AT_BLEND>,
        alpha_dly: Delay<U8, { crate::blend::LATENCY }>,
    }
}

impl<const DC: bool> Logic for PolarPipeline<DC> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, shader, power, blend, pw_dly, alpha_dly);
        // the shade
        self.shader.valid_in.next = self.valid_in.val();
        self.shader.s.next = self.s.val();
        self.shader.r.next = self.r.val();
        self.shader.q.next = self.q.val();
        self.shader.k1.next = self.k1.val();
        self.shader.k2.next = self.k2.val();
        self.shader.k3.next = self.k3.val();
        // the power
        self.pw_dly.d.next = self.pw.val();
        self.power.valid_in.next = self.shader.valid_out.val();
        self.power.x.next = self.shader.shade.val();
        self.power.pw.next = self.pw_dly.q.val();
        // the blend, α = the powered shade
        self.blend.mode.next = self.mode.val();
        self.blend.src_r.next = self.src_r.val();
        self.blend.src_g.next = self.src_g.val();
        self.blend.src_b.next = self.src_b.val();
        self.blend.dst_r.next = self.dst_r.val();
        self.blend.dst_g.next = self.dst_g.val();
        self.blend.dst_b.next = self.dst_b.val();
        self.blend.valid_in.next = self.power.valid_out.val();
        self.blend.alpha.next = self.power.y.val();
        self.alpha_dly.d.next = self.power.y.val();
        self.valid_out.next = self.blend.valid_out.val();
        self.alpha.next = self.alpha_dly.q.val();
        self.out_r.next = self.blend.out_r.val();
        self.out_g.next = self.blend.out_g.val();
        self.out_b.next = self.blend.out_b.val();
    }
}

/// The polar pipeline in the seed's angle scale (the default) and in the Dreamcast toolchains'.
pub type PolarPipelineSeed = PolarPipeline<false>;
pub type PolarPipelineDc = PolarPipeline<true>;
