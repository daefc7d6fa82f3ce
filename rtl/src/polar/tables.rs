//! The contents of the polar path's lookup tables, one formula each, and the power unit's two ROM blocks.
//!
//! The contents are computed here, independently of the model (`vectors::sincos`, `vectors::power`): the rtl is
//! checked against the model, so a formula shared by both would let a wrong table pass. Tests compare every entry
//! of every size the project uses (ARCHITECTURE.md, "Tables"). The sine/cosine unit [10] and the cosine unit [18]
//! are the blocks `SinCos` and `CosSign`, which the polar shade unit holds as they are tested.

use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::ROM;
use std::f64::consts::{FRAC_PI_2, TAU};

/// x ∈ [0, 1] as UNORM_W (2^W − 1 = 1.0), rounded to nearest.
fn unorm(x: f64, w: usize) -> u64 {
    (x * ((1u64 << w) - 1) as f64).round() as u64
}

/// Steps per quarter / full turn of an 8-bit angle: 256 in the seed's scale, 255 in the Dreamcast toolchains'.
fn steps(dc: bool) -> f64 {
    if dc {
        255.0
    } else {
        256.0
    }
}

/// The elevation table [10]: 2^tb entries over a quarter turn, entry i standing for i·90°/2^tb (seed) or
/// i·90°/(2^tb − 1) (Dreamcast: the last entry is 90°); (sin, cos) as UNORM_w.
pub fn elevation(dc: bool, tb: usize, w: usize) -> Vec<(u64, u64)> {
    let d = if dc { ((1u64 << tb) - 1) as f64 } else { (1u64 << tb) as f64 };
    (0..1u64 << tb)
        .map(|i| {
            let a = i as f64 * FRAC_PI_2 / d;
            (unorm(a.sin(), w), unorm(a.cos(), w))
        })
        .collect()
}

/// The cosine table with its sign [18]: 2^tb entries over a full turn, entry i standing for the rotation difference
/// d = i·2^(8 − tb) (d·360°/steps); (|cos| as UNORM_w, cos < 0).
pub fn cos_sign(dc: bool, tb: usize, w: usize) -> Vec<(u64, bool)> {
    (0..1u64 << tb)
        .map(|i| {
            let c = ((i << (8 - tb)) as f64 * TAU / steps(dc)).cos();
            (unorm(c.abs(), w), c < 0.0)
        })
        .collect()
}

/// −log2(x/255)·2^12, rounded (U15); entry 0 unused: the power unit's own.
pub fn log2() -> Vec<u64> {
    log2_of(12)
}

/// −log2(x/255)·2^lf, rounded (U15 for lf ≤ 12); entry 0 unused.
pub fn log2_of(lf: usize) -> Vec<u64> {
    (0..256)
        .map(|x| if x == 0 { 0 } else { (-(x as f64 / 255.0).log2() * (1u64 << lf) as f64).round() as u64 })
        .collect()
}

/// 255·2^(−f/256)·2^7, rounded (U15): the power unit's own.
pub fn exp2() -> Vec<u64> {
    exp2_of(8)
}

/// 255·2^(−f/2^eb)·2^7 for f < 2^eb, rounded (U15).
pub fn exp2_of(eb: usize) -> Vec<u64> {
    (0..1u64 << eb).map(|f| (255.0 * (-(f as f64) / (1u64 << eb) as f64).exp2() * 128.0).round() as u64).collect()
}

/// A ROM block of U15 entries, generic in the one size it has (`$g`, at most `$max`): `$addr` address bits,
/// `$contents($g)` the entries.
macro_rules! rom_block {
    ($(#[$doc:meta])* $name:ident, $g:ident, $max:literal, $addr:tt, $contents:ident) => {
        crate::block! {
            $(#[$doc])*
            pub struct $name<const $g: usize> {
                pub address: Signal<In, Bits<$addr>>,
                pub data: Signal<Out, Bits<15>>,
                rom: ROM<Bits<15>, $addr>,
            }
        }

        impl<const $g: usize> Default for $name<$g> {
            fn default() -> Self {
                assert!($g <= $max, "{}<{}>: at most {}", stringify!($name), $g, $max);
                let rom = ROM::from($contents($g).into_iter().map(Bits::<15>::from));
                Self { address: Default::default(), data: Default::default(), rom }
            }
        }

        impl<const $g: usize> Logic for $name<$g> {
            #[hdl_gen]
            fn update(&mut self) {
                self.rom.address.next = self.address.val();
                self.data.next = self.rom.data.val();
            }
        }
    };
}

rom_block!(
    /// The power unit's logarithm, L with `LF` fraction bits (`LF` ≤ 12: U15).
    LogTable, LF, 12, 8, log2_of);
rom_block!(
    /// The power unit's exponential, 2^`EB` entries (U15).
    ExpTable, EB, 12, EB, exp2_of);
