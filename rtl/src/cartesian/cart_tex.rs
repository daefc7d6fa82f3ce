//! The Cartesian pipelines on the texture unit: the pipelines of `cart_pipeline` with the map in the unit's memory,
//! fed by what a rasteriser gives (u, v, and for a MIP filter their screen derivatives) in place of four texels
//! and two blend factors the host fetched: front (`texture::front`) → cart_decode → normalise ─┐ … as there.
//! Named `cart_tex_<filter>[_two_pass][_surface][_hemi_oct][_matte]` after the host-fed pipeline each replaces (`_surface`:
//! `cart_surface`'s one light per surface); the front's latency comes before the decode, and the side-band lines
//! grow by it (their lengths follow from the `AT_` constants the wiring derives).

use crate::cart_decode::CartDecode;
use crate::cart_decode_hemi_oct::CartDecodeHemiOct;
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

// trilinear with the gloss unit: lights per vertex, seed or hemi-oct texels; one light per surface (the light word
// waits AT_DOT clocks, the front's, the decode's and the normaliser's: 2^6 words)
cartesian_pipeline! {
    module: trilinear,
    block: CartTexTrilinear,
    unit: "cart_tex_trilinear",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexTrilinear, module: trilinear, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: trilinear_hemi_oct,
    block: CartTexTrilinearHemiOct,
    unit: "cart_tex_trilinear_hemi_oct",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexTrilinear, module: trilinear, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: trilinear_surface,
    block: CartTexTrilinearSurface,
    unit: "cart_tex_trilinear_surface",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexTrilinear, module: trilinear, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

// trilinear in two passes of one set of the front's units, a pixel every other clock (beside the one above)
cartesian_pipeline! {
    module: trilinear_two_pass_matte,
    block: CartTexTrilinearTwoPassMatte,
    unit: "cart_tex_trilinear_two_pass_matte",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexTrilinearTwoPass, module: trilinear_two_pass, u: u, v: v },
    interval: 2,
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    module: bilinear_hemi_oct,
    block: CartTexBilinearHemiOct,
    unit: "cart_tex_bilinear_hemi_oct",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexBilinear, module: bilinear, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

// one light per surface: the light word waits AT_DOT clocks (the front, the decode, the normaliser), 2^6 words
cartesian_pipeline! {
    module: bilinear_surface,
    block: CartTexBilinearSurface,
    unit: "cart_tex_bilinear_surface",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexBilinear, module: bilinear, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: bilinear_surface_matte,
    block: CartTexBilinearSurfaceMatte,
    unit: "cart_tex_bilinear_surface_matte",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexBilinear, module: bilinear, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
}

// one light per surface, the nearest texel: the light word waits AT_DOT clocks (the front, the decode, the
// normaliser), 2^5 words; the pipeline with its map memory (in the UP5K's SPRAM) that places on the UP5K
cartesian_pipeline! {
    module: nearest_surface_matte,
    block: CartTexNearestSurfaceMatte,
    unit: "cart_tex_nearest_surface_matte",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearest, module: nearest, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
}

// the same with hemi-octahedral texels (their decode a clock shorter), 2^5 words
cartesian_pipeline! {
    module: nearest_surface_hemi_oct_matte,
    block: CartTexNearestSurfaceHemiOctMatte,
    unit: "cart_tex_nearest_surface_hemi_oct_matte",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearest, module: nearest, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
}

// the gloss unit behind the nearest texel and the nearest texel of the nearest MIP level (lights per vertex)
cartesian_pipeline! {
    module: nearest,
    block: CartTexNearest,
    unit: "cart_tex_nearest",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearest, module: nearest, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: nearest_mip,
    block: CartTexNearestMip,
    unit: "cart_tex_nearest_mip",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearestMip, module: nearest_mip, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

// matte hemi-oct texels, lights per vertex: bilinear and trilinear
cartesian_pipeline! {
    module: bilinear_hemi_oct_matte,
    block: CartTexBilinearHemiOctMatte,
    unit: "cart_tex_bilinear_hemi_oct_matte",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexBilinear, module: bilinear, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    module: trilinear_hemi_oct_matte,
    block: CartTexTrilinearHemiOctMatte,
    unit: "cart_tex_trilinear_hemi_oct_matte",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexTrilinear, module: trilinear, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

// matte, one light per surface, trilinear: the light word waits AT_DOT clocks, as with gloss
cartesian_pipeline! {
    module: trilinear_surface_matte,
    block: CartTexTrilinearSurfaceMatte,
    unit: "cart_tex_trilinear_surface_matte",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexTrilinear, module: trilinear, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
}

// the blend's destination colour from a colour map in the front's second memory (RGB565), filtered on the bump
// texel's footprint and blend factors; the mode and lit colour wait for it beside the front
cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: bilinear_colour,
    block: CartTexBilinearColour,
    unit: "cart_tex_bilinear_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexBilinearColour, module: bilinear_colour, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: bilinear_surface_colour,
    block: CartTexBilinearSurfaceColour,
    unit: "cart_tex_bilinear_surface_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexBilinearColour, module: bilinear_colour, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

// the colour map beside the nearest texel, of level 0 or of the nearest MIP level: the colour texel is the one the
// bump texel is, widened to bytes and not filtered
cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_colour,
    block: CartTexNearestColour,
    unit: "cart_tex_nearest_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearestColour, module: nearest_colour, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_mip_colour,
    block: CartTexNearestMipColour,
    unit: "cart_tex_nearest_mip_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearestMipColour, module: nearest_mip_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

// the rest of issue 24's matrix (texels seed or hemi-oct × lights per vertex or per surface × gloss or matte × the
// four filters): one light per surface, the light word waits AT_DOT = front + decode + normaliser
// clocks, in the fewest address bits that hold it
cartesian_pipeline! {
    module: nearest_hemi_oct,
    block: CartTexNearestHemiOct,
    unit: "cart_tex_nearest_hemi_oct",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearest, module: nearest, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: nearest_hemi_oct_matte,
    block: CartTexNearestHemiOctMatte,
    unit: "cart_tex_nearest_hemi_oct_matte",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearest, module: nearest, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    module: nearest_surface,
    block: CartTexNearestSurface,
    unit: "cart_tex_nearest_surface",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearest, module: nearest, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: nearest_surface_hemi_oct,
    block: CartTexNearestSurfaceHemiOct,
    unit: "cart_tex_nearest_surface_hemi_oct",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearest, module: nearest, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: nearest_mip_hemi_oct,
    block: CartTexNearestMipHemiOct,
    unit: "cart_tex_nearest_mip_hemi_oct",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearestMip, module: nearest_mip, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: nearest_mip_hemi_oct_matte,
    block: CartTexNearestMipHemiOctMatte,
    unit: "cart_tex_nearest_mip_hemi_oct_matte",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearestMip, module: nearest_mip, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    module: nearest_mip_surface,
    block: CartTexNearestMipSurface,
    unit: "cart_tex_nearest_mip_surface",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearestMip, module: nearest_mip, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: nearest_mip_surface_matte,
    block: CartTexNearestMipSurfaceMatte,
    unit: "cart_tex_nearest_mip_surface_matte",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearestMip, module: nearest_mip, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
}

cartesian_pipeline! {
    module: nearest_mip_surface_hemi_oct,
    block: CartTexNearestMipSurfaceHemiOct,
    unit: "cart_tex_nearest_mip_surface_hemi_oct",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearestMip, module: nearest_mip, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: nearest_mip_surface_hemi_oct_matte,
    block: CartTexNearestMipSurfaceHemiOctMatte,
    unit: "cart_tex_nearest_mip_surface_hemi_oct_matte",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearestMip, module: nearest_mip, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
}

cartesian_pipeline! {
    module: bilinear_surface_hemi_oct,
    block: CartTexBilinearSurfaceHemiOct,
    unit: "cart_tex_bilinear_surface_hemi_oct",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexBilinear, module: bilinear, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: bilinear_surface_hemi_oct_matte,
    block: CartTexBilinearSurfaceHemiOctMatte,
    unit: "cart_tex_bilinear_surface_hemi_oct_matte",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexBilinear, module: bilinear, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
}

cartesian_pipeline! {
    module: trilinear_surface_hemi_oct,
    block: CartTexTrilinearSurfaceHemiOct,
    unit: "cart_tex_trilinear_surface_hemi_oct",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexTrilinear, module: trilinear, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    module: trilinear_surface_hemi_oct_matte,
    block: CartTexTrilinearSurfaceHemiOctMatte,
    unit: "cart_tex_trilinear_surface_hemi_oct_matte",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexTrilinear, module: trilinear, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
}

// the colour map under the rest of the matrix (texels seed or hemi-oct × lights per vertex or per surface × gloss
// or matte) for the nearest texel, the nearest MIP level's and bilinear: the colour front's latency is its bump
// front's, so the light word waits as long as there
cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_matte_colour,
    block: CartTexNearestMatteColour,
    unit: "cart_tex_nearest_matte_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearestColour, module: nearest_colour, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_hemi_oct_colour,
    block: CartTexNearestHemiOctColour,
    unit: "cart_tex_nearest_hemi_oct_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearestColour, module: nearest_colour, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_hemi_oct_matte_colour,
    block: CartTexNearestHemiOctMatteColour,
    unit: "cart_tex_nearest_hemi_oct_matte_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearestColour, module: nearest_colour, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_surface_colour,
    block: CartTexNearestSurfaceColour,
    unit: "cart_tex_nearest_surface_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearestColour, module: nearest_colour, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_surface_matte_colour,
    block: CartTexNearestSurfaceMatteColour,
    unit: "cart_tex_nearest_surface_matte_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearestColour, module: nearest_colour, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_surface_hemi_oct_colour,
    block: CartTexNearestSurfaceHemiOctColour,
    unit: "cart_tex_nearest_surface_hemi_oct_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearestColour, module: nearest_colour, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_surface_hemi_oct_matte_colour,
    block: CartTexNearestSurfaceHemiOctMatteColour,
    unit: "cart_tex_nearest_surface_hemi_oct_matte_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearestColour, module: nearest_colour, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 5 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_mip_matte_colour,
    block: CartTexNearestMipMatteColour,
    unit: "cart_tex_nearest_mip_matte_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearestMipColour, module: nearest_mip_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_mip_hemi_oct_colour,
    block: CartTexNearestMipHemiOctColour,
    unit: "cart_tex_nearest_mip_hemi_oct_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearestMipColour, module: nearest_mip_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_mip_hemi_oct_matte_colour,
    block: CartTexNearestMipHemiOctMatteColour,
    unit: "cart_tex_nearest_mip_hemi_oct_matte_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearestMipColour, module: nearest_mip_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_mip_surface_colour,
    block: CartTexNearestMipSurfaceColour,
    unit: "cart_tex_nearest_mip_surface_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearestMipColour, module: nearest_mip_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_mip_surface_matte_colour,
    block: CartTexNearestMipSurfaceMatteColour,
    unit: "cart_tex_nearest_mip_surface_matte_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexNearestMipColour, module: nearest_mip_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_mip_surface_hemi_oct_colour,
    block: CartTexNearestMipSurfaceHemiOctColour,
    unit: "cart_tex_nearest_mip_surface_hemi_oct_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearestMipColour, module: nearest_mip_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: nearest_mip_surface_hemi_oct_matte_colour,
    block: CartTexNearestMipSurfaceHemiOctMatteColour,
    unit: "cart_tex_nearest_mip_surface_hemi_oct_matte_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexNearestMipColour, module: nearest_mip_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: bilinear_matte_colour,
    block: CartTexBilinearMatteColour,
    unit: "cart_tex_bilinear_matte_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexBilinearColour, module: bilinear_colour, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: bilinear_hemi_oct_colour,
    block: CartTexBilinearHemiOctColour,
    unit: "cart_tex_bilinear_hemi_oct_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexBilinearColour, module: bilinear_colour, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: bilinear_hemi_oct_matte_colour,
    block: CartTexBilinearHemiOctMatteColour,
    unit: "cart_tex_bilinear_hemi_oct_matte_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexBilinearColour, module: bilinear_colour, u: u, v: v },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: bilinear_surface_matte_colour,
    block: CartTexBilinearSurfaceMatteColour,
    unit: "cart_tex_bilinear_surface_matte_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexBilinearColour, module: bilinear_colour, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: bilinear_surface_hemi_oct_colour,
    block: CartTexBilinearSurfaceHemiOctColour,
    unit: "cart_tex_bilinear_surface_hemi_oct_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexBilinearColour, module: bilinear_colour, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: bilinear_surface_hemi_oct_matte_colour,
    block: CartTexBilinearSurfaceHemiOctMatteColour,
    unit: "cart_tex_bilinear_surface_hemi_oct_matte_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexBilinearColour, module: bilinear_colour, u: u, v: v },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
}

// the colour map under the trilinear front (texels seed or hemi-oct × lights per vertex or per surface × gloss or
// matte): the colour memory split by level parity as the bump map's, both levels filtered and blended by frac(λ)
cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: trilinear_colour,
    block: CartTexTrilinearColour,
    unit: "cart_tex_trilinear_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexTrilinearColour, module: trilinear_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: trilinear_matte_colour,
    block: CartTexTrilinearMatteColour,
    unit: "cart_tex_trilinear_matte_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexTrilinearColour, module: trilinear_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: trilinear_hemi_oct_colour,
    block: CartTexTrilinearHemiOctColour,
    unit: "cart_tex_trilinear_hemi_oct_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexTrilinearColour, module: trilinear_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: trilinear_hemi_oct_matte_colour,
    block: CartTexTrilinearHemiOctMatteColour,
    unit: "cart_tex_trilinear_hemi_oct_matte_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexTrilinearColour, module: trilinear_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    vertex: { iter: light, norm: light_norm, delay: light_dly, w1: w1, w2: w2 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: trilinear_surface_colour,
    block: CartTexTrilinearSurfaceColour,
    unit: "cart_tex_trilinear_surface_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexTrilinearColour, module: trilinear_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: trilinear_surface_matte_colour,
    block: CartTexTrilinearSurfaceMatteColour,
    unit: "cart_tex_trilinear_surface_matte_colour",
    decode: { block: CartDecode, module: cart_decode, u: texel_x, v: texel_z },
    texture: { block: TexTrilinearColour, module: trilinear_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: trilinear_surface_hemi_oct_colour,
    block: CartTexTrilinearSurfaceHemiOctColour,
    unit: "cart_tex_trilinear_surface_hemi_oct_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexTrilinearColour, module: trilinear_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
    gloss: { unit: gloss, c: conc, delay: conc_dly },
}

cartesian_pipeline! {
    colour: { select: wcolour, delay: colour_dly },
    module: trilinear_surface_hemi_oct_matte_colour,
    block: CartTexTrilinearSurfaceHemiOctMatteColour,
    unit: "cart_tex_trilinear_surface_hemi_oct_matte_colour",
    decode: { block: CartDecodeHemiOct, module: cart_decode_hemi_oct, u: texel_u, v: texel_v },
    texture: { block: TexTrilinearColour, module: trilinear_colour, u: u, v: v },
    mip: { derivatives: [du_dx, dv_dx, du_dy, dv_dy], bias: lod_bias },
    surface: { x: l_x, y: l_y, z: l_z, word: light_word, delay: light_dly, addr_bits: 6 },
}
