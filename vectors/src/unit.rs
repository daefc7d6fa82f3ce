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

/// Declares a unit's ports once, in order: `INPUTS` and `OUTPUTS` (`u` unsigned, `s` two's complement, and the
/// width), and modules `input` and `output` holding each port's index by its own name, so that a vector is read
/// as `v[input::conc]`, never by a number.
#[macro_export]
macro_rules! ports {
    (inputs: [$($i:ident: $ik:ident $iw:expr),* $(,)?], outputs: [$($o:ident: $ok:ident $ow:expr),* $(,)?] $(,)?) => {
        pub const INPUTS: &[$crate::unit::Port] = &[$($crate::unit::Port::$ik(stringify!($i), $iw)),*];
        pub const OUTPUTS: &[$crate::unit::Port] = &[$($crate::unit::Port::$ok(stringify!($o), $ow)),*];
        /// One random input vector: every input port drawn over its range, its ends weighted in.
        #[allow(dead_code)]
        pub fn random_inputs(rng: &mut dyn rand::RngCore) -> Vec<i64> {
            INPUTS.iter().map(|p| $crate::unit::draw(rng, p)).collect()
        }
        /// Each input port's index in an input vector.
        #[allow(non_upper_case_globals, dead_code)]
        pub mod input {
            #[allow(non_camel_case_types)]
            enum Index { $($i),* }
            $(pub const $i: usize = Index::$i as usize;)*
        }
        /// Each output port's index in an output vector.
        #[allow(non_upper_case_globals, dead_code)]
        pub mod output {
            #[allow(non_camel_case_types)]
            enum Index { $($o),* }
            $(pub const $o: usize = Index::$o as usize;)*
        }
    };
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
    /// The unit's error against its ideal, measured: (samples where it draws at random, seed) → one row per metric.
    /// `bumprtl accuracy` prints every unit's, in the table's order.
    pub accuracy: Option<fn(usize, u64) -> Vec<Accuracy>>,
    /// A unit with state (a memory written by some vectors and read by later ones): the model over a whole stream,
    /// from reset. `exact` is then the stream of that one vector.
    pub stream: Option<fn(&[Vec<i64>]) -> Vec<Vec<i64>>>,
}

/// One measured error of a unit against its ideal: what is measured, over which inputs, and the statistics.
pub struct Accuracy {
    pub metric: String,
    pub stats: crate::stats::ErrorStats,
}

impl Accuracy {
    pub fn new(metric: &str, stats: crate::stats::ErrorStats) -> Accuracy {
        Accuracy { metric: metric.to_string(), stats }
    }

    /// One metric over `samples` inputs drawn by `random` from a stream seeded with `seed`; `errors` gives each
    /// input's errors (one, or one per channel), all counted, the worst reported with its input.
    pub fn over_random(
        metric: &str,
        samples: usize,
        seed: u64,
        random: fn(&mut dyn rand::RngCore) -> Vec<i64>,
        errors: impl Fn(&[i64]) -> Vec<f64>,
    ) -> Accuracy {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let mut s = crate::stats::ErrorStats::default();
        for _ in 0..samples {
            let v = random(&mut rng);
            for e in errors(&v) {
                s.add(e, || format!("{v:?}"));
            }
        }
        Accuracy::new(metric, s)
    }
}

impl UnitModel {
    /// A unit whose input space is too large to enumerate (the exhaustive set is added by `with_exhaustive`).
    pub const fn new(
        name: &'static str,
        ports: (&'static [Port], &'static [Port]),
        exact: fn(&[i64]) -> Vec<i64>,
        random: fn(&mut dyn rand::RngCore) -> Vec<i64>,
        hard_cases: fn() -> Vec<Vec<i64>>,
    ) -> UnitModel {
        UnitModel {
            name,
            inputs: ports.0,
            outputs: ports.1,
            exact,
            random,
            exhaustive: None,
            hard_cases,
            accuracy: None,
            stream: None,
        }
    }

    pub const fn with_exhaustive(self, all: fn() -> Vec<Vec<i64>>) -> UnitModel {
        UnitModel { exhaustive: Some(all), ..self }
    }

    pub const fn with_accuracy(self, f: fn(usize, u64) -> Vec<Accuracy>) -> UnitModel {
        UnitModel { accuracy: Some(f), ..self }
    }

    pub const fn with_stream(self, run: fn(&[Vec<i64>]) -> Vec<Vec<i64>>) -> UnitModel {
        UnitModel { stream: Some(run), ..self }
    }

    /// The model's outputs for a stream of vectors in order: vector by vector, or through the unit's state.
    pub fn run(&self, inputs: &[Vec<i64>]) -> Vec<Vec<i64>> {
        match self.stream {
            Some(run) => run(inputs),
            None => inputs.iter().map(|v| (self.exact)(v)).collect(),
        }
    }

    pub fn header(&self) -> Vec<&'static str> {
        self.inputs.iter().chain(self.outputs.iter()).map(|p| p.name).collect()
    }
}

/// A vector's values as the bit patterns its ports carry (two's complement for signed ports), in port order.
pub fn to_patterns(values: &[i64], ports: &[Port]) -> Vec<u64> {
    values.iter().zip(ports).map(|(&v, p)| crate::fixed::to_pattern(v, p.bits)).collect()
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

/// The values a vector's bit patterns stand for (sign-extended for signed ports), in port order.
pub fn from_patterns(patterns: &[u64], ports: &[Port]) -> Vec<i64> {
    patterns.iter().zip(ports).map(|(&p, port)| crate::fixed::from_pattern(p, port.bits, port.signed)).collect()
}
