//! The steps of the rtl whose exact result the interval proof cannot keep inside the declared format, each listed
//! with what it is and why it is right: the width report's `W` sites that are not risks. A test holds every such
//! site of every unit to this list, and every entry to a site that exists, so a new step that may wrap fails it
//! until someone writes down why it does not (or fixes it).
//!
//! Three kinds:
//! - a **split** keeps some bits of a wider word on purpose: a byte of a packed word, the low bits whose top is
//!   tested beside them;
//! - a **modular** step is arithmetic modulo 2^n on purpose: a ring's pointers, the polar R − Q around the circle;
//! - a **bound** cannot leave its format, for a reason intervals do not carry: two operands that share a factor (a
//!   weighted mean), a shift chosen from the data, a saturate's test on the top bits, the one texel value a test
//!   sets aside, or a register's reset zero that only a bubble sees. The argument is written here; the evidence
//!   beside it is the unit's rtl equal to its model, which computes in 64-bit integers without wrapping, on every
//!   vector the width report runs (and on every input where the unit's inputs can be enumerated).

/// What kind of step it is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Split,
    Modular,
    Bound,
}

impl Kind {
    /// The report's flag: `w` wraps on purpose (split or modular), `a` argued in range.
    pub fn flag(self) -> char {
        match self {
            Kind::Split | Kind::Modular => 'w',
            Kind::Bound => 'a',
        }
    }
    pub fn name(self) -> &'static str {
        match self {
            Kind::Split => "split",
            Kind::Modular => "modular",
            Kind::Bound => "bound",
        }
    }
}

/// A listed step: the block that declares the signal, the signal there (array indices dropped, `.d` for a
/// register's input), its kind and why.
pub struct Waived {
    pub block: &'static str,
    pub signal: &'static str,
    pub kind: Kind,
    pub why: &'static str,
}

/// The entry for a step, if it is listed.
pub fn find(block: &str, signal: &str) -> Option<&'static Waived> {
    WAIVED.iter().find(|w| w.block == block && w.signal == signal)
}

const fn w(block: &'static str, signal: &'static str, kind: Kind, why: &'static str) -> Waived {
    Waived { block, signal, kind, why }
}

use Kind::{Bound, Modular, Split};

const BILINEAR_MEAN: &str =
    "t·2^F ± |t' − t|·u with u < 2^F is the weighted mean t·(2^F − u) + t'·u of two UW values: \
    0 .. (2^W − 1)·2^F; intervals see the sign and the magnitude of t' − t apart";
const BILINEAR_WIDE: &str = "a bilinear unit's exact result is a weighted mean of weighted means of UW texels: below \
    2^(W + 2F − D) ≤ 2^25";

pub const WAIVED: &[Waived] = &[
    // shared blocks
    w("BilinearUnit", "s6_a.d", Bound, BILINEAR_MEAN),
    w("Normalise", "s9_out.d", Bound, "with Newton steps (the sweep's `Normalise<T, N>`, N ≥ 1): r' = r·(3 − m·r²)/2 is at most \
        2^12/√m ≤ 2^12 (the step's maximum over r; `vectors::normalise` tests every mantissa of every size), so |n| ≤ 1024 as \
        without one; intervals see r' anywhere in its U13"),
    w("NewtonStep", "mop_d.d", Bound, "3 − m·r² in Uq2.14 is ≥ 0 while m·r² ≤ 3, and every seed table of the sweep gives m·r² ≤ \
        1.25 (`vectors::normalise` tests every mantissa of every size); intervals see m and r apart"),
    w("BilinearUnit", "s6_b.d", Bound, BILINEAR_MEAN),
    w("BilinearUnit", "w_sa", Bound, BILINEAR_MEAN),
    w("BilinearUnit", "w_sb", Bound, BILINEAR_MEAN),
    w("BilinearUnit", "s7_e.d", Bound, "b' − a' of two weighted means each below 2^(W + F − D): |b' − a'| < 2^(W + F − D)"),
    w("BilinearUnit", "w_wide", Bound, "a'·2^F ± |b' − a'|·v is the weighted mean of a' and b' times 2^F: 0 .. 2^(W + 2F − D)"),
    w("BilinearUnit", "w_r", Bound, "the weighted mean (< 2^25) plus 2^(2F − D − 1): below 2^26"),
    w("BilinearUnit", "s11_out.d", Bound, "the rounded weighted mean of UW values shifted down by 2F − D is at most 2^W − 1"),
    w("Blend", "w_sum", Bound, "α·s + (255 − α)·d ≤ 255·255 = 65,025: the two products share α"),
    w("Blend", "s3_t.d", Bound, "w_sum + 128 ≤ 65,153"),
    w("Blend", "w_u", Bound, "t + (t >> 8) ≤ 65,153 + 254 = 65,407"),
    w("Lod", "s6_addr.d", Split, "the table's address: the 8 bits below m's leading one once the shift has put it at bit 24; \
        the leading one itself is dropped on purpose, the bits below bit 16 truncated"),
    w("Lod", "w_frac", Split, "frac(λ) in 8 bits: λ's bits 9..2 (Sq5.10), the integer part above them read apart (w_int), \
        the two lowest bits truncated"),
    w("Lod", "w_int", Split, "⌊λ⌋: bits 14..10 of the Sq5.10 λ, read only when its sign (bit 15) is clear, where they are \
        0 ..= 16; a negative λ reads level 0 on the sign instead"),
    w("Lod", "w_near", Split, "⌊λ + ½⌋: bits 14..10 of λ + 2^9, read only when λ's sign is clear, where they are 0 ..= 16; \
        a negative λ reads level 0 on the sign instead"),
    w("CartSurface", "dot.l_x", Split, "a 12-bit field of the light word (x, y, z packed in one RAM word), read back as the Sq1.10 it was"),
    w("CartSurface", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurface", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceMatte", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceMatte", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceMatte", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceHemiOct", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceHemiOct", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceHemiOct", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceHemiOctMatte", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceHemiOctMatte", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceHemiOctMatte", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceNearest", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceNearest", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceNearest", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceNearestMatte", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceNearestMatte", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceNearestMatte", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceNearestHemiOct", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceNearestHemiOct", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceNearestHemiOct", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceNearestHemiOctMatte", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceNearestHemiOctMatte", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartSurfaceNearestHemiOctMatte", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurface", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurface", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurface", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexTrilinearSurface", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexTrilinearSurface", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexTrilinearSurface", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexTrilinearSurfaceMatte", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexTrilinearSurfaceMatte", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexTrilinearSurfaceMatte", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestSurface", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestSurface", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestSurface", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestSurfaceHemiOct", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestSurfaceHemiOct", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestSurfaceHemiOct", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestMipSurface", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestMipSurface", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestMipSurface", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestMipSurfaceMatte", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestMipSurfaceMatte", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestMipSurfaceMatte", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestMipSurfaceHemiOct", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestMipSurfaceHemiOct", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestMipSurfaceHemiOct", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestMipSurfaceHemiOctMatte", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestMipSurfaceHemiOctMatte", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestMipSurfaceHemiOctMatte", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurfaceHemiOct", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurfaceHemiOct", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurfaceHemiOct", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurfaceHemiOctMatte", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurfaceHemiOctMatte", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurfaceHemiOctMatte", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexTrilinearSurfaceHemiOct", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexTrilinearSurfaceHemiOct", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexTrilinearSurfaceHemiOct", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexTrilinearSurfaceHemiOctMatte", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexTrilinearSurfaceHemiOctMatte", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexTrilinearSurfaceHemiOctMatte", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurfaceMatte", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurfaceMatte", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurfaceMatte", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestSurfaceMatte", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestSurfaceMatte", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestSurfaceMatte", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestSurfaceHemiOctMatte", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestSurfaceHemiOctMatte", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexNearestSurfaceHemiOctMatte", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurfaceColour", "dot.l_x", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurfaceColour", "dot.l_y", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearSurfaceColour", "dot.l_z", Split, "a field of the packed light word, as in CartSurface"),
    w("CartTexBilinearColour", "blend.src_r", Split, "a byte of the packed (src_r, src_g, src_b, mode) word that waits beside the front"),
    w("CartTexBilinearColour", "blend.src_g", Split, "as blend.src_r"),
    w("CartTexBilinearColour", "blend.src_b", Split, "as blend.src_r"),
    w("CartTexNearestColour", "blend.src_r", Split, "as in CartTexBilinearColour"),
    w("CartTexNearestColour", "blend.src_g", Split, "as blend.src_r"),
    w("CartTexNearestColour", "blend.src_b", Split, "as blend.src_r"),
    w("CartTexNearestMipColour", "blend.src_r", Split, "as in CartTexBilinearColour"),
    w("CartTexNearestMipColour", "blend.src_g", Split, "as blend.src_r"),
    w("CartTexNearestMipColour", "blend.src_b", Split, "as blend.src_r"),
    w("CartTexBilinearSurfaceColour", "blend.src_r", Split, "as in CartTexBilinearColour"),
    w("CartTexBilinearSurfaceColour", "blend.src_g", Split, "as in CartTexBilinearColour"),
    w("CartTexBilinearSurfaceColour", "blend.src_b", Split, "as in CartTexBilinearColour"),
    w("DelayedBlend", "blend.src_r", Split, "a byte of the six colours packed in one RAM word"),
    w("DelayedBlend", "blend.src_g", Split, "a byte of the packed colours"),
    w("DelayedBlend", "blend.src_b", Split, "a byte of the packed colours"),
    w("DelayedBlend", "blend.dst_r", Split, "a byte of the packed colours"),
    w("DelayedBlend", "blend.dst_g", Split, "a byte of the packed colours"),
    w("Gloss", "m3_lo", Split, "the low 10 bits of m >> 3, read only where m >> 3 ≤ 1023 (tested beside it; else L = 0)"),
    w("Gloss", "s5_d.d", Bound, "L − Q with Q = ⌊L·L / 1024⌋ ≤ L for L ≤ 1023: never negative"),
    w("Gloss", "s8_p.d", Bound, "L − ⌈C·(L − Q) / 256⌉ ≥ L − (L − Q) = Q ≥ 0 for C ≤ 255"),
    w("RamDelay", "wp.d", Modular, "the ring's write pointer counts modulo 2^A"),
    w("RamDelay", "ram.read_address", Modular, "wp − (N − 2) modulo 2^A, the ring's read pointer (wp + 2^A − N + 2)"),
    w("SmMul", "s1_m.d", Bound, "|x| of an N-bit x kept in 16 bits: every caller's |x| is below 2^16 (a texel difference, |b' − a'|)"),
    w("SmMulWide", "s1_lo.d", Split, "the low half of |x|, multiplied apart from the high half"),
    w("SmMulWide", "w_hi16", Bound, "hi·w·2^16 ≤ |x|·w < 2^32 for every caller: height_normal's 7k·|t| < 1785·2^20, \
        tangent's |d2 − d1|·V < 2^29"),
    w("SmMulWide", "s4_p.d", Bound, "lo·w + hi·w·2^16 = |x|·w < 2^32: the caller's bound"),
    // Cartesian
    w("CartDecode", "lo_x", Split, "the low 7 bits of the texel: T − 128 where bit 7 (tested beside them) is set"),
    w("CartDecode", "lo_z", Split, "as lo_x"),
    w("CartDecode", "s2_sum.d", Bound, "each magnitude is 127 − T or T − 127 with T = 255 set aside (it gives 127): ≤ 127 each, \
        the sum ≤ 254; intervals do not carry the T = 255 test into T − 127"),
    w("CartDecode", "s3_mx.d", Bound, "127 + (ax − az) ∈ 0..254 and 2·ax ≤ 254, for ax, az ≤ 127 (as s2_sum)"),
    w("CartDecode", "s3_mz.d", Bound, "as s3_mx"),
    w("CartDecode", "twice_sum", Bound, "2·sum is read only where the sum is below 128 (bit 7 clear): ≤ 254"),
    w("CartDecodeHemiOct", "s3_y.d", Bound, "|x| + |z| = max(|2U − 255|, |2V − 255|) ≤ 255 for every texel (x = U + V − 255, \
        z = U − V), so 255 − |x| − |z| ≥ 0"),
    w("LightLane", "w_hi", Split, "the top 5 bits of the S14, a test only"),
    w("LightLane", "s7_out.d", Bound, "a saturate: the low 10 bits are taken only where bits 13..9 are all equal, which makes \
        them the value; else ±511 / −512"),
    // height maps
    w("HeightAddr", "s2_blend.d", Split, "the fraction: the low 8 bits of the coordinate"),
    w("HeightFetch", "w_um", Bound, "2^log2 − 1 for log2 ≤ 7 (bit 3 clear; else 255): 0..127"),
    w("HeightFetch", "w_vm", Bound, "as w_um"),
    w("HeightFetch", "s1_x.d", Bound, "x AND (2^s − 1) with 2^s − 1 ≤ 255 (wrap mode), or a clamp to 0..2^s − 1: U8"),
    w("HeightFetch", "s1_y.d", Bound, "as s1_x"),
    w("HeightFetch", "s4_out.d", Split, "one height of the fetched word, selected by a shift"),
    w("HeightNormal", "s1_k7.d", Bound, "8k − k = 7k ≥ 0: the same k on both sides"),
    w("HeightNormal", "w_sm1", Bound, "s − 1 with s ∈ 11..23 (chosen at stage 7); only the register's reset zero, before the \
        first vector reaches the stage, gives −1, and what it makes is never valid"),
    w("HeightNormal", "s9_a1.d", Bound, "a magnitude < 2^31 plus 2^(s − 1) ≤ 2^22: below 2^32"),
    w("HeightNormal", "s9_a2.d", Bound, "as s9_a1"),
    w("HeightNormal", "s9_ay.d", Bound, "as s9_a1"),
    w("HeightNormal", "s10_q1.d", Bound, "rounded at the shift s chosen from the largest of the three magnitudes: ≤ 511 by \
        that choice; intervals cannot tie s to the magnitude"),
    w("HeightNormal", "s10_q2.d", Bound, "as s10_q1"),
    w("HeightNormal", "s10_qy.d", Bound, "as s10_q1"),
    w("HeightNormal", "s11_x.d", Bound, "±q with q ≤ 511 (s10_q1): S10"),
    w("HeightNormal", "s11_y.d", Bound, "q ≤ 511 (s10_qy): S10"),
    w("HeightNormal", "s11_z.d", Bound, "as s11_x"),
    w("HeightPipeline", "back.red", Bound, BILINEAR_WIDE),
    w("HeightPipeline", "back.green", Bound, BILINEAR_WIDE),
    w("HeightPipeline", "back.blue", Bound, BILINEAR_WIDE),
    w("HeightPipeline", "back.alpha", Bound, BILINEAR_WIDE),
    w("TextureFilter", "back.red", Bound, BILINEAR_WIDE),
    w("TextureFilter", "back.green", Bound, BILINEAR_WIDE),
    w("TextureFilter", "back.blue", Bound, BILINEAR_WIDE),
    w("TextureFilter", "back.alpha", Bound, BILINEAR_WIDE),
    w("TextureFilter", "out_r", Split, "a byte of the filtered RGBA word"),
    w("TextureFilter", "out_g", Split, "a byte of the filtered RGBA word"),
    w("TextureFilter", "out_b", Split, "a byte of the filtered RGBA word"),
    w("Tangent", "s2_dd.d", Bound, "d2 − d1 of two S21 values, each sign-extended to 22 bits by an OR on its sign: S22; \
        intervals lose the sign extension's two sides"),
    w("Tangent", "s2_ee.d", Bound, "as s2_dd"),
    w("Tangent", "s2_b1.d", Modular, "d1·256 as the 29-bit pattern of an S21 shifted up: the sign lands in bit 28, so the \
        pattern is d1·256's two's complement"),
    w("Tangent", "s2_b2.d", Modular, "as s2_b1"),
    w("Tangent", "s7_t1.d", Bound, "d1·256 ± |d2 − d1|·V with V ≤ 255 lies between d1·256 and d2·256: S29, inside S30"),
    w("Tangent", "s7_t2.d", Bound, "as s7_t1"),
    w("Tangent", "s8_t1.d", Bound, "bits 8..28 of a convex combination of S21 values times 2^8: back in S21"),
    w("Tangent", "s8_t2.d", Bound, "as s8_t1"),
    w("BlinnPipeline", "w_d1", Bound, "G − R of two bilinear results, each below 2^25 (a weighted mean): S26"),
    w("BlinnPipeline", "w_d2", Bound, "B − R, as w_d1"),
    w("BlinnPipeline", "s2_t1.d", Bound, "(G − R) >> 6 of an S26: S20 in 21"),
    w("BlinnPipeline", "s2_t2.d", Bound, "as s2_t1"),
    // palettes
    w("PaletteLookup", "out_r", Split, "a byte of the 32-bit table entry"),
    w("PaletteLookup", "out_g", Split, "a byte of the 32-bit table entry"),
    w("PaletteLookup", "out_b", Split, "a byte of the 32-bit table entry"),
    // polar
    w("PolarShade", "w_d", Modular, "R − Q modulo 256: the angle difference goes round the circle (the seed's subtractor [16])"),
    w("PolarShade", "s10_shade.d", Bound, "a clamp [28]: the low 8 bits only where the sign (bit 10) and bits 9..8 are clear"),
    w("Power", "s4_f.d", Split, "g's fraction: EB bits of e + 2^(k − 1) from bit k = 2 + LF − EB (6..13 in the unit); its \
        integer part, above, is taken beside it"),
    w("Power", "s6_w.d", Bound, "E >> (n + 6) with E ≤ 32,640 (the exp table's largest) and n + 6 ≥ 6: ≤ 510; only the \
        shift register's reset zero, seen by bubbles, gives more"),
    w("Power", "w_w1", Bound, "(E >> (n + 6)) + 1 ≤ 511 (s6_w)"),
    // the texture unit
    w("TexBilinearColour", "fetch.w_log2", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexBilinearColour", "fetch.wx", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexBilinearColour", "fetch.wy", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexBilinearColour", "colour_fetch.w_log2", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexBilinearColour", "colour_fetch.wx", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexBilinearColour", "colour_fetch.wy", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexBilinearColour", "filter.t00", Split, "as in TexBilinear"),
    w("TexBilinearColour", "filter.t10", Split, "as in TexBilinear"),
    w("TexBilinearColour", "filter.t01", Split, "as in TexBilinear"),
    w("TexBilinearColour", "filter.t11", Split, "as in TexBilinear"),
    w("TexBilinearColour", "filter.ublend", Split, "as in TexBilinear"),
    w("TexBilinearColour", "colour_filter.ublend", Split, "the low byte of the packed (ublend, vblend) word, as filter.ublend"),
    w("TexBilinearColour", "colour_filter.t00", Split, "a byte of the widened RGB565 texel (R, G, B packed in 24 bits by Rgb565), read back as the U8 it was"),
    w("TexBilinearColour", "colour_filter.t10", Split, "as colour_filter.t00"),
    w("TexBilinearColour", "colour_filter.t01", Split, "as colour_filter.t00"),
    w("TexBilinearColour", "colour_filter.t11", Split, "as colour_filter.t00"),
    w("TexFetch", "bank.address", Split, "the low A bits of the 13-bit word address: below 2^A for every level the memory holds (the \
        even levels end at word 1,093 of 2^11); a level it does not hold is never written and reads as zeros"),
    w("LevelLerp", "w_sum", Bound, "b₀·2^8 ± |b₁ − b₀|·f: the minus only when b₁ < b₀, where |b₁ − b₀|·f ≤ b₀·255, so the sum is b₀·(2^8 − f) + b₁·f, a mean of two bytes times 2^8: 0 .. 65,280"),
    w("LevelLerp", "w_r", Bound, "w_sum + 2^7 ≤ 65,408"),
    w("LevelLerp", "s5_out.d", Split, "bits 8..15 of w_r ≤ 65,408: the rounded byte, nothing above it"),
    w("TexTrilinear", "side_log2", Split, "the log_side field of the packed position word, read back as the U4 it was"),
    w("TexBilinear", "fetch.we", Split, "bit 0 of the write word (we, w_log2, wx, wy, wdata packed low to high), read back as the bit it was"),
    w("TexBilinear", "fetch.w_log2", Split, "a field of the packed write word, as fetch.we"),
    w("TexBilinear", "fetch.wx", Split, "a field of the packed write word, as fetch.we"),
    w("TexBilinear", "fetch.wy", Split, "a field of the packed write word, as fetch.we"),
    w("TexBilinear", "filter.t00", Split, "the low byte of a 16-bit texel, one of the two channels the front filters apart"),
    w("TexBilinear", "filter.t10", Split, "as filter.t00"),
    w("TexBilinear", "filter.t01", Split, "as filter.t00"),
    w("TexBilinear", "filter.t11", Split, "as filter.t00"),
    w("TexBilinear", "filter.ublend", Split, "the low byte of the packed (ublend, vblend) word, read back as the U8 it was"),
    w("TexNearest", "fetch.we", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearest", "fetch.w_log2", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearest", "fetch.wx", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearest", "fetch.wy", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearest", "lo", Split, "the low byte of the 16-bit texel (TexelX or U), the high byte its other channel"),
    w("TexNearestMip", "fetch.we", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestMip", "fetch.w_log2", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestMip", "fetch.wx", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestMip", "fetch.wy", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestMip", "lo", Split, "the low byte of the 16-bit texel (TexelX or U), the high byte its other channel"),
    w("TexNearestMip", "addr.u", Split, "a field of the packed position word (u, v, log_side, uwrap, vwrap low to high) that waits \
        beside the LOD unit, read back as the Sq11.8 it was"),
    w("TexNearestMip", "addr.v", Split, "a field of the packed position word, as addr.u"),
    w("TexNearestMip", "addr.log_side", Split, "a field of the packed position word, as addr.u"),
    w("TexNearestMip", "addr.uwrap", Split, "a field of the packed position word, as addr.u"),
    w("TexNearestColour", "fetch.w_log2", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestColour", "fetch.wx", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestColour", "fetch.wy", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestColour", "colour_fetch.w_log2", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestColour", "colour_fetch.wx", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestColour", "colour_fetch.wy", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestColour", "lo", Split, "as in TexNearest"),
    w("TexNearestColour", "c_r", Split, "a byte of the widened RGB565 texel (R, G, B packed in 24 bits by Rgb565), read back as the U8 it was"),
    w("TexNearestColour", "c_g", Split, "as c_r"),
    w("TexNearestMipColour", "fetch.w_log2", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestMipColour", "fetch.wx", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestMipColour", "fetch.wy", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestMipColour", "colour_fetch.w_log2", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestMipColour", "colour_fetch.wx", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestMipColour", "colour_fetch.wy", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexNearestMipColour", "lo", Split, "as in TexNearest"),
    w("TexNearestMipColour", "c_r", Split, "a byte of the widened RGB565 texel (R, G, B packed in 24 bits by Rgb565), read back as the U8 it was"),
    w("TexNearestMipColour", "c_g", Split, "as c_r"),
    w("TexNearestMipColour", "addr.u", Split, "a field of the packed position word, as in TexNearestMip"),
    w("TexNearestMipColour", "addr.v", Split, "a field of the packed position word, as in TexNearestMip"),
    w("TexNearestMipColour", "addr.log_side", Split, "a field of the packed position word, as in TexNearestMip"),
    w("TexNearestMipColour", "addr.uwrap", Split, "a field of the packed position word, as in TexNearestMip"),
    w("TexTrilinear", "fetch_even.we", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexTrilinear", "fetch_even.w_log2", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexTrilinear", "fetch_even.wx", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexTrilinear", "fetch_even.wy", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexTrilinear", "fetch_odd.we", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexTrilinear", "fetch_odd.w_log2", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexTrilinear", "fetch_odd.wx", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexTrilinear", "fetch_odd.wy", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexTrilinear", "prev_level", Split, "⌊λ⌋ − 1, wrapping at ⌊λ⌋ = 0 on purpose: the second level is not it there"),
    w("TexTrilinear", "addr.u", Split, "a field of the packed position word, as in TexNearestMip"),
    w("TexTrilinear", "addr.v", Split, "a field of the packed position word, as in TexNearestMip"),
    w("TexTrilinear", "addr.log_side", Split, "a field of the packed position word, as in TexNearestMip"),
    w("TexTrilinear", "addr.uwrap", Split, "a field of the packed position word, as in TexNearestMip"),
    w("TexTrilinear", "filter.t00", Split, "a byte of a 16-bit texel, as in TexBilinear"),
    w("TexTrilinear", "filter.t10", Split, "as filter.t00"),
    w("TexTrilinear", "filter.t01", Split, "as filter.t00"),
    w("TexTrilinear", "filter.t11", Split, "as filter.t00"),
    w("TexTrilinear", "filter.ublend", Split, "a byte of a level's packed (ublend, vblend) word, as in TexBilinear"),
    w("TexTrilinear", "next_level", Bound, "⌊λ⌋ + 1 with ⌊λ⌋ ≤ 8 (the LOD unit clamps λ to the map's last level, log_side ≤ 8): ≤ 9"),
    w("TexTrilinearTwoPass", "side_log2", Split, "as in TexTrilinear"),
    w("TexTrilinearTwoPass", "next_level", Bound, "as in TexTrilinear: ≤ 9"),
    w("TexTrilinearTwoPass", "prev_level", Split, "as in TexTrilinear: wraps at ⌊λ⌋ = 0, not read there"),
    w("TexTrilinearTwoPass", "addr.u", Split, "a field of the packed position word (the first pass's or the one kept for the second), as in TexNearestMip"),
    w("TexTrilinearTwoPass", "addr.v", Split, "as addr.u"),
    w("TexTrilinearTwoPass", "addr.log_side", Split, "as addr.u"),
    w("TexTrilinearTwoPass", "addr.uwrap", Split, "as addr.u"),
    w("TexTrilinearTwoPass", "fetch.we", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexTrilinearTwoPass", "fetch.w_log2", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexTrilinearTwoPass", "fetch.wx", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexTrilinearTwoPass", "fetch.wy", Split, "a field of the packed write word, as in TexBilinear"),
    w("TexTrilinearTwoPass", "filter.t00", Split, "a byte of a 16-bit texel, as in TexBilinear"),
    w("TexTrilinearTwoPass", "filter.t10", Split, "as filter.t00"),
    w("TexTrilinearTwoPass", "filter.t01", Split, "as filter.t00"),
    w("TexTrilinearTwoPass", "filter.t11", Split, "as filter.t00"),
    w("TexTrilinearTwoPass", "filter.ublend", Split, "a byte of a pass's packed (ublend, vblend) word, as in TexBilinear"),
    w("TexAddr", "w_ua", Split, "floor(u / 2^n') as the 30-bit two's complement pattern of a signed value: given a signed u (inside a \
        pipeline, from its Sq11.8 port), the proof sees the negative values the pattern stands for"),
    w("TexAddr", "w_va", Split, "as w_ua, for v"),
    w("TexAddr", "s1_m.d", Bound, "s − n' with n' = min(level, s): 0..8"),
    w("TexAddr", "w_ua22", Split, "bits 0..21 of u sign-extended to 30 bits and shifted right by n' ≤ 8: floor(u / 2^n') in two's \
        complement (S20 in 22), the bits above it the sign's copies and the shift's zeros"),
    w("TexAddr", "w_va22", Split, "as w_ua22, for v"),
    w("TexAddr", "s2_cu.d", Bound, "floor(u / 2^n') − 128 with floor(u / 2^n') in S20: −2^19 − 128 .. 2^19 − 1, inside S21"),
    w("TexAddr", "s2_cv.d", Bound, "as s2_cu, for v"),
    w("TexAddr", "w_span", Bound, "2^m · 256 with m = s − n' ≤ 8 (s1_m): at most 2^16"),
    w("TexAddr", "s2_mask.d", Bound, "256·2^m − 1 with m ≤ 8: 255 .. 65,535"),
    w("TexAddr", "s2_top.d", Bound, "256·2^m − 256 or − 1 with m ≤ 8: 0 .. 65,535"),
    w("TexAddr", "s2_last.d", Bound, "2^m − 1 with m ≤ 8: the level's last texel, 0..255"),
    w("TexAddr", "s3_ru.d", Bound, "c AND (256·2^m − 1) (repeat) or c clamped to 0..top (clamp), both ≤ 65,535 for m ≤ 8"),
    w("TexAddr", "s3_rv.d", Bound, "as s3_ru, for v"),
    w("TexAddr", "s4_ub.d", Split, "the blend factor: r's low byte, the texel above it read apart (w_tu)"),
    w("TexAddr", "s4_vb.d", Split, "as s4_ub, for v"),
    w("TexAddr", "w_tu1", Modular, "t0 + 1 modulo 256: only t0 = 255 wraps, the last texel of a 256-texel level, where repeat wants \
        0 (the AND with 255) and clamp keeps t0"),
    w("TexAddr", "w_tv1", Modular, "as w_tu1, for v"),
];
