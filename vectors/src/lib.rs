//! This is the bumprtl reference model: for every hardware unit, a float `ideal()` (the mathematics the hardware
//! approximates) and a bit-exact `exact()` in integers of exactly the rtl widths, plus the vector generator.
//! It has no rust-hdl dependency: the rtl is checked against it, never the other way round.

pub mod blend;
pub mod bilinear;
pub mod cart_decode;
pub mod cart_decode_hemi_oct;
pub mod cart_encode;
pub mod cart_pipeline;
pub mod cos_sign;
pub mod csv;
pub mod dot3;
pub mod fixed;
pub mod gloss;
pub mod height;
pub mod light_iter;
pub mod normalise;
pub mod polar_encode;
pub mod polar_pipeline;
pub mod polar_shade;
pub mod power;
pub mod scene;
pub mod sincos;
pub mod stats;
pub mod unit;

pub use unit::{Port, UnitModel, UNITS};
