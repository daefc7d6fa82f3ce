//! This is the bumprtl simulation crate: scenes rendered through the f64 ideal, the bit-exact model, rust-hdl's
//! simulation of the rtl and the Verilator build of its exported Verilog; PNG images, error heat maps and VCDs.

pub mod accuracy;
pub mod axis_rules;
pub mod fst;
pub mod glyphs;
pub mod gtkw;
pub mod heightmap;
pub mod minify;
pub mod peer;
pub mod pipeline;
pub mod pipelines;
pub mod prepared;
pub mod prove;
pub mod raster;
pub mod render;
pub mod rtl_paths;
pub mod scene;
pub mod scene_file;
pub mod shortcomings;
pub mod surface;
pub mod units;
pub mod variants;
pub mod wave;
