//! Named fixed-point steps shared by every `exact()`. Widening is free; every narrowing goes through one of these,
//! so a reader can see where bits are dropped and how.

/// Arithmetic shift right: floor division by 2^k (two's complement `>>>`). Truncation toward −∞.
pub fn truncate(x: i64, k: u32) -> i64 {
    x >> k
}

/// Round half up (toward +∞) while dropping `k` fraction bits.
pub fn round_half_up(x: i64, k: u32) -> i64 {
    if k == 0 {
        x
    } else {
        (x + (1 << (k - 1))) >> k
    }
}

/// Round half away from zero while dropping `k` fraction bits (the rtl rounds magnitudes, then restores the sign).
pub fn round_half_away(x: i64, k: u32) -> i64 {
    let m = round_half_up(x.abs(), k);
    if x < 0 {
        -m
    } else {
        m
    }
}

/// Saturate into `[lo, hi]`.
pub fn saturate(x: i64, lo: i64, hi: i64) -> i64 {
    x.clamp(lo, hi)
}

/// Range of a signed `bits`-wide two's complement value.
pub fn signed_range(bits: u32) -> (i64, i64) {
    (-(1 << (bits - 1)), (1 << (bits - 1)) - 1)
}

/// Range of an unsigned `bits`-wide value.
pub fn unsigned_range(bits: u32) -> (i64, i64) {
    (0, (1 << bits) - 1)
}

/// Two's complement bit pattern of `x` in `bits` bits (what the rtl carries on its wires).
pub fn to_pattern(x: i64, bits: u32) -> u64 {
    (x as u64) & ((1u64 << bits) - 1)
}

/// Value of a `bits`-wide bit pattern, read as signed or unsigned.
pub fn from_pattern(p: u64, bits: u32, signed: bool) -> i64 {
    let p = p & ((1u64 << bits) - 1);
    if signed && (p >> (bits - 1)) & 1 == 1 {
        p as i64 - (1i64 << bits)
    } else {
        p as i64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn truncate_floors_negative_values() {
        assert_eq!(truncate(-1, 3), -1);
        assert_eq!(truncate(-8, 3), -1);
        assert_eq!(truncate(-9, 3), -2);
        assert_eq!(truncate(15, 3), 1);
    }

    #[test]
    fn rounding_modes_differ_only_on_negative_halves() {
        assert_eq!(round_half_up(-4, 3), 0);
        assert_eq!(round_half_away(-4, 3), -1);
        assert_eq!(round_half_up(4, 3), 1);
        assert_eq!(round_half_away(4, 3), 1);
        assert_eq!(round_half_away(-3, 3), 0);
    }

    #[test]
    fn patterns_round_trip_at_the_extremes() {
        for bits in [1u32, 8, 9, 10, 12, 20] {
            let (lo, hi) = signed_range(bits);
            for v in [lo, -1, 0, hi] {
                if bits == 1 && v == -1 {
                    continue;
                }
                assert_eq!(from_pattern(to_pattern(v, bits), bits, true), v, "{v} in {bits} bits");
            }
        }
        assert_eq!(from_pattern(0x100, 9, true), -256);
        assert_eq!(from_pattern(0x100, 9, false), 256);
    }
}
