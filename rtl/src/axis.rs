//! `Axis`: any unit behind AXI4-Stream, with back-pressure and a synchronous active-low reset, so it drops into a
//! valid/ready fabric (LiteX, Amaranth, an IP integrator's AXI interconnect) as it is.
//!
//! A unit is a pipeline that cannot stop: a beat taken in leaves `LATENCY` clocks later whatever the sink does. So
//! the wrapper takes a beat only when it has a place to put it: `AxisCtl` holds a FIFO of the unit's output words and
//! a count of the places **reserved** (words in the FIFO plus beats inside the unit); `s_axis_tready` is high while
//! that count is below the FIFO's depth. A beat reserves its place from the edge that takes it in (edge c) to the
//! edge that hands it out (c + LATENCY + 1, one edge after the FIFO is written), so one beat a clock needs a depth of
//! **LATENCY + 2** ([`depth`]): the minimum, and what `axis_of!` builds (a test shows one place fewer loses the rate).
//!
//! The rules it keeps (tested in rust-hdl, Verilator and Icarus under random `tvalid` gaps and `tready` stalls):
//! - `m_axis_tvalid` and `s_axis_tready` are functions of registers and `aresetn` only: no valid waits for a ready;
//! - a word offered on `m_axis_tdata` stays there, unchanged, until `m_axis_tready` takes it;
//! - no beat is lost, duplicated or reordered;
//! - on a clock edge with `aresetn` low the FIFO and the count empty, and for `LATENCY` clocks after it the wrapper
//!   takes nothing (`s_axis_tready` low) and drops what the unit still puts out, the beats taken before the reset,
//!   so it emits nothing until new input arrives. The unit itself has no reset (its registers hold data, and its
//!   valid chain empties in those clocks). While `aresetn` is low both `m_axis_tvalid` and `s_axis_tready` are low.
//!
//! The FIFO is a RAM of 2^A words with a synchronous read, read ahead: every clock it reads the word the next clock
//! offers (the head, or the one after it if this clock's word is taken); when that word is being written on the same
//! edge (the FIFO about to be empty) a register beside the RAM keeps it instead.
//!
//! `s_axis_tdata` packs the unit's inputs as the exported `<unit>_in.hex` words do (the first input port in the low
//! bits), `m_axis_tdata` its outputs as `<unit>_out.hex`; each is padded with zeros at the top to a whole number of
//! bytes, as AXI4-Stream's TDATA is (the input's pad bits are ignored).

use crate::stream::StreamUnit;
use rust_hdl::prelude::*;

/// A port list's bits padded to whole bytes: the TDATA width.
pub const fn word(ports: &[(&str, usize)]) -> usize {
    let mut bits = 0;
    let mut k = 0;
    while k < ports.len() {
        bits += ports[k].1;
        k += 1;
    }
    bits.div_ceil(8) * 8
}

/// The FIFO depth that keeps one beat a clock behind a unit of this latency: LATENCY + 2 (see the module's text).
pub const fn depth(latency: usize) -> usize {
    latency + 2
}

/// Address bits of a FIFO of `depth(latency)` words: the smallest A with 2^A ≥ that depth.
pub const fn addr_bits(latency: usize) -> usize {
    let mut a = 0;
    while (1 << a) < depth(latency) {
        a += 1;
    }
    a
}

/// `Axis` for a concrete unit type, its widths worked out from the unit's ports and latency.
#[macro_export]
macro_rules! axis_of {
    ($u:ty) => {
        $crate::axis::Axis<
            $u,
            { $crate::axis::word(<$u as $crate::stream::StreamUnit>::INPUTS) },
            { $crate::axis::word(<$u as $crate::stream::StreamUnit>::OUTPUTS) },
            { $crate::axis::addr_bits(<$u as $crate::stream::StreamUnit>::LATENCY) },
            { $crate::axis::addr_bits(<$u as $crate::stream::StreamUnit>::LATENCY) + 1 },
        >
    };
}

crate::block! {
    /// The wrapper's control and output FIFO, for output words of W bits in 2^A places, counts in C = A + 1 bits.
    pub struct AxisCtl<const W: usize, const A: usize, const C: usize> {
        pub clock: Signal<In, Clock>,
        pub aresetn: Signal<In, Bit>,
        /// the source offers a beat
        pub s_valid: Signal<In, Bit>,
        /// the wrapper takes one
        pub s_ready: Signal<Out, Bit>,
        /// a beat taken this clock: the unit's valid_in
        pub accept: Signal<Out, Bit>,
        /// the unit's valid_out and its output word
        pub push: Signal<In, Bit>,
        pub push_data: Signal<In, Bits<W>>,
        /// the sink takes the word offered
        pub m_ready: Signal<In, Bit>,
        pub m_valid: Signal<Out, Bit>,
        pub m_data: Signal<Out, Bits<W>>,
        ram: RAM<Bits<W>, A>,
        /// write and read pointers, modulo 2^A
        wp: DFF<Bits<A>>,
        rp: DFF<Bits<A>>,
        /// words in the FIFO, 0 ..= depth
        count: DFF<Bits<C>>,
        /// places reserved: words in the FIFO and beats inside the unit, 0 ..= depth
        held: DFF<Bits<C>>,
        /// clocks left of the flush after a reset, 0 ..= LATENCY
        flush: DFF<Bits<C>>,
        /// the word offered next was written on the edge that read the RAM: kept here instead
        byp: DFF<Bit>,
        byp_data: DFF<Bits<W>>,
        full: Constant<Bits<C>>,
        flush_len: Constant<Bits<C>>,
        w_run: Signal<Local, Bit>,
        w_idle: Signal<Local, Bit>,
        w_ready: Signal<Local, Bit>,
        w_take: Signal<Local, Bit>,
        w_valid: Signal<Local, Bit>,
        w_pop: Signal<Local, Bit>,
        w_put: Signal<Local, Bit>,
        w_rp: Signal<Local, Bits<A>>,
        w_left: Signal<Local, Bits<C>>,
        w_count: Signal<Local, Bits<C>>,
        w_held: Signal<Local, Bits<C>>,
    }
}

impl<const W: usize, const A: usize, const C: usize> AxisCtl<W, A, C> {
    /// A FIFO of `depth` places (≤ 2^A) behind a unit of `latency` clocks.
    pub fn new(depth: usize, latency: usize) -> Self {
        assert!(C == A + 1, "AxisCtl: C = A + 1 (A = {A}, C = {C})");
        assert!((1..=1 << A).contains(&depth), "AxisCtl: depth {depth} does not fit 2^{A} places");
        assert!(latency < 1 << C, "AxisCtl: latency {latency} does not fit {C} bits");
        Self {
            clock: Default::default(),
            aresetn: Default::default(),
            s_valid: Default::default(),
            s_ready: Default::default(),
            accept: Default::default(),
            push: Default::default(),
            push_data: Default::default(),
            m_ready: Default::default(),
            m_valid: Default::default(),
            m_data: Default::default(),
            ram: Default::default(),
            wp: Default::default(),
            rp: Default::default(),
            count: Default::default(),
            held: Default::default(),
            flush: Default::default(),
            byp: Default::default(),
            byp_data: Default::default(),
            full: Constant::new(Bits::<C>::from(depth as u64)),
            flush_len: Constant::new(Bits::<C>::from(latency as u64)),
            w_run: Default::default(),
            w_idle: Default::default(),
            w_ready: Default::default(),
            w_take: Default::default(),
            w_valid: Default::default(),
            w_pop: Default::default(),
            w_put: Default::default(),
            w_rp: Default::default(),
            w_left: Default::default(),
            w_count: Default::default(),
            w_held: Default::default(),
        }
    }
}

impl<const W: usize, const A: usize, const C: usize> Logic for AxisCtl<W, A, C> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, wp, rp, count, held, flush, byp, byp_data);
        self.ram.read_clock.next = self.clock.val();
        self.ram.write_clock.next = self.clock.val();
        // the handshakes: each a function of registers and aresetn (none waits on the other side's ready)
        self.w_run.next = self.aresetn.val();
        self.w_idle.next = self.flush.q.val() == 0;
        self.w_ready.next = self.w_run.val() & self.w_idle.val() & (self.held.q.val() != self.full.val());
        self.w_take.next = self.w_ready.val() & self.s_valid.val();
        self.w_valid.next = self.w_run.val() & (self.count.q.val() != 0);
        self.w_pop.next = self.w_valid.val() & self.m_ready.val();
        // the unit's word goes in unless the flush after a reset is dropping the beats taken before it
        self.w_put.next = self.w_run.val() & self.w_idle.val() & self.push.val();
        self.s_ready.next = self.w_ready.val();
        self.accept.next = self.w_take.val();
        self.m_valid.next = self.w_valid.val();
        // the FIFO: written at wp, read ahead at the word the next clock offers
        self.ram.write_enable.next = self.w_put.val();
        self.ram.write_address.next = self.wp.q.val();
        self.ram.write_data.next = self.push_data.val();
        self.w_rp.next = self.rp.q.val();
        if self.w_pop.val() {
            self.w_rp.next = self.rp.q.val() + 1; // modulo 2^A: a ring
        }
        self.ram.read_address.next = self.w_rp.val();
        // words left once this clock's is taken, count − pop: pop only when count ≥ 1, so ≥ 0, exact
        self.w_left.next = self.count.q.val();
        if self.w_pop.val() {
            self.w_left.next = self.count.q.val() - 1; // ≥ 0: exact
        }
        self.byp.d.next = self.w_put.val() & (self.w_left.val() == 0);
        self.byp_data.d.next = self.push_data.val();
        if self.byp.q.val() {
            self.m_data.next = self.byp_data.q.val();
        } else {
            self.m_data.next = self.ram.read_data.val();
        }
        // count − pop + put and held + take − pop stay in 0 ..= depth (< 2^C): exact
        self.w_count.next = self.w_left.val();
        if self.w_put.val() {
            self.w_count.next = self.w_left.val() + 1; // ≤ depth: exact
        }
        self.w_held.next = self.held.q.val();
        if self.w_take.val() {
            self.w_held.next = self.held.q.val() + 1; // ≤ depth: taken only below it, exact
        }
        self.wp.d.next = self.wp.q.val();
        if self.w_put.val() {
            self.wp.d.next = self.wp.q.val() + 1; // modulo 2^A: a ring
        }
        self.rp.d.next = self.w_rp.val();
        self.count.d.next = self.w_count.val();
        self.held.d.next = self.w_held.val();
        if self.w_pop.val() {
            self.held.d.next = self.w_held.val() - 1; // ≥ 0: a word handed out was held, exact
        }
        self.flush.d.next = self.flush.q.val();
        if !self.w_idle.val() {
            self.flush.d.next = self.flush.q.val() - 1; // > 0 here: no wrap
        }
        if !self.aresetn.val() {
            self.wp.d.next = 0.into();
            self.rp.d.next = 0.into();
            self.count.d.next = 0.into();
            self.held.d.next = 0.into();
            self.byp.d.next = false;
            self.flush.d.next = self.flush_len.val();
        }
    }
}

crate::block! {
    /// A unit `U` behind AXI4-Stream: TDATA of IW and OW bits (`word` of its ports), a FIFO of 2^A places, counts of
    /// C = A + 1 bits. `axis_of!(Unit)` names the type with its widths worked out.
    pub struct Axis<U: StreamUnit, const IW: usize, const OW: usize, const A: usize, const C: usize> {
        pub aclk: Signal<In, Clock>,
        pub aresetn: Signal<In, Bit>,
        pub s_axis_tdata: Signal<In, Bits<IW>>,
        pub s_axis_tvalid: Signal<In, Bit>,
        pub s_axis_tready: Signal<Out, Bit>,
        pub m_axis_tdata: Signal<Out, Bits<OW>>,
        pub m_axis_tvalid: Signal<Out, Bit>,
        pub m_axis_tready: Signal<In, Bit>,
        pub uut: U,
        pub ctl: AxisCtl<OW, A, C>,
    }
}

impl<U: StreamUnit, const IW: usize, const OW: usize, const A: usize, const C: usize> Axis<U, IW, OW, A, C> {
    /// The wrapper at the minimum depth for one beat a clock.
    pub fn build() -> Self {
        Self::with_depth(depth(U::LATENCY))
    }

    /// The wrapper with a FIFO of `places` (a test's shallower one, to show the minimum is the minimum).
    pub fn with_depth(places: usize) -> Self {
        assert_eq!(
            IW,
            word(U::INPUTS),
            "{}: s_axis_tdata is {IW} bits, the inputs pack into {}",
            U::NAME,
            word(U::INPUTS)
        );
        assert_eq!(OW, word(U::OUTPUTS), "{}: m_axis_tdata is {OW} bits, the outputs {}", U::NAME, word(U::OUTPUTS));
        Axis {
            aclk: Default::default(),
            aresetn: Default::default(),
            s_axis_tdata: Default::default(),
            s_axis_tvalid: Default::default(),
            s_axis_tready: Default::default(),
            m_axis_tdata: Default::default(),
            m_axis_tvalid: Default::default(),
            m_axis_tready: Default::default(),
            uut: U::build(),
            ctl: AxisCtl::new(places, U::LATENCY),
        }
    }

    /// The exported module's name.
    pub fn name() -> String {
        format!("{}_axis", U::NAME)
    }
}

/// The bits of one port of a packed word, from bit `at`, as a bit pattern (ports are at most 64 bits wide).
fn field<const N: usize>(w: Bits<N>, at: usize, width: usize) -> u64 {
    (0..width.min(64)).filter(|b| w.get_bit(at + b)).fold(0, |v, b| v | 1 << b)
}

impl<U: StreamUnit, const IW: usize, const OW: usize, const A: usize, const C: usize> Logic for Axis<U, IW, OW, A, C> {
    // Plain wiring, so written twice by hand: here for rust-hdl's simulation, in `hdl` for the Verilog. The tests run
    // the wrapper in both against the same vectors, as every block is.
    fn update(&mut self) {
        self.ctl.clock.next = self.aclk.val();
        self.uut.set_clock(self.aclk.val().clk);
        self.ctl.aresetn.next = self.aresetn.val();
        self.ctl.s_valid.next = self.s_axis_tvalid.val();
        self.ctl.m_ready.next = self.m_axis_tready.val();
        let word = self.s_axis_tdata.val();
        let mut at = 0;
        let ins: Vec<u64> = U::INPUTS
            .iter()
            .map(|&(_, w)| {
                at += w;
                field(word, at - w, w)
            })
            .collect();
        self.uut.set_inputs(self.ctl.accept.val(), &ins);
        self.ctl.push.next = self.uut.valid_out();
        let mut out = Bits::<OW>::default();
        let mut at = 0;
        for (&(_, w), v) in U::OUTPUTS.iter().zip(self.uut.outputs()) {
            for b in 0..w.min(64) {
                out = out.replace_bit(at + b, (v >> b) & 1 == 1);
            }
            at += w;
        }
        self.ctl.push_data.next = out;
        self.s_axis_tready.next = self.ctl.s_ready.val();
        self.m_axis_tvalid.next = self.ctl.m_valid.val();
        self.m_axis_tdata.next = self.ctl.m_data.val();
    }

    fn connect(&mut self) {
        self.ctl.clock.connect();
        self.ctl.aresetn.connect();
        self.ctl.s_valid.connect();
        self.ctl.m_ready.connect();
        self.ctl.push.connect();
        self.ctl.push_data.connect();
        self.uut.connect_inputs();
        self.s_axis_tready.connect();
        self.m_axis_tvalid.connect();
        self.m_axis_tdata.connect();
    }

    fn hdl(&self) -> Verilog {
        let mut v = vec![
            "uut$clock = aclk;".to_string(),
            "ctl$clock = aclk;".into(),
            "ctl$aresetn = aresetn;".into(),
            "ctl$s_valid = s_axis_tvalid;".into(),
            "ctl$m_ready = m_axis_tready;".into(),
            "uut$valid_in = ctl$accept;".into(),
        ];
        let mut at = 0;
        for (n, w) in U::INPUTS {
            v.push(format!("uut${n} = s_axis_tdata[{}:{at}];", at + w - 1));
            at += w;
        }
        v.push("ctl$push = uut$valid_out;".into());
        let bits: usize = U::OUTPUTS.iter().map(|p| p.1).sum();
        let mut parts: Vec<String> = U::OUTPUTS.iter().rev().map(|(n, _)| format!("uut${n}")).collect();
        if OW > bits {
            parts.insert(0, format!("{}'b0", OW - bits));
        }
        v.push(format!("ctl$push_data = {{{}}};", parts.join(", ")));
        v.push("s_axis_tready = ctl$s_ready;".into());
        v.push("m_axis_tvalid = ctl$m_valid;".into());
        v.push("m_axis_tdata = ctl$m_data;".into());
        Verilog::Custom(format!("always @(*) begin\n    {}\nend\n", v.join("\n    ")))
    }
}

/// What one clock of the wrapper did: the handshakes at its edge, read once the inputs had settled with the clock
/// low (every one of them is a function of registers and the inputs, so this is what the edge sees).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Beat {
    /// s_axis_tready, and whether a beat went in (tvalid and tready)
    pub s_ready: bool,
    pub took: bool,
    /// m_axis_tvalid, m_axis_tdata as the unit's output values, and whether the beat was taken
    pub m_valid: bool,
    pub m_data: Vec<u64>,
    pub gave: bool,
}

/// The wrapper clocked by a plain loop, as `stream::Runner` clocks a unit.
pub struct AxisRunner<U: StreamUnit, const IW: usize, const OW: usize, const A: usize, const C: usize> {
    pub uut: Axis<U, IW, OW, A, C>,
    pub cycle: u64,
}

impl<U: StreamUnit, const IW: usize, const OW: usize, const A: usize, const C: usize> AxisRunner<U, IW, OW, A, C> {
    pub fn new(uut: Axis<U, IW, OW, A, C>) -> Self {
        let mut r = AxisRunner { uut, cycle: 0 };
        r.uut.connect_all();
        r.uut.aclk.next = Clock { clk: false };
        r.uut.aresetn.next = true;
        r.settle();
        r
    }

    fn settle(&mut self) {
        assert!(simulate(&mut self.uut, 10_000), "{}: logic did not settle", Axis::<U, IW, OW, A, C>::name());
    }

    /// One clock: `aresetn`, the source's tvalid and its beat (the unit's input values), the sink's tready.
    pub fn step(&mut self, aresetn: bool, s_valid: bool, s_data: &[u64], m_ready: bool) -> Beat {
        let mut w = Bits::<IW>::default();
        let mut at = 0;
        for (&(_, width), v) in U::INPUTS.iter().zip(s_data) {
            for b in 0..width.min(64) {
                w = w.replace_bit(at + b, (v >> b) & 1 == 1);
            }
            at += width;
        }
        self.uut.aresetn.next = aresetn;
        self.uut.s_axis_tvalid.next = s_valid;
        self.uut.s_axis_tdata.next = w;
        self.uut.m_axis_tready.next = m_ready;
        self.uut.aclk.next = Clock { clk: false };
        self.settle();
        let word = self.uut.m_axis_tdata.val();
        let mut at = 0;
        let m_data = U::OUTPUTS
            .iter()
            .map(|&(_, width)| {
                at += width;
                field(word, at - width, width)
            })
            .collect();
        let (s_ready, m_valid) = (self.uut.s_axis_tready.val(), self.uut.m_axis_tvalid.val());
        self.uut.aclk.next = Clock { clk: true };
        self.settle();
        self.cycle += 1;
        Beat { s_ready, took: s_valid && s_ready, m_valid, m_data, gave: m_valid && m_ready }
    }
}

/// A wrapper a testbench can clock, whatever its unit and widths.
pub trait AxisDut {
    fn name(&self) -> String;
    fn latency(&self) -> usize;
    fn step(&mut self, aresetn: bool, s_valid: bool, s_data: &[u64], m_ready: bool) -> Beat;
}

impl<U: StreamUnit, const IW: usize, const OW: usize, const A: usize, const C: usize> AxisDut
    for AxisRunner<U, IW, OW, A, C>
{
    fn name(&self) -> String {
        Axis::<U, IW, OW, A, C>::name()
    }
    fn latency(&self) -> usize {
        U::LATENCY
    }
    fn step(&mut self, aresetn: bool, s_valid: bool, s_data: &[u64], m_ready: bool) -> Beat {
        AxisRunner::step(self, aresetn, s_valid, s_data, m_ready)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tdata_is_whole_bytes_and_the_fifo_holds_latency_plus_two() {
        assert_eq!(word(&[("a", 3), ("b", 8)]), 16);
        assert_eq!(word(&[("a", 8), ("b", 8)]), 16);
        assert_eq!(word(&[("a", 1)]), 8);
        assert_eq!((depth(11), addr_bits(11)), (13, 4));
        assert_eq!((depth(14), addr_bits(14)), (16, 4));
        assert_eq!((depth(15), addr_bits(15)), (17, 5));
    }
}
