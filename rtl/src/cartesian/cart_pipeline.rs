//! `cart_pipeline`: US 6,819,319's second embodiment, one pixel per clock, built from the unit blocks themselves:
//! bilinear(TexelX, TexelZ) → cart_decode → normalise ─────────────┐
//! light_iter → (delay 9) → normalise ─────────────────────────────┴→ dot3 → gloss → α = P >> 2 → blend.
//! Side-band values ride beside the stages they skip: C in a block-RAM delay line (`RamDelay`), the mode and the
//! colours in the `DelayedBlend`, the light and P in short DFF chains.
//! Latency 59 = bilinear 13 + cart_decode 4 + normalise 14 + dot3 7 + gloss 14 + blend 7.
//!
//! Four variants, each written by `cartesian_pipeline!` (`wiring.rs`, shared with `cart_surface`), so each exported
//! Verilog holds only its own units:
//! - `CartPipeline` (`cart_pipeline`): the seed's offset-binary texels through `cart_decode`;
//! - `CartPipelineHemiOct` (`cart_pipeline_hemi_oct`): rotated hemi-octahedral texels (U on the red channel, V on
//!   green) through `cart_decode_hemi_oct`, latency 57. Bilinear filtering of (U, V) is filtering of (x, z): the
//!   map between them is linear.
//! - `CartPipelineMatte` (`cart_pipeline_matte`) and `CartPipelineHemiOctMatte` (`cart_pipeline_hemi_oct_matte`):
//!   the same for a material with C = 0, where the gloss unit's P = X: no gloss unit, no C port, no C delay line,
//!   α = X >> 2 (latency 45 and 44).

use crate::cart_decode::CartDecode;
use crate::cart_decode_hemi_oct::CartDecodeHemiOct;
use crate::cartesian::wiring::cartesian_pipeline;
use rust_hdl::prelude::*;

cartesian_pipeline! {
    module: seed,
    block: CartPipeline,
    unit: "cart_pipeline",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    filter: { units: filter, valid: filter_valid, u: ublend, v: vblend },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: matte,
    block: CartPipelineMatte,
    unit: "cart_pipeline_matte",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    filter: { units: filter, valid: filter_valid, u: ublend, v: vblend },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    module: hemi_oct,
    block: CartPipelineHemiOct,
    unit: "cart_pipeline_hemi_oct",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    filter: { units: filter, valid: filter_valid, u: ublend, v: vblend },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: hemi_oct_matte,
    block: CartPipelineHemiOctMatte,
    unit: "cart_pipeline_hemi_oct_matte",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    filter: { units: filter, valid: filter_valid, u: ublend, v: vblend },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}
