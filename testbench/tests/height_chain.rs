//! The height path as a chain of rtl blocks, each run in rust-hdl: `height_addr` (both axes) → `height_fetch` (the
//! map in its interleaved memory) → `height_pipeline`, the outputs of each block fed to the next, against the model
//! of the whole path (`filters::Filter::BSpline` on the map, clamped; the fetch model's window, wrapped). The maps
//! are the hard cases: a 2 × 2 map, a 1 × 8 and an 8 × 1 map, the steepest step (0 → 255 in one texel), a
//! flat map, and a random 16 × 16 map, each in clamp and in wrap, at the blend factors' ends and between.
use rtl::height_addr::HeightAddr;
use rtl::height_fetch::HeightFetch;
use rtl::height_pipeline::HeightPipeline;
use rtl::stream::Runner;
use rtl::StreamUnit;
use vectors::fixed::from_pattern;
use vectors::height::filters::{Filter, Grid};
use vectors::height_fetch::Map;
use vectors::unit::to_patterns;

/// One stream through a block in rust-hdl, back to back: the output values in order.
fn through<U: StreamUnit>(model: &vectors::UnitModel, inputs: &[Vec<i64>]) -> Vec<Vec<i64>> {
    let slots = inputs.iter().map(|v| Some(to_patterns(v, model.inputs)));
    let got = Runner::<U>::new().run(slots);
    assert_eq!(got.outputs.len(), inputs.len(), "{}: outputs lost", U::NAME);
    got.outputs
        .iter()
        .map(|o| o.iter().zip(model.outputs).map(|(&p, port)| from_pattern(p, port.bits, port.signed)).collect())
        .collect()
}

fn chain(name: &str, w: usize, h: usize, heights: &[i64]) {
    let (ul, vl) = (w.trailing_zeros() as i64, h.trailing_zeros() as i64);
    // coordinates in height mode (UQ8.8 texels): every texel at factors 0, ½ and the largest, and one beyond the map
    let mut coords = vec![];
    for j in 0..=h as i64 {
        for i in 0..=w as i64 {
            for (fu, fv) in [(0, 0), (128, 128), (255, 255), (255, 0)] {
                coords.push((i * 256 + fu, j * 256 + fv));
            }
        }
    }
    for wrap in [false, true] {
        let axis = |c: &Vec<(i64, i64)>, pick: fn(&(i64, i64)) -> i64, log2: i64| -> Vec<Vec<i64>> {
            let inputs: Vec<Vec<i64>> = c.iter().map(|x| vec![pick(x).min(65_535), log2, wrap as i64, 1]).collect();
            through::<HeightAddr>(&vectors::height_addr::MODEL, &inputs)
        };
        let (au, av) = (axis(&coords, |x| x.0, ul), axis(&coords, |x| x.1, vl));
        let map = Map::from_heights(heights, w, h);
        let mut fetch_in = map.writes(w, h);
        let n_writes = fetch_in.len();
        fetch_in.extend(au.iter().zip(&av).map(|(u, v)| Map::read(u[0], v[0], ul, vl, wrap, wrap)));
        let windows = through::<HeightFetch>(&vectors::height_fetch::MODEL, &fetch_in);
        let k = 16;
        let normal_in: Vec<Vec<i64>> = windows[n_writes..]
            .iter()
            .zip(au.iter().zip(&av))
            .map(|(win, (u, v))| [win.clone(), vec![u[1], v[1], k]].concat())
            .collect();
        let normals = through::<HeightPipeline>(&vectors::height_pipeline::MODEL, &normal_in);
        let grid = Grid { side: w.max(h), h: heights };
        for (q, ((cu, cv), n)) in coords.iter().zip(&normals).enumerate() {
            let want: Vec<i64> = if !wrap && w == h {
                // the whole path's model on the map, clamped: texel and factor from the coordinate, clamped
                let (cu, cv) = ((*cu).min((w as i64) * 256 - 1), (*cv).min((h as i64) * 256 - 1));
                Filter::BSpline.exact(&grid, &grid, k, cu, cv).to_vec()
            } else {
                let (u, v) = (&au[q], &av[q]);
                let win = map.window(u[0], v[0], ul, vl, wrap, wrap);
                (vectors::height_pipeline::MODEL.exact)(&[win.to_vec(), vec![u[1], v[1], k]].concat())
            };
            assert_eq!(n, &want, "{name}, wrap {wrap}: coordinate ({cu}, {cv})");
        }
        if heights.iter().all(|&x| x == heights[0]) {
            assert!(normals.iter().all(|n| n == &vec![0, 1024, 0]), "{name}: a flat map is straight up");
        }
    }
}

#[test]
fn a_2_by_2_map() {
    chain("2 × 2", 2, 2, &[0, 255, 255, 0]);
}

#[test]
fn a_1_by_8_and_an_8_by_1_map() {
    let h: Vec<i64> = (0..8).map(|k| k * 30).collect();
    chain("1 × 8", 1, 8, &h);
    chain("8 × 1", 8, 1, &h);
}

#[test]
fn the_steepest_step_and_a_flat_map() {
    let step: Vec<i64> = (0..64).map(|k| if k % 8 < 4 { 0 } else { 255 }).collect();
    chain("steepest step", 8, 8, &step);
    chain("flat", 8, 8, &[77; 64]);
}

#[test]
fn a_random_16_by_16_map() {
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(21);
    let h: Vec<i64> = (0..256).map(|_| rng.gen_range(0..256)).collect();
    chain("random 16 × 16", 16, 16, &h);
}
