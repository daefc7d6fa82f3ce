//! `cart_surface`: seed 000's Cartesian pipeline for a scene with one light per surface (a directional light, or
//! a point light taken at the surface's centre): the light arrives already a unit vector, once per surface, so the
//! pipeline holds no `light_iter` and no light normaliser. The light still travels with each pixel (a curved
//! surface's triangles each have their own), in one block-RAM delay line to the dot product.
//! bilinear(TexelX, TexelZ) → cart_decode → normalise ─┐
//! L (unit, Sq1.10) ─────────── (RAM delay 26) ────────┴→ dot3 → gloss(C) → α = P >> 2 → blend.
//! Latency 48 = bilinear 11 + cart_decode 4 + normalise 11 + dot3 6 + gloss 11 + blend 5.
//!
//! `cart_surface_matte` is the same pipeline for a material with C = 0, where the gloss unit's P = X: it holds no
//! gloss unit and has no C port, and α = X >> 2 (latency 37). The `_hemi_oct` variants read hemi-octahedral texels
//! through `cart_decode_hemi_oct` (one clock less). `cartesian_pipeline!` (`wiring.rs`, shared with `cart_pipeline`)
//! writes all eight, so each exported Verilog holds only its own units.

use crate::cart_decode::CartDecode;
use crate::cart_decode_hemi_oct::CartDecodeHemiOct;
use crate::cartesian::wiring::cartesian_pipeline;
use rust_hdl::prelude::*;

const BILINEAR: usize = crate::bilinear::LATENCY;

cartesian_pipeline!(seed, CartSurface, "cart_surface", CartDecode, cart_decode, texel_x, texel_z, BILINEAR, 1, filter: filter, filter_valid, ublend, vblend, surface: l_x, l_y, l_z, light_word, light_dly, gloss: gloss, conc, conc_dly);
cartesian_pipeline!(matte, CartSurfaceMatte, "cart_surface_matte", CartDecode, cart_decode, texel_x, texel_z, BILINEAR, 0, filter: filter, filter_valid, ublend, vblend, surface: l_x, l_y, l_z, light_word, light_dly);
cartesian_pipeline!(hemi_oct, CartSurfaceHemiOct, "cart_surface_hemi_oct", CartDecodeHemiOct, cart_decode_hemi_oct, texel_u, texel_v, BILINEAR, 1, filter: filter, filter_valid, ublend, vblend, surface: l_x, l_y, l_z, light_word, light_dly, gloss: gloss, conc, conc_dly);
cartesian_pipeline!(hemi_oct_matte, CartSurfaceHemiOctMatte, "cart_surface_hemi_oct_matte", CartDecodeHemiOct, cart_decode_hemi_oct, texel_u, texel_v, BILINEAR, 0, filter: filter, filter_valid, ublend, vblend, surface: l_x, l_y, l_z, light_word, light_dly);
cartesian_pipeline!(nearest, CartSurfaceNearest, "cart_surface_nearest", CartDecode, cart_decode, texel_x, texel_z, 0, 1, nearest: t_x, t_z, surface: l_x, l_y, l_z, light_word, light_dly, gloss: gloss, conc, conc_dly);
cartesian_pipeline!(nearest_matte, CartSurfaceNearestMatte, "cart_surface_nearest_matte", CartDecode, cart_decode, texel_x, texel_z, 0, 0, nearest: t_x, t_z, surface: l_x, l_y, l_z, light_word, light_dly);
cartesian_pipeline!(nearest_hemi_oct, CartSurfaceNearestHemiOct, "cart_surface_nearest_hemi_oct", CartDecodeHemiOct, cart_decode_hemi_oct, texel_u, texel_v, 0, 1, nearest: t_x, t_z, surface: l_x, l_y, l_z, light_word, light_dly, gloss: gloss, conc, conc_dly);
cartesian_pipeline!(nearest_hemi_oct_matte, CartSurfaceNearestHemiOctMatte, "cart_surface_nearest_hemi_oct_matte", CartDecodeHemiOct, cart_decode_hemi_oct, texel_u, texel_v, 0, 0, nearest: t_x, t_z, surface: l_x, l_y, l_z, light_word, light_dly);
