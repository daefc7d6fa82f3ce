//! The height path against analytic surfaces: sine surfaces of wavelength 8, 16 and 32 texels at 45° peak slope and
//! a spherical cap, sampled at texel centres (control point i of the B-spline sits at x = i + ½), stored as 8-bit
//! UQ6.2 heights with the per-model scale factor (¶82) making up the range, and evaluated across the texels.
//! Four angles against the surface's own normal: the method in reals on the true heights (what the B-spline's
//! smoothing costs), the method in reals on the 8-bit codes (and the quantization), the exact pipeline on the codes
//! (and the datapath), and the exact pipeline against the method in reals on the same codes (the datapath alone).

use crate::height::filters::{self, Filter, Grid};
use crate::stats::{angle_deg, ErrorStats};

/// A surface y = h(x, z) in texel units, with its gradient.
pub struct Surface {
    pub name: String,
    pub h: Box<dyn Fn(f64, f64) -> f64>,
    pub grad: Box<dyn Fn(f64, f64) -> (f64, f64)>,
    /// the extent of the texels sampled, and the heights' range (for the offset and the scale)
    pub texels: usize,
    pub lo: f64,
    pub hi: f64,
}

/// h = A·sin(2πx/λ)·sin(2πz/λ) with A = λ/2π: the steepest slope is 1, 45°.
pub fn sine(wavelength: f64) -> Surface {
    let a = wavelength / std::f64::consts::TAU;
    let w = std::f64::consts::TAU / wavelength;
    Surface {
        name: format!("sine, wavelength {wavelength} texels, 45° peak"),
        h: Box::new(move |x, z| a * (w * x).sin() * (w * z).sin()),
        grad: Box::new(move |x, z| (a * w * (w * x).cos() * (w * z).sin(), a * w * (w * x).sin() * (w * z).cos())),
        texels: 64,
        lo: -a,
        hi: a,
    }
}

/// A spherical cap of radius 24 texels standing 8 texels out of a flat plane, centred on a 48-texel square.
pub fn cap() -> Surface {
    let (r, c, base) = (24.0f64, 24.0f64, 16.0f64);
    let h = move |x: f64, z: f64| {
        let d2 = (x - c).powi(2) + (z - c).powi(2);
        if d2 < r * r {
            ((r * r - d2).sqrt() - base).max(0.0)
        } else {
            0.0
        }
    };
    let grad = move |x: f64, z: f64| {
        let d2 = (x - c).powi(2) + (z - c).powi(2);
        let y = (r * r - d2).max(0.0).sqrt();
        if y > base {
            (-(x - c) / y, -(z - c) / y)
        } else {
            (0.0, 0.0)
        }
    };
    Surface {
        name: "spherical cap, radius 24, 8 texels high".into(),
        h: Box::new(h),
        grad: Box::new(grad),
        texels: 48,
        lo: 0.0,
        hi: r - base,
    }
}

pub struct Row {
    pub name: String,
    /// the filter (`filters::Filter::name`)
    pub filter: &'static str,
    /// the scale factor used (UQ4.4; the codes' step is a quarter texel times scale/16)
    pub scale: i64,
    pub float_true: ErrorStats,
    pub float_codes: ErrorStats,
    pub exact: ErrorStats,
    pub exact_vs_float: ErrorStats,
}

/// The unit normal of a height field with gradient (hx, hz).
fn normal(hx: f64, hz: f64) -> [f64; 3] {
    let l = (hx * hx + 1.0 + hz * hz).sqrt();
    [-hx / l, 1.0 / l, -hz / l]
}

/// The seed's B-spline path's four errors on a surface.
pub fn measure(s: &Surface, per: usize) -> Row {
    measure_filter(Filter::BSpline, s, per)
}

/// A filter's four errors on a surface, evaluated at `per` × `per` points in each texel two texels or more from the
/// border (the derivative filters read a 4 × 4 block).
pub fn measure_filter(f: Filter, s: &Surface, per: usize) -> Row {
    let n = s.texels;
    let true_h = true_heights(s);
    let (mut codes, scale) = crate::height::height_normal::encode_heights_in(&true_h, 0.0, s.hi - s.lo, f.bits());
    if f.bits() == 4 {
        codes.iter_mut().for_each(|c| *c *= 2); // UQ3.1 into the 8-bit datapath's UQ6.2: exact
    }
    let true_c = in_code_units(&true_h, scale);
    let codes_f: Vec<f64> = codes.iter().map(|&c| c as f64).collect();
    // MIP level 1: the stored (rounded) codes, which the method in reals on the codes reads too; of the true heights
    let l1 = filters::mip_exact(&codes, n);
    let (l1_true, l1_codes) = (filters::mip_ideal(&true_c, n), l1.iter().map(|&c| c as f64).collect::<Vec<f64>>());
    let (g_true, g_codes_f, g_codes) =
        (Grid { side: n, h: &true_c[..] }, Grid { side: n, h: &codes_f[..] }, Grid { side: n, h: &codes[..] });
    let (h_true, h_codes_f, h_codes) = (
        Grid { side: n / 2, h: &l1_true[..] },
        Grid { side: n / 2, h: &l1_codes[..] },
        Grid { side: n / 2, h: &l1[..] },
    );
    let mut row = Row {
        name: s.name.clone(),
        filter: f.name(),
        scale,
        float_true: ErrorStats::default(),
        float_codes: ErrorStats::default(),
        exact: ErrorStats::default(),
        exact_vs_float: ErrorStats::default(),
    };
    for j in 2..n - 2 {
        for i in 2..n - 2 {
            for sj in 0..per {
                for si in 0..per {
                    let (cu, cv) = ((i * 256 + si * 256 / per) as i64, (j * 256 + sj * 256 / per) as i64);
                    let (x, z) = (cu as f64 / 256.0, cv as f64 / 256.0);
                    let (gx, gz) = (s.grad)(x, z);
                    let truth = normal(gx, gz);
                    let at = || format!("({x:.3}, {z:.3})");
                    // the method in reals on the true heights: what the filter's smoothing costs
                    row.float_true.add(angle_deg(f.ideal(&g_true, &h_true, scale as f64, x, z), truth), at);
                    let ideal = f.ideal(&g_codes_f, &h_codes_f, scale as f64, x, z);
                    row.float_codes.add(angle_deg(ideal, truth), at);
                    let e = f.exact(&g_codes, &h_codes, scale, cu, cv).map(|c| c as f64);
                    row.exact.add(angle_deg(e, truth), at);
                    row.exact_vs_float.add(angle_deg(e, ideal), at);
                }
            }
        }
    }
    row
}

/// The surfaces of the accuracy table, in order.
pub fn all() -> Vec<Surface> {
    vec![sine(8.0), sine(16.0), sine(32.0), cap()]
}

/// The surface sampled at texel centres, above its lowest point (texel units).
fn true_heights(s: &Surface) -> Vec<f64> {
    let n = s.texels;
    (0..n * n).map(|k| (s.h)((k % n) as f64 + 0.5, (k / n) as f64 + 0.5) - s.lo).collect()
}

/// Heights in texel units in the 8-bit codes' units for scale k (UQ6.2 steps: 4·m per texel, k = 16/m), unrounded.
fn in_code_units(h: &[f64], scale: i64) -> Vec<f64> {
    let m = (1 << crate::height::height_normal::SCALE_FRAC) as f64 / scale as f64;
    h.iter().map(|x| x * 4.0 * m).collect()
}

/// A surface's true heights in 8-bit code units and its scale k: the map a method in reals reads.
pub fn codes_in_reals(s: &Surface) -> (Vec<f64>, i64) {
    let true_h = true_heights(s);
    let (_, scale) = crate::height::height_normal::encode_heights(&true_h, 0.0, s.hi - s.lo);
    (in_code_units(&true_h, scale), scale)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hardware_adds_under_a_tenth_of_a_degree_to_its_own_ideal() {
        for s in all() {
            for f in filters::ALL {
                let r = measure_filter(f, &s, 2);
                if f == Filter::Bezier {
                    // equation 1's points rounded to the units' 8 bits cost more than the blend-adjusted path's floors
                    let seed = measure_filter(Filter::BSpline, &s, 2);
                    assert!(
                        r.exact_vs_float.mean() > seed.exact_vs_float.mean(),
                        "{}: {:.4}°",
                        r.name,
                        r.exact_vs_float.mean()
                    );
                } else if f.bits() == 8 {
                    assert!(
                        r.exact_vs_float.mean() < 0.1,
                        "{} / {}: {:.4}° mean",
                        r.filter,
                        r.name,
                        r.exact_vs_float.mean()
                    );
                }
                // and the B-spline in reals follows a long wave closely
                if s.name.contains("wavelength 32") && f == Filter::BSpline {
                    assert!(r.float_true.mean() < 1.0, "{}: {:.3}°", r.name, r.float_true.mean());
                }
            }
        }
    }
}
