//! Tarini et al.'s preprocessing (Tarini et al. 2000, §4): a normal map quantized to a palette of s_N normals chosen
//! only from the normals it uses, and an index map into it; optional error-diffusion dithering; the mip levels of an
//! index map (§5.2). Software, run once per map.
//!
//! The palette: median cut over the map's distinct normals (weighted by how many texels use each), each box split at
//! its weighted median across its longest side until there are s_N boxes or no box holds two distinct normals; each
//! box's weighted mean, renormalised; then k-means on the sphere (every distinct normal to its nearest palette
//! normal by angle, every palette normal to its members' renormalised mean) until no assignment changes or
//! `KMEANS_ROUNDS` rounds. When s_N is at least the number of distinct normals the palette is those normals and the
//! map is kept exactly.

/// The most k-means rounds.
pub const KMEANS_ROUNDS: usize = 12;

use crate::stats::dot;

/// A mean or a sum of normals at unit length; one that cancels to zero is taken as straight up.
fn unit(v: [f64; 3]) -> [f64; 3] {
    if dot(v, v) > 0.0 {
        crate::stats::unit(v)
    } else {
        [0.0, 1.0, 0.0]
    }
}

/// Bits an index into `n` palette entries takes: ⌈log2 n⌉, at least 1.
pub fn index_bits(n: usize) -> u32 {
    (usize::BITS - (n.max(2) - 1).leading_zeros()).max(1)
}

/// A quantized normal map.
#[derive(Clone, Debug)]
pub struct Quantized {
    /// the palette N: unit normals
    pub palette: Vec<[f64; 3]>,
    /// one index per texel, row-major
    pub index: Vec<u32>,
    /// the map's distinct normals
    pub distinct: usize,
}

impl Quantized {
    /// Bits an index takes: ⌈log2 s_N⌉ of the palette as built (at least 1).
    pub fn index_bits(&self) -> u32 {
        index_bits(self.palette.len())
    }
}

/// The map's distinct normals (bit-exact keys) and how many texels use each, in first-use order, and each texel's
/// distinct normal.
fn distinct(normals: &[[f64; 3]]) -> (Vec<[f64; 3]>, Vec<u64>, Vec<usize>) {
    let mut seen: std::collections::HashMap<[u64; 3], usize> = Default::default();
    let (mut d, mut w, mut of) = (vec![], vec![], Vec::with_capacity(normals.len()));
    for n in normals {
        let key = n.map(f64::to_bits);
        let k = *seen.entry(key).or_insert_with(|| {
            d.push(*n);
            w.push(0);
            d.len() - 1
        });
        w[k] += 1;
        of.push(k);
    }
    (d, w, of)
}

/// Median cut: boxes of distinct normals (indices into `pts`), split until `target` boxes or none splits.
fn median_cut(pts: &[[f64; 3]], wts: &[u64], target: usize) -> Vec<Vec<usize>> {
    let extent = |b: &[usize]| -> (usize, f64) {
        let mut best = (0, -1.0);
        for axis in 0..3 {
            let (lo, hi) =
                b.iter().fold((f64::MAX, f64::MIN), |(lo, hi), &i| (lo.min(pts[i][axis]), hi.max(pts[i][axis])));
            if hi - lo > best.1 {
                best = (axis, hi - lo);
            }
        }
        best
    };
    let mut boxes: Vec<Vec<usize>> = vec![(0..pts.len()).collect()];
    while boxes.len() < target {
        // the box to split: the widest (side × texels, so that crowded regions get more normals), of two or more
        let pick = boxes
            .iter()
            .enumerate()
            .filter(|(_, b)| b.len() >= 2)
            .map(|(k, b)| (k, extent(b).1 * b.iter().map(|&i| wts[i]).sum::<u64>() as f64))
            .max_by(|a, b| a.1.total_cmp(&b.1));
        let Some((k, _)) = pick else { break };
        let mut b = boxes.swap_remove(k);
        let (axis, _) = extent(&b);
        b.sort_by(|&x, &y| pts[x][axis].total_cmp(&pts[y][axis]));
        let total: u64 = b.iter().map(|&i| wts[i]).sum();
        let (mut acc, mut cut) = (0u64, 1);
        for (p, &i) in b.iter().enumerate() {
            acc += wts[i];
            if 2 * acc >= total {
                cut = (p + 1).clamp(1, b.len() - 1);
                break;
            }
        }
        let rest = b.split_off(cut);
        boxes.push(b);
        boxes.push(rest);
    }
    boxes
}

/// A static k-d tree over the palette: nearest palette normal by Euclidean distance (by angle, for unit vectors).
pub struct Nearest {
    pts: Vec<[f64; 3]>,
    /// (point index, split axis) in tree order: a node at k, its children at 2k+1, 2k+2 (implicit, balanced)
    nodes: Vec<(usize, usize)>,
}

impl Nearest {
    pub fn new(pts: &[[f64; 3]]) -> Nearest {
        let mut idx: Vec<usize> = (0..pts.len()).collect();
        let mut nodes = vec![(usize::MAX, 0); pts.len().next_power_of_two() * 2];
        fn build(pts: &[[f64; 3]], idx: &mut [usize], node: usize, depth: usize, nodes: &mut Vec<(usize, usize)>) {
            if idx.is_empty() {
                return;
            }
            let axis = depth % 3;
            idx.sort_by(|&a, &b| pts[a][axis].total_cmp(&pts[b][axis]));
            let mid = idx.len() / 2;
            if node >= nodes.len() {
                nodes.resize(node + 1, (usize::MAX, 0));
            }
            nodes[node] = (idx[mid], axis);
            let (left, right) = idx.split_at_mut(mid);
            build(pts, left, 2 * node + 1, depth + 1, nodes);
            build(pts, &mut right[1..], 2 * node + 2, depth + 1, nodes);
        }
        build(pts, &mut idx, 0, 0, &mut nodes);
        Nearest { pts: pts.to_vec(), nodes }
    }

    /// The index of the palette normal nearest `q` (the lowest index among equals).
    pub fn find(&self, q: [f64; 3]) -> usize {
        let mut best = (usize::MAX, f64::MAX);
        self.search(0, q, &mut best);
        best.0
    }

    fn search(&self, node: usize, q: [f64; 3], best: &mut (usize, f64)) {
        let Some(&(p, axis)) = self.nodes.get(node) else { return };
        if p == usize::MAX {
            return;
        }
        let d = (0..3).map(|c| (self.pts[p][c] - q[c]).powi(2)).sum::<f64>();
        if d < best.1 || (d == best.1 && p < best.0) {
            *best = (p, d);
        }
        let delta = q[axis] - self.pts[p][axis];
        let (near, far) = if delta < 0.0 { (2 * node + 1, 2 * node + 2) } else { (2 * node + 2, 2 * node + 1) };
        self.search(near, q, best);
        if delta * delta <= best.1 {
            self.search(far, q, best);
        }
    }
}

/// Quantize unit normals (one per texel) to at most `s_n` palette normals.
pub fn quantize(normals: &[[f64; 3]], s_n: usize) -> Quantized {
    assert!(s_n >= 1, "a palette holds at least one normal");
    let (pts, wts, of) = distinct(normals);
    if pts.len() <= s_n {
        // the input normals are unit vectors: the palette is them, bit for bit
        return Quantized { palette: pts.clone(), index: of.iter().map(|&k| k as u32).collect(), distinct: pts.len() };
    }
    let mean = |members: &mut dyn Iterator<Item = usize>| -> [f64; 3] {
        let mut s = [0.0; 3];
        for i in members {
            for c in 0..3 {
                s[c] += pts[i][c] * wts[i] as f64;
            }
        }
        unit(s)
    };
    let mut palette: Vec<[f64; 3]> = median_cut(&pts, &wts, s_n).iter().map(|b| mean(&mut b.iter().copied())).collect();
    // k-means on the sphere over the distinct normals, weighted
    let mut assign = vec![usize::MAX; pts.len()];
    for _ in 0..KMEANS_ROUNDS {
        let tree = Nearest::new(&palette);
        let mut changed = false;
        for (i, p) in pts.iter().enumerate() {
            let k = tree.find(*p);
            changed |= assign[i] != k;
            assign[i] = k;
        }
        if !changed {
            break;
        }
        let mut sums = vec![[0.0; 3]; palette.len()];
        for (i, &k) in assign.iter().enumerate() {
            for c in 0..3 {
                sums[k][c] += pts[i][c] * wts[i] as f64;
            }
        }
        for (k, s) in sums.iter().enumerate() {
            if s.iter().any(|&c| c != 0.0) {
                palette[k] = unit(*s);
            }
        }
    }
    let tree = Nearest::new(&palette);
    let index = of.iter().map(|&k| tree.find(pts[k]) as u32).collect();
    Quantized { palette, index, distinct: pts.len() }
}

/// The most error a texel carries into its choice (a chord on the unit sphere: 0.35 is about 20°).
pub const MAX_CARRY: f64 = 0.35;

/// Floyd–Steinberg error diffusion of the normals over a `w` × `h` map against a palette: each texel takes the
/// palette normal nearest its normal plus the error carried to it (renormalised), and passes on the difference
/// (7/16 right, 3/16 below left, 5/16 below, 1/16 below right), row by row.
pub fn dither(normals: &[[f64; 3]], w: usize, h: usize, palette: &[[f64; 3]]) -> Vec<u32> {
    let tree = Nearest::new(palette);
    let mut err = vec![[0.0f64; 3]; w * h];
    let mut index = vec![0u32; w * h];
    for y in 0..h {
        for x in 0..w {
            let q = y * w + x;
            // the carried error is bounded (at the edge of the palette's spread it cannot be paid back and would grow)
            let carried = dot(err[q], err[q]).sqrt();
            let scale = if carried > MAX_CARRY { MAX_CARRY / carried } else { 1.0 };
            let want = unit([0, 1, 2].map(|c| normals[q][c] + err[q][c] * scale));
            let k = tree.find(want);
            index[q] = k as u32;
            let e = [0, 1, 2].map(|c| want[c] - palette[k][c]); // on the sphere: the radial part is not carried
            let mut spread = |dx: isize, dy: usize, f: f64| {
                let (nx, ny) = (x as isize + dx, y + dy);
                if nx >= 0 && (nx as usize) < w && ny < h {
                    let t = ny * w + nx as usize;
                    for c in 0..3 {
                        err[t][c] += e[c] * f;
                    }
                }
            };
            spread(1, 0, 7.0 / 16.0);
            spread(-1, 1, 3.0 / 16.0);
            spread(0, 1, 5.0 / 16.0);
            spread(1, 1, 1.0 / 16.0);
        }
    }
    index
}

/// One mip level of an index map (§5.2): each texel of the ⌈w/2⌉ × ⌈h/2⌉ level is the palette index nearest the
/// renormalised mean of the (up to four, fewer at an odd edge) normals it covers.
pub fn mip(index: &[u32], w: usize, h: usize, palette: &[[f64; 3]]) -> (Vec<u32>, usize, usize) {
    let tree = Nearest::new(palette);
    let (w2, h2) = (w.div_ceil(2), h.div_ceil(2));
    let mut out = Vec::with_capacity(w2 * h2);
    for y in 0..h2 {
        for x in 0..w2 {
            let mut s = [0.0; 3];
            for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let (sx, sy) = (2 * x + dx, 2 * y + dy);
                if sx < w && sy < h {
                    let n = palette[index[sy * w + sx] as usize];
                    for c in 0..3 {
                        s[c] += n[c];
                    }
                }
            }
            out.push(tree.find(unit(s)) as u32);
        }
    }
    (out, w2, h2)
}

/// The whole mip chain down to 1 × 1, level 0 first.
pub fn mip_chain(index: &[u32], w: usize, h: usize, palette: &[[f64; 3]]) -> Vec<(Vec<u32>, usize, usize)> {
    let mut chain = vec![(index.to_vec(), w, h)];
    while let Some((i, w, h)) = chain.last().filter(|(_, w, h)| *w > 1 || *h > 1).cloned() {
        chain.push(mip(&i, w, h, palette));
    }
    chain
}

/// Angle between each texel's normal and its palette normal, degrees: (mean, max).
pub fn angular_error(normals: &[[f64; 3]], index: &[u32], palette: &[[f64; 3]]) -> crate::stats::ErrorStats {
    let mut s = crate::stats::ErrorStats::default();
    for (q, (n, &k)) in normals.iter().zip(index).enumerate() {
        s.add(crate::stats::angle_deg(*n, palette[k as usize]), || format!("texel {q}"));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    fn bumpy(w: usize, h: usize) -> Vec<[f64; 3]> {
        (0..w * h)
            .map(|q| {
                let (x, y) = ((q % w) as f64, (q / w) as f64);
                // an 8-bit-coded normal map of a wavy surface: what a user's RGB map holds
                let n = unit([-0.6 * (x / 5.0).cos(), 1.0, -0.5 * (y / 7.0).sin()]);
                n.map(|c| ((c * 127.5 + 127.5).round() - 127.5) / 127.5)
            })
            .map(unit)
            .collect()
    }

    #[test]
    fn enough_normals_is_lossless_and_one_normal_is_their_mean() {
        let n = bumpy(32, 32);
        let q = quantize(&n, 1 << 14);
        assert!(q.palette.len() == q.distinct && q.distinct > 100);
        assert_eq!(angular_error(&n, &q.index, &q.palette).max, 0.0);
        let one = quantize(&n, 1);
        assert_eq!(one.palette.len(), 1);
        assert!(one.index.iter().all(|&i| i == 0));
        assert!(one.palette[0][1] > 0.9, "{:?}", one.palette[0]);
    }

    #[test]
    fn a_constant_map_and_duplicates_need_one_entry() {
        let n = vec![unit([0.3, 0.9, -0.1]); 100];
        for s in [1, 16, 256] {
            let q = quantize(&n, s);
            assert_eq!((q.palette.len(), q.distinct), (1, 1));
            assert_eq!(angular_error(&n, &q.index, &q.palette).max, 0.0);
        }
    }

    #[test]
    fn the_error_falls_as_the_palette_grows_and_every_index_is_its_nearest() {
        let n = bumpy(64, 64);
        let mut last = f64::MAX;
        for s in [16, 64, 256, 1024] {
            let q = quantize(&n, s);
            assert!(q.palette.len() <= s && q.index_bits() <= (s as f64).log2().ceil() as u32);
            let e = angular_error(&n, &q.index, &q.palette);
            assert!(e.mean() < last, "{s}: {} after {last}", e.mean());
            last = e.mean();
            // no texel has a nearer palette normal than its own (brute force)
            for (t, &k) in n.iter().zip(&q.index).step_by(37) {
                let best = q.palette.iter().map(|p| dot(*p, *t)).fold(f64::MIN, f64::max);
                assert!(dot(q.palette[k as usize], *t) >= best - 1e-12);
            }
        }
    }

    #[test]
    fn normals_on_the_horizon_keep_their_direction() {
        // a map of normals on the horizon (y = 0) all round: the palette stays on it
        let n: Vec<[f64; 3]> = (0..360).map(|d| (d as f64).to_radians()).map(|a| [a.cos(), 0.0, a.sin()]).collect();
        let q = quantize(&n, 16);
        assert!(q.palette.iter().all(|p| p[1].abs() < 1e-9), "{:?}", q.palette);
        assert!(angular_error(&n, &q.index, &q.palette).max < 20.0);
    }

    #[test]
    fn the_k_d_tree_finds_the_nearest() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let pts: Vec<[f64; 3]> = (0..300)
            .map(|_| unit([rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0)]))
            .collect();
        let t = Nearest::new(&pts);
        for _ in 0..2_000 {
            let q = unit([rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0)]);
            let brute = (0..pts.len()).min_by(|&a, &b| {
                let (da, db) = (
                    (0..3).map(|c| (pts[a][c] - q[c]).powi(2)).sum::<f64>(),
                    (0..3).map(|c| (pts[b][c] - q[c]).powi(2)).sum::<f64>(),
                );
                da.total_cmp(&db)
            });
            assert_eq!(Some(t.find(q)), brute);
        }
    }

    #[test]
    fn dithering_spreads_the_error_and_mips_shrink_to_one_texel() {
        // normals turning slowly from A to B along x, a palette of A and B alone: the nearest choice makes two bands
        // (every 8 × 8 block as wrong as its texels), error diffusion mixes them so that blocks average to the input
        let (a, b) = (unit([-0.5, 1.0, 0.0]), unit([0.5, 1.0, 0.0]));
        let n: Vec<[f64; 3]> = (0..64 * 64).map(|q| unit([-0.5 + (q % 64) as f64 / 63.0, 1.0, 0.0])).collect();
        let palette = [a, b];
        let tree = Nearest::new(&palette);
        let plain: Vec<u32> = n.iter().map(|&x| tree.find(x) as u32).collect();
        let d = dither(&n, 64, 64, &palette);
        let block_err = |idx: &[u32]| {
            let mut s = 0.0f64;
            for by in 0..8 {
                for bx in 0..8 {
                    let (mut m, mut p) = ([0.0; 3], [0.0; 3]);
                    for y in 8 * by..8 * by + 8 {
                        for x in 8 * bx..8 * bx + 8 {
                            for c in 0..3 {
                                m[c] += n[y * 64 + x][c];
                                p[c] += palette[idx[y * 64 + x] as usize][c];
                            }
                        }
                    }
                    s = s.max(crate::stats::angle_deg(m, p));
                }
            }
            s
        };
        assert!(block_err(&d) < 0.25 * block_err(&plain), "dithered {} vs plain {}", block_err(&d), block_err(&plain));
        let q = quantize(&bumpy(48, 48), 16);
        // a 5 × 3 map (not a power of two): 3 × 2, 2 × 1, 1 × 1
        let small: Vec<u32> = (0..15).map(|i| q.index[i]).collect();
        let chain = mip_chain(&small, 5, 3, &q.palette);
        assert_eq!(chain.iter().map(|(_, w, h)| (*w, *h)).collect::<Vec<_>>(), [(5, 3), (3, 2), (2, 1), (1, 1)]);
        // four equal normals average to themselves
        let same = vec![3u32; 16];
        assert!(mip(&same, 4, 4, &q.palette).0.iter().all(|&i| i == 3));
    }
}
