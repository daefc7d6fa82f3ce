//! `bumprtl hardcases`: the hard cases the seeds warn about, each as a row: the unit, the case, what the seeds (or
//! SPEC.md) ask, what the rtl does (run in rust-hdl, and held equal to the model), and pass or fail. Software units
//! (the encoders, the quantizer) are run on their model. The command fails if any row fails; a test runs it.
//!
//! Every check is the ask written as a test of the outputs (a length, a sign, an equality between two inputs), not
//! the model's own value copied.

/// One hard case: its vectors through `unit` (the row reads the last vector's outputs), and the check of them.
pub struct Case {
    pub unit: &'static str,
    pub case: String,
    pub ask: &'static str,
    pub inputs: Vec<Vec<i64>>,
    /// what is seen (a short text), and whether it is what the seeds ask
    pub check: Box<dyn Fn(&[Vec<i64>]) -> (String, bool)>,
}

/// A row of the table.
pub struct Row {
    pub unit: &'static str,
    pub case: String,
    pub ask: &'static str,
    pub seen: String,
    pub pass: bool,
}

fn len3(v: &[i64]) -> f64 {
    ((v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) as f64).sqrt()
}

fn case(
    unit: &'static str,
    case: &str,
    ask: &'static str,
    inputs: Vec<Vec<i64>>,
    check: impl Fn(&[Vec<i64>]) -> (String, bool) + 'static,
) -> Case {
    Case { unit, case: case.to_string(), ask, inputs, check: Box::new(check) }
}

/// The cases run on an rtl block.
pub fn rtl_cases() -> Vec<Case> {
    let mut v = vec![];
    // US 6,819,319, the Cartesian texel decode: illegal texels, texel 255
    let legal = |o: &[Vec<i64>]| {
        let b = &o[o.len() - 1];
        (format!("({}, {}, {})", b[0], b[1], b[2]), b[1] >= 1 && b[0].abs() + b[1] + b[2].abs() == 255)
    };
    for t in [[0, 0], [255, 255], [0, 254], [200, 10]] {
        v.push(case(
            "cart_decode",
            &format!("invalid texel ({}, {}): outside the diamond", t[0], t[1]),
            "a legal hemisphere vector: y ≥ 1, |x| + y + |z| = 255 (US 6,819,319: guard against illegal texels)",
            vec![t.to_vec()],
            legal,
        ));
    }
    v.push(case(
        "cart_decode",
        "texel 255 on x: (255, 127)",
        "no INT9 overflow: 255 reads as 254 (+127/127), so x = +254, y = 1",
        vec![vec![255, 127]],
        |o| {
            let b = &o[0];
            (format!("({}, {}, {})", b[0], b[1], b[2]), b[0] == 254 && b[1] == 1 && b[2] == 0)
        },
    ));
    v.push(case("cart_decode", "texel (127, 127)", "straight up: (0, 255, 0)", vec![vec![127, 127]], |o| {
        let b = &o[0];
        (format!("({}, {}, {})", b[0], b[1], b[2]), b[..] == [0, 255, 0])
    }));
    // the normaliser
    v.push(case(
        "normalise",
        "zero-length vector (0, 0, 0)",
        "defined: (0, 0, 0), so N·L = 0 (no light direction, no light)",
        vec![vec![0, 0, 0]],
        |o| (format!("{:?}", o[0]), o[0] == [0, 0, 0]),
    ));
    v.push(case(
        "normalise",
        "the most negative S10: (−512, −512, −512)",
        "each −1024/√3 = −591.2, within 1",
        vec![vec![-512, -512, -512]],
        |o| (format!("{:?}", o[0]), o[0].iter().all(|&c| (c as f64 + 1024.0 / 3f64.sqrt()).abs() <= 1.0)),
    ));
    v.push(case(
        "normalise",
        "a vector shortened by interpolation: (1, 1, 0)",
        "unit length again: (724, 724, 0) within 1 (1024/√2 = 724.1)",
        vec![vec![1, 1, 0]],
        |o| (format!("{:?}", o[0]), (o[0][0] - 724).abs() <= 1 && (o[0][1] - 724).abs() <= 1 && o[0][2] == 0),
    ));
    // the light iterator: vertex lights 180° and 120° apart, interpolated through their midpoint
    v.push(case(
        "light_iter",
        "vertex lights 180° apart, at the midpoint",
        "US 6,819,319's warning: the interpolated vector shrinks to zero length (|L| ≤ 1 LSB)",
        vec![vec![127, 0, 0, -127, 0, 0, 127, 0, 0, 128, 0]],
        |o| (format!("{:?}", o[0]), len3(&o[0]) <= 1.0),
    ));
    let a = vectors::light_iter::quantise_vertex([0.866_025_403_784_438_6, 0.5, 0.0]);
    let b = vectors::light_iter::quantise_vertex([-0.866_025_403_784_438_6, 0.5, 0.0]);
    v.push(case(
        "light_iter",
        "vertex lights 120° apart, at the midpoint",
        "shortened to cos 60° = ½ of the vertices' length (127·4 in Sq7.2), pointing between them: (0, ≈254, 0)",
        vec![[a.to_vec(), b.to_vec(), a.to_vec(), vec![128, 0]].concat()],
        |o| {
            let l = len3(&o[0]);
            (format!("{:?}, |L| = {l:.1}", o[0]), o[0][0].abs() <= 2 && (l / 508.0 - 0.5).abs() < 0.02)
        },
    ));
    // N·L at and below the horizon
    let up = [0, 1024, 0];
    for (what, l, ask, want) in [
        ("light below the horizon", [0, -1024, 0], "clamped: N·L = 0, the back is dark", 0),
        ("light on the horizon", [1024, 0, 0], "N·L = 0", 0),
        ("light straight above", [0, 1024, 0], "N·L = 1023 (1.0 in U10)", 1023),
        (
            "the most negative Sq1.10 on both",
            [-2048, -2048, -2048],
            "N·L of two equal vectors is positive, saturated: 1023",
            1023,
        ),
    ] {
        let n = if what.starts_with("the most") { [-2048, -2048, -2048] } else { up };
        v.push(case("dot3", what, ask, vec![[n.to_vec(), l.to_vec()].concat()], move |o| {
            (format!("{}", o[0][0]), o[0][0] == want)
        }));
    }
    // one light per surface, the smallest pipeline: the light made once, at its ends
    let surface = |t: [i64; 2], l: [i64; 3]| [t.to_vec(), l.to_vec(), vec![1, 200, 150, 100, 10, 20, 30]].concat();
    for (what, t, l, ask, pass) in [
        (
            "flat texel (127, 127), the surface light straight above",
            [127, 127],
            [0, 1024, 0],
            "full: P ≥ 1020 of 1023 (the decode's 255 and the light's 1024 normalised)",
            (|p: i64| p >= 1020) as fn(i64) -> bool,
        ),
        ("flat texel, the surface light below the horizon", [127, 127], [0, -1024, 0], "dark: P = 0", |p| p == 0),
        ("flat texel, the zero light (a zero-length light made once)", [127, 127], [0, 0, 0], "no light: P = 0", |p| {
            p == 0
        }),
        (
            "texel 255 (guarded to (127, 1, 127)), lit along +x",
            [255, 255],
            [1024, 0, 0],
            "half lit: P = 1023·127/√(2·127² + 1) ≈ 723, within 2",
            |p| (p - 723).abs() <= 2,
        ),
    ] {
        v.push(case("cart_surface_nearest_matte", what, ask, vec![surface(t, l)], move |o| {
            (format!("P = {}", o[0][0]), pass(o[0][0]))
        }));
    }
    // R's wrap: R − Q is taken mod 256 [16]
    let light = vectors::polar_encode::encode_light(vectors::polar_encode::Scale::Seed, [0.3, 0.8, 0.2], 1.0);
    let at = |r: i64, q: i64| vec![100, r, q, light.k1, light.k2, light.k3];
    v.push(case(
        "polar_shade",
        "R's wrap: R = 250, Q = 5 against R = 0, Q = 11 and R = 11, Q = 0",
        "R − Q mod 256 [16]: an angle 11 steps across the wrap shades as 11 steps anywhere (all three equal)",
        vec![at(250, 5), at(0, 11), at(11, 0)],
        |o| (format!("shade {}, {}, {}", o[0][1], o[1][1], o[2][1]), o[0][1] == o[1][1] && o[1][1] == o[2][1]),
    ));
    v.push(case(
        "polar_shade",
        "R opposite Q: R − Q = 128",
        "cos(180°) < 0: the subtracting path [24], shade below the same S at R = Q",
        vec![at(133, 5), at(5, 5)],
        |o| (format!("shade {} against {}", o[0][1], o[1][1]), o[0][1] < o[1][1]),
    ));
    // US 2004/0207631: the steepest height steps
    let step = |w: [i64; 9], ub: i64, vb: i64, s: i64| [w.to_vec(), vec![ub, vb, s]].concat();
    v.push(case(
        "height_pipeline",
        "the steepest step: 0 → 255 in one texel along u, the largest scale",
        "no overflow: a unit normal (|n| = 1024 ± 2) leaning away from the rise (n_x < 0)",
        vec![step([0, 255, 255, 0, 255, 255, 0, 255, 255], 128, 128, 255)],
        |o| {
            let l = len3(&o[0]);
            (format!("{:?}, |n| = {l:.1}", o[0]), (l - 1024.0).abs() <= 2.0 && o[0][0] < 0)
        },
    ));
    v.push(case(
        "height_pipeline",
        "the steepest step along v, falling",
        "a unit normal leaning towards +v (n_z > 0), |n| = 1024 ± 2",
        vec![step([255, 255, 255, 0, 0, 0, 0, 0, 0], 128, 128, 255)],
        |o| {
            let l = len3(&o[0]);
            (format!("{:?}, |n| = {l:.1}", o[0]), (l - 1024.0).abs() <= 2.0 && o[0][2] > 0)
        },
    ));
    v.push(case(
        "height_pipeline",
        "a flat map at the top code (255 everywhere)",
        "straight up: (0, 1024, 0)",
        vec![step([255; 9], 255, 255, 255)],
        |o| (format!("{:?}", o[0]), o[0] == [0, 1024, 0]),
    ));
    v
}

/// The most negative value of every signed input of every unit at once, the unsigned ones at 0: a row per unit.
pub fn most_negative(units: &'static [sim::units::Unit]) -> Vec<Case> {
    units
        .iter()
        .map(|u| u.model)
        .filter(|m| m.inputs.iter().any(|p| p.signed))
        .map(|m| {
            let input: Vec<i64> = m.inputs.iter().map(|p| if p.signed { p.range().0 } else { 0 }).collect();
            let ranges: Vec<(i64, i64)> = m.outputs.iter().map(|p| p.range()).collect();
            case(
                m.name,
                "every signed input at its most negative",
                "no wrap: the rtl equals the model (64-bit, no wrap) and every output is in its port's range",
                vec![input],
                move |o| {
                    let ok = o[0].iter().zip(&ranges).all(|(&x, &(lo, hi))| (lo..=hi).contains(&x));
                    (format!("{:?}", o[0]), ok)
                },
            )
        })
        .collect()
}

/// Software cases: run on the model (these units have no rtl).
pub fn software_rows() -> Vec<Row> {
    let mut rows = vec![];
    // the polar light below the horizon
    let l = vectors::polar_encode::encode_light(vectors::polar_encode::Scale::Seed, [0.6, -0.2, 0.3], 1.0);
    rows.push(Row {
        unit: "polar_encode",
        case: "light 18° below the horizon".into(),
        ask: "US 6,819,319's shortcoming: a polar light cannot go below; it is moved onto the horizon (T = 0) and flagged",
        seen: format!("T = {:.3}°, moved = {}", l.t.to_degrees(), l.moved),
        pass: l.moved && l.t == 0.0,
    });
    let l = vectors::polar_encode::encode_light(vectors::polar_encode::Scale::Seed, [0.6, 0.0, 0.3], 1.0);
    rows.push(Row {
        unit: "polar_encode",
        case: "light on the horizon".into(),
        ask: "T = 0 as it is, not flagged as moved",
        seen: format!("T = {:.3}°, moved = {}", l.t.to_degrees(), l.moved),
        pass: !l.moved && l.t.abs() < 1e-12,
    });
    // s_N = 1: a palette of one normal
    let normals = sim::scene::Scene { tex: 32, ..Default::default() }.normals();
    let q = vectors::palette::quantize::quantize(&normals, 1);
    let mean: [f64; 3] = std::array::from_fn(|c| normals.iter().map(|n| n[c]).sum::<f64>());
    let ml = (mean[0] * mean[0] + mean[1] * mean[1] + mean[2] * mean[2]).sqrt();
    let p = q.palette.first().copied().unwrap_or([0.0; 3]);
    let cos = (0..3).map(|c| p[c] * mean[c] / ml).sum::<f64>();
    rows.push(Row {
        unit: "quantize",
        case: "s_N = 1 on the demo's 32 × 32 map".into(),
        ask: "one entry, every texel's index 0, the entry the direction of the map's mean normal (within 0.5°)",
        seen: format!(
            "{} entry, indices {:?}, {:.3}° from the mean",
            q.palette.len(),
            q.index.iter().max(),
            cos.clamp(-1.0, 1.0).acos().to_degrees()
        ),
        pass: q.palette.len() == 1 && q.index.iter().all(|&i| i == 0) && cos.clamp(-1.0, 1.0).acos().to_degrees() < 0.5,
    });
    rows
}

/// Every case: through the unit's rtl block in rust-hdl, back to back, and through its model, checked.
pub fn rows() -> Result<Vec<Row>, String> {
    let mut cases = rtl_cases();
    cases.extend(most_negative(sim::units::UNITS));
    let mut rows = vec![];
    for c in cases {
        let u = sim::units::find(c.unit).ok_or_else(|| format!("hard case of an unknown unit `{}`", c.unit))?;
        let model = u.model.run(&c.inputs);
        let got = u.rtl.outputs(u.model, &c.inputs);
        let (seen, ok) = (c.check)(&got);
        let same = got == model;
        rows.push(Row {
            unit: c.unit,
            case: c.case,
            ask: c.ask,
            seen: if same { seen } else { format!("{seen}; the rtl differs from the model ({model:?})") },
            pass: ok && same,
        });
    }
    rows.extend(software_rows());
    Ok(rows)
}

/// The table, and an error if a row fails.
pub fn run() -> Result<(), String> {
    let rows = rows()?;
    println!("| unit | hard case | what the sources ask | what the rtl does | |");
    println!("| --- | --- | --- | --- | --- |");
    // a cell's own `|` (|x|, |L|) escaped, so that the Markdown table keeps its columns
    let cell = |t: &str| t.replace('|', "\\|");
    for r in &rows {
        println!(
            "| {} | {} | {} | {} | {} |",
            r.unit,
            cell(&r.case),
            cell(r.ask),
            cell(&r.seen),
            if r.pass { "pass" } else { "FAIL" }
        );
    }
    let failed: Vec<String> = rows.iter().filter(|r| !r.pass).map(|r| format!("{}: {}", r.unit, r.case)).collect();
    let units: std::collections::BTreeSet<&str> = rows.iter().map(|r| r.unit).collect();
    println!(
        "\n{} hard cases over {} units: {} pass, {} fail",
        rows.len(),
        units.len(),
        rows.len() - failed.len(),
        failed.len()
    );
    if !failed.is_empty() {
        return Err(format!("{} hard cases fail: {}", failed.len(), failed.join("; ")));
    }
    Ok(())
}
