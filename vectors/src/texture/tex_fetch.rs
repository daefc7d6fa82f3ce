//! `tex_fetch`: the texture unit's map memory and fetch (US 2004/0207631's [151]): a map of 16-bit texels (a
//! Cartesian bump texel's two bytes, or a colour) with its whole MIP chain, every level down to 1 × 1, in four
//! banks, so that one clock reads the four texels of any bilinear footprint.
//!
//! The layout, which the unit makes (a writer names a texel by its level and place, never by an address):
//! - the texels are 2×2-interleaved: texel (x, y) of a level sits in bank (x mod 2) + 2·(y mod 2), at word
//!   (y >> 1)·2^(m−1) + (x >> 1) of the level's part of the bank, for a level of side 2^m (m ≥ 1); the two
//!   columns and two rows of a footprint, adjacent (or the last and the first of a repeating level), have
//!   different parities, so its four texels are in four banks;
//! - the levels sit from the smallest up, so where a level starts does not depend on the map's size: the 1 × 1
//!   level at word 0 of bank 0, the level of side 2^m (m ≥ 1) at base(m) = 1 + (4^(m−1) − 1)/3 = 1, 2, 6, 22, 86,
//!   342, 1366 in every bank, each level taking 4^(m−1) words of each;
//! - levels up to side 2^7 (a 128 × 128 map and its chain: 5,462 words a bank, of the 8,192 of a 13-bit address);
//!   the largest side is the unit's parameter, 2^0 … 2^8: built for 2^8 (`Chain<8>`, `rtl`'s `TexFetch<_, 15, 8>`)
//!   a bank holds a 256 × 256 map's chain, 21,846 words of a 15-bit address, and a side log2 saturates at 8. Four
//!   banks of 2^15 16-bit words are more block RAM than the ECP5-45F has (108 DP16KD), so the pipelines are built
//!   for 2^7; the parameter is for a larger part;
//! - trilinear's two reads a clock split the chain by the parity of a level's side log2 (`Levels`): each half in a
//!   memory of its own with the same layout over the levels it holds; a write of a level a half does not hold is
//!   dropped there, and a read of one gives zeros.
//!
//! A vector either writes (`we` = 1: `wdata` into texel (wx, wy) of the level of side 2^w_log2; its outputs are
//! zero) or reads the footprint of columns x0, x1 and rows y0, y1 of the level of side 2^level_log2:
//! t00 = (x0, y0), t10 = (x1, y0), t01 = (x0, y1), t11 = (x1, y1). A side log2 above 7 is read as 7 and a
//! coordinate is taken modulo its level's side (its bits above the level's are ignored). The footprint's columns
//! must be equal or neighbours, as `tex_addr` gives them: each bank reads one texel, the bank of parity p the column
//! of x0 if x0 has parity p, else the column of x1 (so a second column of x0's parity but not x0 reads as x0), and
//! the rows likewise. A read sees every texel written by the vectors before it. The memory is stateful, so the
//! unit's model is a stream (`UnitModel::with_stream`); a lone vector reads an empty (zero) map, as rust-hdl's
//! simulation and the FPGA's block RAM (zero at configuration) do, where Icarus reads an unwritten word as x: the
//! vectors read only texels they have written.

use crate::unit::{run_machine, Accuracy, Machine, UnitModel};

crate::ports! {
    inputs: [
        level_log2: u 4, x0: u 8, x1: u 8, y0: u 8, y1: u 8, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    ],
    outputs: [
        t00: u 16, t10: u 16, t01: u 16, t11: u 16,
    ],
}

/// The largest level the memory holds: side 2^7.
pub const MAX_LOG_SIDE: i64 = 7;
/// A bank's address bits (2^13 = 8,192 words; the chain of a 2^7 map takes 5,462).
pub const ADDR_BITS: u32 = 13;

/// The levels a memory holds: the whole chain (one memory a map), or, for trilinear's two fetches a clock, the even
/// levels (0, 2, 4, 6) or the odd ones (1, 3, 5, 7): ⌊λ⌋ and the level it is blended with always differ by one, so
/// each is in a memory of its own and the pair costs one copy of the chain, not two (the parity split). Each holds
/// its levels as `All` does, smallest first: the even ones at 0, 1, 5, 69 (1,093 words a bank: 11 address bits),
/// the odd ones at 0, 1, 17, 273 (4,369 words: 13 bits).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Levels {
    #[default]
    All,
    Even,
    Odd,
}

impl Levels {
    /// Whether the memory holds the level of side 2^m (m ≤ 7).
    pub fn holds(self, m: i64) -> bool {
        match self {
            Levels::All => true,
            Levels::Even => m % 2 == 0,
            Levels::Odd => m % 2 == 1,
        }
    }

    /// Where the level of side 2^m starts in every bank: the words of the held levels below it (a level the memory
    /// does not hold is never placed: its writes are dropped and it reads as zeros).
    pub fn base(self, m: i64) -> i64 {
        let size = |k: i64| if k == 0 { 1 } else { 1i64 << (2 * (k - 1)) };
        (0..m).filter(|&j| self.holds(j)).map(size).sum()
    }

    /// A bank's address bits.
    pub fn addr_bits(self) -> u32 {
        self.addr_bits_up_to(MAX_LOG_SIDE)
    }

    /// A bank's address bits for a memory whose largest level has side 2^top: the fewest that hold the words of
    /// its levels (13, 11 and 13 for the whole chain, the even and the odd levels of a 128 × 128 map; 15, 15 and 13
    /// at 256 × 256).
    pub fn addr_bits_up_to(self, top: i64) -> u32 {
        let words = self.base(top + 1);
        (0..).find(|&b| words <= 1 << b).unwrap()
    }
}

/// Where the level of side 2^m starts in every bank.
pub fn base(m: i64) -> i64 {
    if m == 0 {
        0
    } else {
        1 + ((1i64 << (2 * (m - 1))) - 1) / 3
    }
}

/// Words of each bank the chain of a map of side 2^m takes (all its levels; the 1 × 1 level one word of bank 0).
pub fn words(m: i64) -> i64 {
    base(m) + if m == 0 { 1 } else { 1 << (2 * (m - 1)) }
}

/// The level's side log2 as the unit reads it (saturated to 7) and a coordinate modulo the level's side.
pub fn level(m: i64) -> i64 {
    m.min(MAX_LOG_SIDE)
}

pub fn wrap(c: i64, m: i64) -> i64 {
    c & ((1 << m) - 1)
}

/// (bank, word) of texel (x, y) of the level of side 2^m (x, y inside it).
pub fn place(x: i64, y: i64, m: i64) -> (usize, usize) {
    ((x & 1) as usize + 2 * (y & 1) as usize, (base(m) + ((y >> 1) << m >> 1) + (x >> 1)) as usize)
}

/// The four banks, word for word as the rtl holds them, the levels they hold, and the largest level's side log2
/// (`top`: the unit's own 7, or 8 for the 256 × 256 parameter, `rtl`'s `TexFetch<_, 15, 8>`).
#[derive(Clone)]
pub struct Memory {
    pub banks: [Vec<u16>; 4],
    pub levels: Levels,
    pub top: i64,
}

impl Default for Memory {
    fn default() -> Memory {
        Memory::holding(Levels::All)
    }
}

impl Memory {
    /// An empty (zero) memory holding these levels of a map up to 128 × 128.
    pub fn holding(levels: Levels) -> Memory {
        Memory::sized(levels, MAX_LOG_SIDE)
    }

    /// An empty (zero) memory holding these levels of a map up to side 2^top (top ≤ 8).
    pub fn sized(levels: Levels, top: i64) -> Memory {
        assert!((0..=8).contains(&top), "the memory holds sides up to 2^8, not 2^{top}");
        Memory { banks: std::array::from_fn(|_| vec![0; 1 << levels.addr_bits_up_to(top)]), levels, top }
    }

    /// (bank, word) of texel (x, y) of the level of side 2^m (inside it), in this memory's layout: `place` for the
    /// whole chain; the word taken modulo the banks' size.
    fn at(&self, x: i64, y: i64, m: i64) -> (usize, usize) {
        let (b, w) = place(x, y, m);
        let w = (w as i64 - base(m) + self.levels.base(m)) as usize;
        (b, w & ((1 << self.levels.addr_bits_up_to(self.top)) - 1))
    }

    /// A write of a level the memory does not hold writes nothing.
    pub fn write(&mut self, m: i64, x: i64, y: i64, texel: i64) {
        let m = m.min(self.top);
        if !self.levels.holds(m) {
            return;
        }
        let (b, w) = self.at(wrap(x, m), wrap(y, m), m);
        self.banks[b][w] = texel as u16;
    }

    /// The texel at (x, y) of the level of side 2^m (inside it).
    pub fn texel(&self, m: i64, x: i64, y: i64) -> i64 {
        let (b, w) = self.at(x, y, m);
        self.banks[b][w] as i64
    }

    /// The footprint t00, t10, t01, t11 as the banks read it: bank (p, q) reads column x0 if x0 mod 2 = p, else
    /// x1, and row y0 if y0 mod 2 = q, else y1; each output takes the word of its column's and row's bank.
    pub fn footprint(&self, m: i64, x: [i64; 2], y: [i64; 2]) -> [i64; 4] {
        let m = m.min(self.top);
        if !self.levels.holds(m) {
            return [0; 4]; // a level the memory does not hold reads as zeros
        }
        let (x, y) = (x.map(|c| wrap(c, m)), y.map(|c| wrap(c, m)));
        let col = |p: i64| if x[0] & 1 == p { x[0] } else { x[1] };
        let row = |q: i64| if y[0] & 1 == q { y[0] } else { y[1] };
        let read = |cx: i64, ry: i64| self.texel(m, col(cx & 1), row(ry & 1));
        [read(x[0], y[0]), read(x[1], y[0]), read(x[0], y[1]), read(x[1], y[1])]
    }
}

/// The write vector for texel (x, y) of the level of side 2^m.
pub fn write(m: i64, x: i64, y: i64, texel: i64) -> Vec<i64> {
    vec![0, 0, 0, 0, 0, 1, m, x, y, texel]
}

/// The read vector for a footprint.
pub fn read(m: i64, x: [i64; 2], y: [i64; 2]) -> Vec<i64> {
    vec![m, x[0], x[1], y[0], y[1], 0, 0, 0, 0, 0]
}

/// The write vectors that load a whole chain: every texel of every level of a map of side 2^m, `texel(level
/// side log2, x, y)` each.
pub fn load(m: i64, texel: impl Fn(i64, i64, i64) -> i64) -> Vec<Vec<i64>> {
    let mut v = vec![];
    for k in (0..=m).rev() {
        for y in 0..1 << k {
            for x in 0..1 << k {
                v.push(write(k, x, y, texel(k, x, y)));
            }
        }
    }
    v
}

/// The unit as a machine: a write vector writes its texel (outputs zero), a read vector reads its footprint.
impl Machine for Memory {
    fn step(&mut self, v: &[i64]) -> Vec<i64> {
        use input::*;
        if v[we] == 1 {
            self.write(v[w_log2], v[wx], v[wy], v[wdata]);
            vec![0; 4]
        } else {
            self.footprint(v[level_log2], [v[x0], v[x1]], [v[y0], v[y1]]).to_vec()
        }
    }
}

/// The unit built for maps up to side 2^L as a machine: `Chain<7>` is `Memory`'s default, `Chain<8>` the
/// 256 × 256 parameter.
#[derive(Clone)]
pub struct Chain<const L: i64>(pub Memory);

impl<const L: i64> Default for Chain<L> {
    fn default() -> Self {
        Chain(Memory::sized(Levels::All, L))
    }
}

impl<const L: i64> Machine for Chain<L> {
    fn step(&mut self, v: &[i64]) -> Vec<i64> {
        self.0.step(v)
    }
}

/// The unit over a stream of vectors, from an empty (zero) memory.
pub fn run(inputs: &[Vec<i64>]) -> Vec<Vec<i64>> {
    run_machine::<Memory>(inputs)
}

fn exact_ports(v: &[i64]) -> Vec<i64> {
    run(&[v.to_vec()]).remove(0)
}

/// A texel that shows a crossed wire, a wrong bank or a wrong level: distinct along rows and columns, each level
/// apart, both bytes used.
pub fn pattern(m: i64, x: i64, y: i64) -> i64 {
    ((x * 7 + y * 37 + (x * y) % 11 + m * 4099) * 2_654_435_761 % 65_521) & 0xffff
}

/// The levels the random vectors read and write: the chain of a 16 × 16 map.
const REGION_LOG2: i64 = 4;

/// A footprint of the level of side 2^m as `tex_addr` gives it: x1 the neighbour of x0 (modulo the side), or x0.
fn footprint_at(x: i64, y: i64, m: i64, second: bool) -> ([i64; 2], [i64; 2]) {
    let n = |c: i64| if second { (c + 1) & ((1 << m) - 1) } else { c };
    ([x, n(x)], [y, n(y)])
}

/// First the chain of a 16 × 16 map written (the random vectors' region), then every footprint of each of its
/// levels (every place, the seam included, with its neighbour and alone); the 128 × 128 level's corners and edges
/// after writing the texels they read; side log2 above 7, coordinates above the level's side, non-neighbour
/// columns; and a write followed at once by a read of that texel.
pub fn hard_cases() -> Vec<Vec<i64>> {
    hard_cases_with(MAX_LOG_SIDE)
}

/// The hard cases of the unit built for maps up to side 2^top.
pub fn hard_cases_with(top: i64) -> Vec<Vec<i64>> {
    let mut v = load(REGION_LOG2, pattern);
    for m in 0..=REGION_LOG2 {
        for y in 0..1 << m {
            for x in 0..1 << m {
                for second in [true, false] {
                    let (xs, ys) = footprint_at(x, y, m, second);
                    v.push(read(m, xs, ys));
                }
            }
        }
    }
    // the largest level: its corners and the middles of its edges, written first
    let last = (1 << top) - 1;
    let half = 1 << (top - 1);
    let mut reads = vec![];
    for (x, y) in [
        (last, last),
        (0, last),
        (last, 0),
        (0, 0),
        (half - 1, last),
        (last, half),
        (half, 0),
        (0, half - 1),
        (100 & last, 27 & last),
    ] {
        for second in [true, false] {
            let (xs, ys) = footprint_at(x, y, top, second);
            reads.push(read(top, xs, ys));
        }
    }
    let mut texels = std::collections::BTreeSet::new();
    for r in &reads {
        for &x in &r[1..3] {
            for &y in &r[3..5] {
                texels.insert((x, y));
            }
        }
    }
    for &(x, y) in &texels {
        v.push(write(top, x, y, pattern(top, x, y)));
    }
    v.extend(reads);
    // a side log2 past the memory (read as top), and its texels written the same way; coordinates past the level
    v.push(read(15, [last, 0], [last, 0]));
    // (200, 130) written at a side log2 past the memory's, so into its top level: at 128, (200 mod 128, 130 mod
    // 128) = (72, 2) of level 7, and the three beside it (every texel a read touches is written first: an unwritten
    // word is undefined in a simulator that models it so); at 256 (200, 130) itself
    v.push(write(9, 200, 130, 0xbeef));
    v.push(write(9, 201, 130, 0x0001));
    v.push(write(9, 200, 131, 0x8000));
    v.push(write(9, 201, 131, 0xffff));
    v.push(read(top, [200 & last, 201 & last], [130 & last, 131 & last]));
    v.push(read(3, [8 + 7, 16], [255, 0])); // level 3: (7, 0) and (7, 0)
                                            // columns that are not neighbours: the second of x0's parity reads as x0
    v.push(read(4, [2, 6], [5, 9]));
    v.push(read(4, [3, 8], [0, 15]));
    // a write, then at once a read of that texel, then a write over it and a read again
    v.push(write(2, 3, 1, 0x1234));
    v.push(read(2, [3, 0], [1, 2]));
    v.push(write(2, 3, 1, 0xfedc));
    v.push(read(2, [2, 3], [0, 1]));
    v
}

/// Reads (three in four) and writes inside the 16 × 16 chain the hard cases fill, so that a stream of them after
/// the hard cases reads only written texels; footprints as `tex_addr` gives them, one in eight any four coordinates.
fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    use rand::Rng;
    let m = rng.gen_range(0..=REGION_LOG2);
    let side = 1i64 << m;
    if rng.gen_range(0..4) == 0 {
        return write(m, rng.gen_range(0..side), rng.gen_range(0..side), rng.gen_range(0..=0xffff));
    }
    if rng.gen_range(0..8) == 0 {
        let mut c = || rng.gen_range(0..256);
        return read(m, [c(), c()], [c(), c()]);
    }
    let (xs, ys) = footprint_at(rng.gen_range(0..side), rng.gen_range(0..side), m, rng.gen_range(0..4) != 0);
    read(m, xs, ys)
}

/// A fetch has no arithmetic to be wrong by: counted over the hard cases' stream, each footprint texel against the
/// texel the stream wrote there, kept apart by (level, x, y) with no banks and no layout.
fn accuracy(_samples: usize, _seed: u64) -> Vec<Accuracy> {
    use input::*;
    let inputs = hard_cases();
    let got = run(&inputs);
    let mut plain = std::collections::HashMap::new();
    let mut s = crate::stats::ErrorStats::default();
    for (v, out) in inputs.iter().zip(&got) {
        let m = v[level_log2].min(MAX_LOG_SIDE);
        if v[we] == 1 {
            let k = v[w_log2].min(MAX_LOG_SIDE);
            plain.insert((k, wrap(v[wx], k), wrap(v[wy], k)), v[wdata]);
            continue;
        }
        let (xs, ys) = ([v[x0], v[x1]].map(|c| wrap(c, m)), [v[y0], v[y1]].map(|c| wrap(c, m)));
        // only the footprints the unit promises: columns and rows equal or neighbours
        let near = |c: [i64; 2]| c[0] == c[1] || (c[0] + 1) & ((1 << m) - 1) == c[1];
        if !near(xs) || !near(ys) {
            continue;
        }
        for (k, (x, y)) in [(xs[0], ys[0]), (xs[1], ys[0]), (xs[0], ys[1]), (xs[1], ys[1])].into_iter().enumerate() {
            let want = plain.get(&(m, x, y)).copied().unwrap_or(0);
            s.add((out[k] != want) as i64 as f64, || format!("{v:?}"));
        }
    }
    vec![Accuracy::new("texel differs from the one written there (0 or 1), hard cases' stream", s)]
}

pub static MODEL: UnitModel = UnitModel::new("tex_fetch", (INPUTS, OUTPUTS), exact_ports, random, hard_cases)
    .with_stream::<Memory>()
    .with_accuracy(accuracy);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_levels_sit_end_to_end_and_the_largest_chain_fits_the_banks() {
        assert_eq!((0..=8).map(base).collect::<Vec<_>>(), [0, 1, 2, 6, 22, 86, 342, 1366, 5462]);
        for m in 1..=8 {
            assert_eq!(base(m), words(m - 1), "level {m} starts where the smaller chain ends");
        }
        assert_eq!(words(MAX_LOG_SIDE), 5462);
        assert!(words(MAX_LOG_SIDE) <= 1 << ADDR_BITS);
        // every texel of the largest chain has a place of its own
        let mut seen = std::collections::HashSet::new();
        for m in 0..=MAX_LOG_SIDE {
            for y in 0..1 << m {
                for x in 0..1 << m {
                    assert!(seen.insert(place(x, y, m)), "({x}, {y}) of level {m}");
                }
            }
        }
        assert_eq!(seen.len(), (0..=MAX_LOG_SIDE).map(|m| 1usize << (2 * m)).sum::<usize>());
    }

    #[test]
    fn a_footprint_reads_the_texels_written_at_its_corners_every_level_and_seam() {
        let v = load(3, pattern);
        let mut mem = Memory::default();
        for w in &v {
            mem.write(w[6], w[7], w[8], w[9]);
        }
        for m in 0..=3 {
            let side = 1 << m;
            for y in 0..side {
                for x in 0..side {
                    let (xs, ys) = footprint_at(x, y, m, true);
                    let want =
                        [(xs[0], ys[0]), (xs[1], ys[0]), (xs[0], ys[1]), (xs[1], ys[1])].map(|(a, b)| pattern(m, a, b));
                    assert_eq!(mem.footprint(m, xs, ys), want, "({x}, {y}) of level {m}");
                }
            }
        }
    }

    #[test]
    fn the_vectors_read_only_texels_they_have_written() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        let mut v = hard_cases();
        v.extend((0..20_000).map(|_| random(&mut rng)));
        let mut written = std::collections::HashSet::new();
        for (k, i) in v.iter().enumerate() {
            if i[input::we] == 1 {
                let m = level(i[input::w_log2]);
                written.insert((m, wrap(i[input::wx], m), wrap(i[input::wy], m)));
                continue;
            }
            let m = level(i[input::level_log2]);
            for &x in &i[1..3] {
                for &y in &i[3..5] {
                    assert!(written.contains(&(m, wrap(x, m), wrap(y, m))), "vector {k} {i:?}");
                }
            }
        }
    }

    #[test]
    fn the_hard_cases_read_back_what_they_wrote() {
        let a = accuracy(0, 0);
        assert_eq!(a[0].stats.max, 0.0, "{}", a[0].stats.argmax);
        assert!(a[0].stats.count > 1000, "{}", a[0].stats.count);
    }

    /// The parity split's layouts: the levels each half holds start where the sizes of those below end (the 1 × 1
    /// level 1 word, side 2^m 4^(m−1)): even 0, 1 (after the 1 × 1), 5 (+4), 69 (+64), ending at 1,093 (+1,024)
    /// inside 2^11; odd 0, 1, 17 (+16), 273 (+256), ending at 4,369 (+4,096) inside 2^13; the whole chain's as `base`.
    /// Two memories loaded with a whole chain hold each texel once, and each reads back what `All` reads.
    #[test]
    fn the_parity_halves_hold_every_level_once_and_read_what_the_whole_chain_does() {
        assert_eq!([0, 2, 4, 6].map(|m| Levels::Even.base(m)), [0, 1, 5, 69]);
        assert_eq!([1, 3, 5, 7].map(|m| Levels::Odd.base(m)), [0, 1, 17, 273]);
        assert!(Levels::Even.base(6) + 1024 <= 1 << Levels::Even.addr_bits());
        assert!(Levels::Odd.base(7) + 4096 <= 1 << Levels::Odd.addr_bits());
        assert!((0..=7).all(|m| Levels::All.base(m) == base(m)));
        let (mut all, mut even, mut odd) =
            (Memory::default(), Memory::holding(Levels::Even), Memory::holding(Levels::Odd));
        for v in load(MAX_LOG_SIDE, pattern) {
            all.step(&v);
            even.step(&v);
            odd.step(&v);
        }
        let nonzero = |m: &Memory| m.banks.iter().map(|b| b.iter().filter(|&&w| w != 0).count()).sum::<usize>();
        assert!(nonzero(&even) + nonzero(&odd) == nonzero(&all) && nonzero(&all) > 21_000);
        for m in 0..=MAX_LOG_SIDE {
            let half = if m % 2 == 0 { &even } else { &odd };
            for (x, y) in [(0, 0), ((1 << m) - 1, 0), (0, (1 << m) - 1), ((1 << m) - 1, (1 << m) - 1), (5, 3)] {
                let (x, y) = (wrap(x, m), wrap(y, m));
                let f = |mem: &Memory| mem.footprint(m, [x, wrap(x + 1, m)], [y, wrap(y + 1, m)]);
                assert_eq!(f(half), f(&all), "level {m} at ({x}, {y})");
            }
        }
    }
}
