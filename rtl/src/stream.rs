//! The streaming interface every unit block implements, so that one driver, one monitor and one Verilog harness
//! serve them all. Values cross it as bit patterns (`u64`, two's complement for signed ports).

use rust_hdl::prelude::*;

pub trait StreamUnit: Block + Sized + crate::prim::declared::Declared {
    /// The unit's name, the same in every crate.
    const NAME: &'static str;
    /// Clock edges from an input vector to its output vector.
    const LATENCY: usize;
    /// Data input ports (name, width) in the order the model lists them.
    const INPUTS: &'static [(&'static str, usize)];
    /// Data output ports (name, width).
    const OUTPUTS: &'static [(&'static str, usize)];
    /// The memory write port, for a unit whose write beat only writes (its outputs are no one's): the enable (one
    /// bit) first, then the address and data ports, all among `INPUTS`. The AXI4-Stream wrapper takes it as a
    /// second stream (`axis::AxisMap`). Empty for every other unit.
    const MAP: &'static [&'static str] = &[];
    /// Clocks a vector takes: 1 for every unit that takes one a clock; k for a variant that takes k clocks a pixel
    /// to save area (`texture::front::TexTrilinearTwoPass`), which may be given a vector at most every k-th clock
    /// (the clocks between carry none, `valid_in` low; their data are not read). The harnesses and the AXI4-Stream
    /// wrapper keep that gap.
    const INTERVAL: usize = 1;
    /// The signals the block's Verilog leaves unused on purpose, each as `instance$port` with the reason: the
    /// exported `<unit>.vlt` waives them, and the lints hold every other warning an error. Empty for most units.
    fn waivers() -> Vec<Waiver> {
        vec![]
    }
    fn build() -> Self;
    fn set_clock(&mut self, level: bool);
    fn clock_level(&self) -> bool;
    fn set_inputs(&mut self, valid: bool, values: &[u64]);
    /// Mark the clock, valid and data inputs as driven, for a block that drives them from its own `update` (the
    /// AXI4-Stream wrapper).
    fn connect_inputs(&mut self);
    fn valid_out(&self) -> bool;
    fn outputs(&self) -> Vec<u64>;
}

/// A lint waiver: the signal as `instance$port`, and why the Verilog leaves it unused.
pub type Waiver = (&'static str, &'static str);

/// Lists of waivers as one: a part's list is written once for every block holding that part.
pub fn waivers(lists: &[&[Waiver]]) -> Vec<Waiver> {
    lists.concat()
}

/// Declares a unit's block once: its data ports, in the model's order (`in { name: Type, ... }`, then `out { ... }`),
/// then its inner fields; writes the struct with its clock and valid ports through `crate::block!` (so it is
/// `#[derive(LogicBlock)]` and `Declared`), and implements `StreamUnit` from the same list, so the harnesses' port
/// lists and widths cannot drift from the block. The unit's name is an expression (a const-generic block can name
/// each instance: `if DC { "a_dc" } else { "a" }`). After the latency, optionally: `map = PORTS` (`StreamUnit::MAP`),
/// `interval = K` (`StreamUnit::INTERVAL`), `waivers = LIST` (`StreamUnit::waivers`, a slice or a `Vec`).
/// ```ignore
/// stream_block! {
///     #[derive(Default)]
///     pub struct Gloss: unit("gloss", LATENCY) {
///         in {
///             conc: U8,
///             x: Uq0_10,
///         }
///         out {
///             p: Uq0_10,
///         }
///         s1_k: DFF<Uq6_3>, // inner fields as in any block
///     }
/// }
/// ```
#[macro_export]
macro_rules! stream_block {
    (
        $(#[$attr:meta])*
        pub struct $t:ident $(< $(const $g:ident : $gt:ty $(= $gd:literal)?),* >)?
            : unit($name:expr, $latency:expr $(, map = $map:expr)? $(, interval = $iv:expr)? $(, waivers = $w:expr)?) {
            in { $($i:ident : $it:ty),* $(,)? }
            out { $($o:ident : $ot:ty),* $(,)? }
            $($(#[$fa:meta])* $fv:vis $f:ident : $ft:ty),* $(,)?
        }
    ) => {
        $crate::block! {
            $(#[$attr])*
            pub struct $t $(< $(const $g: $gt $(= $gd)?),* >)? {
                pub clock: Signal<In, Clock>,
                pub valid_in: Signal<In, Bit>,
                $(pub $i: Signal<In, $it>,)*
                pub valid_out: Signal<Out, Bit>,
                $(pub $o: Signal<Out, $ot>,)*
                $($(#[$fa])* $fv $f: $ft,)*
            }
        }

        impl $(< $(const $g: $gt),* >)? $crate::stream::StreamUnit for $t $(< $($g),* >)? {
            const NAME: &'static str = $name;
            const LATENCY: usize = $latency;
            const INPUTS: &'static [(&'static str, usize)] = &[$((stringify!($i), <$it as Synth>::BITS)),*];
            const OUTPUTS: &'static [(&'static str, usize)] = &[$((stringify!($o), <$ot as Synth>::BITS)),*];
            $(const MAP: &'static [&'static str] = $map;)?
            $(const INTERVAL: usize = $iv;)?
            $(fn waivers() -> Vec<$crate::stream::Waiver> {
                $w.to_vec()
            })?
            fn build() -> Self {
                Self::default()
            }
            fn set_clock(&mut self, level: bool) {
                self.clock.next = Clock { clk: level };
            }
            fn clock_level(&self) -> bool {
                self.clock.val().clk
            }
            #[allow(unused_assignments)]
            fn set_inputs(&mut self, valid: bool, values: &[u64]) {
                self.valid_in.next = valid;
                let mut k = 0;
                $( self.$i.next = <$it>::from(values[k]); k += 1; )*
                debug_assert_eq!(k, values.len());
            }
            fn connect_inputs(&mut self) {
                self.clock.connect();
                self.valid_in.connect();
                $( self.$i.connect(); )*
            }
            fn valid_out(&self) -> bool {
                self.valid_out.val()
            }
            fn outputs(&self) -> Vec<u64> {
                vec![$( self.$o.val().to_u64() ),*]
            }
        }
    };
}

/// Input vectors (bit patterns) as a unit's clock slots: each followed by `INTERVAL − 1` empty slots, so a unit
/// that takes k clocks a vector gets one every k-th clock (one a clock for every other unit).
pub fn paced<U: StreamUnit>(vectors: impl IntoIterator<Item = Vec<u64>>) -> impl Iterator<Item = Option<Vec<u64>>> {
    vectors.into_iter().flat_map(|v| std::iter::once(Some(v)).chain(std::iter::repeat_n(None, U::INTERVAL - 1)))
}

/// One clocked run of a unit over a stream of (valid, values) slots: a plain loop calling rust-hdl's `simulate`
/// (no threads), optionally tracing every signal to a VCD. Inputs are applied with the clock low, the rising edge
/// is then simulated and the outputs sampled, so an input in slot `c` leaves in slot `c + LATENCY − 1`.
pub struct Runner<U: StreamUnit> {
    pub uut: U,
    cycle: u64,
    vcd: Option<rust_hdl::core::vcd_probe::VCDProbe<Guarded>>,
    sink: Option<Sink>,
}

type Sink = std::sync::Arc<std::sync::Mutex<(Box<dyn std::io::Write>, Option<std::io::Error>)>>;

/// The VCD's writer as rust-hdl sees it: rust-hdl unwraps every VCD write, so a full disk would panic inside it.
/// This writer never fails towards rust-hdl; it keeps the first error for `Runner::finish` to return, and writes
/// nothing after it.
pub struct Guarded(Sink);

impl std::io::Write for Guarded {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        let mut g = self.0.lock().unwrap_or_else(|e| e.into_inner());
        if g.1.is_none() {
            if let Err(e) = g.0.write_all(buf) {
                g.1 = Some(e);
            }
        }
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        let mut g = self.0.lock().unwrap_or_else(|e| e.into_inner());
        if g.1.is_none() {
            if let Err(e) = g.0.flush() {
                g.1 = Some(e);
            }
        }
        Ok(())
    }
}

/// What left the unit: the cycle each output vector was sampled in, and its values.
#[derive(Clone, Debug, Default)]
pub struct Collected {
    pub cycles: Vec<u64>,
    pub outputs: Vec<Vec<u64>>,
}

impl<U: StreamUnit> Runner<U> {
    pub fn new() -> Self {
        Self::with_vcd(None)
    }

    /// A runner that writes a VCD of every signal, one timestamp per clock phase (a 10 ns clock).
    pub fn with_vcd(out: Option<Box<dyn std::io::Write>>) -> Self {
        let mut uut = U::build();
        uut.connect_all();
        // one thread writes the VCD (the runner through rust-hdl's probe); the Arc shares it with `finish`
        #[allow(clippy::arc_with_non_send_sync)]
        let sink: Option<Sink> = out.map(|w| std::sync::Arc::new(std::sync::Mutex::new((w, None))));
        let vcd = sink.as_ref().map(|s| write_vcd_header(Guarded(s.clone()), &uut));
        let mut r = Runner { uut, cycle: 0, vcd, sink };
        r.uut.set_inputs(false, &vec![0; U::INPUTS.len()]);
        r.uut.set_clock(false);
        r.settle();
        if let Some(v) = r.vcd.take() {
            r.vcd = Some(write_vcd_dump(v, &r.uut));
        }
        r
    }

    fn settle(&mut self) {
        assert!(simulate(&mut self.uut, 10_000), "{}: logic did not settle", U::NAME);
    }

    fn trace(&mut self, t: u64) {
        if let Some(mut v) = self.vcd.take() {
            // cannot fail: `Guarded` keeps the error for `finish`
            let _ = v.timestamp(t);
            self.vcd = Some(write_vcd_change(v, &self.uut));
        }
    }

    /// One clock: apply a slot with the clock low, raise it, and return the output vector if one is valid.
    pub fn step(&mut self, valid: bool, values: &[u64]) -> Option<Vec<u64>> {
        self.step_probed(valid, values, None)
    }

    /// `step`, with `probe` shown every signal (as `uut.<field>…`) once the slot has settled with the clock low:
    /// then every register's d holds what the edge will latch and every wire what this slot makes of it.
    pub fn step_probed(
        &mut self,
        valid: bool,
        values: &[u64],
        probe: Option<&mut dyn rust_hdl::core::probe::Probe>,
    ) -> Option<Vec<u64>> {
        self.uut.set_inputs(valid, values);
        self.uut.set_clock(false);
        self.settle();
        if let Some(p) = probe {
            self.uut.accept("uut", p);
        }
        self.trace(self.cycle * 10_000);
        self.uut.set_clock(true);
        self.settle();
        self.trace(self.cycle * 10_000 + 5_000);
        self.cycle += 1;
        if self.uut.valid_out() {
            Some(self.uut.outputs())
        } else {
            None
        }
    }

    /// Feed a whole stream of slots (None = a bubble), then flush the pipeline; collect every valid output.
    pub fn run(&mut self, slots: impl IntoIterator<Item = Option<Vec<u64>>>) -> Collected {
        let zeros = vec![0u64; U::INPUTS.len()];
        let mut c = Collected::default();
        for s in slots {
            let out = match s {
                Some(v) => self.step(true, &v),
                None => self.step(false, &zeros),
            };
            if let Some(o) = out {
                c.cycles.push(self.cycle - 1);
                c.outputs.push(o);
            }
        }
        for _ in 0..U::LATENCY + 1 {
            if let Some(o) = self.step(false, &zeros) {
                c.cycles.push(self.cycle - 1);
                c.outputs.push(o);
            }
        }
        c
    }

    /// Close the VCD and flush it; Err carries the first write error, if any write failed.
    pub fn finish(mut self) -> std::io::Result<()> {
        drop(self.vcd.take());
        let Some(sink) = self.sink.take() else { return Ok(()) };
        let mut g = sink.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(e) = g.1.take() {
            return Err(e);
        }
        g.0.flush()
    }
}

impl<U: StreamUnit> Default for Runner<U> {
    fn default() -> Self {
        Self::new()
    }
}

/// The same stream through rust-hdl's own threaded `Simulation`: a clock thread and a testbench thread that pass the
/// circuit between them over channels, the way rust-hdl's examples test blocks. Slots are applied with the clock
/// low and outputs sampled after the rising edge, as `Runner` does, so both give the same `Collected`. Kept beside
/// the loop to measure the two (`cargo bench -p sim --bench simulators`).
pub fn run_threaded<U: StreamUnit + Send + 'static>(slots: Vec<Option<Vec<u64>>>) -> Result<Collected, String> {
    use std::sync::{Arc, Mutex};
    let n = slots.len();
    let slots = Arc::new(slots);
    let got = Arc::new(Mutex::new(Collected::default()));
    let mut sim = Simulation::<U>::new();
    sim.add_clock(5, |x: &mut Box<U>| {
        let level = x.clock_level();
        x.set_clock(!level)
    });
    let (feed, sink) = (slots.clone(), got.clone());
    sim.add_testbench(move |mut sim: Sim<U>| {
        let mut x = sim.init()?;
        let zeros = vec![0u64; U::INPUTS.len()];
        for cycle in 0..n + U::LATENCY + 1 {
            x = sim.watch(|u: &U| !u.clock_level(), x)?;
            match feed.get(cycle) {
                Some(Some(v)) => x.set_inputs(true, v),
                _ => x.set_inputs(false, &zeros),
            }
            x = sim.watch(|u: &U| u.clock_level(), x)?;
            if x.valid_out() {
                let mut c = sink.lock().expect("collector");
                c.cycles.push(cycle as u64);
                c.outputs.push(x.outputs());
            }
        }
        sim.done(x)
    });
    let mut uut = U::build();
    uut.connect_all();
    let max_time = 10 * (n + U::LATENCY + 4) as u64;
    sim.run(Box::new(uut), max_time).map_err(|e| format!("{}: rust-hdl Simulation failed: {e:?}", U::NAME))?;
    let c = got.lock().expect("collector").clone();
    Ok(c)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A writer that takes `room` bytes and then fails, as a full disk does.
    struct Full {
        room: usize,
    }

    impl std::io::Write for Full {
        fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
            if self.room == 0 {
                return Err(std::io::Error::new(std::io::ErrorKind::StorageFull, "no space left on device"));
            }
            let n = buf.len().min(self.room);
            self.room -= n;
            Ok(n)
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn a_failed_vcd_write_is_an_error_not_a_panic() {
        for room in [0, 100, 5_000] {
            let mut r = Runner::<crate::gloss::Gloss>::with_vcd(Some(Box::new(Full { room })));
            let got = r.run((0..64).map(|k| Some(vec![k % 256, (k * 16) % 1024])));
            assert_eq!(got.outputs.len(), 64, "the simulation runs on");
            let e = r.finish().expect_err("the VCD could not be written whole");
            assert_eq!(e.kind(), std::io::ErrorKind::StorageFull);
        }
        let mut r = Runner::<crate::gloss::Gloss>::with_vcd(Some(Box::new(Full { room: usize::MAX })));
        r.run((0..4).map(|k| Some(vec![k, k])));
        assert!(r.finish().is_ok());
    }
}
