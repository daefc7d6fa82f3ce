//! `cart_tex_*`: the Cartesian pipelines on the texture unit. Each is a host-fed Cartesian pipeline (`cart_pipeline`
//! or `cart_surface` and their variants) with the texture unit's front (`texture::front`) in place of the texels and
//! blend factors the host fetched: the front's ports first, then the host pipeline's other ports, by name.
//!
//! The model is the two wired, vector by vector over the front's memory: the front gives the texel's two bytes
//! (filtered, or the nearest), which go in at every texel port of the host model with blend factors of zero (the
//! host's bilinear unit then returns the texel itself, a test checks it), and the host model does the rest. With a
//! colour map (`_colour`) the front's colour, from the colour map's memory, goes in at the host's destination
//! colour (`dst_r`, `dst_g`, `dst_b`): the pixel's existing colour that the blend mixes with the lit one.

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

/// Whether a textured pipeline's ports hold a colour map's (its memory select).
pub fn has_colour(ports: &[Port]) -> bool {
    ports.iter().any(|p| p.name == front::COLOUR.name)
}

fn sources(host: &UnitModel, ports: &[Port]) -> Vec<Source> {
    let colour = has_colour(ports);
    host.inputs
        .iter()
        .map(|p| {
            let texel = is_texel(p.name);
            match p.name {
                "ublend" | "vblend" => Source::Zero,
                "dst_r" if colour => Source::Colour(0),
                "dst_g" if colour => Source::Colour(1),
                "dst_b" if colour => Source::Colour(2),
                n if texel && n.ends_with("_x") => Source::Byte(0),
                n if texel && n.ends_with("_z") => Source::Byte(1),
                n => Source::Port(front::index(ports, n)),
            }
        })
        .collect()
}

/// A textured pipeline as a machine: the front with its memory (empty from reset), and the host model it feeds.
#[derive(Clone)]
pub struct Textured {
    front: Front,
    at: At,
    src: Vec<Source>,
    host: &'static UnitModel,
}

impl Textured {
    /// The pipeline on a front that reads its levels in `passes` clocks (1, or 2 for trilinear's two passes).
    pub fn new(filter: Filter, passes: usize, host: &'static UnitModel, ports: &[Port]) -> Textured {
        let front = if has_colour(ports) { Front::with_colour(filter) } else { Front::in_passes(filter, passes) };
        Textured { front, at: At::of(ports, filter.mip()), src: sources(host, ports), host }
    }
}

impl Machine for Textured {
    fn step(&mut self, v: &[i64]) -> Vec<i64> {
        let (t, c) = self.front.step_all(v, &self.at);
        (self.host.exact)(&host_of(&self.src, v, t, c))
    }
    /// The front's step alone: the host's outputs are what nobody reads.
    fn load(&mut self, v: &[i64]) {
        self.front.step(v, &self.at);
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
/// level, zero and the largest.
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
    let (tx, tz) = (
        host.inputs.iter().position(|p| p.name == "t00_x" || p.name == "t_x").expect("a texel port"),
        host.inputs.iter().position(|p| p.name == "t00_z" || p.name == "t_z").expect("a texel port"),
    );
    let dst = ["dst_r", "dst_g", "dst_b"].map(|n| host.inputs.iter().position(|p| p.name == n));
    for h in &hosts {
        out.push(write(0, 0, 0, h[tx] | (h[tz] << 8)));
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
    out
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
    let dropped = |n: &str| matches!(n, "ublend" | "vblend") || is_texel(n) || dst(n);
    v.extend(host.inputs.iter().filter(|p| !dropped(p.name)).copied());
    v
}

macro_rules! textured {
    ($m:ident, $name:literal, $filter:expr, $host:path, $(passes: $passes:literal,)? inputs: [$($ports:tt)*]) => {
        pub mod $m {
            use super::*;
            crate::ports! {
                inputs: [$($ports)*],
                outputs: [p: u 10, out_r: u 8, out_g: u 8, out_b: u 8],
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

textured!(bilinear, "cart_tex_bilinear", Filter::Bilinear, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(bilinear_matte, "cart_tex_bilinear_matte", Filter::Bilinear, crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(nearest_matte, "cart_tex_nearest_matte", Filter::Nearest, crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(nearest_mip_matte, "cart_tex_nearest_mip_matte", Filter::NearestMip, crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(trilinear_matte, "cart_tex_trilinear_matte", Filter::Trilinear, crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(trilinear, "cart_tex_trilinear", Filter::Trilinear, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_hemi_oct, "cart_tex_trilinear_hemi_oct", Filter::Trilinear, crate::cart_pipeline::MODEL_HEMI_OCT,
    inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_surface, "cart_tex_trilinear_surface", Filter::Trilinear, crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_two_pass_matte, "cart_tex_trilinear_two_pass_matte", Filter::Trilinear,
    crate::cart_pipeline::MODEL_MATTE, passes: 2, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    bilinear_hemi_oct, "cart_tex_bilinear_hemi_oct", Filter::Bilinear, crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    bilinear_surface, "cart_tex_bilinear_surface", Filter::Bilinear, crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    bilinear_surface_matte, "cart_tex_bilinear_surface_matte", Filter::Bilinear, crate::cart_surface::MODEL_MATTE,
    inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_surface_matte, "cart_tex_nearest_surface_matte", Filter::Nearest, crate::cart_surface::MODEL_MATTE,
    inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_surface_hemi_oct_matte, "cart_tex_nearest_surface_hemi_oct_matte", Filter::Nearest,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(bilinear_colour, "cart_tex_bilinear_colour", Filter::Bilinear, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_surface_colour, "cart_tex_bilinear_surface_colour", Filter::Bilinear, crate::cart_surface::MODEL,
    inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(nearest, "cart_tex_nearest", Filter::Nearest, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(nearest_mip, "cart_tex_nearest_mip", Filter::NearestMip, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    bilinear_hemi_oct_matte, "cart_tex_bilinear_hemi_oct_matte", Filter::Bilinear,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_hemi_oct_matte, "cart_tex_trilinear_hemi_oct_matte", Filter::Trilinear,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_surface_matte, "cart_tex_trilinear_surface_matte", Filter::Trilinear, crate::cart_surface::MODEL_MATTE,
    inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(nearest_colour, "cart_tex_nearest_colour", Filter::Nearest, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(nearest_mip_colour, "cart_tex_nearest_mip_colour", Filter::NearestMip, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_hemi_oct, "cart_tex_nearest_hemi_oct", Filter::Nearest,
    crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_hemi_oct_matte, "cart_tex_nearest_hemi_oct_matte", Filter::Nearest,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_surface, "cart_tex_nearest_surface", Filter::Nearest,
    crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_surface_hemi_oct, "cart_tex_nearest_surface_hemi_oct", Filter::Nearest,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_mip_hemi_oct, "cart_tex_nearest_mip_hemi_oct", Filter::NearestMip,
    crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_mip_hemi_oct_matte, "cart_tex_nearest_mip_hemi_oct_matte", Filter::NearestMip,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_mip_surface, "cart_tex_nearest_mip_surface", Filter::NearestMip,
    crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_mip_surface_matte, "cart_tex_nearest_mip_surface_matte", Filter::NearestMip,
    crate::cart_surface::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_mip_surface_hemi_oct, "cart_tex_nearest_mip_surface_hemi_oct", Filter::NearestMip,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_mip_surface_hemi_oct_matte, "cart_tex_nearest_mip_surface_hemi_oct_matte", Filter::NearestMip,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    bilinear_surface_hemi_oct, "cart_tex_bilinear_surface_hemi_oct", Filter::Bilinear,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    bilinear_surface_hemi_oct_matte, "cart_tex_bilinear_surface_hemi_oct_matte", Filter::Bilinear,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_surface_hemi_oct, "cart_tex_trilinear_surface_hemi_oct", Filter::Trilinear,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    trilinear_surface_hemi_oct_matte, "cart_tex_trilinear_surface_hemi_oct_matte", Filter::Trilinear,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
]);

textured!(
    nearest_matte_colour, "cart_tex_nearest_matte_colour", Filter::Nearest,
    crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_hemi_oct_colour, "cart_tex_nearest_hemi_oct_colour", Filter::Nearest,
    crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_hemi_oct_matte_colour, "cart_tex_nearest_hemi_oct_matte_colour", Filter::Nearest,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_surface_colour, "cart_tex_nearest_surface_colour", Filter::Nearest,
    crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_surface_matte_colour, "cart_tex_nearest_surface_matte_colour", Filter::Nearest,
    crate::cart_surface::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_surface_hemi_oct_colour, "cart_tex_nearest_surface_hemi_oct_colour", Filter::Nearest,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_surface_hemi_oct_matte_colour, "cart_tex_nearest_surface_hemi_oct_matte_colour", Filter::Nearest,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_matte_colour, "cart_tex_nearest_mip_matte_colour", Filter::NearestMip,
    crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_hemi_oct_colour, "cart_tex_nearest_mip_hemi_oct_colour", Filter::NearestMip,
    crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_hemi_oct_matte_colour, "cart_tex_nearest_mip_hemi_oct_matte_colour", Filter::NearestMip,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_surface_colour, "cart_tex_nearest_mip_surface_colour", Filter::NearestMip,
    crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_surface_matte_colour, "cart_tex_nearest_mip_surface_matte_colour", Filter::NearestMip,
    crate::cart_surface::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_surface_hemi_oct_colour, "cart_tex_nearest_mip_surface_hemi_oct_colour", Filter::NearestMip,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    nearest_mip_surface_hemi_oct_matte_colour, "cart_tex_nearest_mip_surface_hemi_oct_matte_colour", Filter::NearestMip,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_matte_colour, "cart_tex_bilinear_matte_colour", Filter::Bilinear,
    crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_hemi_oct_colour, "cart_tex_bilinear_hemi_oct_colour", Filter::Bilinear,
    crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_hemi_oct_matte_colour, "cart_tex_bilinear_hemi_oct_matte_colour", Filter::Bilinear,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_surface_matte_colour, "cart_tex_bilinear_surface_matte_colour", Filter::Bilinear,
    crate::cart_surface::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_surface_hemi_oct_colour, "cart_tex_bilinear_surface_hemi_oct_colour", Filter::Bilinear,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    bilinear_surface_hemi_oct_matte_colour, "cart_tex_bilinear_surface_hemi_oct_matte_colour", Filter::Bilinear,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(trilinear_colour, "cart_tex_trilinear_colour", Filter::Trilinear, crate::cart_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_matte_colour, "cart_tex_trilinear_matte_colour", Filter::Trilinear,
    crate::cart_pipeline::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_hemi_oct_colour, "cart_tex_trilinear_hemi_oct_colour", Filter::Trilinear,
    crate::cart_pipeline::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_hemi_oct_matte_colour, "cart_tex_trilinear_hemi_oct_matte_colour", Filter::Trilinear,
    crate::cart_pipeline::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l0_x: s 8, l0_y: s 8, l0_z: s 8, l1_x: s 8, l1_y: s 8, l1_z: s 8, l2_x: s 8, l2_y: s 8, l2_z: s 8,
    w1: u 9, w2: u 9, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_surface_colour, "cart_tex_trilinear_surface_colour", Filter::Trilinear,
    crate::cart_surface::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_surface_matte_colour, "cart_tex_trilinear_surface_matte_colour", Filter::Trilinear,
    crate::cart_surface::MODEL_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_surface_hemi_oct_colour, "cart_tex_trilinear_surface_hemi_oct_colour", Filter::Trilinear,
    crate::cart_surface::MODEL_HEMI_OCT, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, conc: u 8, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

textured!(
    trilinear_surface_hemi_oct_matte_colour, "cart_tex_trilinear_surface_hemi_oct_matte_colour", Filter::Trilinear,
    crate::cart_surface::MODEL_HEMI_OCT_MATTE, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    wcolour: u 1,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    l_x: s 12, l_y: s 12, l_z: s 12, mode: u 1, src_r: u 8, src_g: u 8, src_b: u 8,
]);

/// Every textured pipeline's model, its filter and its host.
pub fn all() -> [(&'static UnitModel, Filter, &'static UnitModel); 65] {
    [
        (&bilinear::MODEL, bilinear::FILTER, bilinear::host()),
        (&bilinear_matte::MODEL, bilinear_matte::FILTER, bilinear_matte::host()),
        (&nearest_matte::MODEL, nearest_matte::FILTER, nearest_matte::host()),
        (&nearest_mip_matte::MODEL, nearest_mip_matte::FILTER, nearest_mip_matte::host()),
        (&trilinear_matte::MODEL, trilinear_matte::FILTER, trilinear_matte::host()),
        (&trilinear_two_pass_matte::MODEL, trilinear_two_pass_matte::FILTER, trilinear_two_pass_matte::host()),
        (&trilinear::MODEL, trilinear::FILTER, trilinear::host()),
        (&trilinear_hemi_oct::MODEL, trilinear_hemi_oct::FILTER, trilinear_hemi_oct::host()),
        (&trilinear_surface::MODEL, trilinear_surface::FILTER, trilinear_surface::host()),
        (&bilinear_hemi_oct::MODEL, bilinear_hemi_oct::FILTER, bilinear_hemi_oct::host()),
        (&bilinear_surface::MODEL, bilinear_surface::FILTER, bilinear_surface::host()),
        (&bilinear_surface_matte::MODEL, bilinear_surface_matte::FILTER, bilinear_surface_matte::host()),
        (&nearest_surface_matte::MODEL, nearest_surface_matte::FILTER, nearest_surface_matte::host()),
        (
            &nearest_surface_hemi_oct_matte::MODEL,
            nearest_surface_hemi_oct_matte::FILTER,
            nearest_surface_hemi_oct_matte::host(),
        ),
        (&nearest::MODEL, nearest::FILTER, nearest::host()),
        (&nearest_mip::MODEL, nearest_mip::FILTER, nearest_mip::host()),
        (&bilinear_hemi_oct_matte::MODEL, bilinear_hemi_oct_matte::FILTER, bilinear_hemi_oct_matte::host()),
        (&trilinear_hemi_oct_matte::MODEL, trilinear_hemi_oct_matte::FILTER, trilinear_hemi_oct_matte::host()),
        (&trilinear_surface_matte::MODEL, trilinear_surface_matte::FILTER, trilinear_surface_matte::host()),
        (&bilinear_colour::MODEL, bilinear_colour::FILTER, bilinear_colour::host()),
        (&bilinear_surface_colour::MODEL, bilinear_surface_colour::FILTER, bilinear_surface_colour::host()),
        (&nearest_colour::MODEL, nearest_colour::FILTER, nearest_colour::host()),
        (&nearest_mip_colour::MODEL, nearest_mip_colour::FILTER, nearest_mip_colour::host()),
        (&nearest_hemi_oct::MODEL, nearest_hemi_oct::FILTER, nearest_hemi_oct::host()),
        (&nearest_hemi_oct_matte::MODEL, nearest_hemi_oct_matte::FILTER, nearest_hemi_oct_matte::host()),
        (&nearest_surface::MODEL, nearest_surface::FILTER, nearest_surface::host()),
        (&nearest_surface_hemi_oct::MODEL, nearest_surface_hemi_oct::FILTER, nearest_surface_hemi_oct::host()),
        (&nearest_mip_hemi_oct::MODEL, nearest_mip_hemi_oct::FILTER, nearest_mip_hemi_oct::host()),
        (&nearest_mip_hemi_oct_matte::MODEL, nearest_mip_hemi_oct_matte::FILTER, nearest_mip_hemi_oct_matte::host()),
        (&nearest_mip_surface::MODEL, nearest_mip_surface::FILTER, nearest_mip_surface::host()),
        (&nearest_mip_surface_matte::MODEL, nearest_mip_surface_matte::FILTER, nearest_mip_surface_matte::host()),
        (
            &nearest_mip_surface_hemi_oct::MODEL,
            nearest_mip_surface_hemi_oct::FILTER,
            nearest_mip_surface_hemi_oct::host(),
        ),
        (
            &nearest_mip_surface_hemi_oct_matte::MODEL,
            nearest_mip_surface_hemi_oct_matte::FILTER,
            nearest_mip_surface_hemi_oct_matte::host(),
        ),
        (&bilinear_surface_hemi_oct::MODEL, bilinear_surface_hemi_oct::FILTER, bilinear_surface_hemi_oct::host()),
        (
            &bilinear_surface_hemi_oct_matte::MODEL,
            bilinear_surface_hemi_oct_matte::FILTER,
            bilinear_surface_hemi_oct_matte::host(),
        ),
        (&trilinear_surface_hemi_oct::MODEL, trilinear_surface_hemi_oct::FILTER, trilinear_surface_hemi_oct::host()),
        (
            &trilinear_surface_hemi_oct_matte::MODEL,
            trilinear_surface_hemi_oct_matte::FILTER,
            trilinear_surface_hemi_oct_matte::host(),
        ),
        (&nearest_matte_colour::MODEL, nearest_matte_colour::FILTER, nearest_matte_colour::host()),
        (&nearest_hemi_oct_colour::MODEL, nearest_hemi_oct_colour::FILTER, nearest_hemi_oct_colour::host()),
        (
            &nearest_hemi_oct_matte_colour::MODEL,
            nearest_hemi_oct_matte_colour::FILTER,
            nearest_hemi_oct_matte_colour::host(),
        ),
        (&nearest_surface_colour::MODEL, nearest_surface_colour::FILTER, nearest_surface_colour::host()),
        (
            &nearest_surface_matte_colour::MODEL,
            nearest_surface_matte_colour::FILTER,
            nearest_surface_matte_colour::host(),
        ),
        (
            &nearest_surface_hemi_oct_colour::MODEL,
            nearest_surface_hemi_oct_colour::FILTER,
            nearest_surface_hemi_oct_colour::host(),
        ),
        (
            &nearest_surface_hemi_oct_matte_colour::MODEL,
            nearest_surface_hemi_oct_matte_colour::FILTER,
            nearest_surface_hemi_oct_matte_colour::host(),
        ),
        (&nearest_mip_matte_colour::MODEL, nearest_mip_matte_colour::FILTER, nearest_mip_matte_colour::host()),
        (&nearest_mip_hemi_oct_colour::MODEL, nearest_mip_hemi_oct_colour::FILTER, nearest_mip_hemi_oct_colour::host()),
        (
            &nearest_mip_hemi_oct_matte_colour::MODEL,
            nearest_mip_hemi_oct_matte_colour::FILTER,
            nearest_mip_hemi_oct_matte_colour::host(),
        ),
        (&nearest_mip_surface_colour::MODEL, nearest_mip_surface_colour::FILTER, nearest_mip_surface_colour::host()),
        (
            &nearest_mip_surface_matte_colour::MODEL,
            nearest_mip_surface_matte_colour::FILTER,
            nearest_mip_surface_matte_colour::host(),
        ),
        (
            &nearest_mip_surface_hemi_oct_colour::MODEL,
            nearest_mip_surface_hemi_oct_colour::FILTER,
            nearest_mip_surface_hemi_oct_colour::host(),
        ),
        (
            &nearest_mip_surface_hemi_oct_matte_colour::MODEL,
            nearest_mip_surface_hemi_oct_matte_colour::FILTER,
            nearest_mip_surface_hemi_oct_matte_colour::host(),
        ),
        (&bilinear_matte_colour::MODEL, bilinear_matte_colour::FILTER, bilinear_matte_colour::host()),
        (&bilinear_hemi_oct_colour::MODEL, bilinear_hemi_oct_colour::FILTER, bilinear_hemi_oct_colour::host()),
        (
            &bilinear_hemi_oct_matte_colour::MODEL,
            bilinear_hemi_oct_matte_colour::FILTER,
            bilinear_hemi_oct_matte_colour::host(),
        ),
        (
            &bilinear_surface_matte_colour::MODEL,
            bilinear_surface_matte_colour::FILTER,
            bilinear_surface_matte_colour::host(),
        ),
        (
            &bilinear_surface_hemi_oct_colour::MODEL,
            bilinear_surface_hemi_oct_colour::FILTER,
            bilinear_surface_hemi_oct_colour::host(),
        ),
        (
            &bilinear_surface_hemi_oct_matte_colour::MODEL,
            bilinear_surface_hemi_oct_matte_colour::FILTER,
            bilinear_surface_hemi_oct_matte_colour::host(),
        ),
        (&trilinear_colour::MODEL, trilinear_colour::FILTER, trilinear_colour::host()),
        (&trilinear_matte_colour::MODEL, trilinear_matte_colour::FILTER, trilinear_matte_colour::host()),
        (&trilinear_hemi_oct_colour::MODEL, trilinear_hemi_oct_colour::FILTER, trilinear_hemi_oct_colour::host()),
        (
            &trilinear_hemi_oct_matte_colour::MODEL,
            trilinear_hemi_oct_matte_colour::FILTER,
            trilinear_hemi_oct_matte_colour::host(),
        ),
        (&trilinear_surface_colour::MODEL, trilinear_surface_colour::FILTER, trilinear_surface_colour::host()),
        (
            &trilinear_surface_matte_colour::MODEL,
            trilinear_surface_matte_colour::FILTER,
            trilinear_surface_matte_colour::host(),
        ),
        (
            &trilinear_surface_hemi_oct_colour::MODEL,
            trilinear_surface_hemi_oct_colour::FILTER,
            trilinear_surface_hemi_oct_colour::host(),
        ),
        (
            &trilinear_surface_hemi_oct_matte_colour::MODEL,
            trilinear_surface_hemi_oct_matte_colour::FILTER,
            trilinear_surface_hemi_oct_matte_colour::host(),
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_pipeline_has_the_fronts_ports_then_its_hosts_others() {
        for (m, f, h) in all() {
            let want = expected_ports(f, h, m.name.ends_with("_colour"));
            let got: Vec<_> = m.inputs.iter().map(|p| (p.name, p.bits, p.signed)).collect();
            assert_eq!(got, want.iter().map(|p| (p.name, p.bits, p.signed)).collect::<Vec<_>>(), "{}", m.name);
        }
    }

    #[test]
    fn the_hosts_filter_returns_a_texel_given_four_times_with_blends_of_zero() {
        for t in 0..256 {
            assert_eq!(crate::bilinear::exact_channel(t, t, t, t, 0, 0, crate::bilinear::F), t);
        }
    }

    /// The texel the front gives is the one the host would be given: a quad of texels written at level 0, read at
    /// a position inside it, matches the host model fed those four texels and tex_addr's blend factors.
    #[test]
    fn the_bilinear_front_gives_the_host_the_texels_and_blends_it_would_have_fetched() {
        use crate::cart_pipeline::input as h;
        let ports = bilinear::INPUTS;
        let at = At::of(ports, false);
        let host = bilinear::host();
        let mut base = from_host(host, ports, &(host.hard_cases)()[0]);
        let mut stream = vec![];
        for y in 0..4 {
            for x in 0..4 {
                front::put_write(&mut base, &at, 2, x, y, pattern(2, x, y));
                stream.push(base.clone());
            }
        }
        let (u, v) = (256 + 128 + 77, 2 * 256 + 128 + 200); // texels 1..2 × 2..3, blends 77 and 200
        front::put_read(&mut base, &at, [u, v], 2, [true, true], [0; 4]);
        stream.push(base.clone());
        let got = bilinear::MODEL.run(&stream).pop().unwrap();
        let mut hv = (host.hard_cases)()[0].clone();
        for (k, (x, y)) in [(1, 2), (2, 2), (1, 3), (2, 3)].into_iter().enumerate() {
            let t = pattern(2, x, y);
            (hv[crate::cart_pipeline::TEXELS[k][0]], hv[crate::cart_pipeline::TEXELS[k][1]]) = (t & 0xff, t >> 8);
        }
        (hv[h::ublend], hv[h::vblend]) = (77, 200);
        assert_eq!(got, (host.exact)(&hv));
    }

    /// Two levels of one value each, 0 on level 0 and 255 on level 1 (both bytes): between them the trilinear front
    /// gives 255·frac(λ), λ from the f64 formula, to within the LOD table's error and a rounding.
    #[test]
    fn the_trilinear_front_blends_two_levels_by_the_fraction_of_lambda() {
        let ports = trilinear_matte::INPUTS;
        let at = At::of(ports, true);
        let mut f = Front::new(Filter::Trilinear);
        let mut v = vec![0; ports.len()];
        for (m, t) in [(1, 0x0000), (0, 0xffff)] {
            for y in 0..1 << m {
                for x in 0..1 << m {
                    front::put_write(&mut v, &at, m, x, y, t);
                    assert_eq!(f.step(&v, &at), [0, 0]);
                }
            }
        }
        let mut seen = std::collections::BTreeSet::new();
        for edge in (256..512).step_by(5) {
            let d = [edge, 0, 0, 0];
            front::put_read(&mut v, &at, [300, 100], 1, [true, true], d);
            let got = f.step(&v, &at);
            let want = 255.0 * crate::lod::ideal_lambda(d);
            assert!(got[0] == got[1] && (got[0] as f64 - want).abs() <= 1.5, "edge {edge}: {got:?} against {want:.2}");
            seen.insert(got[0]);
        }
        assert!(seen.len() > 40, "{seen:?}");
        // a bias of −½ level (−128 in Sq3.8) moves each of them half a level toward level 0
        for edge in (362..512).step_by(7) {
            let d = [edge, 0, 0, 0];
            front::put_read(&mut v, &at, [300, 100], 1, [true, true], d);
            front::put_bias(&mut v, &at, -128);
            let got = f.step(&v, &at);
            let want = 255.0 * (crate::lod::ideal_lambda(d) - 0.5);
            assert!(got[0] == got[1] && (got[0] as f64 - want).abs() <= 1.5, "edge {edge}: {got:?} against {want:.2}");
        }
    }

    #[test]
    fn the_vectors_read_only_texels_they_have_written() {
        use rand::SeedableRng;
        for (m, _, _) in all() {
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
            let mut v = (m.hard_cases)();
            v.extend((0..5_000).map(|_| (m.random)(&mut rng)));
            let at = At::of(m.inputs, m.inputs.iter().any(|p| p.name == "du_dx"));
            let mut written = std::collections::HashSet::new();
            for (k, i) in v.iter().enumerate() {
                if i[at.we] == 1 {
                    let s = i[at.w_log2].min(crate::tex_fetch::MAX_LOG_SIDE);
                    written.insert(s);
                    assert!(i[at.wx] < 1 << s && i[at.wy] < 1 << s, "{}: vector {k}", m.name);
                    continue;
                }
                // a read of a map of side 2^s reads levels 0..=s of its chain, all of which the load wrote
                assert!(i[at.log_side] <= REGION_LOG2, "{}: vector {k} reads past the loaded chain", m.name);
            }
            assert!((0..=REGION_LOG2).all(|s| written.contains(&s)));
        }
    }

    #[test]
    fn every_pipeline_sweeps_the_1_2_and_16_texel_maps_and_every_front_one_pipeline_every_side() {
        // the sides a pipeline's hard cases read at the seam and the clamp edge: both wraps, one per axis
        let swept = |m: &UnitModel| -> std::collections::BTreeSet<i64> {
            let at = At::of(m.inputs, m.inputs.iter().any(|p| p.name == "du_dx"));
            let reads: Vec<Vec<i64>> = (m.hard_cases)().into_iter().filter(|i| i[at.we] == 0).collect();
            let wrapped = |i: &Vec<i64>, w: [i64; 2]| i[at.uwrap] == w[0] && i[at.vwrap] == w[1];
            (0..=REGION_LOG2)
                .filter(|s| {
                    let at_side: Vec<&Vec<i64>> = reads.iter().filter(|i| i[at.log_side] == *s).collect();
                    at_side.iter().any(|i| wrapped(i, [1, 0])) && at_side.iter().any(|i| wrapped(i, [0, 1]))
                })
                .collect()
        };
        let every: std::collections::BTreeSet<i64> = (0..=REGION_LOG2).collect();
        let mut fronts_with_every_side = std::collections::BTreeSet::new();
        for (m, f, _) in all() {
            let sides = swept(m);
            assert!([0, 1, REGION_LOG2].iter().all(|s| sides.contains(s)), "{}: {sides:?}", m.name);
            if sides == every {
                fronts_with_every_side.insert((format!("{f:?}"), m.name.contains("two_pass")));
            }
        }
        let fronts: std::collections::BTreeSet<_> =
            all().iter().map(|(m, f, _)| (format!("{f:?}"), m.name.contains("two_pass"))).collect();
        assert_eq!(fronts_with_every_side, fronts);
    }

    /// RGB565 widened back to bytes: every code's byte is within one of its exact value c·255/31 (or /63), the
    /// ends exact; an 8-bit colour packed and widened is within half a 5-bit step (4.1) or 6-bit step (2.0) and that
    /// one: 5 and 3 LSB.
    #[test]
    fn rgb565_widens_to_within_one_of_each_codes_value_and_packs_to_within_half_a_step() {
        for t in 0..=0xffff {
            let e = front::expand565(t);
            let codes = [(t >> 11) & 0x1f, (t >> 5) & 0x3f, t & 0x1f];
            for c in 0..3 {
                let top = if c == 1 { 63.0 } else { 31.0 };
                let exact = codes[c] as f64 * 255.0 / top;
                assert!((e[c] as f64 - exact).abs() < 1.0, "{t:#06x} channel {c}: {} against {exact}", e[c]);
            }
        }
        assert_eq!((front::expand565(0xffff), front::expand565(0)), ([255; 3], [0; 3]));
        let mut worst = [0; 3];
        for v in 0..=255u8 {
            let e = front::expand565(front::pack565([v, v, v]));
            for c in 0..3 {
                worst[c] = worst[c].max((e[c] - v as i64).abs());
            }
        }
        assert!(worst[0] <= 5 && worst[2] <= 5 && worst[1] <= 3, "{worst:?}");
    }

    /// The colour front reads its own memory at the bump texel's footprint and blend factors: a colour quad
    /// written at level 0 and read inside it gives each channel's bilinear of the widened texels, and the host is
    /// handed it as its destination colour (a write to one memory leaves the other's texels as they were).
    #[test]
    fn the_colour_front_filters_its_own_memory_on_the_bump_footprint_into_the_destination_colour() {
        let ports = bilinear_colour::INPUTS;
        let at = At::of(ports, false);
        let host = bilinear_colour::host();
        let mut m = bilinear_colour::Unit::default();
        let mut v = from_host(host, ports, &(host.hard_cases)()[0]);
        for y in 0..4 {
            for x in 0..4 {
                front::put_write(&mut v, &at, 2, x, y, pattern(2, x, y));
                assert_eq!(m.step(&v), write_outputs(host, ports, &v), "a write leaves as zeros");
                front::put_colour_write(&mut v, &at, 2, x, y, colour_pattern(2, x, y));
                m.step(&v);
            }
        }
        let (u, w) = (256 + 128 + 77, 2 * 256 + 128 + 200); // texels 1..2 × 2..3, blends 77 and 200
        front::put_read(&mut v, &at, [u, w], 2, [true, true], [0; 4]);
        let got = m.step(&v);
        let quad = [(1, 2), (2, 2), (1, 3), (2, 3)];
        let mut hv = (host.hard_cases)()[0].clone();
        for (k, (x, y)) in quad.into_iter().enumerate() {
            let t = pattern(2, x, y);
            (hv[crate::cart_pipeline::TEXELS[k][0]], hv[crate::cart_pipeline::TEXELS[k][1]]) = (t & 0xff, t >> 8);
        }
        (hv[crate::cart_pipeline::input::ublend], hv[crate::cart_pipeline::input::vblend]) = (77, 200);
        let c = quad.map(|(x, y)| front::expand565(colour_pattern(2, x, y)));
        for (ch, port) in crate::cart_pipeline::DST.iter().enumerate() {
            hv[*port] =
                crate::bilinear::exact_channel(c[0][ch], c[1][ch], c[2][ch], c[3][ch], 77, 200, crate::bilinear::F);
        }
        assert_eq!(got, (host.exact)(&hv));
        // the destination colour matters: the blend at the same pixel with another colour differs
        hv[crate::cart_pipeline::DST[0]] ^= 0x80;
        assert_ne!(got, (host.exact)(&hv));
    }

    /// The host's outputs for a write vector: every texel and the destination colour zero.
    fn write_outputs(host: &UnitModel, ports: &[Port], v: &[i64]) -> Vec<i64> {
        (host.exact)(&host_vector(host, ports, v, [0, 0], [0; 3]))
    }
}
