//! The height path against analytic surfaces: sine surfaces of wavelength 8, 16 and 32 texels at 45° peak slope and
//! a spherical cap, sampled at texel centres (control point i of the B-spline sits at x = i + ½), stored as 8-bit
//! UQ6.2 heights with the per-model scale factor (¶82) making up the range, and evaluated across the texels.
//! Four angles against the surface's own normal: the method in reals on the true heights (what the B-spline's
//! smoothing costs), the method in reals on the 8-bit codes (and the quantization), the exact pipeline on the codes
//! (and the datapath), and the exact pipeline against the method in reals on the same codes (the datapath alone).

use crate::height::height_pipeline;
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
        if d2 < r * r { ((r * r - d2).sqrt() - base).max(0.0) } else { 0.0 }
    };
    let grad = move |x: f64, z: f64| {
        let d2 = (x - c).powi(2) + (z - c).powi(2);
        let y = (r * r - d2).max(0.0).sqrt();
        if y > base { (-(x - c) / y, -(z - c) / y) } else { (0.0, 0.0) }
    };
    Surface { name: "spherical cap, radius 24, 8 texels high".into(), h: Box::new(h), grad: Box::new(grad), texels: 48, lo: 0.0, hi: r - base }
}

pub struct Row {
    pub name: String,
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

/// Every surface's four errors, evaluated at `per` × `per` points in each texel away from the border.
pub fn measure(s: &Surface, per: usize) -> Row {
    let n = s.texels;
    let true_h: Vec<f64> = (0..n * n).map(|k| (s.h)((k % n) as f64 + 0.5, (k / n) as f64 + 0.5) - s.lo).collect();
    let (codes, scale) = crate::height::height_normal::encode_heights(&true_h, 0.0, s.hi - s.lo);
    let mut row = Row {
        name: s.name.clone(), scale, float_true: ErrorStats::default(), float_codes: ErrorStats::default(),
        exact: ErrorStats::default(), exact_vs_float: ErrorStats::default(),
    };
    for j in 1..n - 1 {
        for i in 1..n - 1 {
            let window = |v: &dyn Fn(usize) -> f64| -> [f64; 9] { std::array::from_fn(|p| v((j + p / 3 - 1) * n + i + p % 3 - 1)) };
            let wt = window(&|k| true_h[k]);
            let wc: [i64; 9] = std::array::from_fn(|p| codes[(j + p / 3 - 1) * n + i + p % 3 - 1]);
            for sj in 0..per {
                for si in 0..per {
                    let (ub, vb) = ((si * 256 / per) as i64, (sj * 256 / per) as i64);
                    let (x, z) = (i as f64 + ub as f64 / 256.0, j as f64 + vb as f64 / 256.0);
                    let (gx, gz) = (s.grad)(x, z);
                    let truth = normal(gx, gz);
                    let at = || format!("({x:.3}, {z:.3})");
                    // the method in reals on the true heights: the B-spline's own derivative
                    let (_, hu, hv) = height_pipeline::bspline(&wt, ub as f64 / 256.0, vb as f64 / 256.0);
                    row.float_true.add(angle_deg(normal(hu, hv), truth), at);
                    let input = [wc.to_vec(), vec![ub, vb, scale]].concat();
                    let ideal = height_pipeline::ideal(&input);
                    row.float_codes.add(angle_deg(ideal, truth), at);
                    let e = height_pipeline::exact_trace(&input).normal.map(|c| c as f64);
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hardware_adds_under_a_tenth_of_a_degree_to_its_own_ideal() {
        for s in all() {
            let r = measure(&s, 4);
            assert!(r.exact_vs_float.mean() < 0.1, "{}: {:.4}° mean", r.name, r.exact_vs_float.mean());
            // and the B-spline in reals follows a long wave closely
            if s.name.contains("wavelength 32") {
                assert!(r.float_true.mean() < 1.0, "{}: {:.3}°", r.name, r.float_true.mean());
            }
        }
    }
}
