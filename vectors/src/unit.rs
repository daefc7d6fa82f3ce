//! The description every unit shares: its ports (named as the rtl block names them), its bit-exact function and
//! a way to draw legal random inputs. The vector generator, the testbenches and the Verilog harnesses all read it.

use rand::Rng;

/// One port of a unit: its name in the rtl block, its width, and whether its bits are two's complement.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Port {
    pub name: &'static str,
    pub bits: u32,
    pub signed: bool,
}

impl Port {
    pub const fn u(name: &'static str, bits: u32) -> Port {
        Port { name, bits, signed: false }
    }
    pub const fn s(name: &'static str, bits: u32) -> Port {
        Port { name, bits, signed: true }
    }
    pub fn range(&self) -> (i64, i64) {
        if self.signed {
            crate::fixed::signed_range(self.bits)
        } else {
            crate::fixed::unsigned_range(self.bits)
        }
    }
}

/// A streaming unit as the testbench sees it: inputs in, outputs out, one vector per clock.
pub struct UnitModel {
    pub name: &'static str,
    pub inputs: &'static [Port],
    pub outputs: &'static [Port],
    /// The bit-exact model: input values (in port order) → output values.
    pub exact: fn(&[i64]) -> Vec<i64>,
    /// One random input vector drawn from the legal input space (edges weighted in).
    pub random: fn(&mut dyn rand::RngCore) -> Vec<i64>,
    /// The whole input space, in order, when it is small enough to enumerate (≤ 2^20 vectors).
    pub exhaustive: Option<fn() -> Vec<Vec<i64>>>,
    /// Inputs the seeds warn about or that sit at the edge of a range; always in the golden file.
    pub hard_cases: fn() -> Vec<Vec<i64>>,
}

impl UnitModel {
    pub fn header(&self) -> Vec<&'static str> {
        self.inputs.iter().chain(self.outputs.iter()).map(|p| p.name).collect()
    }
}

/// Every unit with an rtl block, by name.
pub const UNITS: &[&UnitModel] = &[
    &crate::cart_decode::MODEL,
    &crate::cart_decode_hemi_oct::MODEL,
    &crate::bilinear::MODEL,
    &crate::light_iter::MODEL,
    &crate::normalise::MODEL,
    &crate::dot3::MODEL,
    &crate::gloss::MODEL,
    &crate::blend::MODEL,
    &crate::cart_pipeline::MODEL,
    &crate::cart_pipeline::MODEL_HEMI_OCT,
    &crate::sincos::MODEL,
    &crate::cos_sign::MODEL,
    &crate::polar_shade::MODEL,
    &crate::power::MODEL,
    &crate::polar_pipeline::MODEL,
    &crate::polar_pipeline::MODEL_DC,
];

/// A vector's values as the bit patterns its ports carry (two's complement for signed ports), in port order.
pub fn to_patterns(values: &[i64], ports: &[Port]) -> Vec<u64> {
    values.iter().zip(ports).map(|(&v, p)| crate::fixed::to_pattern(v, p.bits)).collect()
}

pub fn find(name: &str) -> Option<&'static UnitModel> {
    UNITS.iter().copied().find(|u| u.name == name)
}

/// A value drawn uniformly from a port's range, with its two ends weighted in (1 draw in 8 is an end).
pub fn draw(rng: &mut dyn rand::RngCore, p: &Port) -> i64 {
    let (lo, hi) = p.range();
    match rng.gen_range(0..16) {
        0 => lo,
        1 => hi,
        _ => rng.gen_range(lo..=hi),
    }
}

/// The vectors for a unit: either its whole input space, each input exactly once (the hard cases are in it), or
/// its hard cases first and then `count` random vectors drawn from a ChaCha8 stream seeded with `seed` (the same
/// seed gives the same file on every machine).
pub fn generate(unit: &UnitModel, exhaustive: bool, count: usize, seed: u64) -> Result<Vec<Vec<i64>>, String> {
    use rand::SeedableRng;
    if exhaustive {
        let all = unit.exhaustive.ok_or_else(|| {
            format!("{} has no exhaustive vector set: its input space is above 2^20; use --count", unit.name)
        })?;
        return Ok(all());
    }
    let mut v = (unit.hard_cases)();
    {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        v.extend((0..count).map(|_| (unit.random)(&mut rng)));
    }
    Ok(v)
}
