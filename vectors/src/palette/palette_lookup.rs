//! `palette_lookup`: Tarini et al.'s paletted texture read (§5, step 2) as hardware: the colour table C in block RAM,
//! one entry read per pixel by its normal index, while the next frame's table is written beside it. The RAM holds
//! two tables: a pixel reads table `frame`, a write goes to the other one, so frame N's pixels never see an entry of
//! frame N + 1's table, however the writes and reads interleave; flipping `frame` shows the table just written.
//!
//! A vector reads (its outputs are entry `idx` of table `frame`, RGBA, r in the low byte of the entry) and, when
//! `we` = 1, also writes `wdata` at `waddr` of the other table; a read sees every write of the vectors before it.
//! The index is ⌈log2 s_N⌉ bits: this unit is the 8-bit one (s_N up to 256, the paper's smallest palette that
//! looks right); the tests build 1, 4, 12 and 14 bits (up to 16,384 normals).

use crate::unit::{run_machine, Accuracy, Machine, UnitModel};

/// Index bits of the unit in the table.
pub const INDEX_BITS: u32 = 8;

crate::ports! {
    inputs: [
        frame: u 1, idx: u 8, we: u 1, waddr: u 8, wdata: u 32,
    ],
    outputs: [
        out_r: u 8, out_g: u 8, out_b: u 8, out_a: u 8,
    ],
}

/// The two tables of an index of `BITS` bits, from empty (zero): the unit as a machine.
#[derive(Clone)]
pub struct Tables<const BITS: u32>(pub [Vec<u32>; 2]);

impl<const BITS: u32> Default for Tables<BITS> {
    fn default() -> Self {
        Tables(std::array::from_fn(|_| vec![0; 1 << BITS]))
    }
}

impl<const BITS: u32> Machine for Tables<BITS> {
    fn step(&mut self, v: &[i64]) -> Vec<i64> {
        use input::*;
        let e = self.0[v[frame] as usize][v[idx] as usize];
        self.load(v);
        (0..4).map(|c| ((e >> (8 * c)) & 0xff) as i64).collect()
    }
    fn load(&mut self, v: &[i64]) {
        use input::*;
        if v[we] == 1 {
            self.0[1 - v[frame] as usize][v[waddr] as usize] = v[wdata] as u32;
        }
    }
}

/// The unit over a stream, from empty (zero) tables.
pub fn run(inputs: &[Vec<i64>]) -> Vec<Vec<i64>> {
    run_machine::<Tables<INDEX_BITS>>(inputs)
}

fn exact_ports(v: &[i64]) -> Vec<i64> {
    run(&[v.to_vec()]).remove(0)
}

/// A read of entry `idx` of table `frame`, writing nothing.
pub fn read(frame: i64, idx: i64) -> Vec<i64> {
    vec![frame, idx, 0, 0, 0]
}

/// A read, and a write of `data` at `addr` of the other table.
pub fn write(frame: i64, idx: i64, addr: i64, data: i64) -> Vec<i64> {
    vec![frame, idx, 1, addr, data]
}

/// The entries the random vectors touch: the first 64 and the last 64 of each table (all of a smaller one), written
/// by the hard cases.
const REGION: i64 = 64;

/// How many entries at each end of a table of `bits` index bits the region holds.
pub fn region_end(bits: u32) -> i64 {
    REGION.min((1i64 << bits) / 2).max(1)
}

/// An entry of the region at random.
pub fn in_region(rng: &mut dyn rand::RngCore, bits: u32) -> i64 {
    use rand::Rng;
    let n = region_end(bits);
    let k = rng.gen_range(0..2 * n);
    if k < n {
        k
    } else {
        (1i64 << bits) - 1 - (k - n)
    }
}

/// Both tables' first and last entries written (each write while the other table is read), then frames flipped
/// back and forth with reads of entries just written, the index's ends, and a write and a read of the same entry
/// in one vector (the write goes to the other table: the read must not see it).
pub fn hard_cases_with(bits: u32) -> Vec<Vec<i64>> {
    let (top, n) = (1i64 << bits, region_end(bits));
    let entries: Vec<i64> = (0..n).chain(top - n..top).collect();
    let data = |f: i64, e: i64| ((e * 2_654_435_761 + f * 97) % (1 << 32)) ^ 0x5a5a_5a5a;
    let mut v = vec![];
    for f in [0, 1] {
        // frame f is shown while table 1 − f is written
        for &e in &entries {
            v.push(write(f, e, e, data(1 - f, e)));
        }
    }
    for f in [1, 0, 1] {
        for &e in &entries {
            v.push(read(f, e));
        }
    }
    // a write and a read of the same entry in one vector: the read sees the shown table, the write the other
    v.push(write(0, 0, 0, 0x0102_0304));
    v.push(read(0, 0));
    v.push(read(1, 0));
    v.push(write(1, top - 1, top - 1, 0xffff_ffff));
    v.push(read(1, top - 1));
    v.push(read(0, top - 1));
    v
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    hard_cases_with(INDEX_BITS)
}

/// Reads and writes of the entries the hard cases fill, frames at random.
pub fn random_with(rng: &mut dyn rand::RngCore, bits: u32) -> Vec<i64> {
    use rand::Rng;
    let (f, i) = (rng.gen_range(0..2), in_region(rng, bits));
    if rng.gen_range(0..3) == 0 {
        write(f, i, in_region(rng, bits), rng.gen_range(0..=u32::MAX as i64))
    } else {
        read(f, i)
    }
}

fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    random_with(rng, INDEX_BITS)
}

/// A table read has nothing to be wrong by: its outputs against the entry last written, kept in a plain map.
fn accuracy(_samples: usize, _seed: u64) -> Vec<Accuracy> {
    use input::*;
    let v = hard_cases();
    let outs = run(&v);
    let mut written: std::collections::HashMap<(i64, i64), i64> = Default::default();
    let mut s = crate::stats::ErrorStats::default();
    for (x, o) in v.iter().zip(&outs) {
        let want = written.get(&(x[frame], x[idx])).copied().unwrap_or(0);
        for c in 0..4 {
            s.add((o[c] - ((want >> (8 * c)) & 0xff)).abs() as f64, || format!("{x:?}"));
        }
        if x[we] == 1 {
            written.insert((1 - x[frame], x[waddr]), x[wdata]);
        }
    }
    vec![Accuracy::new("8-bit LSB against the entry last written (a read: exact)", s)]
}

pub static MODEL: UnitModel = UnitModel::new("palette_lookup", (INPUTS, OUTPUTS), exact_ports, random, hard_cases)
    .with_stream::<Tables<INDEX_BITS>>()
    .with_accuracy(accuracy);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_frame_never_sees_the_table_being_written() {
        let v = vec![
            write(0, 5, 5, 0x1111_1111),
            read(0, 5),
            read(1, 5),
            write(1, 5, 5, 0x2222_2222),
            read(1, 5),
            read(0, 5),
        ];
        let o = run(&v);
        assert_eq!(o[1], vec![0; 4], "frame 0 still shows the empty table");
        assert_eq!(o[2], vec![0x11; 4], "flipped: the table written");
        assert_eq!(o[4], vec![0x11; 4], "frame 1's writes went to table 0");
        assert_eq!(o[5], vec![0x22; 4]);
    }
}
