//! cart_tex_*: the Cartesian pipelines on the texture unit, each the front (position → [level →] address → memory
//! → texel) and the host-fed pipeline's units, against the composed model three ways: golden vectors (the map
//! loaded first); random streams through rust-hdl, and through Verilator after the hard cases have loaded the chain
//! they read.
use rtl::cart_tex::{
    CartTexBilinear, CartTexBilinearColour, CartTexBilinearHemiOct, CartTexBilinearMatte, CartTexBilinearSurface,
    CartTexBilinearSurfaceColour, CartTexBilinearSurfaceMatte, CartTexNearestMatte, CartTexNearestMipMatte,
    CartTexNearestSurfaceHemiOctMatte, CartTexNearestSurfaceMatte, CartTexTrilinearMatte,
};
use rtl::StreamUnit;
use testbench::{external, random_vs_model, rust_hdl, unit_tests, Bubbles};
use vectors::cart_tex::{
    bilinear, bilinear_colour, bilinear_hemi_oct, bilinear_matte, bilinear_surface, bilinear_surface_colour,
    bilinear_surface_matte, nearest_matte, nearest_mip_matte, nearest_surface_hemi_oct_matte, nearest_surface_matte,
    trilinear_matte,
};
use vectors::UnitModel;

unit_tests!(cart_tex_bilinear, CartTexBilinear, bilinear::MODEL);
unit_tests!(cart_tex_bilinear_matte, CartTexBilinearMatte, bilinear_matte::MODEL);
unit_tests!(cart_tex_nearest_matte, CartTexNearestMatte, nearest_matte::MODEL);
unit_tests!(cart_tex_nearest_mip_matte, CartTexNearestMipMatte, nearest_mip_matte::MODEL);
unit_tests!(cart_tex_trilinear_matte, CartTexTrilinearMatte, trilinear_matte::MODEL);
unit_tests!(cart_tex_bilinear_hemi_oct, CartTexBilinearHemiOct, bilinear_hemi_oct::MODEL);
unit_tests!(cart_tex_bilinear_surface, CartTexBilinearSurface, bilinear_surface::MODEL);
unit_tests!(cart_tex_bilinear_surface_matte, CartTexBilinearSurfaceMatte, bilinear_surface_matte::MODEL);
unit_tests!(cart_tex_nearest_surface_matte, CartTexNearestSurfaceMatte, nearest_surface_matte::MODEL);
unit_tests!(cart_tex_bilinear_colour, CartTexBilinearColour, bilinear_colour::MODEL);
unit_tests!(cart_tex_bilinear_surface_colour, CartTexBilinearSurfaceColour, bilinear_surface_colour::MODEL);
unit_tests!(
    cart_tex_nearest_surface_hemi_oct_matte,
    CartTexNearestSurfaceHemiOctMatte,
    nearest_surface_hemi_oct_matte::MODEL
);

/// Random streams through rust-hdl (from an empty memory, which both read as zero), the hard cases with bubbles,
/// and a long random stream under Verilator after the hard cases have loaded the chain it reads.
fn three_streams<U: StreamUnit>(m: &'static UnitModel, seed: u64) {
    use rand::SeedableRng;
    random_vs_model::<U>(m, 4, 500);
    rust_hdl::<U>(m, &(m.hard_cases)(), Bubbles::Random { one_in: 2, seed }).assert_clean("hard cases, bubbles");
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut inputs = (m.hard_cases)();
    inputs.extend((0..30_000).map(|_| (m.random)(&mut rng)));
    external::<U>(synth::cosim::Simulator::Verilator, m, &inputs, Bubbles::Random { one_in: 3, seed })
        .assert_clean("verilator, random after the hard cases");
}

#[test]
fn cart_tex_bilinear_streams() {
    three_streams::<CartTexBilinear>(&bilinear::MODEL, 23);
}

#[test]
fn cart_tex_bilinear_matte_streams() {
    three_streams::<CartTexBilinearMatte>(&bilinear_matte::MODEL, 24);
}

#[test]
fn cart_tex_nearest_matte_streams() {
    three_streams::<CartTexNearestMatte>(&nearest_matte::MODEL, 25);
}

#[test]
fn cart_tex_nearest_mip_matte_streams() {
    three_streams::<CartTexNearestMipMatte>(&nearest_mip_matte::MODEL, 26);
}

#[test]
fn cart_tex_trilinear_matte_streams() {
    three_streams::<CartTexTrilinearMatte>(&trilinear_matte::MODEL, 27);
}

#[test]
fn cart_tex_bilinear_hemi_oct_streams() {
    three_streams::<CartTexBilinearHemiOct>(&bilinear_hemi_oct::MODEL, 28);
}

#[test]
fn cart_tex_bilinear_surface_streams() {
    three_streams::<CartTexBilinearSurface>(&bilinear_surface::MODEL, 29);
}

#[test]
fn cart_tex_bilinear_surface_matte_streams() {
    three_streams::<CartTexBilinearSurfaceMatte>(&bilinear_surface_matte::MODEL, 30);
}

#[test]
fn cart_tex_nearest_surface_matte_streams() {
    three_streams::<CartTexNearestSurfaceMatte>(&nearest_surface_matte::MODEL, 31);
}

#[test]
fn cart_tex_nearest_surface_hemi_oct_matte_streams() {
    three_streams::<CartTexNearestSurfaceHemiOctMatte>(&nearest_surface_hemi_oct_matte::MODEL, 32);
}

#[test]
fn cart_tex_bilinear_colour_streams() {
    three_streams::<CartTexBilinearColour>(&bilinear_colour::MODEL, 33);
}

#[test]
fn cart_tex_bilinear_surface_colour_streams() {
    three_streams::<CartTexBilinearSurfaceColour>(&bilinear_surface_colour::MODEL, 34);
}
