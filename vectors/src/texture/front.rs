//! The texture unit's fronts, the model of `rtl::texture::front`: [lod →] tex_addr → tex_fetch [→ bilinear on each
//! byte], wired from the units' own `exact`s over one memory (`tex_fetch::Memory`), vector by vector in order.
//!
//! A front's ports, by name, in the vector of the pipeline that holds it: `u`, `v` (Sq11.8, texels of level 0),
//! `log_side`, `uwrap`, `vwrap`, the write port `we`, `w_log2`, `wx`, `wy`, `wdata`, and with a MIP filter the four
//! derivatives `du_dx`, `dv_dx`, `du_dy`, `dv_dy` (Sq8.8) and the LOD bias `lod_bias` (Sq3.8, levels). A write puts `wdata` into its texel and leaves as a
//! texel of zero; a read sees every write before it.
//!
//! A front with a colour map holds a second memory of the same layout: the colour texture, RGB565 texels (red in
//! bits 15..11, green 10..5, blue 4..0), written through the same port with `wcolour` = 1. A read gives its colour
//! beside the bump texel, from the same footprint, blend factors and levels: each channel widened to 8 bits by
//! repeating its top bits (`expand565`: within one of c·255/31 or c·255/63, 0 → 0 and the top code → 255), then
//! filtered as an 8-bit channel.

use crate::texture::{lod, tex_addr, tex_fetch};
use crate::unit::Port;
use crate::{
    bilinear,
    fixed::{round_half_up, saturate},
};

/// Which texel a front gives (the scene's `[bump] filter`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filter {
    /// the texel that holds the sample, on level 0
    Nearest,
    /// the texel that holds the sample, on the nearest level ⌊λ + ½⌋
    NearestMip,
    /// the four texels round the sample on level 0, filtered
    Bilinear,
    /// the four texels round the sample on level ⌊λ⌋ and the four on level ⌊λ⌋ + 1, each filtered, the two
    /// blended by frac(λ) (`lerp`)
    Trilinear,
}

impl Filter {
    pub fn mip(self) -> bool {
        matches!(self, Filter::NearestMip | Filter::Trilinear)
    }
    pub fn linear(self) -> bool {
        matches!(self, Filter::Bilinear | Filter::Trilinear)
    }
}

/// The front's ports (and the derivatives' with a MIP filter), in the order the pipelines put them first.
pub const PORTS: &[Port] = &[
    Port::s("u", 20),
    Port::s("v", 20),
    Port::u("log_side", 4),
    Port::u("uwrap", 1),
    Port::u("vwrap", 1),
    Port::u("we", 1),
    Port::u("w_log2", 4),
    Port::u("wx", 8),
    Port::u("wy", 8),
    Port::u("wdata", 16),
];
/// The MIP filters' ports: the four derivatives and the LOD bias.
pub const DERIVATIVES: &[Port] =
    &[Port::s("du_dx", 17), Port::s("dv_dx", 17), Port::s("du_dy", 17), Port::s("dv_dy", 17), Port::s("lod_bias", 12)];

/// The colour front's memory select, after `wdata`: 1 writes the colour map's memory, 0 the bump map's.
pub const COLOUR: Port = Port::u("wcolour", 1);

/// An RGB565 texel's three channels (U5, U6, U5) widened to U8 by bit repetition: `(c << 3) | (c >> 2)` for five
/// bits, `(c << 2) | (c >> 4)` for six (the code's own top bits fill the low ones: within one of c·255/31 or
/// c·255/63, 0 and the top code exact).
pub fn expand565(t: i64) -> [i64; 3] {
    let (r, g, b) = ((t >> 11) & 0x1f, (t >> 5) & 0x3f, t & 0x1f);
    [(r << 3) | (r >> 2), (g << 2) | (g >> 4), (b << 3) | (b >> 2)]
}

/// An 8-bit colour as an RGB565 texel: each channel scaled to its 5 or 6 bits and rounded half up
/// (`round(c·31/255)`, `round(c·63/255)`).
pub fn pack565(rgb: [u8; 3]) -> i64 {
    let q = |c: u8, top: i64| (i64::from(c) * top * 2 + 255) / 510;
    (q(rgb[0], 31) << 11) | (q(rgb[1], 63) << 5) | q(rgb[2], 31)
}

/// Where a front's ports sit in a pipeline's vector.
#[derive(Clone, Copy, Debug)]
pub struct At {
    pub u: usize,
    pub v: usize,
    pub log_side: usize,
    pub uwrap: usize,
    pub vwrap: usize,
    pub we: usize,
    pub w_log2: usize,
    pub wx: usize,
    pub wy: usize,
    pub wdata: usize,
    /// wcolour, with a colour map
    pub wcolour: Option<usize>,
    /// du_dx, dv_dx, du_dy, dv_dy, with a MIP filter
    pub d: Option<[usize; 4]>,
    /// lod_bias, with a MIP filter
    pub bias: Option<usize>,
}

/// The index of the port called `name`; panics if there is none (a pipeline's port list is fixed at compile time,
/// and a test runs every pipeline's model).
pub fn index(ports: &[Port], name: &str) -> usize {
    ports.iter().position(|p| p.name == name).unwrap_or_else(|| panic!("no port {name}"))
}

impl At {
    pub fn of(ports: &[Port], mip: bool) -> At {
        let i = |n: &str| index(ports, n);
        At {
            u: i("u"),
            v: i("v"),
            log_side: i("log_side"),
            uwrap: i("uwrap"),
            vwrap: i("vwrap"),
            we: i("we"),
            w_log2: i("w_log2"),
            wx: i("wx"),
            wy: i("wy"),
            wdata: i("wdata"),
            wcolour: ports.iter().position(|p| p.name == COLOUR.name),
            d: mip.then(|| [i("du_dx"), i("dv_dx"), i("du_dy"), i("dv_dy")]),
            bias: mip.then(|| i("lod_bias")),
        }
    }
}

/// One front and its memory (and with a colour map the colour's), from reset (empty, zero memories). Trilinear's
/// maps are split by level parity (`tex_fetch::Levels`): `mem` holds the bump map's even levels and `odd` its odd
/// ones, `colour` and `colour_odd` the colour map's.
#[derive(Clone)]
pub struct Front {
    pub filter: Filter,
    pub mem: tex_fetch::Memory,
    pub odd: Option<tex_fetch::Memory>,
    pub colour: Option<tex_fetch::Memory>,
    pub colour_odd: Option<tex_fetch::Memory>,
}

impl Front {
    pub fn new(filter: Filter) -> Front {
        use tex_fetch::{Levels, Memory};
        match filter {
            Filter::Trilinear => Front {
                filter,
                mem: Memory::holding(Levels::Even),
                odd: Some(Memory::holding(Levels::Odd)),
                colour: None,
                colour_odd: None,
            },
            _ => Front { filter, mem: Memory::default(), odd: None, colour: None, colour_odd: None },
        }
    }

    /// A front that reads its levels in passes, one a clock, from one memory holding the whole chain
    /// (`rtl::texture::front::TexTrilinearTwoPass`): with two passes trilinear needs no parity split. The same
    /// outputs as `new`'s.
    pub fn in_passes(filter: Filter, passes: usize) -> Front {
        match passes {
            1 => Front::new(filter),
            _ => Front { filter, mem: tex_fetch::Memory::default(), odd: None, colour: None, colour_odd: None },
        }
    }

    /// A front with a colour map's memory beside the bump map's, split by level parity as the bump map's is.
    pub fn with_colour(filter: Filter) -> Front {
        use tex_fetch::{Levels, Memory};
        let bump = Front::new(filter);
        match bump.odd {
            Some(_) => Front {
                colour: Some(Memory::holding(Levels::Even)),
                colour_odd: Some(Memory::holding(Levels::Odd)),
                ..bump
            },
            None => Front { colour: Some(Memory::default()), ..bump },
        }
    }

    /// Of a map's memories (`even`, and with the parity split `odd`), the one that holds MIP level `level` (an
    /// index, 0 the largest) of a map of side 2^log_side: with the split the one of the parity of its side's log2,
    /// log_side − level.
    fn half<'a>(
        even: &'a tex_fetch::Memory,
        odd: Option<&'a tex_fetch::Memory>,
        level: i64,
        log_side: i64,
    ) -> &'a tex_fetch::Memory {
        match odd {
            Some(odd) if (log_side - level).rem_euclid(2) == 1 => odd,
            _ => even,
        }
    }

    /// The levels the address units read for this vector (the LOD unit's nearest level; ⌊λ⌋ and its neighbour;
    /// or 0), and the weight of the second, frac(λ) (U8; 0 with one level).
    pub fn levels(&self, v: &[i64], at: &At) -> (Vec<i64>, i64) {
        let bias = at.bias.map_or(0, |k| v[k]);
        let l = |d: [usize; 4]| lod::exact(d.map(|k| v[k]), v[at.log_side], bias);
        match (at.d, self.filter) {
            (Some(d), Filter::NearestMip) => (vec![l(d)[lod::output::nearest]], 0),
            (Some(d), Filter::Trilinear) => {
                let o = l(d);
                let (first, second) = neighbour(o[lod::output::level], v[at.log_side]);
                (vec![first, second], o[lod::output::frac])
            }
            _ => (vec![0], 0),
        }
    }

    /// The address unit's outputs for this read vector at `level`.
    fn address(&self, v: &[i64], at: &At, level: i64) -> Vec<i64> {
        let lin = i64::from(self.filter.linear());
        tex_addr::exact(&[v[at.u], v[at.v], level, v[at.log_side], v[at.uwrap], v[at.vwrap], lin])
    }

    /// The texels a read vector's footprint reads, as (level side log2, x, y) the memory holds them (the side
    /// saturated to the memory's, the place modulo the side); none for a write.
    pub fn reads(&self, v: &[i64], at: &At) -> Vec<(i64, i64, i64)> {
        if v[at.we] == 1 {
            return vec![];
        }
        use tex_addr::output as o;
        let mut t = vec![];
        for level in self.levels(v, at).0 {
            let a = self.address(v, at, level);
            let m = tex_fetch::level(a[o::level_log2]);
            for y in [a[o::y0], a[o::y1]] {
                for x in [a[o::x0], a[o::x1]] {
                    t.push((m, tex_fetch::wrap(x, m), tex_fetch::wrap(y, m)));
                }
            }
        }
        t
    }

    /// The texel a write vector writes, as `reads` names texels (in whichever memory it writes: `writes_colour`).
    pub fn writes(v: &[i64], at: &At) -> Option<(i64, i64, i64)> {
        let m = tex_fetch::level(v[at.w_log2]);
        (v[at.we] == 1).then(|| (m, tex_fetch::wrap(v[at.wx], m), tex_fetch::wrap(v[at.wy], m)))
    }

    /// Whether a write vector writes the colour map's memory.
    pub fn writes_colour(v: &[i64], at: &At) -> bool {
        at.wcolour.is_some_and(|k| v[k] == 1)
    }

    /// One vector: (lo, hi), the texel's two bytes, filtered or the nearest one; a write gives (0, 0).
    pub fn step(&mut self, v: &[i64], at: &At) -> [i64; 2] {
        self.step_all(v, at).0
    }

    /// One vector: the bump texel's two bytes and, with a colour map, its colour (R, G, B, U8 each); a write
    /// gives zeros.
    pub fn step_all(&mut self, v: &[i64], at: &At) -> ([i64; 2], [i64; 3]) {
        if v[at.we] == 1 {
            // the colour map's memory, or the bump map's (both halves take it, as the rtl's two fetches do: each
            // keeps the levels it holds)
            let (m, x, y, t) = (v[at.w_log2], v[at.wx], v[at.wy], v[at.wdata]);
            match (&mut self.colour, Front::writes_colour(v, at)) {
                (Some(c), true) => {
                    c.write(m, x, y, t);
                    if let Some(odd) = &mut self.colour_odd {
                        odd.write(m, x, y, t);
                    }
                }
                _ => {
                    self.mem.write(m, x, y, t);
                    if let Some(odd) = &mut self.odd {
                        odd.write(m, x, y, t);
                    }
                }
            }
            return ([0, 0], [0; 3]);
        }
        (self.read(v, at), self.read_colour(v, at))
    }

    /// A read vector's colour from the colour map's memory as it stands (zeros without one): the same levels,
    /// footprint and blend factors as the bump texel's, each channel widened (`expand565`) and then filtered.
    pub fn read_colour(&self, v: &[i64], at: &At) -> [i64; 3] {
        let Some(mem) = &self.colour else { return [0; 3] };
        let (levels, frac) = self.levels(v, at);
        let half = |l| Front::half(mem, self.colour_odd.as_ref(), l, v[at.log_side]);
        let b = levels.iter().map(|&l| self.sample_in(half(l), v, at, l, 3)).collect::<Vec<_>>();
        match b[..] {
            [ref one] => [one[0], one[1], one[2]],
            [ref b0, ref b1] => [0, 1, 2].map(|c| lerp(b0[c], b1[c], frac)),
            _ => unreachable!("a front reads one level or two"),
        }
    }

    /// A read vector's (lo, hi) from the memory as it stands (`step` without its writes).
    pub fn read(&self, v: &[i64], at: &At) -> [i64; 2] {
        let (levels, frac) = self.levels(v, at);
        let b = levels.iter().map(|&l| self.sample(v, at, l)).collect::<Vec<_>>();
        match b[..] {
            [one] => one,
            [b0, b1] => [0, 1].map(|c| lerp(b0[c], b1[c], frac)),
            _ => unreachable!("a front reads one level or two"),
        }
    }

    /// The texel's two bytes at one level: filtered, or the nearest texel's.
    fn sample(&self, v: &[i64], at: &At, level: i64) -> [i64; 2] {
        let b = self.sample_in(Front::half(&self.mem, self.odd.as_ref(), level, v[at.log_side]), v, at, level, 2);
        [b[0], b[1]]
    }

    /// The `n` channels of a texel of `mem` at one level, filtered or the nearest texel's: with n = 2 a bump
    /// texel's two bytes, with n = 3 a colour texel's channels widened from RGB565.
    fn sample_in(&self, mem: &tex_fetch::Memory, v: &[i64], at: &At, level: i64, n: usize) -> Vec<i64> {
        let a = self.address(v, at, level);
        use tex_addr::output as o;
        let t = mem.footprint(a[o::level_log2], [a[o::x0], a[o::x1]], [a[o::y0], a[o::y1]]);
        let chan = |k: usize, c: usize| if n == 3 { expand565(t[k])[c] } else { (t[k] >> (8 * c)) & 0xff };
        (0..n)
            .map(|c| {
                if self.filter.linear() {
                    bilinear::exact_channel(
                        chan(0, c),
                        chan(1, c),
                        chan(2, c),
                        chan(3, c),
                        a[o::ublend],
                        a[o::vblend],
                        bilinear::F,
                    )
                } else {
                    chan(0, c)
                }
            })
            .collect()
    }
}

/// Trilinear's two MIP levels (indices, 0 the largest) for ⌊λ⌋ = `level` on a map of side 2^log_side: ⌊λ⌋ and
/// ⌊λ⌋ + 1, or where ⌊λ⌋ is the last level (log_side: there frac(λ) is 0, so the second is never seen) ⌊λ⌋ − 1, or
/// for a 1 × 1 map level 1 (which the address unit clamps to 0). The two differ by one, so their sides' log2 have
/// different parities and each is read from its own memory (`tex_fetch::Levels`); the second's weight is frac(λ).
pub fn neighbour(level: i64, log_side: i64) -> (i64, i64) {
    let second = if level < log_side {
        level + 1
    } else if level >= 1 {
        level - 1
    } else {
        1
    };
    (level, second)
}

/// The blend of two levels' bytes b₀, b₁ (U8) by the second's weight f (U8, /2^8): `b₀·2^8 + (b₁ − b₀)·f`
/// (exact, a weighted mean of the two times 2^8), rounded half up to U8.
pub fn lerp(b0: i64, b1: i64, f: i64) -> i64 {
    round_half_up(b0 * 256 + (b1 - b0) * f, 8)
}

/// A read vector's front ports for the sample (u, v) (Sq11.8) of a map of side 2^log_side, with the wrap modes
/// and, for a MIP filter, the derivatives (and a LOD bias of 0: `put_bias` sets another); written into `v` at `at`.
pub fn put_read(v: &mut [i64], at: &At, uv: [i64; 2], log_side: i64, wrap: [bool; 2], d: [i64; 4]) {
    (v[at.u], v[at.v], v[at.log_side]) = (uv[0], uv[1], log_side);
    (v[at.uwrap], v[at.vwrap], v[at.we]) = (i64::from(wrap[0]), i64::from(wrap[1]), 0);
    (v[at.w_log2], v[at.wx], v[at.wy], v[at.wdata]) = (0, 0, 0, 0);
    if let Some(k) = at.wcolour {
        v[k] = 0;
    }
    if let Some(k) = at.d {
        for c in 0..4 {
            v[k[c]] = d[c];
        }
    }
    put_bias(v, at, 0);
}

/// A write vector's front ports for an RGB565 texel of the colour map's memory; panics for a front without one.
pub fn put_colour_write(v: &mut [i64], at: &At, m: i64, x: i64, y: i64, texel: i64) {
    put_write(v, at, m, x, y, texel);
    v[at.wcolour.expect("a front with a colour map")] = 1;
}

/// A read vector's LOD bias (Sq3.8, levels), for a MIP filter; nothing without one.
pub fn put_bias(v: &mut [i64], at: &At, bias: i64) {
    if let Some(k) = at.bias {
        v[k] = bias;
    }
}

/// A write vector's front ports: texel (x, y) of the level of side 2^m, in the bump map's memory.
pub fn put_write(v: &mut [i64], at: &At, m: i64, x: i64, y: i64, texel: i64) {
    (v[at.u], v[at.v], v[at.log_side], v[at.uwrap], v[at.vwrap]) = (0, 0, 0, 0, 0);
    (v[at.we], v[at.w_log2], v[at.wx], v[at.wy], v[at.wdata]) = (1, m, x, y, texel);
    if let Some(k) = at.wcolour {
        v[k] = 0;
    }
    if let Some(k) = at.d {
        for c in k {
            v[c] = 0;
        }
    }
    put_bias(v, at, 0);
}

/// A random sample position: mostly within a few repeats of the map either side of 0, one draw in eight an end
/// of the range (Sq11.8).
pub fn random_position(rng: &mut dyn rand::RngCore, log_side: i64) -> i64 {
    use rand::Rng;
    let lim = (1i64 << 19) - 1;
    if rng.gen_range(0..8) == 0 {
        return [-lim - 1, lim, 0, -1][rng.gen_range(0..4)];
    }
    let span = (256i64 << log_side) * 3;
    saturate(rng.gen_range(-span..=span), -lim - 1, lim)
}
