//! The lookup tables of the polar path, each a ROM widget in a small block that loads its own contents, so the
//! units that hold them can derive `Default`. Contents are computed here, independently of the model; tests
//! compare them entry by entry with `vectors::sincos` and `vectors::power`. Every table has a registered address
//! in the unit that reads it and its data is registered there too, so yosys maps each to SB_RAM40_4K.

use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::ROM;
use std::f64::consts::{FRAC_PI_2, TAU};

fn unorm8(x: f64) -> u64 {
    (x * 255.0).round() as u64
}

/// Steps per quarter / full turn: 256 in the seed's scale, 255 in the Dreamcast toolchains' (`dc`).
fn steps(dc: bool) -> f64 {
    if dc { 255.0 } else { 256.0 }
}

/// sin and cos of a quarter turn in 256 entries (entry i is i·90°/steps), UNORM8: sin low, cos high.
pub fn elevation(dc: bool) -> Vec<u64> {
    (0..256).map(|i| {
        let a = i as f64 * FRAC_PI_2 / steps(dc);
        unorm8(a.sin()) | (unorm8(a.cos()) << 8)
    }).collect()
}

/// |cos| of a full turn in 256 entries (entry d is d·360°/steps), UNORM8, with the sign (cos < 0) in bit 8.
pub fn cos_sign(dc: bool) -> Vec<u64> {
    (0..256).map(|d| {
        let c = (d as f64 * TAU / steps(dc)).cos();
        unorm8(c.abs()) | (((c < 0.0) as u64) << 8)
    }).collect()
}

/// −log2(x/255)·2^12, rounded (U15); entry 0 unused.
pub fn log2() -> Vec<u64> {
    (0..256).map(|x| if x == 0 { 0 } else { (-(x as f64 / 255.0).log2() * 4096.0).round() as u64 }).collect()
}

/// 255·2^(−f/256)·2^7, rounded (U15).
pub fn exp2() -> Vec<u64> {
    (0..256).map(|f| (255.0 * (-(f as f64) / 256.0).exp2() * 128.0).round() as u64).collect()
}

/// A table whose contents depend on the angle scale: `DC` = the Dreamcast toolchains' 255 steps.
macro_rules! scaled_table_block {
    ($(#[$doc:meta])* $name:ident, $d:literal, $contents:path) => {
        $(#[$doc])*
        #[derive(LogicBlock)]
        pub struct $name<const DC: bool> {
            pub address: Signal<In, Bits<8>>,
            pub data: Signal<Out, Bits<$d>>,
            rom: ROM<Bits<$d>, 8>,
        }

        impl<const DC: bool> Default for $name<DC> {
            fn default() -> Self {
                let rom = ROM::from($contents(DC).into_iter().map(Bits::<$d>::from));
                Self { address: Default::default(), data: Default::default(), rom }
            }
        }

        impl<const DC: bool> Logic for $name<DC> {
            #[hdl_gen]
            fn update(&mut self) {
                self.rom.address.next = self.address.val();
                self.data.next = self.rom.data.val();
            }
        }
    };
}

macro_rules! table_block {
    ($(#[$doc:meta])* $name:ident, $d:literal, $contents:path) => {
        $(#[$doc])*
        #[derive(LogicBlock)]
        pub struct $name {
            pub address: Signal<In, Bits<8>>,
            pub data: Signal<Out, Bits<$d>>,
            rom: ROM<Bits<$d>, 8>,
        }

        impl Default for $name {
            fn default() -> Self {
                let rom = ROM::from($contents().into_iter().map(Bits::<$d>::from));
                Self { address: Default::default(), data: Default::default(), rom }
            }
        }

        impl Logic for $name {
            #[hdl_gen]
            fn update(&mut self) {
                self.rom.address.next = self.address.val();
                self.data.next = self.rom.data.val();
            }
        }
    };
}

scaled_table_block!(
    /// The sine/cosine unit [10]: S → (sin S, cos S).
    ElevationTable, 16, elevation);
scaled_table_block!(
    /// The cosine unit with sign [18]: (R − Q) mod 256 → |cos|, sign.
    CosSignTable, 9, cos_sign);
table_block!(
    /// The power unit's logarithm.
    LogTable, 15, log2);
table_block!(
    /// The power unit's exponential.
    ExpTable, 15, exp2);
