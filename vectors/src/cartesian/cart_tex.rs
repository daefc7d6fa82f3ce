//! `cart_tex_*`: the Cartesian pipelines on the texture unit, each a host-fed Cartesian pipeline (`cart_pipeline` or
//! `cart_surface` and their variants) with the texture unit's front in its texels' place (`texture::textured`: the
//! model is the two wired; with a colour map the front's colour is the blend's destination colour).

use crate::texture::front::Filter;
use crate::texture::textured::{hard_cases, random, textured, Sweep, Textured};
use crate::unit::{Machine, UnitModel};

textured!(bilinear, "cart_tex_bilinear", Filter::Bilinear, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(bilinear_matte, "cart_tex_bilinear_matte", Filter::Bilinear, crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(nearest_matte, "cart_tex_nearest_matte", Filter::Nearest, crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(nearest_mip_matte, "cart_tex_nearest_mip_matte", Filter::NearestMip, crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(trilinear_matte, "cart_tex_trilinear_matte", Filter::Trilinear, crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(trilinear, "cart_tex_trilinear", Filter::Trilinear, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_hemi_oct, "cart_tex_trilinear_hemi_oct", Filter::Trilinear, crate::cart_pipeline::MODEL_HEMI_OCT,
    inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_surface, "cart_tex_trilinear_surface", Filter::Trilinear, crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_two_pass_matte, "cart_tex_trilinear_two_pass_matte", Filter::Trilinear,
    crate::cart_pipeline::MODEL_MATTE, passes: 2, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    bilinear_hemi_oct, "cart_tex_bilinear_hemi_oct", Filter::Bilinear, crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    bilinear_surface, "cart_tex_bilinear_surface", Filter::Bilinear, crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    bilinear_surface_matte, "cart_tex_bilinear_surface_matte", Filter::Bilinear, crate::cart_surface::MODEL_MATTE,
    inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_surface_matte, "cart_tex_nearest_surface_matte", Filter::Nearest, crate::cart_surface::MODEL_MATTE,
    inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_surface_hemi_oct_matte, "cart_tex_nearest_surface_hemi_oct_matte", Filter::Nearest,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(bilinear_colour, "cart_tex_bilinear_colour", Filter::Bilinear, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_surface_colour, "cart_tex_bilinear_surface_colour", Filter::Bilinear, crate::cart_surface::MODEL,
    inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(nearest, "cart_tex_nearest", Filter::Nearest, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(nearest_mip, "cart_tex_nearest_mip", Filter::NearestMip, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    bilinear_hemi_oct_matte, "cart_tex_bilinear_hemi_oct_matte", Filter::Bilinear,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_hemi_oct_matte, "cart_tex_trilinear_hemi_oct_matte", Filter::Trilinear,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_surface_matte, "cart_tex_trilinear_surface_matte", Filter::Trilinear, crate::cart_surface::MODEL_MATTE,
    inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(nearest_colour, "cart_tex_nearest_colour", Filter::Nearest, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(nearest_mip_colour, "cart_tex_nearest_mip_colour", Filter::NearestMip, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_hemi_oct, "cart_tex_nearest_hemi_oct", Filter::Nearest,
    crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_hemi_oct_matte, "cart_tex_nearest_hemi_oct_matte", Filter::Nearest,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_surface, "cart_tex_nearest_surface", Filter::Nearest,
    crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_surface_hemi_oct, "cart_tex_nearest_surface_hemi_oct", Filter::Nearest,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_mip_hemi_oct, "cart_tex_nearest_mip_hemi_oct", Filter::NearestMip,
    crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_mip_hemi_oct_matte, "cart_tex_nearest_mip_hemi_oct_matte", Filter::NearestMip,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_mip_surface, "cart_tex_nearest_mip_surface", Filter::NearestMip,
    crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_mip_surface_matte, "cart_tex_nearest_mip_surface_matte", Filter::NearestMip,
    crate::cart_surface::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_mip_surface_hemi_oct, "cart_tex_nearest_mip_surface_hemi_oct", Filter::NearestMip,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_mip_surface_hemi_oct_matte, "cart_tex_nearest_mip_surface_hemi_oct_matte", Filter::NearestMip,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    bilinear_surface_hemi_oct, "cart_tex_bilinear_surface_hemi_oct", Filter::Bilinear,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    bilinear_surface_hemi_oct_matte, "cart_tex_bilinear_surface_hemi_oct_matte", Filter::Bilinear,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_surface_hemi_oct, "cart_tex_trilinear_surface_hemi_oct", Filter::Trilinear,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_surface_hemi_oct_matte, "cart_tex_trilinear_surface_hemi_oct_matte", Filter::Trilinear,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_matte_colour, "cart_tex_nearest_matte_colour", Filter::Nearest,
    crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_hemi_oct_colour, "cart_tex_nearest_hemi_oct_colour", Filter::Nearest,
    crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_hemi_oct_matte_colour, "cart_tex_nearest_hemi_oct_matte_colour", Filter::Nearest,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_surface_colour, "cart_tex_nearest_surface_colour", Filter::Nearest,
    crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_surface_matte_colour, "cart_tex_nearest_surface_matte_colour", Filter::Nearest,
    crate::cart_surface::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_surface_hemi_oct_colour, "cart_tex_nearest_surface_hemi_oct_colour", Filter::Nearest,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_surface_hemi_oct_matte_colour, "cart_tex_nearest_surface_hemi_oct_matte_colour", Filter::Nearest,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_matte_colour, "cart_tex_nearest_mip_matte_colour", Filter::NearestMip,
    crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_hemi_oct_colour, "cart_tex_nearest_mip_hemi_oct_colour", Filter::NearestMip,
    crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_hemi_oct_matte_colour, "cart_tex_nearest_mip_hemi_oct_matte_colour", Filter::NearestMip,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_surface_colour, "cart_tex_nearest_mip_surface_colour", Filter::NearestMip,
    crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_surface_matte_colour, "cart_tex_nearest_mip_surface_matte_colour", Filter::NearestMip,
    crate::cart_surface::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_surface_hemi_oct_colour, "cart_tex_nearest_mip_surface_hemi_oct_colour", Filter::NearestMip,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_surface_hemi_oct_matte_colour, "cart_tex_nearest_mip_surface_hemi_oct_matte_colour", Filter::NearestMip,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_matte_colour, "cart_tex_bilinear_matte_colour", Filter::Bilinear,
    crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_hemi_oct_colour, "cart_tex_bilinear_hemi_oct_colour", Filter::Bilinear,
    crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_hemi_oct_matte_colour, "cart_tex_bilinear_hemi_oct_matte_colour", Filter::Bilinear,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_surface_matte_colour, "cart_tex_bilinear_surface_matte_colour", Filter::Bilinear,
    crate::cart_surface::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_surface_hemi_oct_colour, "cart_tex_bilinear_surface_hemi_oct_colour", Filter::Bilinear,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_surface_hemi_oct_matte_colour, "cart_tex_bilinear_surface_hemi_oct_matte_colour", Filter::Bilinear,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(trilinear_colour, "cart_tex_trilinear_colour", Filter::Trilinear, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_matte_colour, "cart_tex_trilinear_matte_colour", Filter::Trilinear,
    crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_hemi_oct_colour, "cart_tex_trilinear_hemi_oct_colour", Filter::Trilinear,
    crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_hemi_oct_matte_colour, "cart_tex_trilinear_hemi_oct_matte_colour", Filter::Trilinear,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_surface_colour, "cart_tex_trilinear_surface_colour", Filter::Trilinear,
    crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_surface_matte_colour, "cart_tex_trilinear_surface_matte_colour", Filter::Trilinear,
    crate::cart_surface::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_surface_hemi_oct_colour, "cart_tex_trilinear_surface_hemi_oct_colour", Filter::Trilinear,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_surface_hemi_oct_matte_colour, "cart_tex_trilinear_surface_hemi_oct_matte_colour", Filter::Trilinear,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

/// Every textured pipeline's model, its filter and its host.
pub fn all() -> [(&'static UnitModel, Filter, &'static UnitModel); 65] {
    [
        (&bilinear::MODEL, bilinear::FILTER, bilinear::host()),
        (&bilinear_matte::MODEL, bilinear_matte::FILTER, bilinear_matte::host()),
        (&nearest_matte::MODEL, nearest_matte::FILTER, nearest_matte::host()),
        (&nearest_mip_matte::MODEL, nearest_mip_matte::FILTER, nearest_mip_matte::host()),
        (&trilinear_matte::MODEL, trilinear_matte::FILTER, trilinear_matte::host()),
        (&trilinear_two_pass_matte::MODEL, trilinear_two_pass_matte::FILTER, trilinear_two_pass_matte::host()),
        (&trilinear::MODEL, trilinear::FILTER, trilinear::host()),
        (&trilinear_hemi_oct::MODEL, trilinear_hemi_oct::FILTER, trilinear_hemi_oct::host()),
        (&trilinear_surface::MODEL, trilinear_surface::FILTER, trilinear_surface::host()),
        (&bilinear_hemi_oct::MODEL, bilinear_hemi_oct::FILTER, bilinear_hemi_oct::host()),
        (&bilinear_surface::MODEL, bilinear_surface::FILTER, bilinear_surface::host()),
        (&bilinear_surface_matte::MODEL, bilinear_surface_matte::FILTER, bilinear_surface_matte::host()),
        (&nearest_surface_matte::MODEL, nearest_surface_matte::FILTER, nearest_surface_matte::host()),
        (
            &nearest_surface_hemi_oct_matte::MODEL,
            nearest_surface_hemi_oct_matte::FILTER,
            nearest_surface_hemi_oct_matte::host(),
        ),
        (&nearest::MODEL, nearest::FILTER, nearest::host()),
        (&nearest_mip::MODEL, nearest_mip::FILTER, nearest_mip::host()),
        (&bilinear_hemi_oct_matte::MODEL, bilinear_hemi_oct_matte::FILTER, bilinear_hemi_oct_matte::host()),
        (&trilinear_hemi_oct_matte::MODEL, trilinear_hemi_oct_matte::FILTER, trilinear_hemi_oct_matte::host()),
        (&trilinear_surface_matte::MODEL, trilinear_surface_matte::FILTER, trilinear_surface_matte::host()),
        (&bilinear_colour::MODEL, bilinear_colour::FILTER, bilinear_colour::host()),
        (&bilinear_surface_colour::MODEL, bilinear_surface_colour::FILTER, bilinear_surface_colour::host()),
        (&nearest_colour::MODEL, nearest_colour::FILTER, nearest_colour::host()),
        (&nearest_mip_colour::MODEL, nearest_mip_colour::FILTER, nearest_mip_colour::host()),
        (&nearest_hemi_oct::MODEL, nearest_hemi_oct::FILTER, nearest_hemi_oct::host()),
        (&nearest_hemi_oct_matte::MODEL, nearest_hemi_oct_matte::FILTER, nearest_hemi_oct_matte::host()),
        (&nearest_surface::MODEL, nearest_surface::FILTER, nearest_surface::host()),
        (&nearest_surface_hemi_oct::MODEL, nearest_surface_hemi_oct::FILTER, nearest_surface_hemi_oct::host()),
        (&nearest_mip_hemi_oct::MODEL, nearest_mip_hemi_oct::FILTER, nearest_mip_hemi_oct::host()),
        (&nearest_mip_hemi_oct_matte::MODEL, nearest_mip_hemi_oct_matte::FILTER, nearest_mip_hemi_oct_matte::host()),
        (&nearest_mip_surface::MODEL, nearest_mip_surface::FILTER, nearest_mip_surface::host()),
        (&nearest_mip_surface_matte::MODEL, nearest_mip_surface_matte::FILTER, nearest_mip_surface_matte::host()),
        (
            &nearest_mip_surface_hemi_oct::MODEL,
            nearest_mip_surface_hemi_oct::FILTER,
            nearest_mip_surface_hemi_oct::host(),
        ),
        (
            &nearest_mip_surface_hemi_oct_matte::MODEL,
            nearest_mip_surface_hemi_oct_matte::FILTER,
            nearest_mip_surface_hemi_oct_matte::host(),
        ),
        (&bilinear_surface_hemi_oct::MODEL, bilinear_surface_hemi_oct::FILTER, bilinear_surface_hemi_oct::host()),
        (
            &bilinear_surface_hemi_oct_matte::MODEL,
            bilinear_surface_hemi_oct_matte::FILTER,
            bilinear_surface_hemi_oct_matte::host(),
        ),
        (&trilinear_surface_hemi_oct::MODEL, trilinear_surface_hemi_oct::FILTER, trilinear_surface_hemi_oct::host()),
        (
            &trilinear_surface_hemi_oct_matte::MODEL,
            trilinear_surface_hemi_oct_matte::FILTER,
            trilinear_surface_hemi_oct_matte::host(),
        ),
        (&nearest_matte_colour::MODEL, nearest_matte_colour::FILTER, nearest_matte_colour::host()),
        (&nearest_hemi_oct_colour::MODEL, nearest_hemi_oct_colour::FILTER, nearest_hemi_oct_colour::host()),
        (
            &nearest_hemi_oct_matte_colour::MODEL,
            nearest_hemi_oct_matte_colour::FILTER,
            nearest_hemi_oct_matte_colour::host(),
        ),
        (&nearest_surface_colour::MODEL, nearest_surface_colour::FILTER, nearest_surface_colour::host()),
        (
            &nearest_surface_matte_colour::MODEL,
            nearest_surface_matte_colour::FILTER,
            nearest_surface_matte_colour::host(),
        ),
        (
            &nearest_surface_hemi_oct_colour::MODEL,
            nearest_surface_hemi_oct_colour::FILTER,
            nearest_surface_hemi_oct_colour::host(),
        ),
        (
            &nearest_surface_hemi_oct_matte_colour::MODEL,
            nearest_surface_hemi_oct_matte_colour::FILTER,
            nearest_surface_hemi_oct_matte_colour::host(),
        ),
        (&nearest_mip_matte_colour::MODEL, nearest_mip_matte_colour::FILTER, nearest_mip_matte_colour::host()),
        (&nearest_mip_hemi_oct_colour::MODEL, nearest_mip_hemi_oct_colour::FILTER, nearest_mip_hemi_oct_colour::host()),
        (
            &nearest_mip_hemi_oct_matte_colour::MODEL,
            nearest_mip_hemi_oct_matte_colour::FILTER,
            nearest_mip_hemi_oct_matte_colour::host(),
        ),
        (&nearest_mip_surface_colour::MODEL, nearest_mip_surface_colour::FILTER, nearest_mip_surface_colour::host()),
        (
            &nearest_mip_surface_matte_colour::MODEL,
            nearest_mip_surface_matte_colour::FILTER,
            nearest_mip_surface_matte_colour::host(),
        ),
        (
            &nearest_mip_surface_hemi_oct_colour::MODEL,
            nearest_mip_surface_hemi_oct_colour::FILTER,
            nearest_mip_surface_hemi_oct_colour::host(),
        ),
        (
            &nearest_mip_surface_hemi_oct_matte_colour::MODEL,
            nearest_mip_surface_hemi_oct_matte_colour::FILTER,
            nearest_mip_surface_hemi_oct_matte_colour::host(),
        ),
        (&bilinear_matte_colour::MODEL, bilinear_matte_colour::FILTER, bilinear_matte_colour::host()),
        (&bilinear_hemi_oct_colour::MODEL, bilinear_hemi_oct_colour::FILTER, bilinear_hemi_oct_colour::host()),
        (
            &bilinear_hemi_oct_matte_colour::MODEL,
            bilinear_hemi_oct_matte_colour::FILTER,
            bilinear_hemi_oct_matte_colour::host(),
        ),
        (
            &bilinear_surface_matte_colour::MODEL,
            bilinear_surface_matte_colour::FILTER,
            bilinear_surface_matte_colour::host(),
        ),
        (
            &bilinear_surface_hemi_oct_colour::MODEL,
            bilinear_surface_hemi_oct_colour::FILTER,
            bilinear_surface_hemi_oct_colour::host(),
        ),
        (
            &bilinear_surface_hemi_oct_matte_colour::MODEL,
            bilinear_surface_hemi_oct_matte_colour::FILTER,
            bilinear_surface_hemi_oct_matte_colour::host(),
        ),
        (&trilinear_colour::MODEL, trilinear_colour::FILTER, trilinear_colour::host()),
        (&trilinear_matte_colour::MODEL, trilinear_matte_colour::FILTER, trilinear_matte_colour::host()),
        (&trilinear_hemi_oct_colour::MODEL, trilinear_hemi_oct_colour::FILTER, trilinear_hemi_oct_colour::host()),
        (
            &trilinear_hemi_oct_matte_colour::MODEL,
            trilinear_hemi_oct_matte_colour::FILTER,
            trilinear_hemi_oct_matte_colour::host(),
        ),
        (&trilinear_surface_colour::MODEL, trilinear_surface_colour::FILTER, trilinear_surface_colour::host()),
        (
            &trilinear_surface_matte_colour::MODEL,
            trilinear_surface_matte_colour::FILTER,
            trilinear_surface_matte_colour::host(),
        ),
        (
            &trilinear_surface_hemi_oct_colour::MODEL,
            trilinear_surface_hemi_oct_colour::FILTER,
            trilinear_surface_hemi_oct_colour::host(),
        ),
        (
            &trilinear_surface_hemi_oct_matte_colour::MODEL,
            trilinear_surface_hemi_oct_matte_colour::FILTER,
            trilinear_surface_hemi_oct_matte_colour::host(),
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tex_fetch::pattern;
    use crate::texture::front::{self, At, Front};
    use crate::texture::textured::*;
    use crate::unit::Port;

    #[test]
    fn each_pipeline_has_the_fronts_ports_then_its_hosts_others() {
        for (m, f, h) in all() {
            let want = expected_ports(f, h, m.name.ends_with("_colour"));
            let got: Vec<_> = m.inputs.iter().map(|p| (p.name, p.bits, p.signed)).collect();
            assert_eq!(got, want.iter().map(|p| (p.name, p.bits, p.signed)).collect::<Vec<_>>(), "{}", m.name);
        }
    }

    #[test]
    fn the_hosts_filter_returns_a_texel_given_four_times_with_blends_of_zero() {
        for t in 0..256 {
            assert_eq!(crate::bilinear::exact_channel(t, t, t, t, 0, 0, crate::bilinear::F), t);
        }
    }

    /// The texel the front gives is the one the host would be given: a quad of texels written at level 0, read at
    /// a position inside it, matches the host model fed those four texels and tex_addr's blend factors.
    #[test]
    fn the_bilinear_front_gives_the_host_the_texels_and_blends_it_would_have_fetched() {
        use crate::cart_pipeline::input as h;
        let ports = bilinear::INPUTS;
        let at = At::of(ports, false);
        let host = bilinear::host();
        let mut base = from_host(host, ports, &(host.hard_cases)()[0]);
        let mut stream = vec![];
        for y in 0..4 {
            for x in 0..4 {
                front::put_write(&mut base, &at, 2, x, y, pattern(2, x, y));
                stream.push(base.clone());
            }
        }
        let (u, v) = (256 + 128 + 77, 2 * 256 + 128 + 200); // texels 1..2 × 2..3, blends 77 and 200
        front::put_read(&mut base, &at, [u, v], 2, [true, true], [0; 4]);
        stream.push(base.clone());
        let got = bilinear::MODEL.run(&stream).pop().unwrap();
        let mut hv = (host.hard_cases)()[0].clone();
        for (k, (x, y)) in [(1, 2), (2, 2), (1, 3), (2, 3)].into_iter().enumerate() {
            let t = pattern(2, x, y);
            (hv[crate::cart_pipeline::TEXELS[k][0]], hv[crate::cart_pipeline::TEXELS[k][1]]) = (t & 0xff, t >> 8);
        }
        (hv[h::ublend], hv[h::vblend]) = (77, 200);
        assert_eq!(got, (host.exact)(&hv));
    }

    /// Two levels of one value each, 0 on level 0 and 255 on level 1 (both bytes): between them the trilinear front
    /// gives 255·frac(λ), λ from the f64 formula, to within the LOD table's error and a rounding.
    #[test]
    fn the_trilinear_front_blends_two_levels_by_the_fraction_of_lambda() {
        let ports = trilinear_matte::INPUTS;
        let at = At::of(ports, true);
        let mut f = Front::new(Filter::Trilinear);
        let mut v = vec![0; ports.len()];
        for (m, t) in [(1, 0x0000), (0, 0xffff)] {
            for y in 0..1 << m {
                for x in 0..1 << m {
                    front::put_write(&mut v, &at, m, x, y, t);
                    assert_eq!(f.step(&v, &at), [0, 0]);
                }
            }
        }
        let mut seen = std::collections::BTreeSet::new();
        for edge in (256..512).step_by(5) {
            let d = [edge, 0, 0, 0];
            front::put_read(&mut v, &at, [300, 100], 1, [true, true], d);
            let got = f.step(&v, &at);
            let want = 255.0 * crate::lod::ideal_lambda(d);
            assert!(got[0] == got[1] && (got[0] as f64 - want).abs() <= 1.5, "edge {edge}: {got:?} against {want:.2}");
            seen.insert(got[0]);
        }
        assert!(seen.len() > 40, "{seen:?}");
        // a bias of −½ level (−128 in Sq3.8) moves each of them half a level toward level 0
        for edge in (362..512).step_by(7) {
            let d = [edge, 0, 0, 0];
            front::put_read(&mut v, &at, [300, 100], 1, [true, true], d);
            front::put_bias(&mut v, &at, -128);
            let got = f.step(&v, &at);
            let want = 255.0 * (crate::lod::ideal_lambda(d) - 0.5);
            assert!(got[0] == got[1] && (got[0] as f64 - want).abs() <= 1.5, "edge {edge}: {got:?} against {want:.2}");
        }
    }

    #[test]
    fn the_vectors_read_only_texels_they_have_written() {
        use rand::SeedableRng;
        for (m, _, _) in all() {
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
            let mut v = (m.hard_cases)();
            v.extend((0..5_000).map(|_| (m.random)(&mut rng)));
            let at = At::of(m.inputs, m.inputs.iter().any(|p| p.name == "du_dx"));
            let mut written = std::collections::HashSet::new();
            for (k, i) in v.iter().enumerate() {
                if i[at.we] == 1 {
                    let s = i[at.w_log2].min(crate::tex_fetch::MAX_LOG_SIDE);
                    written.insert(s);
                    assert!(i[at.wx] < 1 << s && i[at.wy] < 1 << s, "{}: vector {k}", m.name);
                    continue;
                }
                // a read of a map of side 2^s reads levels 0..=s of its chain, all of which the load wrote
                assert!(i[at.log_side] <= REGION_LOG2, "{}: vector {k} reads past the loaded chain", m.name);
            }
            assert!((0..=REGION_LOG2).all(|s| written.contains(&s)));
        }
    }

    #[test]
    fn every_pipeline_sweeps_the_1_2_and_16_texel_maps_and_every_front_one_pipeline_every_side() {
        // the sides a pipeline's hard cases read at the seam and the clamp edge: both wraps, one per axis
        let swept = |m: &UnitModel| -> std::collections::BTreeSet<i64> {
            let at = At::of(m.inputs, m.inputs.iter().any(|p| p.name == "du_dx"));
            let reads: Vec<Vec<i64>> = (m.hard_cases)().into_iter().filter(|i| i[at.we] == 0).collect();
            let wrapped = |i: &Vec<i64>, w: [i64; 2]| i[at.uwrap] == w[0] && i[at.vwrap] == w[1];
            (0..=REGION_LOG2)
                .filter(|s| {
                    let at_side: Vec<&Vec<i64>> = reads.iter().filter(|i| i[at.log_side] == *s).collect();
                    at_side.iter().any(|i| wrapped(i, [1, 0])) && at_side.iter().any(|i| wrapped(i, [0, 1]))
                })
                .collect()
        };
        let every: std::collections::BTreeSet<i64> = (0..=REGION_LOG2).collect();
        let mut fronts_with_every_side = std::collections::BTreeSet::new();
        for (m, f, _) in all() {
            let sides = swept(m);
            assert!([0, 1, REGION_LOG2].iter().all(|s| sides.contains(s)), "{}: {sides:?}", m.name);
            if sides == every {
                fronts_with_every_side.insert((format!("{f:?}"), m.name.contains("two_pass")));
            }
        }
        let fronts: std::collections::BTreeSet<_> =
            all().iter().map(|(m, f, _)| (format!("{f:?}"), m.name.contains("two_pass"))).collect();
        assert_eq!(fronts_with_every_side, fronts);
    }

    /// RGB565 widened back to bytes: every code's byte is within one of its exact value c·255/31 (or /63), the
    /// ends exact; an 8-bit colour packed and widened is within half a 5-bit step (4.1) or 6-bit step (2.0) and that
    /// one: 5 and 3 LSB.
    #[test]
    fn rgb565_widens_to_within_one_of_each_codes_value_and_packs_to_within_half_a_step() {
        for t in 0..=0xffff {
            let e = front::expand565(t);
            let codes = [(t >> 11) & 0x1f, (t >> 5) & 0x3f, t & 0x1f];
            for c in 0..3 {
                let top = if c == 1 { 63.0 } else { 31.0 };
                let exact = codes[c] as f64 * 255.0 / top;
                assert!((e[c] as f64 - exact).abs() < 1.0, "{t:#06x} channel {c}: {} against {exact}", e[c]);
            }
        }
        assert_eq!((front::expand565(0xffff), front::expand565(0)), ([255; 3], [0; 3]));
        let mut worst = [0; 3];
        for v in 0..=255u8 {
            let e = front::expand565(front::pack565([v, v, v]));
            for c in 0..3 {
                worst[c] = worst[c].max((e[c] - v as i64).abs());
            }
        }
        assert!(worst[0] <= 5 && worst[2] <= 5 && worst[1] <= 3, "{worst:?}");
    }

    /// The colour front reads its own memory at the bump texel's footprint and blend factors: a colour quad
    /// written at level 0 and read inside it gives each channel's bilinear of the widened texels, and the host is
    /// handed it as its destination colour (a write to one memory leaves the other's texels as they were).
    #[test]
    fn the_colour_front_filters_its_own_memory_on_the_bump_footprint_into_the_destination_colour() {
        let ports = bilinear_colour::INPUTS;
        let at = At::of(ports, false);
        let host = bilinear_colour::host();
        let mut m = bilinear_colour::Unit::default();
        let mut v = from_host(host, ports, &(host.hard_cases)()[0]);
        for y in 0..4 {
            for x in 0..4 {
                front::put_write(&mut v, &at, 2, x, y, pattern(2, x, y));
                assert_eq!(m.step(&v), write_outputs(host, ports, &v), "a write leaves as zeros");
                front::put_colour_write(&mut v, &at, 2, x, y, colour_pattern(2, x, y));
                m.step(&v);
            }
        }
        let (u, w) = (256 + 128 + 77, 2 * 256 + 128 + 200); // texels 1..2 × 2..3, blends 77 and 200
        front::put_read(&mut v, &at, [u, w], 2, [true, true], [0; 4]);
        let got = m.step(&v);
        let quad = [(1, 2), (2, 2), (1, 3), (2, 3)];
        let mut hv = (host.hard_cases)()[0].clone();
        for (k, (x, y)) in quad.into_iter().enumerate() {
            let t = pattern(2, x, y);
            (hv[crate::cart_pipeline::TEXELS[k][0]], hv[crate::cart_pipeline::TEXELS[k][1]]) = (t & 0xff, t >> 8);
        }
        (hv[crate::cart_pipeline::input::ublend], hv[crate::cart_pipeline::input::vblend]) = (77, 200);
        let c = quad.map(|(x, y)| front::expand565(colour_pattern(2, x, y)));
        for (ch, port) in crate::cart_pipeline::DST.iter().enumerate() {
            hv[*port] =
                crate::bilinear::exact_channel(c[0][ch], c[1][ch], c[2][ch], c[3][ch], 77, 200, crate::bilinear::F);
        }
        assert_eq!(got, (host.exact)(&hv));
        // the destination colour matters: the blend at the same pixel with another colour differs
        hv[crate::cart_pipeline::DST[0]] ^= 0x80;
        assert_ne!(got, (host.exact)(&hv));
    }

    /// The host's outputs for a write vector: every texel and the destination colour zero.
    fn write_outputs(host: &UnitModel, ports: &[Port], v: &[i64]) -> Vec<i64> {
        (host.exact)(&host_vector(host, ports, v, [0, 0], [0; 3]))
    }
}
