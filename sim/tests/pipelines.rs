//! The table of pipelines against the scene reader: every scene the reader accepts gets exactly one row, the one its
//! choices name, and every row is some scene's.
use sim::pipelines::{self, Choices, Encoding, Filter, Per, PIPELINES};
use std::collections::BTreeSet;

/// The pipeline a scene's choices name, by the project's naming of its rtl tops.
fn expected(encoding: &str, per_surface: bool, nearest: bool, gloss: bool, palette: Option<usize>) -> String {
    let hemi = if encoding == "hemi_oct" { "_hemi_oct" } else { "" };
    let matte = if gloss { "" } else { "_matte" };
    match encoding {
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
    }
}

#[test]
fn every_scene_the_reader_takes_has_exactly_one_pipeline_and_every_pipeline_a_scene() {
    let mut reached = BTreeSet::new();
    let mut taken = 0;
    for encoding in ["seed", "hemi_oct", "polar", "polar_dc255", "heights", "palette"] {
        for per in [None, Some("vertex"), Some("surface")] {
            for gloss in [None, Some(0), Some(96)] {
                for filter in [None, Some("bilinear"), Some("nearest")] {
                    for palette in [None, Some(256), Some(300), Some(4096)] {
                        for shape in ["quad", "torus"] {
                            let mut t = format!("size = 32\n[surface]\nshape = \"{shape}\"\n[bump]\nsource = \"procedural\"\ntexels = 16\nencoding = \"{encoding}\"\n");
                            if let Some(f) = filter {
                                t += &format!("filter = \"{f}\"\n");
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
                                filter == Some("nearest"),
                                gloss.unwrap_or(96) != 0,
                                palette,
                            );
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
                for filter in [Filter::Bilinear, Filter::Nearest] {
                    for index_bits in [0, 8, 12] {
                        let c = Choices { encoding, per, gloss, filter, index_bits };
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
