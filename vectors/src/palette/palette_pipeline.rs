//! `palette_pipeline`: Tarini et al.'s rendering phase as one block: the table builder (`table_builder`) writing the
//! next
//! frame's colour table while the pixels of this frame read theirs (`palette_lookup`), one normal and one pixel a
//! clock. The pixel's index and frame wait beside the builder, so a write and a read meet the table RAM in the order
//! their vectors came, whatever the idle clocks between them: a pixel sees every entry built by the vectors before
//! it in the table it reads, and a frame never reads the table being built (writes go to table !frame).
//!
//! A vector: the pixel (`frame`, `idx`) and, when `build` = 1, one palette normal to shade into entry `b_idx` of
//! the other table (the normal, L, H, C and the specular colour of `table_builder`). The model is `table_builder`'s
//! entry fed to `palette_lookup`'s stream: at 8 index bits (s_N up to 256) as `palette_pipeline`, at 12 (up to 4,096)
//! as `palette_pipeline_12` (module `wide`: the same ports in the same order, the two indices wider).

use crate::palette::{palette_lookup, table_builder};
use crate::unit::{run_machine, Machine, UnitModel};

crate::ports! {
    inputs: [
        frame: u 1, idx: u 8, build: u 1, b_idx: u 8, n_x: s 10, n_y: s 10, n_z: s 10, l_x: s 12, l_y: s 12, l_z: s 12,
        h_x: s 12, h_y: s 12, h_z: s 12, conc: u 8, spec_r: u 8, spec_g: u 8, spec_b: u 8,
    ],
    outputs: [
        out_r: u 8, out_g: u 8, out_b: u 8, out_a: u 8,
    ],
}

/// An entry (r, g, b, α) as the table RAM's 32-bit word holds it, r in the low byte.
pub fn pack(e: [i64; 4]) -> i64 {
    e[0] | e[1] << 8 | e[2] << 16 | e[3] << 24
}

/// The lookup's vector for one of ours: the pixel, and the built entry packed when building.
fn lookup_vector(v: &[i64]) -> Vec<i64> {
    use input::*;
    let e = || {
        table_builder::exact(
            [v[n_x], v[n_y], v[n_z]],
            [v[l_x], v[l_y], v[l_z]],
            [v[h_x], v[h_y], v[h_z]],
            v[conc],
            [v[spec_r], v[spec_g], v[spec_b]],
        )
    };
    vec![v[frame], v[idx], v[build], v[b_idx], if v[build] == 1 { pack(e()) } else { 0 }]
}

/// The unit with indices of `BITS` bits, from empty (zero) tables, as a machine: the builder's entry fed to the
/// lookup's tables.
#[derive(Clone, Default)]
pub struct Unit<const BITS: u32>(palette_lookup::Tables<BITS>);

impl<const BITS: u32> Machine for Unit<BITS> {
    fn step(&mut self, v: &[i64]) -> Vec<i64> {
        self.0.step(&lookup_vector(v))
    }
    fn load(&mut self, v: &[i64]) {
        self.0.load(&lookup_vector(v))
    }
}

/// The unit over a stream, from empty (zero) tables.
pub fn run(inputs: &[Vec<i64>]) -> Vec<Vec<i64>> {
    run_machine::<Unit<8>>(inputs)
}

fn run_12(inputs: &[Vec<i64>]) -> Vec<Vec<i64>> {
    run_machine::<Unit<12>>(inputs)
}

fn exact_ports(v: &[i64]) -> Vec<i64> {
    run(&[v.to_vec()]).remove(0)
}

fn exact_ports_12(v: &[i64]) -> Vec<i64> {
    run_12(&[v.to_vec()]).remove(0)
}

/// A palette normal to build into entry `e` while pixel `p` of frame `f` is read.
pub fn build(f: i64, p: i64, e: i64, n: [i64; 3], conc: i64) -> Vec<i64> {
    let up = [0, 1024, 0];
    let l = table_builder::sq1_10([0.3, 1.0, 0.2]);
    [vec![f, p, 1, e], n.to_vec(), l.to_vec(), up.to_vec(), vec![conc, 255, 200, 120]].concat()
}

/// A pixel alone.
pub fn pixel(f: i64, p: i64) -> Vec<i64> {
    [vec![f, p, 0, 0], vec![0; 9], vec![0, 0, 0, 0]].concat()
}

fn normal_of(e: i64) -> [i64; 3] {
    // a fan of normals over the hemisphere, one per entry
    let a = e as f64 * 0.7;
    let t = (e % 16) as f64 / 16.0 * 1.4;
    [(t.sin() * a.cos() * 400.0) as i64, (t.cos() * 400.0) as i64 + 50, (t.sin() * a.sin() * 400.0) as i64]
}

/// Frame 0 shown while table 1 is built, the flip, frame 1's pixels reading it while table 0 is built with other
/// light (a different C), the flip back; pixels read every entry built between; a build and a read of the same entry
/// in one vector, and the flip straight after the last build. At 8 bits every entry is built; wider, the
/// `palette_lookup` region (the first and last 64 entries), which the random vectors then stay in.
pub fn hard_cases_with(bits: u32) -> Vec<Vec<i64>> {
    let (top, n) = (1i64 << bits, palette_lookup::region_end(bits).min(128));
    let entries: Vec<i64> = if bits <= 8 { (0..top).collect() } else { (0..n).chain(top - n..top).collect() };
    let mut v = vec![];
    for &e in &entries {
        v.push(build(0, e, e, normal_of(e), 96));
    }
    for (k, &e) in entries.iter().enumerate() {
        v.push(build(1, entries[entries.len() - 1 - k], e, normal_of(e), 250)); // frame 1 shows table 1, table 0 is built
    }
    for &e in &entries {
        v.push(pixel(0, e));
    }
    v.push(build(1, 7, 7, [0, 0, 0], 0)); // a zero-length normal into entry 7 of table 0, pixel 7 of table 1
    v.push(pixel(0, 7));
    v.push(pixel(1, 7));
    v.push(build(0, top - 1, top - 1, [0, -511, 0], 96)); // the last entry of table 1 facing away, read by frame 1 next
    v.push(pixel(1, top - 1));
    v
}

pub fn hard_cases() -> Vec<Vec<i64>> {
    hard_cases_with(8)
}

fn hard_cases_12() -> Vec<Vec<i64>> {
    hard_cases_with(12)
}

/// Pixels and builds at random, flips at random, the indices in the entries the hard cases built.
fn random_with(rng: &mut dyn rand::RngCore, bits: u32) -> Vec<i64> {
    use rand::Rng;
    let mut v = random_inputs(rng);
    if bits > 8 {
        (v[input::idx], v[input::b_idx]) = (palette_lookup::in_region(rng, bits), palette_lookup::in_region(rng, bits));
    }
    let (l, h) = (
        table_builder::sq1_10([rng.gen_range(-1.0..1.0), 1.0, rng.gen_range(-1.0..1.0)]),
        table_builder::sq1_10([rng.gen_range(-0.5..0.5), 1.0, rng.gen_range(-0.5..0.5)]),
    );
    v[input::l_x..input::l_x + 3].copy_from_slice(&l);
    v[input::h_x..input::h_x + 3].copy_from_slice(&h);
    v
}

fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    random_with(rng, 8)
}

fn random_12(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    random_with(rng, 12)
}

/// The 12-bit unit's ports: `palette_pipeline`'s, the pixel's and the built entry's index 12 bits wide.
pub mod wide {
    crate::ports! {
        inputs: [
            frame: u 1, idx: u 12, build: u 1, b_idx: u 12, n_x: s 10, n_y: s 10, n_z: s 10, l_x: s 12, l_y: s 12,
            l_z: s 12, h_x: s 12, h_y: s 12, h_z: s 12, conc: u 8, spec_r: u 8, spec_g: u 8, spec_b: u 8,
        ],
        outputs: [
            out_r: u 8, out_g: u 8, out_b: u 8, out_a: u 8,
        ],
    }
}

pub static MODEL: UnitModel =
    UnitModel::new("palette_pipeline", (INPUTS, OUTPUTS), exact_ports, random, hard_cases).with_stream::<Unit<8>>();
pub static MODEL_12: UnitModel =
    UnitModel::new("palette_pipeline_12", (wide::INPUTS, wide::OUTPUTS), exact_ports_12, random_12, hard_cases_12)
        .with_stream::<Unit<12>>();

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_wide_unit_has_the_same_ports_in_the_same_order() {
        let names = |p: &[crate::unit::Port]| p.iter().map(|p| p.name).collect::<Vec<_>>();
        assert_eq!(names(wide::INPUTS), names(INPUTS));
        assert_eq!(names(wide::OUTPUTS), names(OUTPUTS));
        assert_eq!((wide::INPUTS[input::idx].bits, wide::INPUTS[input::b_idx].bits), (12, 12));
    }

    #[test]
    fn a_frame_shows_only_the_table_built_for_it() {
        let mut v = vec![];
        for e in 0..4 {
            v.push(build(0, 0, e, normal_of(e), 96)); // table 1 built while frame 0 is shown
        }
        v.push(pixel(0, 2));
        v.push(pixel(1, 2));
        v.push(build(1, 2, 2, [0, -400, 0], 96)); // entry 2 of table 0 facing away, while frame 1 reads table 1
        v.push(pixel(1, 2));
        v.push(pixel(0, 2));
        let o = run(&v);
        let want = table_builder::exact(
            normal_of(2),
            table_builder::sq1_10([0.3, 1.0, 0.2]),
            [0, 1024, 0],
            96,
            [255, 200, 120],
        );
        assert_eq!(o[4], vec![0; 4], "frame 0 reads table 0, still empty");
        assert_eq!(o[5], want.to_vec(), "frame 1 reads the table built for it");
        assert_eq!(o[7], want.to_vec(), "and does not see table 0 being rebuilt");
        assert_eq!(o[8], vec![0; 4], "facing away: a black entry in table 0");
    }
}
