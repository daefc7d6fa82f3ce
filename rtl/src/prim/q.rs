//! The rtl's one fixed-point convention, and the types every block shares.
//!
//! - `SqM_N`: two's complement with M integer bits, **not counting the sign bit**, and N fraction bits: it is
//!   `Bits<1 + M + N>` and holds −2^M .. 2^M − 2^−N.
//! - `UqM_N`: unsigned with M integer bits and N fraction bits: `Bits<M + N>`, 0 .. 2^M − 2^−N.
//! - Plain integers are named by their width: `U8` is `Bits<8>` (0..255), `S8` an 8-bit two's complement integer
//!   (the sign counted in the 8: an `S8` is an `Sq7_0`).
//!
//! The same bits can be read at two scales by two blocks: the light leaves `light_iter` as an `Sq7_2` and enters
//! `normalise` as an `Sq9_0` (the normaliser is scale-free: it reads any 10-bit vector as an integer).
//!
//! Narrowing in hdl_gen code is written with `get_bits` on a named signal (rust-hdl can slice only named signals)
//! and says beside it, in a comment, whether it truncates (floor), rounds (and how) or saturates, and why it cannot
//! overflow; the models in `vectors::fixed` carry the same steps by name (`truncate`, `round_half_up`, `saturate`).

use rust_hdl::prelude::{Bits, Synth};

/// Writes each alias (`pub type Name = Type;`) and, from the same list, `ALIASES`: every alias's name with its width,
/// so that the width report reads a signal's format from the name its declaration gives it.
macro_rules! q_types {
    ($($(#[$doc:meta])* $name:ident = $ty:ty;)*) => {
        $($(#[$doc])* pub type $name = $ty;)*

        /// Every alias above, by name, with its width in bits (`SBits<N>`, generic, is not one of them).
        pub const ALIASES: &[(&str, usize)] = &[$((stringify!($name), <$ty as Synth>::BITS)),*];
    };
}

q_types! {
    U8 = Bits<8>;
    U16 = Bits<16>;
    S8 = Bits<8>;
    S9 = Bits<9>;
    S11 = Bits<11>;
    /// The bump vector's components (INT9: −255..255).
    Sq8_0 = Bits<9>;
    /// The normaliser's input components, read as integers.
    Sq9_0 = Bits<10>;
    /// The interpolated light, two fraction bits.
    Sq7_2 = Bits<10>;
    /// The light interpolator's accumulator: l0·256 + Σ d·w, eight fraction bits.
    Sq11_8 = Bits<20>;
    /// A screen derivative of a texture coordinate, texels of level 0 a pixel (the level of detail's input).
    Sq8_8 = Bits<17>;
    /// A unit vector's components, 1024 = 1.0.
    Sq1_10 = Bits<12>;
    /// A product of two `Sq1_10`, or the sum of three (|Σ| < 3·2^20 < 2^22, with room).
    Sq4_20 = Bits<25>;
    /// A 10-bit fraction: X, L, Q and P of the gloss unit, 1023 ≈ 1.0.
    Uq0_10 = Bits<10>;
    /// The gloss unit's k = C + 8, three fraction bits.
    Uq6_3 = Bits<9>;
    /// The normaliser's table entries, 2^12/√m ∈ 2049..4096.
    Uq1_12 = Bits<13>;
    /// log2 of a mantissa, the level of detail's table.
    Uq0_9 = Bits<9>;
    /// A level of detail λ, ten fraction bits.
    Uq4_10 = Bits<14>;
    /// A level of detail with its sign: log2 ρ (below 0 for a magnified pixel) plus a bias.
    Sq5_10 = Bits<16>;
    /// A LOD bias, levels: −8 .. 8 − 1/256.
    Sq3_8 = Bits<12>;
}

/// A two's complement integer of a width a block takes as a parameter (`SmMul<N>`'s operand).
pub type SBits<const N: usize> = Bits<N>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_type_is_as_wide_as_its_name_says() {
        // SqM_N: 1 + M + N bits (the sign not counted in M); UqM_N: M + N
        assert_eq!(Sq8_0::BITS, 1 + 8);
        assert_eq!(Sq9_0::BITS, 1 + 9);
        assert_eq!(Sq7_2::BITS, 1 + 7 + 2);
        assert_eq!(Sq11_8::BITS, 1 + 11 + 8);
        assert_eq!(Sq1_10::BITS, 1 + 1 + 10);
        assert_eq!(Sq4_20::BITS, 1 + 4 + 20);
        assert_eq!(Uq0_10::BITS, 10);
        assert_eq!(Uq6_3::BITS, 6 + 3);
        assert_eq!(Uq1_12::BITS, 1 + 12);
        assert_eq!((Sq5_10::BITS, Sq3_8::BITS), (1 + 5 + 10, 1 + 3 + 8));
        assert_eq!((U8::BITS, U16::BITS, S8::BITS, S9::BITS, S11::BITS), (8, 16, 8, 9, 11));
    }
}
