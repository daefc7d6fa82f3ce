//! One rust-hdl block per bumprtl unit, each a pipeline that takes one input per clock with a valid flag.
//!
//! Conventions every block keeps (see ARCHITECTURE.md):
//! - Signed values travel as two's complement in `Bits<N>` (named `Sqm_n`), never `Signed<N>`: rust-hdl's
//!   `Signed` multiplies and compares go through big integers and its `signed_bit_cast` overflows the stack on the
//!   most negative value. Signed products are magnitude × magnitude (`Bits<16>×Bits<16>`) with the sign restored.
//! - One wrapping operation per signal; shifts and compares only on whole named signals; slices only of named
//!   signals. This keeps the exported Verilog (32-bit literals) equal to rust-hdl's simulation.
//! - Every stage boundary is a `DFF`; `LATENCY` is the number of clock edges from an input to its output.

pub mod bilinear;
pub mod blend;
pub mod cart_decode;
pub mod cart_decode_hemi_oct;
pub mod cart_pipeline;
pub mod cos_sign;
pub mod delay;
pub mod div255;
pub mod dot3;
pub mod gloss;
pub mod light_iter;
pub mod normalise;
pub mod polar_pipeline;
pub mod polar_shade;
pub mod power;
pub mod q;
pub mod ram_delay;
pub mod sincos;
pub mod stream;
pub mod tables;

pub use stream::StreamUnit;
