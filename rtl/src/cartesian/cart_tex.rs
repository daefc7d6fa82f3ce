//! The Cartesian pipelines on the texture unit: the pipelines of `cart_pipeline` with the map in the unit's memory,
//! fed by what a rasteriser gives (u, v, and for a MIP filter their screen derivatives) in place of four texels
//! and two blend factors the host fetched: front (`texture::front`) → cart_decode → normalise ─┐ … as there.
//! Named `cart_tex_<filter>[_matte]`; the front's latency comes before the decode, and the side-band lines grow by
//! it (their lengths follow from the `AT_` constants the wiring derives).

use crate::cart_decode::CartDecode;
use crate::cartesian::wiring::cartesian_pipeline;
use rust_hdl::prelude::*;

cartesian_pipeline! {
    module: bilinear,
    block: CartTexBilinear,
    unit: "cart_tex_bilinear",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexBilinear, module: bilinear, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: bilinear_matte,
    block: CartTexBilinearMatte,
    unit: "cart_tex_bilinear_matte",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexBilinear, module: bilinear, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    module: nearest_matte,
    block: CartTexNearestMatte,
    unit: "cart_tex_nearest_matte",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearest, module: nearest, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    module: nearest_mip_matte,
    block: CartTexNearestMipMatte,
    unit: "cart_tex_nearest_mip_matte",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearestMip, module: nearest_mip, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    module: trilinear_matte,
    block: CartTexTrilinearMatte,
    unit: "cart_tex_trilinear_matte",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexTrilinear, module: trilinear, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}
