//! polar_tex_*: the polar pipeline on the texture unit, the front (position → [level →] address → memory → S and
//! R filtered as numbers) and `polar_pipeline`'s units, against the composed model three ways: golden vectors (the
//! map loaded first); random streams through rust-hdl, and through Verilator after the hard cases have loaded the
//! chain they read.
use rtl::polar_tex::{PolarTexBilinear, PolarTexTrilinear};
use testbench::{three_streams, unit_tests};
use vectors::polar_tex::{bilinear, trilinear};

unit_tests!(polar_tex_bilinear, PolarTexBilinear, bilinear::MODEL);
unit_tests!(polar_tex_trilinear, PolarTexTrilinear, trilinear::MODEL);

#[test]
fn polar_tex_bilinear_streams() {
    three_streams::<PolarTexBilinear>(&bilinear::MODEL, 41);
}

#[test]
fn polar_tex_trilinear_streams() {
    three_streams::<PolarTexTrilinear>(&trilinear::MODEL, 42);
}
