//! `palette_pipeline_shared`: `palette_pipeline` on eight multipliers (the iCE40 UP5K's eight SB_MAC16), s_N up to
//! 256. Two differences from `palette_pipeline`, both from sharing:
//! - the palette's normals arrive normalised (Sq1.10, S12: what `normalise::exact` makes of the S10 the quantizer
//!   stores), because a palette changes per map, not per frame: its normaliser runs once per map, not in the
//!   per-frame builder. An entry is `table_builder::exact_normalised`, the same numbers as `palette_pipeline`'s for
//!   the same palette;
//! - the builder takes one normal every two clocks, so a vector's build is *taken* unless the vector before it had
//!   its build taken; a refused build writes nothing, and its pixel is read as usual. The rule looks at vectors, not
//!   clocks, so what is built does not depend on idle clocks between them. A table of s_N entries takes 2·s_N
//!   vectors, builds alternating with pixels alone.
//!
//! The rest is `palette_pipeline`: writes go to table !frame, a read sees every entry built by the vectors before
//! it, a flip shows a finished table.

use crate::palette::{palette_lookup, palette_pipeline, table_builder};
use crate::unit::{run_machine, Machine, UnitModel};

crate::ports! {
    inputs: [
        frame: u 1, idx: u 8, build: u 1, b_idx: u 8, n_x: s 12, n_y: s 12, n_z: s 12, l_x: s 12, l_y: s 12, l_z: s 12,
        h_x: s 12, h_y: s 12, h_z: s 12, conc: u 8, spec_r: u 8, spec_g: u 8, spec_b: u 8,
    ],
    outputs: [
        out_r: u 8, out_g: u 8, out_b: u 8, out_a: u 8,
    ],
}

/// Which vectors' builds are taken (`Unit::take`): a build, unless the vector before it had its build taken.
pub fn taken(inputs: &[Vec<i64>]) -> Vec<bool> {
    let mut u = Unit::default();
    inputs.iter().map(|v| u.take(v)).collect()
}

/// The unit from empty (zero) tables as a machine: the tables, and whether the last vector's build was taken.
#[derive(Clone, Default)]
pub struct Unit {
    tables: palette_lookup::Tables<8>,
    last: bool,
}

impl Unit {
    /// Whether `v`'s build is taken: a build, unless the vector before it had its build taken.
    fn take(&mut self, v: &[i64]) -> bool {
        self.last = v[input::build] == 1 && !self.last;
        self.last
    }

    /// The lookup's vector for `v`, the builder's turn moved on.
    fn lookup_vector(&mut self, v: &[i64]) -> Vec<i64> {
        use input::*;
        let take = self.take(v);
        let packed = if take {
            palette_pipeline::pack(table_builder::exact_normalised(
                [v[n_x], v[n_y], v[n_z]],
                [v[l_x], v[l_y], v[l_z]],
                [v[h_x], v[h_y], v[h_z]],
                v[conc],
                [v[spec_r], v[spec_g], v[spec_b]],
            ))
        } else {
            0
        };
        vec![v[frame], v[idx], take as i64, v[b_idx], packed]
    }
}

impl Machine for Unit {
    fn step(&mut self, v: &[i64]) -> Vec<i64> {
        let l = self.lookup_vector(v);
        self.tables.step(&l)
    }
    fn load(&mut self, v: &[i64]) {
        let l = self.lookup_vector(v);
        self.tables.load(&l)
    }
}

/// The unit over a stream, from empty (zero) tables.
pub fn run(inputs: &[Vec<i64>]) -> Vec<Vec<i64>> {
    run_machine::<Unit>(inputs)
}

fn exact_ports(v: &[i64]) -> Vec<i64> {
    run(&[v.to_vec()]).remove(0)
}

/// `palette_pipeline`'s vector for this unit: the normal normalised as the palette RAM holds it.
pub fn from_unshared(v: &[i64]) -> Vec<i64> {
    let mut w = v.to_vec();
    let n = crate::normalise::exact([v[input::n_x], v[input::n_y], v[input::n_z]]);
    w[input::n_x..=input::n_z].copy_from_slice(&n);
    w
}

/// `palette_pipeline`'s hard cases (both tables built at every entry and read, flips, a zero-length normal, the last
/// entry facing away), each build followed by a pixel alone reading the entry the build's vector reads, so that
/// every build is taken; then what sharing adds: two builds in a row (the second refused, its entry left as it was,
/// its pixel read), three in a row (the third taken), and a build after a refused one with idle clocks between
/// (the drivers add those).
pub fn hard_cases() -> Vec<Vec<i64>> {
    use input::*;
    let mut v = vec![];
    for u in palette_pipeline::hard_cases() {
        let w = from_unshared(&u);
        let built = w[build] == 1;
        v.push(w.clone());
        if built {
            v.push(palette_pipeline::pixel(w[frame], w[idx]));
        }
    }
    let b = |f: i64, p: i64, e: i64, n: [i64; 3], c: i64| from_unshared(&palette_pipeline::build(f, p, e, n, c));
    // table 1 (frame 0 shown): entry 10 rebuilt facing away, then a refused build of entry 11, read back after a flip
    v.push(b(0, 10, 10, [0, -400, 0], 96));
    v.push(b(0, 11, 11, [0, 0, 400], 96));
    v.push(palette_pipeline::pixel(1, 10));
    v.push(palette_pipeline::pixel(1, 11));
    // three in a row: the first and third taken
    v.push(b(0, 12, 20, [0, -400, 0], 96));
    v.push(b(0, 12, 21, [0, -400, 0], 96));
    v.push(b(0, 12, 22, [0, -400, 0], 96));
    for e in 20..23 {
        v.push(palette_pipeline::pixel(1, e));
    }
    // the most negative normal components (an unnormalised word: the RAM is the user's)
    v.push(
        [
            vec![0, 0, 1, 30],
            vec![-2048; 3],
            table_builder::sq1_10([-1.0, -1.0, -1.0]).to_vec(),
            table_builder::sq1_10([-1.0, -1.0, -1.0]).to_vec(),
            vec![255, 255, 255, 255],
        ]
        .concat(),
    );
    v.push(palette_pipeline::pixel(1, 30));
    v
}

/// Pixels and builds at random (so builds in a row, refused), flips at random; the normals mostly as the palette
/// holds them (normalised), some any S12; unit L and H.
fn random(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    use rand::Rng;
    let mut v = random_inputs(rng);
    if rng.gen_range(0..8) != 0 {
        let n = crate::normalise::exact([rng.gen_range(-512..512), rng.gen_range(-512..512), rng.gen_range(-512..512)]);
        v[input::n_x..=input::n_z].copy_from_slice(&n);
    }
    let (l, h) = (
        table_builder::sq1_10([rng.gen_range(-1.0..1.0), 1.0, rng.gen_range(-1.0..1.0)]),
        table_builder::sq1_10([rng.gen_range(-0.5..0.5), 1.0, rng.gen_range(-0.5..0.5)]),
    );
    v[input::l_x..=input::l_z].copy_from_slice(&l);
    v[input::h_x..=input::h_z].copy_from_slice(&h);
    v
}

pub static MODEL: UnitModel =
    UnitModel::new("palette_pipeline_shared", (INPUTS, OUTPUTS), exact_ports, random, hard_cases).with_stream::<Unit>();

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builds_in_a_row_are_taken_every_other_one() {
        let b = |e| from_unshared(&palette_pipeline::build(0, 0, e, [0, 400, 0], 96));
        let p = palette_pipeline::pixel(0, 0);
        let t = taken(&[b(0), b(1), b(2), p.clone(), b(3), p, b(4), b(5)]);
        assert_eq!(t, [true, false, true, false, true, false, true, false]);
    }

    #[test]
    fn an_entry_is_palette_pipeline_s_for_the_same_palette() {
        // the same stream, builds alternating with pixels: the shared unit reads what the unshared one reads
        let s: Vec<Vec<i64>> = palette_pipeline::hard_cases()
            .iter()
            .flat_map(|u| [u.clone(), palette_pipeline::pixel(u[input::frame], u[input::idx])])
            .collect();
        let shared: Vec<Vec<i64>> = s.iter().map(|u| from_unshared(u)).collect();
        assert!(taken(&shared).iter().zip(&s).all(|(&t, u)| t == (u[input::build] == 1)));
        let (a, b) = (palette_pipeline::run(&s), run(&shared));
        assert_eq!(a, b);
        assert!(a.iter().filter(|o| o.iter().any(|&c| c != 0)).count() > 500, "the stream reads built entries");
    }

    #[test]
    fn a_refused_build_leaves_the_entry_as_it_was() {
        let b = |e, n| from_unshared(&palette_pipeline::build(0, 0, e, n, 96));
        let o =
            run(&[b(5, [0, 400, 0]), b(6, [0, 400, 0]), palette_pipeline::pixel(1, 5), palette_pipeline::pixel(1, 6)]);
        assert_ne!(o[2], vec![0; 4], "entry 5 built");
        assert_eq!(o[3], vec![0; 4], "entry 6 refused: still empty");
    }
}
