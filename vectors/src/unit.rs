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
    /// from reset (`with_stream` makes it from the unit's `Machine`). `exact` is then the stream of that one vector.
    pub stream: Option<Stream>,
}

/// A unit with state as a machine: its state (`Default` is the state from reset) and one vector's step. The
/// stream model is its steps in order; a frame split across threads runs the prologue once and each run from a
/// copy of the state it left.
pub trait Machine: Clone + Send {
    /// One vector: its outputs, the state moved on.
    fn step(&mut self, v: &[i64]) -> Vec<i64>;
    /// One vector whose outputs nobody reads (a frame's prologue): the state moved on exactly as `step` moves it.
    fn load(&mut self, v: &[i64]) {
        self.step(v);
    }
}

/// A stateful unit's model over a stream, from reset: `run` vector by vector; `frame` the outputs of the vectors
/// after the first `prologue` ones into a flat buffer, on `threads` threads (`frame_on`).
#[derive(Clone, Copy)]
pub struct Stream {
    pub run: fn(&[Vec<i64>]) -> Vec<Vec<i64>>,
    pub frame: fn(&[Vec<i64>], usize, usize, &mut [i64]),
}

/// A machine over a whole stream from reset, vector by vector.
pub fn run_machine<M: Machine + Default>(inputs: &[Vec<i64>]) -> Vec<Vec<i64>> {
    let mut m = M::default();
    inputs.iter().map(|v| m.step(v)).collect()
}

/// A machine over a frame from reset: the first `prologue` vectors loaded (their outputs not made), then the rest
/// cut into `threads` runs of consecutive vectors, each on its own thread from a copy of the state the prologue
/// left, its outputs written one vector after another into its own part of `out` (as many values a vector as the
/// unit has outputs: no allocation is kept a vector, so the threads do not wait on the allocator). Sound for a frame
/// whose vectors after the prologue read the state and do not change what a later one reads (a frame's pixels);
/// the tests hold every pipeline's split frame to its one-thread stream.
pub fn frame_on<M: Machine + Default>(inputs: &[Vec<i64>], prologue: usize, threads: usize, out: &mut [i64]) {
    frame_from(M::default(), inputs, prologue, threads, out)
}

fn frame_from<M: Machine>(mut m: M, inputs: &[Vec<i64>], prologue: usize, threads: usize, out: &mut [i64]) {
    let (head, body) = inputs.split_at(prologue.min(inputs.len()));
    for v in head {
        m.load(v);
    }
    if body.is_empty() {
        return;
    }
    let width = out.len() / body.len();
    assert!(width > 0 && out.len() == body.len() * width, "{} outputs for {} vectors", out.len(), body.len());
    let per = body.len().div_ceil(threads.max(1));
    let run = |m: &mut M, vs: &[Vec<i64>], out: &mut [i64]| {
        for (v, o) in vs.iter().zip(out.chunks_exact_mut(width)) {
            o.copy_from_slice(&m.step(v));
        }
    };
    if per >= body.len() {
        return run(&mut m, body, out);
    }
    // the last run on this thread, the others on threads of their own
    let mut runs: Vec<_> = body.chunks(per).zip(out.chunks_mut(per * width)).collect();
    let (vs, o) = runs.pop().expect("two runs or more");
    std::thread::scope(|s| {
        for (vs, o) in runs {
            let mut m = m.clone();
            s.spawn(move || run(&mut m, vs, o));
        }
        run(&mut m, vs, o);
    });
}

/// A unit without state as a machine: each vector through `exact`.
#[derive(Clone, Copy)]
struct Exact(fn(&[i64]) -> Vec<i64>);

impl Machine for Exact {
    fn step(&mut self, v: &[i64]) -> Vec<i64> {
        (self.0)(v)
    }
    fn load(&mut self, _: &[i64]) {}
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

    /// A unit with state: its model over a stream is machine `M`'s steps from reset.
    pub const fn with_stream<M: Machine + Default>(self) -> UnitModel {
        UnitModel { stream: Some(Stream { run: run_machine::<M>, frame: frame_on::<M> }), ..self }
    }

    /// The model's outputs for a stream of vectors in order: vector by vector, or through the unit's state.
    pub fn run(&self, inputs: &[Vec<i64>]) -> Vec<Vec<i64>> {
        match self.stream {
            Some(s) => (s.run)(inputs),
            None => inputs.iter().map(|v| (self.exact)(v)).collect(),
        }
    }

    /// The model over a frame (`frame_on`): the outputs of the vectors after the first `prologue`, which set up the
    /// unit's state, on `threads` threads, flat (`outputs.len()` values a vector, one vector after another); equal
    /// to `run`'s outputs after the prologue.
    pub fn frame(&self, inputs: &[Vec<i64>], prologue: usize, threads: usize) -> Vec<i64> {
        let mut out = vec![0; inputs.len().saturating_sub(prologue) * self.outputs.len()];
        match self.stream {
            Some(s) => (s.frame)(inputs, prologue, threads, &mut out),
            None => frame_from(Exact(self.exact), inputs, prologue, threads, &mut out),
        }
        out
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
