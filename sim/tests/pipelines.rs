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
];

/// The pipeline a scene's choices name, by the project's naming of its rtl tops; None where the reader refuses.
fn expected(
    encoding: &str,
    per_surface: bool,
    filter: &str,
    gloss: bool,
    palette: Option<usize>,
    fetch: Option<&str>,
) -> Option<String> {
    let hemi = if encoding == "hemi_oct" { "_hemi_oct" } else { "" };
    let matte = if gloss { "" } else { "_matte" };
    let on_unit = ON_THE_UNIT.contains(&(encoding, per_surface, filter, gloss));
    let cartesian = matches!(encoding, "seed" | "hemi_oct");
    if (!cartesian && (filter != "bilinear" || fetch.is_some())) || (fetch == Some("unit") && !on_unit) {
        return None;
    }
    if cartesian && fetch != Some("host") && on_unit {
        let surface = if per_surface { "_surface" } else { "" };
        return Some(format!("cart_tex_{filter}{surface}{hemi}{matte}"));
    }
    if filter == "nearest_mip" || (filter == "nearest" && !per_surface) {
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
    for encoding in ["seed", "hemi_oct", "polar", "polar_dc255", "heights", "palette"] {
        for per in [None, Some("vertex"), Some("surface")] {
            for gloss in [None, Some(0), Some(96)] {
                for filter in [None, Some("bilinear"), Some("nearest"), Some("nearest_mip")] {
                    for (palette, fetch) in [None, Some(256), Some(300), Some(4096)]
                        .into_iter()
                        .flat_map(|p| [(p, None), (p, Some("unit")), (p, Some("host"))])
                    {
                        for shape in ["quad", "torus"] {
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
                            if let Some(g) = gloss {
                                t += &format!("[material]\ngloss = {g}\n");
                            }
                            let Ok(spec) = sim::scene_file::parse(&t, "s.toml", std::path::Path::new(".")) else {
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
                for filter in [Filter::Bilinear, Filter::Nearest, Filter::NearestMip] {
                    for (index_bits, fetch) in [0, 8, 12].into_iter().flat_map(|b| [(b, Fetch::Unit), (b, Fetch::Host)])
                    {
                        let c = Choices { encoding, per, gloss, filter, index_bits, fetch };
                        let n = PIPELINES.iter().filter(|r| r.serves == c).count();
                        assert!(n <= 1, "{c:?}: {n} pipelines");
                        assert_eq!(pipelines::choose(&c).is_some(), n == 1);
                        served += n;
                    }
                }
            }
        }
    }
    assert_eq!(served, PIPELINES.len(), "every row serves a combination of these choices");
}
