//! The table of pipelines against the scene reader: every scene the reader accepts gets exactly one row, the one its
//! choices name, and every row is some scene's.
use sim::pipelines::{self, Choices, Encoding, Fetch, Filter, Per, PIPELINES};
use std::collections::BTreeSet;

/// The pipelines on the texture unit, by their choices (encoding, per surface, filter, gloss), written apart from
/// the table: `cart_tex_<filter>[_surface][_hemi_oct][_matte]`.
const ON_THE_UNIT: &[(&str, bool, &str, bool)] = &[
    ("seed", false, "bilinear", true),
    ("seed", false, "bilinear", false),
    ("seed", false, "nearest", false),
    ("seed", false, "nearest_mip", false),
    ("seed", false, "trilinear", false),
    ("seed", false, "trilinear_two_pass", false),
    ("seed", false, "trilinear", true),
    ("hemi_oct", false, "trilinear", true),
    ("seed", true, "trilinear", true),
    ("hemi_oct", false, "bilinear", true),
    ("seed", true, "bilinear", true),
    ("seed", true, "bilinear", false),
    ("seed", true, "nearest", false),
    ("hemi_oct", true, "nearest", false),
    ("seed", false, "nearest", true),
    ("seed", false, "nearest_mip", true),
    ("hemi_oct", false, "bilinear", false),
    ("hemi_oct", false, "trilinear", false),
    ("seed", true, "trilinear", false),
    ("hemi_oct", false, "nearest", true),
    ("hemi_oct", false, "nearest", false),
    ("seed", true, "nearest", true),
    ("hemi_oct", true, "nearest", true),
    ("hemi_oct", false, "nearest_mip", true),
    ("hemi_oct", false, "nearest_mip", false),
    ("seed", true, "nearest_mip", true),
    ("seed", true, "nearest_mip", false),
    ("hemi_oct", true, "nearest_mip", true),
    ("hemi_oct", true, "nearest_mip", false),
    ("hemi_oct", true, "bilinear", true),
    ("hemi_oct", true, "bilinear", false),
    ("hemi_oct", true, "trilinear", true),
    ("hemi_oct", true, "trilinear", false),
];

/// The pipelines with a colour map, likewise: `cart_tex_<filter>[_surface][_hemi_oct][_matte]_colour`.
const WITH_COLOUR: &[(&str, bool, &str, bool)] = &[
    ("seed", false, "bilinear", true),
    ("seed", true, "bilinear", true),
    ("seed", false, "nearest", true),
    ("seed", false, "nearest_mip", true),
    ("seed", false, "nearest", false),
    ("hemi_oct", false, "nearest", true),
    ("hemi_oct", false, "nearest", false),
    ("seed", true, "nearest", true),
    ("seed", true, "nearest", false),
    ("hemi_oct", true, "nearest", true),
    ("hemi_oct", true, "nearest", false),
    ("seed", false, "nearest_mip", false),
    ("hemi_oct", false, "nearest_mip", true),
    ("hemi_oct", false, "nearest_mip", false),
    ("seed", true, "nearest_mip", true),
    ("seed", true, "nearest_mip", false),
    ("hemi_oct", true, "nearest_mip", true),
    ("hemi_oct", true, "nearest_mip", false),
    ("seed", false, "bilinear", false),
    ("hemi_oct", false, "bilinear", true),
    ("hemi_oct", false, "bilinear", false),
    ("seed", true, "bilinear", false),
    ("hemi_oct", true, "bilinear", true),
    ("hemi_oct", true, "bilinear", false),
    ("seed", false, "trilinear", true),
    ("seed", false, "trilinear", false),
    ("hemi_oct", false, "trilinear", true),
    ("hemi_oct", false, "trilinear", false),
    ("seed", true, "trilinear", true),
    ("seed", true, "trilinear", false),
    ("hemi_oct", true, "trilinear", true),
    ("hemi_oct", true, "trilinear", false),
];

/// The pipeline a scene's choices name, by the project's naming of its rtl tops; None where the reader refuses.
fn expected(
    encoding: &str,
    per_surface: bool,
    filter: &str,
    gloss: bool,
    palette: Option<usize>,
    fetch: Option<&str>,
    colour: bool,
) -> Option<String> {
    let hemi = if encoding == "hemi_oct" { "_hemi_oct" } else { "" };
    let matte = if gloss { "" } else { "_matte" };
    let on_unit = ON_THE_UNIT.contains(&(encoding, per_surface, filter, gloss));
    let cartesian = matches!(encoding, "seed" | "hemi_oct");
    if colour {
        let surface = if per_surface { "_surface" } else { "" };
        let served = WITH_COLOUR.contains(&(encoding, per_surface, filter, gloss)) && fetch != Some("host");
        return served.then(|| format!("cart_tex_{filter}{surface}{hemi}{matte}_colour"));
    }
    // palette indices: on the texture unit where the scene names one of its filters (an index is never blended:
    // nearest, nearest_mip) or fetch = "unit" (then the nearest), 8-bit indices only; else fed by the host
    if encoding == "palette" {
        let small = palette.is_some_and(|n| n <= 256);
        return match (filter, fetch) {
            ("nearest" | "nearest_mip", Some("host")) => None,
            ("nearest" | "nearest_mip", _) => small.then(|| format!("palette_tex_{filter}")),
            ("bilinear", Some("unit")) => small.then(|| "palette_tex_nearest".to_string()),
            // (filter = "bilinear", or none: the host-fed pipeline, as before the texture unit held indices)
            ("bilinear", _) if palette.unwrap() <= 256 => Some("palette_pipeline".into()),
            ("bilinear", _) => Some("palette_pipeline_12".into()),
            _ => None,
        };
    }
    // polar texels (the seed's scale) on the texture unit unless fetch = "host" (the scenes' map, 16 texels, is one
    // the unit holds); the host-fed polar pipelines with fetch = "host", and the Dreamcast scale's whatever is said
    let polar = matches!(encoding, "polar" | "polar_dc255");
    if encoding == "polar" && fetch != Some("host") {
        return matches!(filter, "bilinear" | "trilinear").then(|| format!("polar_tex_{filter}"));
    }
    let host_polar = polar && fetch == Some("host");
    if (!cartesian && (filter != "bilinear" || (fetch.is_some() && !host_polar))) || (fetch == Some("unit") && !on_unit)
    {
        return None;
    }
    if cartesian && fetch != Some("host") && on_unit {
        let surface = if per_surface { "_surface" } else { "" };
        return Some(format!("cart_tex_{filter}{surface}{hemi}{matte}"));
    }
    if matches!(filter, "nearest_mip" | "trilinear" | "trilinear_two_pass") || (filter == "nearest" && !per_surface) {
        return None;
    }
    let nearest = filter == "nearest";
    Some(match encoding {
        "seed" | "hemi_oct" if per_surface => {
            format!("cart_surface{}{hemi}{matte}", if nearest { "_nearest" } else { "" })
        }
        "seed" | "hemi_oct" => format!("cart_pipeline{hemi}{matte}"),
        "polar" => "polar_pipeline".into(),
        "polar_dc255" => "polar_pipeline_dc".into(),
        "heights" => "height_pipeline".into(),
        "palette" if palette.unwrap() <= 256 => "palette_pipeline".into(),
        "palette" => "palette_pipeline_12".into(),
        other => panic!("no encoding {other}"),
    })
}

#[test]
fn every_scene_the_reader_takes_has_exactly_one_pipeline_and_every_pipeline_a_scene() {
    let mut reached = BTreeSet::new();
    let mut taken = 0;
    let dir = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/test-files/pipelines");
    std::fs::create_dir_all(&dir).unwrap();
    let tiles = sim::heightmap::ColourMap::tiles(16);
    sim::render::write_png(&dir.join("tiles.png"), 16, |k| tiles.rgb[k].map(|c| c as u8)).unwrap();
    for encoding in ["seed", "hemi_oct", "polar", "polar_dc255", "heights", "palette"] {
        for per in [None, Some("vertex"), Some("surface")] {
            for gloss in [None, Some(0), Some(96)] {
                for filter in [
                    None,
                    Some("bilinear"),
                    Some("nearest"),
                    Some("nearest_mip"),
                    Some("trilinear"),
                    Some("trilinear_two_pass"),
                ] {
                    for (palette, fetch) in [None, Some(256), Some(300), Some(4096)]
                        .into_iter()
                        .flat_map(|p| [(p, None), (p, Some("unit")), (p, Some("host"))])
                    {
                        for (shape, colour) in ["quad", "torus"].into_iter().flat_map(|s| [(s, false), (s, true)]) {
                            let mut t = format!("size = 32\n[surface]\nshape = \"{shape}\"\n[bump]\nsource = \"procedural\"\ntexels = 16\nencoding = \"{encoding}\"\n");
                            if let Some(f) = filter {
                                t += &format!("filter = \"{f}\"\n");
                            }
                            if let Some(f) = fetch {
                                t += &format!("fetch = \"{f}\"\n");
                            }
                            if let Some(n) = palette {
                                t += &format!("palette = {n}\n");
                            }
                            if let Some(p) = per {
                                t += &format!("[light]\nper = \"{p}\"\n");
                            }
                            if gloss.is_some() || colour {
                                t += "[material]\n";
                            }
                            if let Some(g) = gloss {
                                t += &format!("gloss = {g}\n");
                            }
                            if colour {
                                t += "colour_map = \"tiles.png\"\n";
                            }
                            let Ok(spec) = sim::scene_file::parse(&t, "s.toml", &dir) else {
                                continue;
                            };
                            taken += 1;
                            let want = expected(
                                encoding,
                                per == Some("surface"),
                                filter.unwrap_or("bilinear"),
                                gloss.unwrap_or(96) != 0,
                                palette,
                                fetch,
                                colour,
                            );
                            let want = want.unwrap_or_else(|| {
                                panic!("{t}: taken as {}, but no pipeline should serve it", spec.pipeline.name)
                            });
                            assert_eq!(spec.pipeline.name, want, "{t}");
                            assert_eq!(PIPELINES.iter().filter(|r| r.serves == spec.pipeline.serves).count(), 1, "{t}");
                            let built = spec.build();
                            assert_eq!((built.model().name, built.rtl().name()), (want.as_str(), want.as_str()));
                            assert_eq!(spec.scene.per_surface, spec.pipeline.serves.per == Per::Surface, "{t}");
                            reached.insert(spec.pipeline.name);
                        }
                    }
                }
            }
        }
    }
    assert!(taken > 100, "{taken} scenes taken");
    let all: BTreeSet<&str> = PIPELINES.iter().map(|r| r.name).collect();
    assert_eq!(reached, all, "every pipeline is some scene's");
}

#[test]
fn no_combination_of_choices_has_two_pipelines() {
    let encodings = [
        Encoding::Seed,
        Encoding::HemiOct,
        Encoding::Polar,
        Encoding::PolarDc255,
        Encoding::Heights,
        Encoding::Palette,
    ];
    let mut served = 0;
    for encoding in encodings {
        for per in [Per::Vertex, Per::Surface] {
            for gloss in [false, true] {
                for filter in
                    [Filter::Bilinear, Filter::Nearest, Filter::NearestMip, Filter::Trilinear, Filter::TrilinearTwoPass]
                {
                    for (index_bits, fetch) in [0, 8, 12].into_iter().flat_map(|b| [(b, Fetch::Unit), (b, Fetch::Host)])
                    {
                        for colour in [false, true] {
                            let c = Choices { encoding, per, gloss, filter, index_bits, fetch, colour };
                            let n = PIPELINES.iter().filter(|r| r.serves == c).count();
                            assert!(n <= 1, "{c:?}: {n} pipelines");
                            assert_eq!(pipelines::choose(&c).is_some(), n == 1);
                            served += n;
                        }
                    }
                }
            }
        }
    }
    assert_eq!(served, PIPELINES.len(), "every row serves a combination of these choices");
}

mod built {
    use sim::pipeline::*;
    use sim::pipelines::{self, Settings};
    use sim::scene::Scene;
    use vectors::cart_pipeline::Decode;

    fn all() -> Vec<Box<dyn Pipeline>> {
        pipelines::PIPELINES.iter().map(|r| build(r, &Scene::default(), &Settings::default())).collect()
    }

    /// On level 0 the texture unit reads what the host-fed pipeline was given: the same frame, pixel for pixel,
    /// on the quad, on the demo's torus and on a sphere whose map repeats 64 times round it (positions far past
    /// Sq11.8's range unless reduced modulo the map).
    #[test]
    fn the_units_bilinear_frame_is_the_host_fed_frame() {
        use sim::scene::Curved;
        let unit = pipelines::named("cart_tex_bilinear_matte").unwrap();
        let host = pipelines::named("cart_pipeline_matte").unwrap();
        let demo = sim::scene_file::parse(sim::scene_file::DEMO, "demo.toml", std::path::Path::new(".")).unwrap().scene;
        let mut sphere = Scene { size: 96, conc: 0, ..demo.clone() };
        sphere.curved = Some(Curved { shape: sim::surface::Shape::Sphere, repeat: [64, 1], ..demo.curved.unwrap() });
        let quad = Scene { size: 64, conc: 0, ..Scene::default() };
        // the scene's wrap against the surface's own: the quad repeating (at 256 pixels its edge pixels sample
        // within half a texel of its edge), the torus clamped
        let repeating = Scene { size: 256, wrap: Some([true, true]), ..quad.clone() };
        let clamped = Scene { size: 128, wrap: Some([false, false]), ..demo.clone() };
        let outs = |s: &Scene| sim::render::model(host.model(), &build(host, s, &Settings::default()).prepare(s)).outs;
        let own = Scene { wrap: None, ..repeating.clone() };
        assert_ne!(outs(&own), outs(&repeating), "the quad's edge texels blend with the far edge's");
        for (what, scene) in [
            ("quad", quad),
            ("demo", Scene { size: 128, ..demo }),
            ("sphere", sphere),
            ("quad, repeating", repeating),
            ("torus, clamped", clamped),
        ] {
            let (u, h) = (build(unit, &scene, &Settings::default()), build(host, &scene, &Settings::default()));
            let (pu, ph) = (u.prepare(&scene), h.prepare(&scene));
            let (ou, oh) = (sim::render::model(u.model(), &pu), sim::render::model(h.model(), &ph));
            assert!(ou.outs.len() > 1000, "{what}: {} pixels", ou.outs.len());
            let differ = ou.outs.iter().zip(&oh.outs).filter(|(a, b)| a != b).count();
            assert_eq!((differ, ou.outs.len()), (0, oh.outs.len()), "{what}");
            // the normal read through the unit's memory is the host's from its four texels
            let normals = |p: &dyn Pipeline, x: &sim::prepared::Prepared| -> Vec<_> {
                x.pixels().iter().map(|v| p.normal(v).expect("a normal")).collect()
            };
            assert!(normals(u.as_ref(), &pu) == normals(h.as_ref(), &ph), "{what}: normals");
        }
    }

    /// The polar pipeline on the unit at level 0 is the host-fed one: S and R read from the memory and filtered as
    /// numbers by the unit's bilinear units give the frame the host's own filtering gave, pixel for pixel, on the
    /// quad (its R wrapping across footprints) and on the demo's torus, at the scene's power and weight.
    #[test]
    fn the_units_polar_frame_is_the_host_fed_frame() {
        let unit = pipelines::named("polar_tex_bilinear").unwrap();
        let host = pipelines::named("polar_pipeline").unwrap();
        let demo = sim::scene_file::parse(sim::scene_file::DEMO, "demo.toml", std::path::Path::new(".")).unwrap().scene;
        let settings = Settings { pw: 10, h: 0.75, ..Settings::default() };
        for (what, scene) in [("quad", Scene { size: 96, ..Scene::default() }), ("demo", Scene { size: 128, ..demo })] {
            let (u, h) = (build(unit, &scene, &settings), build(host, &scene, &settings));
            let (pu, ph) = (u.prepare(&scene), h.prepare(&scene));
            let (ou, oh) = (sim::render::model(u.model(), &pu), sim::render::model(h.model(), &ph));
            assert!(ou.outs.len() > 1000, "{what}: {} pixels", ou.outs.len());
            let differ = ou.outs.iter().zip(&oh.outs).filter(|(a, b)| a != b).count();
            assert_eq!((differ, ou.outs.len()), (0, oh.outs.len()), "{what}");
        }
    }

    /// The palette pipeline on the unit with the nearest texel of level 0 is the host-fed one: the index map in
    /// the memory, read at each pixel's sample point, gives the host's nearest index, and the table builds of the
    /// host's prologue come after the map's writes; frame and normals alike, pixel for pixel, on the quad.
    #[test]
    fn the_units_palette_frame_is_the_host_fed_frame() {
        let unit = pipelines::named("palette_tex_nearest").unwrap();
        let host = pipelines::named("palette_pipeline").unwrap();
        let settings = Settings { palette: Some(200), ..Settings::default() };
        let scene = Scene { size: 96, ..Scene::default() };
        let (u, h) = (build(unit, &scene, &settings), build(host, &scene, &settings));
        let (pu, ph) = (u.prepare(&scene), h.prepare(&scene));
        let (ou, oh) = (sim::render::model(u.model(), &pu), sim::render::model(h.model(), &ph));
        assert!(ou.outs.len() > 1000, "{} pixels", ou.outs.len());
        let differ = ou.outs.iter().zip(&oh.outs).filter(|(a, b)| a != b).count();
        assert_eq!((differ, ou.outs.len()), (0, oh.outs.len()));
        let normals = |p: &dyn Pipeline, x: &sim::prepared::Prepared| -> Vec<_> {
            x.pixels().iter().map(|v| p.normal(v).expect("a normal")).collect()
        };
        assert!(normals(u.as_ref(), &pu) == normals(h.as_ref(), &ph), "normals");
        // and the model's frame is the Verilator frame's and rust-hdl's elsewhere (the three-way tests); here the
        // prologue holds the map's levels (128 … 1) then 200 builds
        assert_eq!(pu.prologue, (0..=7).map(|k| (128usize >> k).pow(2)).sum::<usize>() + 200);
    }

    #[test]
    fn a_built_pipeline_is_its_row() {
        for (p, r) in all().iter().zip(pipelines::PIPELINES) {
            assert_eq!((p.row().name, p.model().name, p.rtl().name()), (r.name, r.name, r.name));
        }
    }

    /// The per-vertex pipeline without the gloss unit holds the full one's other units and renders a C = 0 scene
    /// as the full one does.
    #[test]
    fn a_matte_scene_gets_the_per_vertex_pipeline_without_gloss_and_the_same_picture() {
        for decode in [Decode::Seed, Decode::HemiOct] {
            let scene = Scene { size: 24, conc: 0, ..Scene::default() };
            let (m, g) = (Cartesian::new(decode, false), Cartesian::glossy(decode));
            assert!(!m.units().contains(&"gloss") && g.units().contains(&"gloss"));
            assert_eq!(
                m.units().iter().filter(|u| **u != "gloss").collect::<Vec<_>>(),
                g.units().iter().filter(|u| **u != "gloss").collect::<Vec<_>>()
            );
            let (pm, pg) = (m.prepare(&scene), g.prepare(&scene));
            assert_eq!(pm.pixels().len(), pg.pixels().len());
            assert!(!pm.pixels().is_empty());
            for (a, b) in pm.pixels().iter().zip(pg.pixels()) {
                assert_eq!(a.len() + 1, b.len());
                assert_eq!((m.model().exact)(a), (g.model().exact)(b));
                assert_eq!(m.normal(a), g.normal(b));
            }
        }
    }

    #[test]
    fn prepared_inputs_are_legal_for_the_model() {
        for p in all() {
            // a pipeline without a gloss unit is built for C = 0
            let conc = if p.units().contains(&"gloss") { Scene::default().conc } else { 0 };
            let mut scene = Scene { size: 8, conc, ..Scene::default() };
            if p.row().serves.colour {
                scene.colour_map = Some(std::sync::Arc::new(sim::heightmap::ColourMap::tiles(scene.tex)));
            }
            let prep = p.prepare(&scene);
            assert_eq!((prep.pixels().len(), prep.ideal.len()), (64, 64));
            for x in &prep.inputs {
                for (v, port) in x.iter().zip(p.model().inputs) {
                    let (lo, hi) = port.range();
                    assert!((lo..=hi).contains(v), "{}: {} = {v}", p.model().name, port.name);
                }
            }
        }
    }
}

mod rows {
    use sim::pipelines::*;
    use vectors::cart_pipeline::Decode;
    use vectors::cart_surface::Variant;

    #[test]
    fn a_row_is_named_after_its_model_and_its_block_and_holds_units_of_the_table() {
        let mut names = std::collections::BTreeSet::new();
        for r in PIPELINES {
            assert!(names.insert(r.name), "{} twice", r.name);
            assert!(sim::units::find(r.name).is_some(), "{} is in the unit table", r.name);
            assert_eq!((r.model().name, r.rtl().name()), (r.name, r.name));
            for u in r.units {
                assert!(sim::units::find(u).is_some(), "{}: unit {u} is not in the unit table", r.name);
            }
        }
    }

    #[test]
    fn no_two_rows_serve_the_same_choices() {
        for (i, a) in PIPELINES.iter().enumerate() {
            for b in &PIPELINES[i + 1..] {
                assert_ne!(a.serves, b.serves, "{} and {}", a.name, b.name);
            }
            assert_eq!(choose(&a.serves), Some(a));
        }
    }

    #[test]
    fn a_surface_row_holds_the_units_its_variant_needs_and_no_others() {
        let mut seen = vec![];
        for r in PIPELINES {
            let Family::CartSurface(variant) = r.family else { continue };
            let has = |u: &str| r.units.contains(&u);
            assert_eq!(has("gloss"), variant.gloss, "{variant:?}");
            assert_eq!(has("bilinear"), !variant.nearest, "{variant:?}");
            assert_eq!(
                (has("cart_decode_hemi_oct"), has("cart_decode")),
                (variant.decode == Decode::HemiOct, variant.decode == Decode::Seed)
            );
            assert!(!has("light_iter") && r.units.iter().filter(|u| **u == "normalise").count() == 1, "{variant:?}");
            assert_eq!(r.model().name, variant.model().name, "{variant:?}");
            seen.push(variant);
        }
        assert!(Variant::ALL.iter().all(|v| seen.contains(v)) && seen.len() == 8);
        let labels: std::collections::BTreeSet<&str> =
            PIPELINES.iter().filter(|r| matches!(r.family, Family::CartSurface(_))).map(|r| r.label).collect();
        assert_eq!(labels.len(), 8);
    }
}
