//! palette_tex_*: the palette pipeline on the texture unit, the front (position → [level →] address → memory → the
//! nearest texel, whose low byte is the index) and `palette_pipeline` (the table builder and the two colour tables),
//! against the composed model three ways: golden vectors (the map loaded and the tables built first); random
//! streams through rust-hdl, and through Verilator after the hard cases have loaded the chain they read.
use rtl::palette_tex::{PaletteTexNearest, PaletteTexNearestMip};
use testbench::{three_streams, unit_tests};
use vectors::palette_tex::{nearest, nearest_mip};

unit_tests!(palette_tex_nearest, PaletteTexNearest, nearest::MODEL);
unit_tests!(palette_tex_nearest_mip, PaletteTexNearestMip, nearest_mip::MODEL);

#[test]
fn palette_tex_nearest_streams() {
    three_streams::<PaletteTexNearest>(&nearest::MODEL, 89);
}

#[test]
fn palette_tex_nearest_mip_streams() {
    three_streams::<PaletteTexNearestMip>(&nearest_mip::MODEL, 90);
}
