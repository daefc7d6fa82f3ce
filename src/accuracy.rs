//! `bumprtl accuracy`: exact against ideal for every unit (error with where its max occurs), the encoders' angular
//! error, and the LUT-size tables of the sine/cosine units (against their yosys cost, when asked).

use vectors::stats::ErrorStats;

fn stat_line(unit: &str, metric: &str, s: &ErrorStats) {
    println!("{unit:<20} {metric:<52} {:>9.4} {:>9.4}   {}", s.mean(), s.max, s.argmax);
}

pub fn accuracy(directions: usize, samples: usize) {
    println!("{:<20} {:<52} {:>9} {:>9}   max at", "unit", "error (exact against ideal)", "mean", "max");
    let count = |rows: &Vec<sim::accuracy::Row>| Some(format!("{} rows", rows.len()));
    let units =
        crate::progress::step("every unit's model against its ideal", count, || sim::accuracy::units(samples, 1));
    for r in units {
        stat_line(&r.unit, &r.metric, &r.stats);
    }
    let seed = sim::accuracy::ENCODER_SEED;
    let encoders = crate::progress::step(&format!("the encoders over {directions} directions"), count, || {
        let mut rows = sim::accuracy::encoders(directions, seed);
        rows.extend(sim::accuracy::polar_encoders(directions, seed));
        rows
    });
    for r in encoders {
        stat_line(&r.unit, &r.metric, &r.stats);
    }
    println!(
        "\nheight maps (US 2004/0207631): each filter against analytic surfaces, angle to the true normal in degrees"
    );
    println!(
        "(float: the method in reals; codes: 8-bit UQ6.2 heights (4-bit UQ3.1 where named) with scale k; exact: the"
    );
    println!("model of the hardware on the codes; exact vs float: what the datapath adds)");
    println!(
        "{:<38} {:<40} {:>3} {:>17} {:>17} {:>17} {:>17}",
        "filter", "surface", "k", "float, true h", "float, codes", "exact, codes", "exact vs float"
    );
    use vectors::height::{filters, surfaces};
    let step = crate::progress::Step::new("height maps: each filter on each surface", Some(filters::ALL.len() as u64));
    for (k, f) in filters::ALL.into_iter().enumerate() {
        step.tick(k as u64);
        for surface in surfaces::all() {
            let r = surfaces::measure_filter(f, &surface, 4);
            let c = |s: &ErrorStats| format!("{:.3} / {:.3}", s.mean(), s.max);
            println!(
                "{:<38} {:<40} {:>3} {:>17} {:>17} {:>17} {:>17}",
                r.filter,
                r.name,
                r.scale,
                c(&r.float_true),
                c(&r.float_codes),
                c(&r.exact),
                c(&r.exact_vs_float)
            );
        }
    }
    step.done(&format!("{} filters", filters::ALL.len()));
    println!(
        "(mean / max; k = 16/m where the codes hold the heights ×m; trilinear reads MIP level 1 as stored, rounded)"
    );
    let a = filters::bezier_agreement(samples, 3);
    println!(
        "equation 1 (Bezier points rounded to 8 bits) against blend adjust, {} random windows at k = 1: {} normals identical ({:.1} %), \
         the others {:.3}° apart on average over all, {:.3}° at most",
        a.samples, a.same, 100.0 * a.same as f64 / a.samples as f64, a.mean_deg, a.max_deg
    );
    let h = filters::interpolated_height_error(samples, 5);
    println!(
        "interpolated height (¶84, a third blend) against the B-spline's in reals: {:.6} / {:.6} height LSB mean / max",
        h.mean(),
        h.max
    );
    println!("\nFIG. 8a against 8b: the largest jump across a texel edge of the derivative of N·L (light (0.6, 0.5, 0.3)) and of");
    println!("the cross tangent (∂/∂x of the v tangent at a vertical edge, and the converse), each method in reals, step 1e-4 texel");
    println!(
        "{:<40} {:>14} {:>14} {:>14} {:>14}",
        "surface", "Blinn N·L", "B-spline N·L", "Blinn cross", "B-spline cross"
    );
    for surface in surfaces::all() {
        let (g, k) = surfaces::codes_in_reals(&surface);
        let j = filters::fig8(&filters::Grid { side: surface.texels, h: &g }, k as f64, [0.6, 0.5, 0.3], 1e-4);
        println!(
            "{:<40} {:>14.4} {:>14.4} {:>14.4} {:>14.4}",
            surface.name, j.blinn.0, j.bspline.0, j.blinn.1, j.bspline.1
        );
    }
    println!("\nnormalise seed table and Newton steps (model; the unit has 10 table bits, no Newton step; `Normalise<T, N>` builds each):");
    println!("{:>11} {:>7} {:>24} {:>9}", "table bits", "Newton", "mean err (Sq1.10 LSB)", "max");
    for (t, n, s) in sim::accuracy::normaliser_tradeoff(samples, 3) {
        println!("{t:>11} {n:>7} {:>24.4} {:>9.4}", s.mean(), s.max);
    }
}

/// The LUT-size tables of the sine/cosine unit [10] and the cosine unit with sign [18]: entries and width against
/// error (every input) and, when `cost` is on, against what yosys makes of the rtl block of that size for iCE40.
pub fn lut_sizes(cost: bool, dir: &std::path::Path) -> Result<(), String> {
    let table = |name: &str, rows: Vec<vectors::sincos::SizeRow>| -> Result<(), String> {
        lut_header();
        let step =
            cost.then(|| crate::progress::Step::new(&format!("yosys: {name} at each size"), Some(rows.len() as u64)));
        let n = rows.len();
        for (k, r) in rows.into_iter().enumerate() {
            let tb = r.entries.trailing_zeros();
            let c = match &step {
                None => None,
                Some(step) => {
                    step.tick(k as u64);
                    let b = crate::units::block(name, (tb, r.width))?;
                    Some(b.synth_unit(
                        &dir.join(format!("{name}_t{}w{}", r.entries, r.width)),
                        synth::fpga::Family::Ice40,
                    )?)
                }
            };
            lut_row(&r, c.as_ref());
        }
        if let Some(step) = step {
            step.done(&format!("{n} sizes"));
        }
        Ok(())
    };
    println!(
        "\nsin/cos unit [10]: table size and width (10-bit elevation in; error in 8-bit LSB; the rtl has 256 × 8):"
    );
    table("sincos", sim::accuracy::sincos_sizes())?;
    println!(
        "\ncosine unit with sign [18]: table size and width (d = R − Q in; error of the signed cosine, 8-bit LSB):"
    );
    table("cos_sign", sim::accuracy::cos_sign_sizes())
}

fn lut_header() {
    println!(
        "{:>8} {:>6} {:>10} {:>9} {:>7} {:>6} {:>5} {:>5}",
        "entries", "width", "mean", "max", "max at", "LUT4", "FF", "BRAM"
    );
}

fn lut_row(r: &vectors::sincos::SizeRow, c: Option<&synth::fpga::Cells>) {
    let f = |x: Option<u64>| x.map(|v| v.to_string()).unwrap_or("-".into());
    println!(
        "{:>8} {:>6} {:>10.4} {:>9.4} {:>7} {:>6} {:>5} {:>5}",
        r.entries,
        r.width,
        r.mean_lsb8,
        r.max_lsb8,
        r.max_at,
        f(c.map(|c| c.lut4)),
        f(c.map(|c| c.ff)),
        f(c.map(|c| c.bram))
    );
}
