//! One rust-hdl block per bumprtl unit, each a pipeline that takes one input per clock with a valid flag.
//!
//! Conventions every block keeps (see ARCHITECTURE.md):
//! - Signed values travel as two's complement in `Bits<N>` (named `Sqm_n`), never `Signed<N>`: rust-hdl's
//!   `Signed` multiplies and compares go through big integers and its `signed_bit_cast` overflows the stack on the
//!   most negative value. Signed products are magnitude × magnitude (`Bits<16>×Bits<16>`) with the sign restored.
//! - One wrapping operation per signal; shifts and compares only on whole named signals; slices only of named
//!   signals. This keeps the exported Verilog (32-bit literals) equal to rust-hdl's simulation.
//! - Every stage boundary is a `DFF`; `LATENCY` is the number of clock edges from an input to its output.

/// The primitives apart from the units, as OpenTitan keeps `prim/`: the fixed-point types (`q`), the delay lines
/// (`delay` in registers, `ram_delay` in block RAM), the single-port RAM (`sp_ram`), the sign-magnitude multiplier
/// (`sm_mul`), and what every block declaration records for the width report (`declared`, with the `block!` macro).
pub mod prim {
    pub mod declared;
    pub mod delay;
    pub mod q;
    pub mod ram_delay;
    pub mod sm_mul;
    pub mod sp_ram;
}

/// Blocks more than one family uses: the colour filter, the normaliser, N·L, glossiness, the blend (and the blend
/// behind its delayed inputs), the /255.
pub mod shared {
    pub mod bilinear;
    pub mod blend;
    pub mod delayed_blend;
    pub mod div255;
    pub mod dot3;
    pub mod gloss;
    pub mod normalise;
}

/// US 6,819,319's second embodiment: Cartesian texels, per-pixel lights.
pub mod cartesian {
    pub mod cart_decode;
    pub mod cart_decode_hemi_oct;
    pub mod cart_pipeline;
    pub mod cart_surface;
    pub mod cart_tex;
    pub mod light_iter;
    pub mod wiring;
}

/// US 6,819,319's first embodiment (FIG. 3): polar texels, one light per surface.
pub mod polar {
    pub mod cos_sign;
    pub mod polar_pipeline;
    pub mod polar_shade;
    pub mod polar_tex;
    pub mod power;
    pub mod sincos;
    pub mod tables;
}

/// US 2004/0207631: normals generated from height maps on the texture filter's bilinear units.
pub mod height {
    pub mod blend_adjust;
    pub mod blinn_pipeline;
    pub mod height_addr;
    pub mod height_fetch;
    pub mod height_normal;
    pub mod height_pipeline;
    pub mod replicate;
    pub mod tangent;
    pub mod tangent_to_normal;
    pub mod texture_filter;
}

/// Tarini et al.: quantized normal maps and per-frame colour tables.
pub mod palette {
    pub mod palette_lookup;
    pub mod palette_pipeline;
    pub mod palette_pipeline_shared;
    pub mod palette_tex;
    pub mod table_builder;
    pub mod table_builder_shared;
}

/// The texture unit in front of every family: level of detail, address, the map memory and its fetch.
pub mod texture {
    pub mod front;
    pub mod lod;
    pub mod tex_addr;
    pub mod tex_fetch;
}

pub mod stream;

/// Any unit behind AXI4-Stream, with back-pressure and reset.
pub mod axis;

// every unit also at the crate root, by its own name, whatever its family
pub use cartesian::{cart_decode, cart_decode_hemi_oct, cart_pipeline, cart_surface, cart_tex, light_iter};
pub use height::{
    blend_adjust, blinn_pipeline, height_addr, height_fetch, height_normal, height_pipeline, replicate, tangent,
    tangent_to_normal, texture_filter,
};
pub use palette::{
    palette_lookup, palette_pipeline, palette_pipeline_shared, palette_tex, table_builder, table_builder_shared,
};
pub use polar::{cos_sign, polar_pipeline, polar_shade, polar_tex, power, sincos, tables};
pub use shared::{bilinear, blend, delayed_blend, div255, dot3, gloss, normalise};
pub use stream::StreamUnit;
pub use texture::{lod, tex_addr, tex_fetch};

/// rust-hdl-core is vendored with its short values' shifts computed in `u64` (vendor/rust-hdl-core/BUMPRTL.md): they
/// must stay the published definition, the value shifted and then masked to its width.
#[cfg(test)]
mod vendored {
    use rust_hdl::prelude::*;

    fn check<const N: usize>() {
        let mask = (1u128 << N) - 1;
        let mut x: u128 = 0x9e37_79b9_7f4a_7c15;
        for _ in 0..64 {
            x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            for v in [(x >> 64) & mask, mask, 1, 0] {
                let b = Bits::<N>::from(v as u64);
                for k in 0..=70u64 {
                    let (right, left) = if k >= 128 { (0, 0) } else { (v >> k, (v << k) & mask) };
                    assert_eq!((b >> k).to_u64() as u128, right, "Bits<{N}> {v:#x} >> {k}");
                    assert_eq!((b << k).to_u64() as u128, left, "Bits<{N}> {v:#x} << {k}");
                }
            }
        }
    }

    #[test]
    fn short_shifts_are_the_published_definition() {
        macro_rules! at {
            ($($n:literal)*) => { $(check::<$n>();)* };
        }
        at!(1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32);
    }

    /// What a VCD says of a value, read here as the published probes read it: bit after bit, most significant
    /// first, `V1` a one and any other a zero; at most 64 bits.
    fn from_vcd(v: VCDValue) -> Option<u64> {
        match v {
            VCDValue::Single(b) => Some(u64::from(b == hdl_vcd::Value::V1)),
            VCDValue::Vector(bits) if bits.len() <= 64 => {
                Some(bits.into_iter().fold(0, |acc, b| acc << 1 | u64::from(b == hdl_vcd::Value::V1)))
            }
            _ => None,
        }
    }

    fn words<const N: usize>() {
        let mut x: u128 = 0x2545_f491_4f6c_dd1d;
        for _ in 0..64 {
            x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            let b = Bits::<N>::from(if N >= 64 { x as u64 } else { x as u64 & ((1 << N) - 1) });
            assert_eq!(Synth::short_word(b), from_vcd(Synth::vcd(b)), "Bits<{N}> {x:#x}");
            let s = Signal::<Out, Bits<N>>::new_with_default(b);
            assert_eq!(Atom::short_word(&s), from_vcd(Atom::vcd(&s)), "Signal<Bits<{N}>> {x:#x}");
        }
        assert_eq!(Synth::short_word(Bits::<N>::default()).is_some(), N <= 64, "Bits<{N}>");
    }

    /// The vendored `short_word` (the probe's read of a value, vendor/rust-hdl-core/BUMPRTL.md) is what the value's
    /// VCD says, at every width a block uses and past 64 bits, for a bit, and for an undriven signal (all `Z`).
    #[test]
    fn short_words_are_what_the_vcd_says() {
        macro_rules! at {
            ($($n:literal)*) => { $(words::<$n>();)* };
        }
        at!(1 2 3 7 8 9 12 16 17 24 31 32 33 40 48 63 64 65 96 128);
        for bit in [false, true] {
            assert_eq!(Synth::short_word(bit), from_vcd(Synth::vcd(bit)));
        }
        let mut open = Signal::<InOut, Bits<12>>::default();
        open.set_tristate_is_output(false);
        open.simulate_connected_tristate(&mut Signal::<InOut, Bits<12>>::default());
        assert!(matches!(Atom::vcd(&open), VCDValue::Vector(ref z) if z.iter().all(|b| *b == hdl_vcd::Value::Z)));
        assert_eq!(Atom::short_word(&open), Some(0));
    }
}
