//! `cart_surface`: US 6,819,319's Cartesian pipeline for a scene with one light per surface (a directional light, or
//! a point light taken at the surface's centre): the light arrives already a unit vector, once per surface, so the
//! pipeline holds no `light_iter` and no light normaliser. The light still travels with each pixel (a curved
//! surface's triangles each have their own), in one block-RAM delay line to the dot product.
//! bilinear(TexelX, TexelZ) → cart_decode → normalise ─┐
//! L (unit, Sq1.10) ─────────── (RAM delay 29) ────────┴→ dot3 → gloss(C) → α = P >> 2 → blend.
//! Latency 59 = bilinear 13 + cart_decode 4 + normalise 14 + dot3 7 + gloss 14 + blend 7.
//!
//! `cart_surface_matte` is the same pipeline for a material with C = 0, where the gloss unit's P = X: it holds no
//! gloss unit and has no C port, and α = X >> 2 (latency 45). The `_hemi_oct` variants read hemi-octahedral texels
//! through `cart_decode_hemi_oct` (one clock less). `cartesian_pipeline!` (`wiring.rs`, shared with `cart_pipeline`)
//! writes all eight, so each exported Verilog holds only its own units.

use crate::cart_decode::CartDecode;
use crate::cart_decode_hemi_oct::CartDecodeHemiOct;
use crate::cartesian::wiring::cartesian_pipeline;
use rust_hdl::prelude::*;

cartesian_pipeline! {
    module: seed,
    block: CartSurface,
    unit: "cart_surface",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    filter: { units: filter, valid: filter_valid, u: ublend, v: vblend },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: matte,
    block: CartSurfaceMatte,
    unit: "cart_surface_matte",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    filter: { units: filter, valid: filter_valid, u: ublend, v: vblend },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
}

cartesian_pipeline! {
    module: hemi_oct,
    block: CartSurfaceHemiOct,
    unit: "cart_surface_hemi_oct",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    filter: { units: filter, valid: filter_valid, u: ublend, v: vblend },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: hemi_oct_matte,
    block: CartSurfaceHemiOctMatte,
    unit: "cart_surface_hemi_oct_matte",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    filter: { units: filter, valid: filter_valid, u: ublend, v: vblend },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
}

cartesian_pipeline! {
    module: nearest,
    block: CartSurfaceNearest,
    unit: "cart_surface_nearest",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    nearest: { x: t_x, z: t_z },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: nearest_matte,
    block: CartSurfaceNearestMatte,
    unit: "cart_surface_nearest_matte",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    nearest: { x: t_x, z: t_z },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
}

cartesian_pipeline! {
    module: nearest_hemi_oct,
    block: CartSurfaceNearestHemiOct,
    unit: "cart_surface_nearest_hemi_oct",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    nearest: { x: t_x, z: t_z },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: nearest_hemi_oct_matte,
    block: CartSurfaceNearestHemiOctMatte,
    unit: "cart_surface_nearest_hemi_oct_matte",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    nearest: { x: t_x, z: t_z },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
}
