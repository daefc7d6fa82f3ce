//! A family's pipeline on the texture unit: a host-fed pipeline (`cart_pipeline`, `cart_surface`, `polar_pipeline`
//! and their variants) with the texture unit's front (`texture::front`) in place of the texels and blend factors the
//! host fetched: the front's ports first, then the host pipeline's other ports, by name.
//!
//! The model is the two wired, vector by vector over the front's memory: the front gives the texel's two bytes
//! (filtered, or the nearest), which go in at every texel port of the host model (a Cartesian host's TexelX or U
//! and TexelZ or V, a polar host's S and R) with blend factors of zero (the host's bilinear unit then returns the
//! texel itself, a test checks it), and the host model does the rest. With a colour map (`_colour`) the front's
//! colour, from the colour map's memory, goes in at the host's destination colour (`dst_r`, `dst_g`, `dst_b`): the
//! pixel's existing colour that the blend mixes with the lit one. `textured!` writes one such pipeline's model;
//! `cart_tex` and `polar_tex` hold the families' pipelines.

use crate::tex_fetch::pattern;
use crate::texture::front::{self, At, Filter, Front};
use crate::unit::{Machine, Port, UnitModel};

/// Where the host model's input `k` comes from.
#[derive(Clone, Copy, Debug)]
enum Source {
    /// the texel's low byte (TexelX or U) or its high byte (TexelZ or V)
    Byte(usize),
    /// a blend factor: zero
    Zero,
    /// a channel of the front's colour (R, G, B), with a colour map
    Colour(usize),
    /// the textured pipeline's own port
    Port(usize),
}

/// Whether a host port carries a texel byte: `t00_x` … `t11_z`, or the nearest texel's `t_x`, `t_z`.
fn is_texel(name: &str) -> bool {
    name.len() <= 5 && name.starts_with('t') && name[1..].trim_start_matches(char::is_numeric).starts_with('_')
}

/// Whether the host is a polar pipeline, whose texel is S (the low byte) and R (the high byte).
fn is_polar(host: &UnitModel) -> bool {
    host.name.starts_with("polar_pipeline")
}

/// Whether the host is the palette pipeline, whose texel's low byte is the index (its high byte unused).
fn is_palette(host: &UnitModel) -> bool {
    host.name == crate::palette_pipeline::MODEL.name
}

/// Which byte of the texel a host port carries: 0 the low byte (TexelX, U, S or a palette index), 1 the high byte
/// (TexelZ, V or R); `None` for a port that carries none.
fn texel_byte(host: &UnitModel, name: &str) -> Option<usize> {
    match name {
        "s" if is_polar(host) => Some(0),
        "r" if is_polar(host) => Some(1),
        "idx" if is_palette(host) => Some(0),
        n if !is_polar(host) && !is_palette(host) && is_texel(n) && n.ends_with("_x") => Some(0),
        n if !is_polar(host) && !is_palette(host) && is_texel(n) && n.ends_with("_z") => Some(1),
        _ => None,
    }
}

/// Whether a textured pipeline's ports hold a colour map's (its memory select).
pub fn has_colour(ports: &[Port]) -> bool {
    ports.iter().any(|p| p.name == front::COLOUR.name)
}

fn sources(host: &UnitModel, ports: &[Port]) -> Vec<Source> {
    let colour = has_colour(ports);
    host.inputs
        .iter()
        .map(|p| match (p.name, texel_byte(host, p.name)) {
            (_, Some(k)) => Source::Byte(k),
            ("ublend" | "vblend", _) => Source::Zero,
            ("dst_r", _) if colour => Source::Colour(0),
            ("dst_g", _) if colour => Source::Colour(1),
            ("dst_b", _) if colour => Source::Colour(2),
            (n, _) => Source::Port(front::index(ports, n)),
        })
        .collect()
}

/// The host's state: none for the shading pipelines (each vector on its own), the two colour tables for the
/// palette pipeline (its builder writes them, its pixels read them).
#[derive(Clone)]
enum HostState {
    Stateless,
    Palette(crate::palette_pipeline::Unit<8>),
}

/// A textured pipeline as a machine: the front with its memory (empty from reset), and the host model it feeds
/// (with its own state from reset, where it has one).
#[derive(Clone)]
pub struct Textured {
    front: Front,
    at: At,
    src: Vec<Source>,
    host: &'static UnitModel,
    state: HostState,
}

impl Textured {
    /// The pipeline on a front that reads its levels in `passes` clocks (1, or 2 for trilinear's two passes).
    pub fn new(filter: Filter, passes: usize, host: &'static UnitModel, ports: &[Port]) -> Textured {
        let front = if has_colour(ports) { Front::with_colour(filter) } else { Front::in_passes(filter, passes) };
        let state = if is_palette(host) {
            HostState::Palette(Default::default())
        } else {
            assert!(host.stream.is_none(), "{}: a host with state other than the palette pipeline's", host.name);
            HostState::Stateless
        };
        Textured { front, at: At::of(ports, filter.mip()), src: sources(host, ports), host, state }
    }
}

impl Machine for Textured {
    fn step(&mut self, v: &[i64]) -> Vec<i64> {
        let (t, c) = self.front.step_all(v, &self.at);
        let h = host_of(&self.src, v, t, c);
        match &mut self.state {
            HostState::Stateless => (self.host.exact)(&h),
            HostState::Palette(p) => p.step(&h),
        }
    }
    /// The front's step, and the host's where it has state: the outputs are what nobody reads.
    fn load(&mut self, v: &[i64]) {
        match &mut self.state {
            HostState::Stateless => {
                self.front.step(v, &self.at);
            }
            HostState::Palette(p) => {
                let (t, c) = self.front.step_all(v, &self.at);
                p.load(&host_of(&self.src, v, t, c));
            }
        }
    }
}

/// The host's vector for a vector `v` of the textured pipeline whose front gave the texel (lo, hi) and the colour
/// `c` (zeros without a colour map): every texel port of the host that texel (a footprint of four equal texels,
/// which the bilinear unit returns unchanged at blend factors of zero), with a colour map its destination colour
/// `c`, its other ports `v`'s of the same name.
pub fn host_vector(host: &UnitModel, ports: &[Port], v: &[i64], t: [i64; 2], c: [i64; 3]) -> Vec<i64> {
    host_of(&sources(host, ports), v, t, c)
}

fn host_of(src: &[Source], v: &[i64], t: [i64; 2], c: [i64; 3]) -> Vec<i64> {
    src.iter()
        .map(|s| match *s {
            Source::Byte(k) => t[k],
            Source::Colour(k) => c[k],
            Source::Zero => 0,
            Source::Port(k) => v[k],
        })
        .collect()
}

/// The levels the random vectors read and write: the chain of a 16 × 16 map, which the hard cases load first.
pub const REGION_LOG2: i64 = 4;

/// A vector of the textured pipeline from a vector of its host: the host's other ports by name, the front's zero.
pub fn from_host(host: &UnitModel, ports: &[Port], h: &[i64]) -> Vec<i64> {
    ports.iter().map(|p| host.inputs.iter().position(|q| q.name == p.name).map_or(0, |k| h[k])).collect()
}

/// One random vector: the host's random ports; one in eight a write inside the region's chain (with a colour map,
/// of either memory), else a read of a map of side up to 2^REGION_LOG2 at a random position and wrap, with the
/// LOD unit's random derivatives.
pub fn random(filter: Filter, host: &UnitModel, ports: &[Port], rng: &mut dyn rand::RngCore) -> Vec<i64> {
    use rand::Rng;
    let mut v = from_host(host, ports, &(host.random)(rng));
    let at = At::of(ports, filter.mip());
    if rng.gen_range(0..8) == 0 {
        let m = rng.gen_range(0..=REGION_LOG2);
        let (x, y) = (rng.gen_range(0..1 << m), rng.gen_range(0..1 << m));
        if at.wcolour.is_some() && rng.gen_bool(0.5) {
            front::put_colour_write(&mut v, &at, m, x, y, rng.gen_range(0..=0xffff));
        } else {
            front::put_write(&mut v, &at, m, x, y, rng.gen_range(0..=0xffff));
        }
        return v;
    }
    let s = rng.gen_range(0..=REGION_LOG2);
    let uv = [front::random_position(rng, s), front::random_position(rng, s)];
    let d = (crate::lod::MODEL.random)(rng);
    front::put_read(&mut v, &at, uv, s, [rng.gen_bool(0.5), rng.gen_bool(0.5)], [d[0], d[1], d[2], d[3]]);
    front::put_bias(&mut v, &at, d[5]);
    v
}

/// A colour texel of the hard cases' colour chain: the bump chain's pattern, its bits turned round, so that the two
/// memories differ at every texel the hard cases read.
pub fn colour_pattern(m: i64, x: i64, y: i64) -> i64 {
    (pattern(m, x, y) as u16).reverse_bits() as i64
}

/// Which map sides the front's sweep of the hard cases reads: `Every` side up to 2^REGION_LOG2, or the `Ends` of
/// that range (the 1 × 1 and the 2 × 2 map, and the largest).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sweep {
    Every,
    Ends,
}

impl Sweep {
    /// The sweep of a textured pipeline: every side on the front's plain pipeline (the host `cart_pipeline`, with
    /// or without a colour map; the two-pass front, which has one pipeline), the ends on the others. The front, its
    /// address unit and its memories are the same blocks in every pipeline of one filter, so the sides in between
    /// are read once a front; a pipeline with another host (matte, hemi-octahedral, vertex lights) keeps every edge
    /// of the position, the wrap and λ (each level among them) at the ends of the sides, and its host's own hard
    /// cases.
    pub fn of(host: &UnitModel, passes: usize) -> Sweep {
        if host.name == crate::cart_pipeline::MODEL.name || passes > 1 {
            Sweep::Every
        } else {
            Sweep::Ends
        }
    }

    fn sides(self) -> Vec<i64> {
        match self {
            Sweep::Every => (0..=REGION_LOG2).collect(),
            Sweep::Ends => vec![0, 1, REGION_LOG2],
        }
    }
}

/// The hard cases: the region's chain loaded (with a colour map, the colour chain too); each of the host's hard
/// cases with its texel (and its destination colour, as RGB565) written into the 1 × 1 map and read from it; then on
/// the loaded chain (its 1 × 1 level written back), for the map sides `sweep` names, both wraps and both ends of
/// each axis, the positions at the seam and the clamp edge (the first and last texel's centres and ends, a step
/// either side); with a MIP filter, derivatives that put λ below 0, at each level, half way and past the last
/// level, zero and the largest; a write into the level being read followed at once by a read of it, and a read
/// followed at once by a write of its texel and the read again (the map rewritten under a read in flight); a polar
/// host's R across its wrap at every level (`r_wrap_seams`).
pub fn hard_cases(filter: Filter, host: &UnitModel, ports: &[Port], sweep: Sweep) -> Vec<Vec<i64>> {
    let at = At::of(ports, filter.mip());
    let hosts = (host.hard_cases)();
    let base = from_host(host, ports, &hosts[0]);
    let mut out = vec![];
    let write = |m: i64, x: i64, y: i64, t: i64| {
        let mut v = base.clone();
        front::put_write(&mut v, &at, m, x, y, t);
        v
    };
    for m in (0..=REGION_LOG2).rev() {
        for y in 0..1 << m {
            for x in 0..1 << m {
                out.push(write(m, x, y, pattern(m, x, y)));
                if at.wcolour.is_some() {
                    let mut v = base.clone();
                    front::put_colour_write(&mut v, &at, m, x, y, colour_pattern(m, x, y));
                    out.push(v);
                }
            }
        }
    }
    let byte = |k| host.inputs.iter().position(|p| texel_byte(host, p.name) == Some(k));
    let (tx, tz) = (byte(0).expect("a texel port"), byte(1));
    let dst = ["dst_r", "dst_g", "dst_b"].map(|n| host.inputs.iter().position(|p| p.name == n));
    for h in &hosts {
        out.push(write(0, 0, 0, h[tx] | tz.map_or(0, |z| h[z] << 8)));
        if let ([Some(r), Some(g), Some(b)], true) = (dst, at.wcolour.is_some()) {
            let mut v = base.clone();
            front::put_colour_write(&mut v, &at, 0, 0, 0, front::pack565([h[r], h[g], h[b]].map(|c| c as u8)));
            out.push(v);
        }
        let mut v = from_host(host, ports, h);
        front::put_read(&mut v, &at, [77, -300], 0, [true, false], [256, 0, 0, 256]);
        out.push(v);
    }
    out.push(write(0, 0, 0, pattern(0, 0, 0)));
    if at.wcolour.is_some() {
        let mut v = base.clone();
        front::put_colour_write(&mut v, &at, 0, 0, 0, colour_pattern(0, 0, 0));
        out.push(v);
    }
    let lambdas: Vec<[i64; 4]> = if filter.mip() {
        // λ = log2 of the longer edge: 2^-3, exactly 1 (level 0), each level k, k + ½ (a √2 edge), past the last;
        // zero derivatives; the largest magnitude (−256 texels a pixel) on each
        let mut d = vec![
            [32, 0, 0, 32],
            [0, 0, 0, 0],
            [-65_536, 0, 0, 0],
            [0, 0, 0, -65_536],
            [65_535, 65_535, 65_535, 65_535],
        ];
        for k in 0..=REGION_LOG2 + 1 {
            d.push([256 << k, 0, 0, 256 << k]);
            d.push([0, -(256 << k), 256 << k, 256 << k]);
            d.push([(256 << k) * 181 / 128, 0, 0, 0]);
            if filter == Filter::Trilinear {
                // just below the next level (frac(λ) ≈ 255/256): the second level's weight at its largest
                d.push([(256 << k) * 255 / 128, 0, 0, 0]);
            }
        }
        d
    } else {
        vec![[0; 4]]
    };
    for s in sweep.sides() {
        let side = 256i64 << s;
        let ends = [
            0,
            1,
            127,
            128,
            129,
            255,
            256,
            -1,
            -127,
            -128,
            -129,
            side - 129,
            side - 128,
            side - 127,
            side - 1,
            side,
            side + 127,
            side + 128,
        ];
        for wrap in [true, false] {
            for (k, e) in ends.iter().enumerate() {
                let d = lambdas[k % lambdas.len()];
                let mut v = base.clone();
                front::put_read(&mut v, &at, [*e, 3 * 256 / 2], s, [wrap, !wrap], d);
                out.push(v.clone());
                front::put_read(&mut v, &at, [side / 2 + 64, *e], s, [!wrap, wrap], d);
                out.push(v);
            }
        }
        for d in &lambdas {
            let mut v = base.clone();
            front::put_read(&mut v, &at, [side / 3, side / 5], s, [true, true], *d);
            out.push(v.clone());
            // with a LOD bias: its ends (below level 0 and past the last level from every footprint), and a level
            // either way
            if filter.mip() {
                for bias in [-(1 << 11), -256, 256, (1 << 11) - 1] {
                    front::put_bias(&mut v, &at, bias);
                    out.push(v.clone());
                }
            }
        }
    }
    // the ends of the position's range, each axis
    for e in [(1 << 19) - 1, -(1 << 19)] {
        for wrap in [true, false] {
            let mut v = base.clone();
            front::put_read(&mut v, &at, [e, -e - 1], REGION_LOG2, [wrap, wrap], lambdas[0]);
            out.push(v);
        }
    }
    // a write into the level being read, then at once a read of that texel
    out.push(write(2, 1, 2, 0x7f7f));
    let mut v = base.clone();
    front::put_read(&mut v, &at, [256 + 128, 512 + 128], 2, [true, true], [1024, 0, 0, 1024]);
    out.push(v.clone());
    if at.wcolour.is_some() {
        // the colour map's likewise, with each channel's extremes: white, black, then each channel's top code alone
        for t in [0xffff, 0x0000, 0xf800, 0x07e0, 0x001f] {
            let mut w = base.clone();
            front::put_colour_write(&mut w, &at, 2, 1, 2, t);
            out.push(w);
            out.push(v.clone());
        }
    }
    // the map rewritten while a read of it is still in the pipeline: texel (1, 2) of the side-4 map read at level
    // 0, written at once, and read again; the first read gives the texel it had, the second the new one
    let mut v = base.clone();
    front::put_read(&mut v, &at, [256 + 128, 512 + 128], 2, [true, true], [256, 0, 0, 256]);
    out.push(v.clone());
    out.push(write(2, 1, 2, 0x1c_e3));
    out.push(v);
    if is_polar(host) {
        out.extend(r_wrap_seams(filter, &at, &base).into_iter().flatten());
    }
    out
}

/// A polar map's R across its 255 → 0 wrap at every level of the region's chain (US 6,819,319's shortcoming 2, made
/// by the front's filter): in the level of side 2^m (m ≥ 1) R = 6 in column 0 and R = 250 in columns 1 and 2^m − 1,
/// S = 100, rows 0 and 1. The first vectors write them; then, level by level, reads at row 0's centre half way
/// between two columns: inside the map (x = 1.0 texels of the level) and across its edge (x = 0: repeating, column
/// 2^m − 1 beside column 0; clamped, column 0 alone), as level 0 of the map of side 2^m and, with a MIP filter, as
/// the level of the region's map that λ names and half a level past it (trilinear: half way to the next).
pub fn r_wrap_seams(filter: Filter, at: &At, base: &[i64]) -> Vec<Vec<Vec<i64>>> {
    let mut writes = vec![];
    for m in 1..=REGION_LOG2 {
        for y in 0..2 {
            for (x, r) in [(0, 6), (1, 250), ((1 << m) - 1, 250)] {
                let mut v = base.to_vec();
                front::put_write(&mut v, at, m, x, y, 100 | (r << 8));
                writes.push(v);
            }
        }
    }
    let mut levels = vec![writes];
    for m in 1..=REGION_LOG2 {
        // (the map's log side, the derivatives, the level's texel in level-0 texels of that map)
        let mut reads: Vec<(i64, [i64; 4], i64)> = vec![(m, [256, 0, 0, 256], 256)];
        if filter.mip() {
            let k = REGION_LOG2 - m;
            reads.push((REGION_LOG2, [256 << k, 0, 0, 256 << k], 256 << k));
            reads.push((REGION_LOG2, [(256 << k) * 181 / 128, 0, 0, 0], 256 << k));
        }
        let mut level = vec![];
        for (s, d, texel) in reads {
            for x in [0, texel] {
                for wrap in [true, false] {
                    let mut v = base.to_vec();
                    front::put_read(&mut v, at, [x, texel / 2], s, [wrap, true], d);
                    level.push(v);
                }
            }
        }
        levels.push(level);
    }
    levels
}

/// The front's ports (with a colour map, its memory select) followed by the host's other ports (with a colour map,
/// but the destination colour), as the textured pipeline's port list must be.
pub fn expected_ports(filter: Filter, host: &UnitModel, colour: bool) -> Vec<Port> {
    let mut v: Vec<Port> = front::PORTS.to_vec();
    if colour {
        v.push(front::COLOUR);
    }
    if filter.mip() {
        v.extend_from_slice(front::DERIVATIVES);
    }
    let dst = |n: &str| colour && matches!(n, "dst_r" | "dst_g" | "dst_b");
    let dropped = |n: &str| matches!(n, "ublend" | "vblend") || texel_byte(host, n).is_some() || dst(n);
    v.extend(host.inputs.iter().filter(|p| !dropped(p.name)).copied());
    v
}

macro_rules! textured {
    // a Cartesian host's outputs unless the invocation names its host's
    (
        $m:ident, $name:literal, $filter:expr, $host:path, $(passes: $passes:literal,)? inputs: [$($ports:tt)*]
    ) => {
        $crate::texture::textured::textured!(
            $m, $name, $filter, $host, $(passes: $passes,)? inputs: [$($ports)*],
            outputs: [p: u 10, out_r: u 8, out_g: u 8, out_b: u 8]
        );
    };
    (
        $m:ident, $name:literal, $filter:expr, $host:path, $(passes: $passes:literal,)? inputs: [$($ports:tt)*],
        outputs: [$($outs:tt)*]
    ) => {
        pub mod $m {
            use super::*;
            crate::ports! {
                inputs: [$($ports)*],
                outputs: [$($outs)*],
            }
            pub const FILTER: Filter = $filter;
            /// The clocks a pixel takes: the front's passes.
            pub const PASSES: usize = 1 $(* $passes)?;
            pub fn host() -> &'static UnitModel {
                &$host
            }
            /// The pipeline from reset as a machine.
            #[derive(Clone)]
            pub struct Unit(Textured);
            impl Default for Unit {
                fn default() -> Unit {
                    Unit(Textured::new(FILTER, PASSES, host(), INPUTS))
                }
            }
            impl Machine for Unit {
                fn step(&mut self, v: &[i64]) -> Vec<i64> {
                    self.0.step(v)
                }
                fn load(&mut self, v: &[i64]) {
                    self.0.load(v)
                }
            }
            fn exact(v: &[i64]) -> Vec<i64> {
                Unit::default().step(v)
            }
            fn random_vector(rng: &mut dyn rand::RngCore) -> Vec<i64> {
                random(FILTER, host(), INPUTS, rng)
            }
            fn hard() -> Vec<Vec<i64>> {
                hard_cases(FILTER, host(), INPUTS, Sweep::of(host(), PASSES))
            }
            pub static MODEL: UnitModel =
                UnitModel::new($name, (INPUTS, OUTPUTS), exact, random_vector, hard).with_stream::<Unit>();
        }
    };
}
pub(crate) use textured;
