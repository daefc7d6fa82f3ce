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
//! - a unit that takes a vector every k clocks at most (`StreamUnit::INTERVAL`, a k-clock variant) gets one: after
//!   a beat taken (of either stream) `s_axis_tready` is low for k − 1 clocks;
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
//!
//! **A unit with a map write port** (`StreamUnit::MAP`: the texture unit's maps, `height_fetch`'s height map) goes
//! behind `AxisMap`, whose writes come on a second AXI4-Stream slave, `s_axis_map_*`: its TDATA packs the write's
//! address and data ports (in port order, the first in the low bits), its tvalid is the write enable, and
//! `s_axis_tdata` packs the other inputs. A write gives no output beat (`AxisMapCtl` marks it through the unit's
//! latency and drops its output), so it holds no FIFO place. The map stream is ready when a pixel would be taken (out
//! of reset and its flush, a FIFO place free), and it goes first: `s_axis_tready` is low in a clock where
//! `s_axis_map_tvalid` is high (a ready may wait on a valid; no valid waits on a ready). The two streams are not ordered against each other: a
//! source that needs a map written before a pixel reads it sends the pixel once the write is taken (the benches send
//! one row of the golden file at a time, in its order). A reset drops the output beats in flight, not the writes
//! taken before it. `palette_lookup` keeps its write in the pixel beat: each of its beats reads this frame's table
//! and writes the next frame's, and gives its output.

use crate::prim::delay::Delay;
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
        /// a beat offered on another stream (`AxisMapCtl`'s map write), taken whenever this one is ready: it
        /// paces as a beat does (the offer, not the take, comes in: a take made outside from `s_ready` would
        /// come back in as a loop through this block)
        pub other_valid: Signal<In, Bit>,
        /// clocks left before the unit takes its next vector, 0 ..= INTERVAL − 1 (a unit taking one a clock: 0)
        gap: DFF<Bits<C>>,
        gap_len: Constant<Bits<C>>,
        w_gap: Signal<Local, Bit>,
        w_other: Signal<Local, Bit>,
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
    /// A FIFO of `depth` places (≤ 2^A) behind a unit of `latency` clocks that takes a vector every `interval`
    /// clocks at most (`StreamUnit::INTERVAL`).
    pub fn new(depth: usize, latency: usize, interval: usize) -> Self {
        assert!(C == A + 1, "AxisCtl: C = A + 1 (A = {A}, C = {C})");
        assert!((1..=1 << A).contains(&depth), "AxisCtl: depth {depth} does not fit 2^{A} places");
        assert!(latency < 1 << C, "AxisCtl: latency {latency} does not fit {C} bits");
        assert!((1..=latency.max(1)).contains(&interval), "AxisCtl: interval {interval} past latency {latency}");
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
            other_valid: Default::default(),
            gap: Default::default(),
            gap_len: Constant::new(Bits::<C>::from(interval as u64 - 1)),
            w_gap: Default::default(),
            w_other: Default::default(),
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
        dff_setup!(self, clock, wp, rp, count, held, flush, gap, byp, byp_data);
        self.ram.read_clock.next = self.clock.val();
        self.ram.write_clock.next = self.clock.val();
        // the handshakes: each a function of registers and aresetn (none waits on the other side's ready)
        self.w_run.next = self.aresetn.val();
        self.w_idle.next = self.flush.q.val() == 0;
        // a unit that takes a vector every INTERVAL clocks: none while the gap after the last one runs
        self.w_gap.next = self.gap.q.val().any();
        self.w_ready.next =
            self.w_run.val() & self.w_idle.val() & (self.held.q.val() != self.full.val()) & !self.w_gap.val();
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
        self.gap.d.next = self.gap.q.val();
        if self.w_gap.val() {
            self.gap.d.next = self.gap.q.val() - 1; // > 0 here: no wrap
        }
        self.w_other.next = self.w_ready.val() & self.other_valid.val();
        if self.w_take.val() | self.w_other.val() {
            self.gap.d.next = self.gap_len.val();
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
            self.gap.d.next = 0.into();
        }
    }
}

crate::block! {
    /// `AxisCtl` with a unit's map write port beside it, for `AxisMap`: both streams are ready when a pixel would be
    /// taken, the map stream goes first, and `marks` follows each write through the unit's `L` clocks so that its
    /// output never reaches the FIFO (a write holds no FIFO place).
    pub struct AxisMapCtl<const W: usize, const A: usize, const C: usize, const L: usize> {
        pub clock: Signal<In, Clock>,
        pub aresetn: Signal<In, Bit>,
        pub s_valid: Signal<In, Bit>,
        pub s_ready: Signal<Out, Bit>,
        /// the map stream's valid and ready
        pub map_valid: Signal<In, Bit>,
        pub map_ready: Signal<Out, Bit>,
        /// a beat of either stream taken this clock: the unit's valid_in; `we`, the beat is a write
        pub accept: Signal<Out, Bit>,
        pub we: Signal<Out, Bit>,
        pub push: Signal<In, Bit>,
        pub push_data: Signal<In, Bits<W>>,
        pub m_ready: Signal<In, Bit>,
        pub m_valid: Signal<Out, Bit>,
        pub m_data: Signal<Out, Bits<W>>,
        pub fifo: AxisCtl<W, A, C>,
        /// the writes inside the unit, a bit a clock
        marks: Delay<Bit, L>,
        w_write: Signal<Local, Bit>,
    }
}

impl<const W: usize, const A: usize, const C: usize, const L: usize> AxisMapCtl<W, A, C, L> {
    /// As `AxisCtl::new`, for a unit of latency `L`.
    pub fn new(depth: usize, interval: usize) -> Self {
        Self {
            clock: Default::default(),
            aresetn: Default::default(),
            s_valid: Default::default(),
            s_ready: Default::default(),
            map_valid: Default::default(),
            map_ready: Default::default(),
            accept: Default::default(),
            we: Default::default(),
            push: Default::default(),
            push_data: Default::default(),
            m_ready: Default::default(),
            m_valid: Default::default(),
            m_data: Default::default(),
            fifo: AxisCtl::new(depth, L, interval),
            marks: Default::default(),
            w_write: Default::default(),
        }
    }
}

impl<const W: usize, const A: usize, const C: usize, const L: usize> Logic for AxisMapCtl<W, A, C, L> {
    #[hdl_gen]
    fn update(&mut self) {
        self.fifo.clock.next = self.clock.val();
        self.marks.clock.next = self.clock.val();
        self.fifo.aresetn.next = self.aresetn.val();
        self.fifo.m_ready.next = self.m_ready.val();
        // a write is taken when a pixel would be (no valid waits on it); a pixel waits while a write is offered
        self.w_write.next = self.fifo.s_ready.val() & self.map_valid.val();
        self.map_ready.next = self.fifo.s_ready.val();
        self.s_ready.next = self.fifo.s_ready.val() & !self.map_valid.val();
        self.fifo.s_valid.next = self.s_valid.val() & !self.map_valid.val();
        self.accept.next = self.fifo.accept.val() | self.w_write.val();
        self.fifo.other_valid.next = self.map_valid.val(); // a write is a vector of the unit's too
        self.we.next = self.w_write.val();
        // a write's output is dropped: the mark that went in with it comes out beside it
        self.marks.d.next = self.w_write.val();
        self.fifo.push.next = self.push.val() & !self.marks.q.val();
        self.fifo.push_data.next = self.push_data.val();
        self.m_valid.next = self.fifo.m_valid.val();
        self.m_data.next = self.fifo.m_data.val();
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

crate::block! {
    /// A unit `U` with a map write port (`StreamUnit::MAP`) behind AXI4-Stream: the pixel stream `s_axis_*` (IW
    /// bits: the inputs but the write port's), the map stream `s_axis_map_*` (MW bits: the write's address and data;
    /// its valid is the enable), the output stream `m_axis_*`. A write beat gives no output beat. `axis_map_of!(Unit)`
    /// names the type.
    pub struct AxisMap<U: StreamUnit, const IW: usize, const MW: usize, const OW: usize, const A: usize, const C: usize, const L: usize> {
        pub aclk: Signal<In, Clock>,
        pub aresetn: Signal<In, Bit>,
        pub s_axis_tdata: Signal<In, Bits<IW>>,
        pub s_axis_tvalid: Signal<In, Bit>,
        pub s_axis_tready: Signal<Out, Bit>,
        pub s_axis_map_tdata: Signal<In, Bits<MW>>,
        pub s_axis_map_tvalid: Signal<In, Bit>,
        pub s_axis_map_tready: Signal<Out, Bit>,
        pub m_axis_tdata: Signal<Out, Bits<OW>>,
        pub m_axis_tvalid: Signal<Out, Bit>,
        pub m_axis_tready: Signal<In, Bit>,
        pub uut: U,
        pub ctl: AxisMapCtl<OW, A, C, L>,
    }
}

/// Which stream carries input port `name` of a unit with write port `map`: 0 the pixel stream, 1 the map stream,
/// 2 neither (the write enable, which is the map stream's tvalid).
pub const fn stream_of(name: &str, map: &[&str]) -> usize {
    let mut k = 0;
    while k < map.len() {
        if same(name, map[k]) {
            return if k == 0 { 2 } else { 1 };
        }
        k += 1;
    }
    0
}

const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut k = 0;
    while k < a.len() {
        if a[k] != b[k] {
            return false;
        }
        k += 1;
    }
    true
}

/// TDATA bits of stream `stream` (0 pixels, 1 map: see `stream_of`) of a unit with write port `map`: its ports'
/// bits, in `ports` order, padded to whole bytes.
pub const fn stream_word(ports: &[(&str, usize)], map: &[&str], stream: usize) -> usize {
    let mut bits = 0;
    let mut k = 0;
    while k < ports.len() {
        if stream_of(ports[k].0, map) == stream {
            bits += ports[k].1;
        }
        k += 1;
    }
    bits.div_ceil(8) * 8
}

/// `AxisMap` for a concrete unit type with a map write port, its widths worked out.
#[macro_export]
macro_rules! axis_map_of {
    ($u:ty) => {
        $crate::axis::AxisMap<
            $u,
            { $crate::axis::stream_word(<$u as $crate::stream::StreamUnit>::INPUTS, <$u as $crate::stream::StreamUnit>::MAP, 0) },
            { $crate::axis::stream_word(<$u as $crate::stream::StreamUnit>::INPUTS, <$u as $crate::stream::StreamUnit>::MAP, 1) },
            { $crate::axis::word(<$u as $crate::stream::StreamUnit>::OUTPUTS) },
            { $crate::axis::addr_bits(<$u as $crate::stream::StreamUnit>::LATENCY) },
            { $crate::axis::addr_bits(<$u as $crate::stream::StreamUnit>::LATENCY) + 1 },
            { <$u as $crate::stream::StreamUnit>::LATENCY },
        >
    };
}

/// What the runner, the export and the report need of a wrapper, plain (`Axis`) or with a map stream (`AxisMap`).
pub trait AxisBlock: Block + Sized {
    type Unit: StreamUnit;
    /// The wrapper's own logic (its control and FIFO) at the depth it builds, to be synthesised alone.
    type Ctl: Block;
    /// The wrapper at the minimum depth for one beat a clock.
    fn build() -> Self {
        Self::with_depth(depth(Self::Unit::LATENCY))
    }
    /// The wrapper with a FIFO of `places` (a test's shallower one, to show the minimum is the minimum).
    fn with_depth(places: usize) -> Self;
    fn ctl() -> Self::Ctl;
    /// The output FIFO: its places, the RAM's words (2^A) and the word's bits (TDATA's).
    fn fifo() -> (usize, usize, usize);
    /// The exported module's name.
    fn name() -> String {
        format!("{}_axis", Self::Unit::NAME)
    }
    /// One clock's inputs with the clock low: `aresetn`, the row offered (the unit's input values) on the stream
    /// that carries it (a write on the map stream), or none, and the sink's tready.
    fn drive(&mut self, aresetn: bool, offer: Option<&[u64]>, m_ready: bool);
    /// The handshakes as they settled: the ready of the stream `row` goes on (`drive`'s), the other stream's ready
    /// (false for a wrapper with one), m_axis_tvalid and m_axis_tdata as the unit's output values.
    fn sample(&self, row: &[u64]) -> (bool, bool, bool, Vec<u64>);
    fn set_clock(&mut self, level: bool);
    /// Whether `row` gives an output beat (a map write gives none).
    fn emits(row: &[u64]) -> bool {
        write_row::<Self::Unit>(row).is_none()
    }
}

/// Where a map unit's write enable sits among its inputs, and whether `row` sets it: `None` for a row that is no
/// write (every row of a unit without a map port).
fn write_row<U: StreamUnit>(row: &[u64]) -> Option<usize> {
    let k = U::MAP.first().and_then(|we| U::INPUTS.iter().position(|p| p.0 == *we))?;
    (row[k] & 1 == 1).then_some(k)
}

/// The bits of one port of a packed word, from bit `at`, as a bit pattern (ports are at most 64 bits wide).
fn field<const N: usize>(w: Bits<N>, at: usize, width: usize) -> u64 {
    (0..width.min(64)).filter(|b| w.get_bit(at + b)).fold(0, |v, b| v | 1 << b)
}

/// `values` of `ports` packed into a word, the first in the low bits.
fn pack<'a, const N: usize>(ports: impl Iterator<Item = &'a (&'a str, usize)>, values: &[u64]) -> Bits<N> {
    // gathered in 64-bit words, then made Bits a word at a time: a wide Bits is an array of bits, and setting them
    // one by one copies the array for each
    let mut words = vec![0u64; N.div_ceil(64)];
    let mut at = 0;
    for (&(_, width), &v) in ports.zip(values) {
        let v = if width < 64 { v & ((1 << width) - 1) } else { v };
        words[at / 64] |= v << (at % 64);
        if at % 64 + width.min(64) > 64 {
            words[at / 64 + 1] |= v >> (64 - at % 64);
        }
        at += width;
    }
    words.iter().enumerate().fold(Bits::<N>::default(), |w, (k, &x)| w | Bits::<N>::from(x) << (64 * k) as u64)
}

/// The values of `ports` unpacked from `word`, the first from the low bits.
fn unpack<const N: usize>(ports: &[(&str, usize)], word: Bits<N>) -> Vec<u64> {
    let mut at = 0;
    ports
        .iter()
        .map(|&(_, w)| {
            at += w;
            field(word, at - w, w)
        })
        .collect()
}

/// The unit's inputs from the two streams' words (a plain wrapper's pixel word holds them all) and the enable.
fn unit_inputs<U: StreamUnit, const IW: usize, const MW: usize>(pixels: Bits<IW>, map: Bits<MW>, we: bool) -> Vec<u64> {
    let (mut p, mut m) = (0, 0);
    U::INPUTS
        .iter()
        .map(|&(n, w)| match stream_of(n, U::MAP) {
            0 => {
                p += w;
                field(pixels, p - w, w)
            }
            1 => {
                m += w;
                field(map, m - w, w)
            }
            _ => u64::from(we),
        })
        .collect()
}

/// The Verilog of the wrapper's wiring (the same as `update`'s, written for the export): the unit's `inputs` from the
/// streams' words (`map`: its map write port's), its `outputs` packed into the FIFO's word of `ow` bits, the
/// control's ports. Not generic over the unit, so compiled once rather than once a unit.
fn wiring(inputs: &[(&str, usize)], outputs: &[(&str, usize)], map: &[&str], ow: usize) -> Verilog {
    let mut v = vec![
        "uut$clock = aclk;".to_string(),
        "ctl$clock = aclk;".into(),
        "ctl$aresetn = aresetn;".into(),
        "ctl$s_valid = s_axis_tvalid;".into(),
        "ctl$m_ready = m_axis_tready;".into(),
        "uut$valid_in = ctl$accept;".into(),
    ];
    if map.is_empty() {
        v.push("ctl$other_valid = 1'b0;".into());
    } else {
        v.push("ctl$map_valid = s_axis_map_tvalid;".into());
    }
    let (mut p, mut m) = (0, 0);
    for (n, w) in inputs {
        match stream_of(n, map) {
            0 => {
                v.push(format!("uut${n} = s_axis_tdata[{}:{p}];", p + w - 1));
                p += w;
            }
            1 => {
                v.push(format!("uut${n} = s_axis_map_tdata[{}:{m}];", m + w - 1));
                m += w;
            }
            _ => v.push(format!("uut${n} = ctl$we;")),
        }
    }
    v.push("ctl$push = uut$valid_out;".into());
    let bits: usize = outputs.iter().map(|p| p.1).sum();
    let mut parts: Vec<String> = outputs.iter().rev().map(|(n, _)| format!("uut${n}")).collect();
    if ow > bits {
        parts.insert(0, format!("{}'b0", ow - bits));
    }
    v.push(format!("ctl$push_data = {{{}}};", parts.join(", ")));
    v.push("s_axis_tready = ctl$s_ready;".into());
    if !map.is_empty() {
        v.push("s_axis_map_tready = ctl$map_ready;".into());
    }
    v.push("m_axis_tvalid = ctl$m_valid;".into());
    v.push("m_axis_tdata = ctl$m_data;".into());
    Verilog::Custom(format!("always @(*) begin\n    {}\nend\n", v.join("\n    ")))
}

impl<U: StreamUnit, const IW: usize, const OW: usize, const A: usize, const C: usize> AxisBlock
    for Axis<U, IW, OW, A, C>
{
    type Unit = U;
    type Ctl = AxisCtl<OW, A, C>;
    fn with_depth(places: usize) -> Self {
        assert!(U::MAP.is_empty(), "{}: a unit with a map write port goes behind AxisMap (axis_map_of!)", U::NAME);
        assert_eq!(IW, word(U::INPUTS), "{}: s_axis_tdata is {IW} bits, the inputs {}", U::NAME, word(U::INPUTS));
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
            ctl: AxisCtl::new(places, U::LATENCY, U::INTERVAL),
        }
    }
    fn ctl() -> Self::Ctl {
        AxisCtl::new(depth(U::LATENCY), U::LATENCY, U::INTERVAL)
    }
    fn fifo() -> (usize, usize, usize) {
        (depth(U::LATENCY), 1 << A, OW)
    }
    fn drive(&mut self, aresetn: bool, offer: Option<&[u64]>, m_ready: bool) {
        self.aresetn.next = aresetn;
        self.s_axis_tvalid.next = offer.is_some();
        self.s_axis_tdata.next = offer.map_or_else(Bits::default, |row| pack(U::INPUTS.iter(), row));
        self.m_axis_tready.next = m_ready;
    }
    fn sample(&self, _row: &[u64]) -> (bool, bool, bool, Vec<u64>) {
        let out = unpack(U::OUTPUTS, self.m_axis_tdata.val());
        (self.s_axis_tready.val(), false, self.m_axis_tvalid.val(), out)
    }
    fn set_clock(&mut self, level: bool) {
        self.aclk.next = Clock { clk: level };
    }
}

impl<
        U: StreamUnit,
        const IW: usize,
        const MW: usize,
        const OW: usize,
        const A: usize,
        const C: usize,
        const L: usize,
    > AxisBlock for AxisMap<U, IW, MW, OW, A, C, L>
{
    type Unit = U;
    type Ctl = AxisMapCtl<OW, A, C, L>;
    fn with_depth(places: usize) -> Self {
        let we = U::MAP.first().and_then(|we| U::INPUTS.iter().find(|p| p.0 == *we));
        assert!(matches!(we, Some((_, 1))), "{}: a map port's first port is its one-bit enable", U::NAME);
        assert!(U::MAP.iter().all(|m| U::INPUTS.iter().any(|p| p.0 == *m)), "{}: a map port not an input", U::NAME);
        assert_eq!(L, U::LATENCY, "{}: the marks follow the unit's {} clocks, not {L}", U::NAME, U::LATENCY);
        assert_eq!(IW, stream_word(U::INPUTS, U::MAP, 0), "{}: s_axis_tdata is {IW} bits", U::NAME);
        assert_eq!(MW, stream_word(U::INPUTS, U::MAP, 1), "{}: s_axis_map_tdata is {MW} bits", U::NAME);
        assert_eq!(OW, word(U::OUTPUTS), "{}: m_axis_tdata is {OW} bits, the outputs {}", U::NAME, word(U::OUTPUTS));
        AxisMap {
            aclk: Default::default(),
            aresetn: Default::default(),
            s_axis_tdata: Default::default(),
            s_axis_tvalid: Default::default(),
            s_axis_tready: Default::default(),
            s_axis_map_tdata: Default::default(),
            s_axis_map_tvalid: Default::default(),
            s_axis_map_tready: Default::default(),
            m_axis_tdata: Default::default(),
            m_axis_tvalid: Default::default(),
            m_axis_tready: Default::default(),
            uut: U::build(),
            ctl: AxisMapCtl::new(places, U::INTERVAL),
        }
    }
    fn ctl() -> Self::Ctl {
        AxisMapCtl::new(depth(U::LATENCY), U::INTERVAL)
    }
    fn fifo() -> (usize, usize, usize) {
        (depth(U::LATENCY), 1 << A, OW)
    }
    fn drive(&mut self, aresetn: bool, offer: Option<&[u64]>, m_ready: bool) {
        let on = |stream: usize| U::INPUTS.iter().filter(move |p| stream_of(p.0, U::MAP) == stream);
        let pick = |row: &[u64], stream: usize| -> Vec<u64> {
            U::INPUTS.iter().zip(row).filter(|(p, _)| stream_of(p.0, U::MAP) == stream).map(|(_, &v)| v).collect()
        };
        let write = offer.is_some_and(|row| write_row::<U>(row).is_some());
        self.aresetn.next = aresetn;
        self.s_axis_tvalid.next = offer.is_some() && !write;
        self.s_axis_map_tvalid.next = write;
        self.s_axis_tdata.next = offer.filter(|_| !write).map_or_else(Bits::default, |r| pack(on(0), &pick(r, 0)));
        self.s_axis_map_tdata.next = offer.filter(|_| write).map_or_else(Bits::default, |r| pack(on(1), &pick(r, 1)));
        self.m_axis_tready.next = m_ready;
    }
    fn sample(&self, row: &[u64]) -> (bool, bool, bool, Vec<u64>) {
        let (s, map) = (self.s_axis_tready.val(), self.s_axis_map_tready.val());
        let out = unpack(U::OUTPUTS, self.m_axis_tdata.val());
        match write_row::<U>(row) {
            Some(_) => (map, s, self.m_axis_tvalid.val(), out),
            None => (s, map, self.m_axis_tvalid.val(), out),
        }
    }
    fn set_clock(&mut self, level: bool) {
        self.aclk.next = Clock { clk: level };
    }
}

impl<U: StreamUnit, const IW: usize, const OW: usize, const A: usize, const C: usize> Logic for Axis<U, IW, OW, A, C> {
    // Plain wiring, so written twice by hand: here for rust-hdl's simulation, in `wiring` for the Verilog. The tests
    // run the wrapper in both against the same vectors, as every block is.
    fn update(&mut self) {
        self.ctl.clock.next = self.aclk.val();
        self.uut.set_clock(self.aclk.val().clk);
        self.ctl.aresetn.next = self.aresetn.val();
        self.ctl.s_valid.next = self.s_axis_tvalid.val();
        self.ctl.m_ready.next = self.m_axis_tready.val();
        self.ctl.other_valid.next = false; // one stream
        let ins = unit_inputs::<U, IW, 8>(self.s_axis_tdata.val(), Bits::default(), false);
        self.uut.set_inputs(self.ctl.accept.val(), &ins);
        self.ctl.push.next = self.uut.valid_out();
        self.ctl.push_data.next = pack(U::OUTPUTS.iter(), &self.uut.outputs());
        self.s_axis_tready.next = self.ctl.s_ready.val();
        self.m_axis_tvalid.next = self.ctl.m_valid.val();
        self.m_axis_tdata.next = self.ctl.m_data.val();
    }

    fn connect(&mut self) {
        self.ctl.clock.connect();
        self.ctl.aresetn.connect();
        self.ctl.s_valid.connect();
        self.ctl.m_ready.connect();
        self.ctl.other_valid.connect();
        self.ctl.push.connect();
        self.ctl.push_data.connect();
        self.uut.connect_inputs();
        self.s_axis_tready.connect();
        self.m_axis_tvalid.connect();
        self.m_axis_tdata.connect();
    }

    fn hdl(&self) -> Verilog {
        wiring(U::INPUTS, U::OUTPUTS, U::MAP, OW)
    }
}

impl<
        U: StreamUnit,
        const IW: usize,
        const MW: usize,
        const OW: usize,
        const A: usize,
        const C: usize,
        const L: usize,
    > Logic for AxisMap<U, IW, MW, OW, A, C, L>
{
    // as `Axis`'s: plain wiring, here for rust-hdl's simulation and in `wiring` for the Verilog
    fn update(&mut self) {
        self.ctl.clock.next = self.aclk.val();
        self.uut.set_clock(self.aclk.val().clk);
        self.ctl.aresetn.next = self.aresetn.val();
        self.ctl.s_valid.next = self.s_axis_tvalid.val();
        self.ctl.map_valid.next = self.s_axis_map_tvalid.val();
        self.ctl.m_ready.next = self.m_axis_tready.val();
        let ins = unit_inputs::<U, IW, MW>(self.s_axis_tdata.val(), self.s_axis_map_tdata.val(), self.ctl.we.val());
        self.uut.set_inputs(self.ctl.accept.val(), &ins);
        self.ctl.push.next = self.uut.valid_out();
        self.ctl.push_data.next = pack(U::OUTPUTS.iter(), &self.uut.outputs());
        self.s_axis_tready.next = self.ctl.s_ready.val();
        self.s_axis_map_tready.next = self.ctl.map_ready.val();
        self.m_axis_tvalid.next = self.ctl.m_valid.val();
        self.m_axis_tdata.next = self.ctl.m_data.val();
    }

    fn connect(&mut self) {
        self.ctl.clock.connect();
        self.ctl.aresetn.connect();
        self.ctl.s_valid.connect();
        self.ctl.map_valid.connect();
        self.ctl.m_ready.connect();
        self.ctl.push.connect();
        self.ctl.push_data.connect();
        self.uut.connect_inputs();
        self.s_axis_tready.connect();
        self.s_axis_map_tready.connect();
        self.m_axis_tvalid.connect();
        self.m_axis_tdata.connect();
    }

    fn hdl(&self) -> Verilog {
        wiring(U::INPUTS, U::OUTPUTS, U::MAP, OW)
    }
}

/// What one clock of the wrapper did: the handshakes at its edge, read once the inputs had settled with the clock
/// low (every one of them is a function of registers and the inputs, so this is what the edge sees).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Beat {
    /// the tready of the stream the row was offered on, and whether it went in (tvalid and tready)
    pub s_ready: bool,
    pub took: bool,
    /// the other input stream's tready (a map unit's), false for a wrapper with one input stream
    pub other_ready: bool,
    /// m_axis_tvalid, m_axis_tdata as the unit's output values, and whether the beat was taken
    pub m_valid: bool,
    pub m_data: Vec<u64>,
    pub gave: bool,
}

/// A wrapper clocked by a plain loop, as `stream::Runner` clocks a unit.
pub struct AxisRunner<W: AxisBlock> {
    pub uut: W,
    pub cycle: u64,
}

impl<W: AxisBlock> AxisRunner<W> {
    pub fn new(uut: W) -> Self {
        let mut r = AxisRunner { uut, cycle: 0 };
        r.uut.connect_all();
        r.uut.set_clock(false);
        r.uut.drive(true, None, false);
        r.settle();
        r
    }

    fn settle(&mut self) {
        assert!(simulate(&mut self.uut, 10_000), "{}: logic did not settle", W::name());
    }

    /// One clock: `aresetn`, the source's tvalid and its row (the unit's input values, on the stream that carries
    /// it), the sink's tready.
    pub fn step(&mut self, aresetn: bool, s_valid: bool, row: &[u64], m_ready: bool) -> Beat {
        self.uut.drive(aresetn, s_valid.then_some(row), m_ready);
        self.uut.set_clock(false);
        self.settle();
        let (s_ready, other_ready, m_valid, m_data) = self.uut.sample(row);
        self.uut.set_clock(true);
        self.settle();
        self.cycle += 1;
        Beat { s_ready, took: s_valid && s_ready, other_ready, m_valid, m_data, gave: m_valid && m_ready }
    }
}

/// A wrapper a testbench can clock, whatever its unit and widths.
pub trait AxisDut {
    fn name(&self) -> String;
    fn latency(&self) -> usize;
    fn step(&mut self, aresetn: bool, s_valid: bool, row: &[u64], m_ready: bool) -> Beat;
    /// Whether `row` gives an output beat (a map write gives none).
    fn emits(&self, row: &[u64]) -> bool;
}

impl<W: AxisBlock> AxisDut for AxisRunner<W> {
    fn name(&self) -> String {
        W::name()
    }
    fn latency(&self) -> usize {
        W::Unit::LATENCY
    }
    fn step(&mut self, aresetn: bool, s_valid: bool, row: &[u64], m_ready: bool) -> Beat {
        AxisRunner::step(self, aresetn, s_valid, row, m_ready)
    }
    fn emits(&self, row: &[u64]) -> bool {
        W::emits(row)
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
