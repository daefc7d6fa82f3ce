//! The AXI4-Stream wrapper's driver and checker: a source that offers the model's vectors with random `tvalid` gaps
//! and holds each beat until it is taken, a sink that stalls `tready` at random (now and then for longer than the
//! unit's latency), an optional reset in the middle of the stream, and a checker of every output beat against the
//! model, in order, and of the rules every clock.

use rand::{Rng, SeedableRng};
use rtl::axis::AxisDut;
use vectors::UnitModel;

/// One pipeline of each family, and the seed of its random stream: the same stream in rust-hdl, Verilator and
/// Icarus.
pub const FAMILIES: [(&str, u64); 5] = [
    ("cart_pipeline", 21),
    ("polar_pipeline", 22),
    ("height_pipeline", 23),
    ("palette_pipeline", 24),
    ("cart_tex_trilinear_matte", 25),
];

/// How the source and the sink behave.
#[derive(Clone, Copy, Debug)]
pub struct Traffic {
    /// a gap (tvalid low) before a beat, one in `gap` (0: never)
    pub gap: u32,
    /// the sink stalls a clock, one in `stall` (0: never)
    pub stall: u32,
    /// a long stall, of up to 3 × the latency, one clock in `long` (0: never)
    pub long: u32,
    pub seed: u64,
}

impl Traffic {
    /// Every beat offered back to back, every output taken: the rate the unit keeps.
    pub const FULL: Traffic = Traffic { gap: 0, stall: 0, long: 0, seed: 0 };
    pub fn random(seed: u64) -> Traffic {
        Traffic { gap: 3, stall: 3, long: 40, seed }
    }
}

/// What the checker found.
#[derive(Debug, Default)]
pub struct AxisReport {
    pub vectors: usize,
    /// the output beats the stream must give: one a vector, none for a map write
    pub expected: usize,
    pub outputs: usize,
    pub mismatches: usize,
    /// clocks where a rule broke: tvalid dropped or tdata changed before the beat was taken, a valid during or
    /// after a reset before new input, an output past the last vector
    pub rule_breaks: usize,
    /// clocks from the first beat in to the last beat out, in the stream after any reset
    pub clocks: u64,
    /// clocks in which the source offered a beat and the wrapper did not take it
    pub refused: u64,
    pub first: Vec<String>,
}

impl AxisReport {
    pub fn assert_clean(&self, what: &str) {
        assert!(
            self.mismatches == 0 && self.rule_breaks == 0 && self.outputs == self.expected,
            "{what}: {} vectors, {} outputs of {}, {} mismatches, {} broken rules; first: {:#?}",
            self.vectors,
            self.outputs,
            self.expected,
            self.mismatches,
            self.rule_breaks,
            self.first
        );
    }
    fn note(&mut self, s: String) {
        if self.first.len() < 6 {
            self.first.push(s);
        }
    }
}

/// A reset in the middle: after `after` clocks of the stream, `aresetn` low for `clocks` clocks; then the stream
/// starts again from its first vector (the beats in flight are dropped).
#[derive(Clone, Copy, Debug)]
pub struct Reset {
    pub after: u64,
    pub clocks: u64,
}

struct Sink {
    stall_left: u32,
}

/// The stream through the wrapper under `traffic`, checked; with `reset`, the stream is cut by it and sent again whole.
pub fn run(
    dut: &mut dyn AxisDut,
    model: &UnitModel,
    inputs: &[Vec<i64>],
    traffic: Traffic,
    reset: Option<Reset>,
) -> AxisReport {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(traffic.seed);
    let ins: Vec<Vec<u64>> = inputs.iter().map(|v| vectors::unit::to_patterns(v, model.inputs)).collect();
    // a map write gives no output beat
    let want: Vec<Vec<u64>> = (model.run(inputs).iter().zip(&ins))
        .filter(|(_, row)| dut.emits(row))
        .map(|(v, _)| vectors::unit::to_patterns(v, model.outputs))
        .collect();
    let mut r = AxisReport { vectors: inputs.len(), expected: want.len(), ..Default::default() };
    let latency = dut.latency();
    let zeros = vec![0u64; model.inputs.len()];
    let mut sink = Sink { stall_left: 0 };
    let ready = |rng: &mut rand_chacha::ChaCha8Rng, sink: &mut Sink| {
        if sink.stall_left > 0 {
            sink.stall_left -= 1;
            return false;
        }
        if traffic.long > 0 && rng.gen_range(0..traffic.long) == 0 {
            sink.stall_left = rng.gen_range(1..=3 * latency as u32);
            return false;
        }
        !(traffic.stall > 0 && rng.gen_range(0..traffic.stall) == 0)
    };
    // the previous clock's offer, for the rule that an offered beat stays until taken
    let mut held: Option<Vec<u64>> = None;
    let check = |r: &mut AxisReport, b: &rtl::axis::Beat, held: &mut Option<Vec<u64>>, clock: u64| {
        if let Some(h) = held.take() {
            if !b.m_valid {
                r.rule_breaks += 1;
                r.note(format!("clock {clock}: m_axis_tvalid fell before its beat was taken"));
            } else if b.m_data != h {
                r.rule_breaks += 1;
                r.note(format!("clock {clock}: m_axis_tdata changed from {h:?} to {:?} before it was taken", b.m_data));
            }
        }
        if b.m_valid && !b.gave {
            *held = Some(b.m_data.clone());
        }
    };
    let mut clock = 0u64;
    if let Some(cut) = reset {
        // the stream until the cut, its outputs checked as far as they go
        let (mut k, mut got, mut offering) = (0usize, 0usize, false);
        while clock < cut.after {
            if !offering && k < ins.len() {
                offering = !(traffic.gap > 0 && rng.gen_range(0..traffic.gap) == 0);
            }
            let m_ready = ready(&mut rng, &mut sink);
            let b = dut.step(true, offering, if offering { &ins[k] } else { &zeros }, m_ready);
            check(&mut r, &b, &mut held, clock);
            if b.took {
                k += 1;
                offering = false;
            }
            if b.gave {
                if want.get(got) != Some(&b.m_data) {
                    r.mismatches += 1;
                    r.note(format!("before the reset, output {got}: {:?}, model {:?}", b.m_data, want.get(got)));
                }
                got += 1;
            }
            clock += 1;
        }
        held = None;
        for _ in 0..cut.clocks {
            let b = dut.step(false, rng.gen_bool(0.5), &ins[0], rng.gen_bool(0.5));
            if b.m_valid || b.s_ready || b.other_ready {
                r.rule_breaks += 1;
                r.note(format!("clock {clock}: in reset, m_axis_tvalid {} and a tready {}", b.m_valid, b.s_ready));
            }
            clock += 1;
        }
        // no input: nothing may come out (the beats taken before the reset are gone)
        for _ in 0..latency + 4 {
            let b = dut.step(true, false, &zeros, rng.gen_bool(0.5));
            if b.m_valid {
                r.rule_breaks += 1;
                r.note(format!("clock {clock}: a beat came out after the reset with no new input"));
            }
            clock += 1;
        }
    }
    // the whole stream
    let (mut k, mut got, mut offering) = (0usize, 0usize, false);
    let (mut start, mut end) = (None, 0u64);
    let limit = clock + 40 * (ins.len() as u64 + latency as u64 + 8) + 100_000;
    while got < want.len() && clock < limit {
        if !offering && k < ins.len() {
            offering = !(traffic.gap > 0 && rng.gen_range(0..traffic.gap) == 0);
        }
        let m_ready = ready(&mut rng, &mut sink);
        let b = dut.step(true, offering, if offering { &ins[k] } else { &zeros }, m_ready);
        check(&mut r, &b, &mut held, clock);
        if offering && !b.took {
            r.refused += 1;
        }
        if b.took {
            start.get_or_insert(clock);
            k += 1;
            offering = false;
        }
        if b.gave {
            if want.get(got) != Some(&b.m_data) {
                r.mismatches += 1;
                r.note(format!("output {got}: {:?}, model {:?}", b.m_data, want.get(got)));
            }
            got += 1;
            end = clock;
        }
        clock += 1;
    }
    // a while longer, everything taken: nothing more may come out
    for _ in 0..latency + 4 {
        let b = dut.step(true, false, &zeros, true);
        if b.m_valid {
            r.rule_breaks += 1;
            r.note(format!("clock {clock}: a beat past the last vector"));
        }
        clock += 1;
    }
    r.outputs = got;
    r.clocks = start.map_or(0, |s| end + 1 - s);
    r
}
