//! `height_fetch`: US 2004/0207631's texel fetch [151] in height mode, with the map's memory. The height map is stored
//! 2×2-interleaved (¶55): the word at (X, Y) holds the four heights (2X, 2Y), (2X + 1, 2Y), (2X, 2Y + 1),
//! (2X + 1, 2Y + 1) in its bytes 0..3, the "space of a single four-dimensional colour", so the map takes the storage
//! of a colour texture of half its resolution each way. The words are spread over four banks by (X mod 2, Y mod 2),
//! as a bilinear colour fetch spreads its texels [60–63], so one clock reads the four words that hold any 3×3 window.
//!
//! A vector either writes one word (`we` = 1: `wdata` at word `waddr` = Y·128 + X; its outputs are zero) or reads
//! the window `a b c / d e f / g h k` around texel (i, j) of a 2^ulog2 × 2^vlog2 map (log2 ≥ 8 read as 8: up to
//! 256 × 256 texels, 128 × 128 words), each of its three columns i − 1, i, i + 1 (and rows likewise) wrapped modulo
//! the size or clamped to [0, size − 1] on its own, so a window at a border repeats the edge or wraps round. A read
//! sees every word written by the vectors before it. The memory is stateful, so the unit's model is a stream
//! (`UnitModel::with_stream`); a lone vector reads an empty (zero) map.

use crate::unit::{run_machine, Accuracy, Machine, UnitModel};

/// Words along each axis of the largest map (256 texels).
pub const WORDS: usize = 128;

crate::ports! {
    inputs: [
        i: u 8, j: u 8, ulog2: u 4, vlog2: u 4, uwrap: u 1, vwrap: u 1, we: u 1, waddr: u 14, wdata: u 32,
    ],
    outputs: [
        a: u 8, b: u 8, c: u 8, d: u 8, e: u 8, f: u 8, g: u 8, h: u 8, k: u 8,
    ],
}

/// The three texel coordinates of one axis (centre t), each wrapped modulo 2^size_log2 or clamped to the map.
pub fn axis(t: i64, size_log2: i64, wrap: bool) -> [i64; 3] {
    let size = 1i64 << crate::fixed::saturate(size_log2, 0, 8);
    std::array::from_fn(|c| {
        let x = t + c as i64 - 1; // S10: −1..256
        if wrap {
            x.rem_euclid(size)
        } else {
            crate::fixed::saturate(x, 0, size - 1)
        }
    })
}

/// The 2×2-interleaved memory: word (X, Y) at Y·128 + X, bytes (x % 2) + 2·(y % 2).
#[derive(Clone)]
pub struct Map {
    pub words: Vec<u32>,
}

impl Default for Map {
    fn default() -> Map {
        Map { words: vec![0; WORDS * WORDS] }
    }
}

impl Map {
    /// A map of `w` × `h` heights (row-major), packed into words.
    pub fn from_heights(heights: &[i64], w: usize, h: usize) -> Map {
        let mut m = Map::default();
        for y in 0..h {
            for x in 0..w {
                m.set(x, y, heights[y * w + x]);
            }
        }
        m
    }

    pub fn set(&mut self, x: usize, y: usize, height: i64) {
        let (word, byte) = ((y / 2) * WORDS + x / 2, (x % 2) + 2 * (y % 2));
        let w = &mut self.words[word];
        *w = (*w & !(0xff << (8 * byte))) | (((height & 0xff) as u32) << (8 * byte));
    }

    pub fn height(&self, x: i64, y: i64) -> i64 {
        let word = self.words[(y as usize / 2) * WORDS + x as usize / 2];
        ((word >> (8 * ((x % 2) + 2 * (y % 2)))) & 0xff) as i64
    }

    /// The write vectors that load this map's words for a `w` × `h` map (every word it touches, row by row).
    pub fn writes(&self, w: usize, h: usize) -> Vec<Vec<i64>> {
        let mut v = vec![];
        for y in 0..h.div_ceil(2) {
            for x in 0..w.div_ceil(2) {
                let addr = y * WORDS + x;
                v.push(vec![0, 0, 0, 0, 0, 0, 1, addr as i64, self.words[addr] as i64]);
            }
        }
        v
    }

    /// The read vector for the window around texel (i, j).
    pub fn read(i: i64, j: i64, ulog2: i64, vlog2: i64, uwrap: bool, vwrap: bool) -> Vec<i64> {
        vec![i, j, ulog2, vlog2, uwrap as i64, vwrap as i64, 0, 0, 0]
    }

    /// The 3×3 window a..k around texel (i, j).
    pub fn window(&self, i: i64, j: i64, ulog2: i64, vlog2: i64, uwrap: bool, vwrap: bool) -> [i64; 9] {
        let (xs, ys) = (axis(i, ulog2, uwrap), axis(j, vlog2, vwrap));
        std::array::from_fn(|p| self.height(xs[p % 3], ys[p / 3]))
    }
}

/// The unit as a machine: a write vector writes its word (outputs zero), a read vector reads its window.
impl Machine for Map {
    fn step(&mut self, v: &[i64]) -> Vec<i64> {
        use input::*;
        if v[we] == 1 {
            self.words[v[waddr] as usize] = v[wdata] as u32;
            vec![0; 9]
        } else {
            self.window(v[i], v[j], v[ulog2], v[vlog2], v[uwrap] == 1, v[vwrap] == 1).to_vec()
        }
    }
}

/// The unit over a stream of vectors, from an empty (zero) memory.
pub fn run(inputs: &[Vec<i64>]) -> Vec<Vec<i64>> {
    run_machine::<Map>(inputs)
}

fn exact_ports(v: &[i64]) -> Vec<i64> {
    run(&[v.to_vec()]).remove(0)
}

/// A map's heights that show a crossed wire or a wrong bank: every texel distinct modulo 256 along a row and the
/// rows apart by an odd step.
fn pattern(x: usize, y: usize) -> i64 {
    ((x * 7 + y * 37 + (x * y) % 11) % 256) as i64
}

/// The region the random vectors read and write: 32 × 32 texels (16 × 16 words), log2 sizes 0..5.
const REGION_LOG2: i64 = 5;

/// First the 32 × 32 region written, then every border and mode of every map size in it (1 × 1 up to 32 × 32,
/// 1 × N and N × 1 among them, 2 × 2), then the largest map's corners and edges in wrap and clamp (every word
/// their windows touch written first), then a write followed at once by a read of the same word.
pub fn hard_cases() -> Vec<Vec<i64>> {
    let n = 1usize << REGION_LOG2;
    let mut map = Map::default();
    for y in 0..n {
        for x in 0..n {
            map.set(x, y, pattern(x, y));
        }
    }
    let mut v = map.writes(n, n);
    for (ul, vl) in [(0, 0), (1, 1), (0, 5), (5, 0), (1, 4), (3, 2), (5, 5)] {
        let (w, h) = (1i64 << ul, 1i64 << vl);
        for (uw, vw) in [(false, false), (true, true), (true, false), (false, true)] {
            for (i, j) in [(0, 0), (w - 1, h - 1), (0, h - 1), (w - 1, 0), (w / 2, h / 2), (1, 1), (255, 255)] {
                v.push(Map::read(i.clamp(0, 255), j.clamp(0, 255), ul, vl, uw, vw));
            }
        }
    }
    // the largest map: its corners and the middles of its edges, after writing every word their windows touch
    let mut reads = vec![];
    for (uw, vw) in [(true, true), (false, false), (true, false)] {
        for (i, j) in [(255, 255), (0, 255), (255, 0), (0, 0), (128, 255), (255, 128), (127, 0), (128, 0), (0, 128)] {
            reads.push(Map::read(i, j, 8, 15, uw, vw));
        }
    }
    let mut words = std::collections::BTreeSet::new();
    for r in &reads {
        for x in axis(r[input::i], 8, r[input::uwrap] == 1) {
            for y in axis(r[input::j], 8, r[input::vwrap] == 1) {
                words.insert((y as usize / 2) * WORDS + x as usize / 2);
            }
        }
    }
    for w in words {
        v.push(vec![0, 0, 0, 0, 0, 0, 1, w as i64, 0x1f3e_5d7c ^ (w as i64 * 2_654_435_761 % (1 << 32))]);
    }
    v.extend(reads);
    // a write, then at once a read of a window holding that word
    v.push(vec![0, 0, 0, 0, 0, 0, 1, (3 * WORDS + 2) as i64, 0xdead_beef]);
    v.push(Map::read(5, 7, 5, 5, false, false));
    v
}

/// Reads (three in four) and writes inside the 32 × 32 region the hard cases fill, so that a stream of them after
/// the hard cases reads only written words; any map size up to it, any centre (beyond the map it wraps or clamps).
fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    use rand::Rng;
    let words = 1i64 << (REGION_LOG2 - 1);
    if rng.gen_range(0..4) == 0 {
        let (x, y) = (rng.gen_range(0..words), rng.gen_range(0..words));
        vec![0, 0, 0, 0, 0, 0, 1, y * WORDS as i64 + x, rng.gen_range(0..=u32::MAX as i64)]
    } else {
        let centre = |rng: &mut dyn rand::RngCore| {
            if rng.gen_range(0..4) == 0 {
                rng.gen_range(0..256)
            } else {
                rng.gen_range(0..32)
            }
        };
        let (i, j) = (centre(rng), centre(rng));
        let (ul, vl) = (rng.gen_range(0..=REGION_LOG2), rng.gen_range(0..=REGION_LOG2));
        Map::read(i, j, ul, vl, rng.gen_range(0..2) == 1, rng.gen_range(0..2) == 1)
    }
}

/// A fetch has no arithmetic to be wrong by: counted over the hard cases' stream, each output against the texel of
/// the map the stream wrote, addressed directly (row-major, no interleave) and wrapped or clamped in reals.
fn accuracy(_samples: usize, _seed: u64) -> Vec<Accuracy> {
    use input::*;
    let inputs = hard_cases();
    let outs = run(&inputs);
    let mut plain = std::collections::HashMap::new();
    let mut s = crate::stats::ErrorStats::default();
    for (v, o) in inputs.iter().zip(&outs) {
        if v[we] == 1 {
            let (x, y) = (v[waddr] as usize % WORDS, v[waddr] as usize / WORDS);
            for byte in 0..4 {
                plain.insert((2 * x + byte % 2, 2 * y + byte / 2), (v[wdata] >> (8 * byte)) & 0xff);
            }
            continue;
        }
        let at = |t: i64, log2: i64, wrap: i64| {
            let size = (1i64 << log2.min(8)) as f64;
            let x = t as f64;
            if wrap == 1 {
                x.rem_euclid(size) as usize
            } else {
                x.clamp(0.0, size - 1.0) as usize
            }
        };
        for p in 0..9 {
            let (x, y) =
                (at(v[i] + p as i64 % 3 - 1, v[ulog2], v[uwrap]), at(v[j] + p as i64 / 3 - 1, v[vlog2], v[vwrap]));
            let want = plain.get(&(x, y)).copied().unwrap_or(0);
            s.add((o[p] - want).abs() as f64, || format!("{v:?}, position {p}"));
        }
    }
    vec![Accuracy::new("8-bit LSB against the map read directly (a fetch: exact)", s)]
}

pub static MODEL: UnitModel = UnitModel::new("height_fetch", (INPUTS, OUTPUTS), exact_ports, random, hard_cases)
    .with_stream::<Map>()
    .with_accuracy(accuracy);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_window_away_from_the_border_is_the_map_around_the_texel() {
        let heights: Vec<i64> = (0..64).map(|k| k * 3 % 256).collect();
        let m = Map::from_heights(&heights, 8, 8);
        // rows 3..5, columns 2..4: heights 3·(8y + x)
        assert_eq!(m.window(3, 4, 3, 3, false, false), [78, 81, 84, 102, 105, 108, 126, 129, 132]);
    }

    #[test]
    fn borders_repeat_the_edge_when_clamped_and_wrap_round_otherwise() {
        let heights: Vec<i64> = (0..16).collect(); // 4 × 4, height = y·4 + x
        let m = Map::from_heights(&heights, 4, 4);
        assert_eq!(m.window(0, 0, 2, 2, false, false), [0, 0, 1, 0, 0, 1, 4, 4, 5]);
        assert_eq!(m.window(0, 0, 2, 2, true, true), [15, 12, 13, 3, 0, 1, 7, 4, 5]);
        assert_eq!(m.window(3, 3, 2, 2, true, false), [10, 11, 8, 14, 15, 12, 14, 15, 12]);
    }

    #[test]
    fn a_one_texel_wide_map_and_a_two_by_two_map() {
        // 1 × 4: every column is x = 0, wrap or clamp
        let m = Map::from_heights(&[10, 20, 30, 40], 1, 4);
        for wrap in [false, true] {
            assert_eq!(m.window(0, 1, 0, 2, wrap, false), [10, 10, 10, 20, 20, 20, 30, 30, 30]);
        }
        // 2 × 2 in one word: wrap alternates, clamp repeats
        let m = Map::from_heights(&[1, 2, 3, 4], 2, 2);
        assert_eq!(m.window(0, 0, 1, 1, true, true), [4, 3, 4, 2, 1, 2, 4, 3, 4]);
        assert_eq!(m.window(1, 1, 1, 1, false, false), [1, 2, 2, 3, 4, 4, 3, 4, 4]);
    }

    #[test]
    fn a_read_sees_the_writes_before_it_and_a_write_reads_nothing() {
        let mut v = Map::from_heights(&[9; 16], 4, 4).writes(4, 4);
        v.push(Map::read(1, 1, 2, 2, false, false));
        let out = run(&v);
        assert!(out[..4].iter().all(|o| o == &vec![0; 9]));
        assert_eq!(out[4], vec![9; 9]);
        assert_eq!(exact_ports(&v[4]), vec![0; 9], "a lone read sees an empty map");
    }
}
