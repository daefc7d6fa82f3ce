//! Scene files: the examples in `scenes/` read as they say; every kind of bad input is one line naming the file and
//! the line:column or the map's file; the parser and the PNG loader survive 100,000 generated and corrupted inputs
//! each without a panic.
use sim::scene::Scene;
use sim::scene_file;
use std::path::{Path, PathBuf};
use vectors::cart_pipeline::Decode;

/// The name of the per-vertex Cartesian pipeline with this decode, with or without the gloss unit.
fn cart(decode: Decode, gloss: bool) -> String {
    let hemi = if decode == Decode::HemiOct { "_hemi_oct" } else { "" };
    format!("cart_pipeline{hemi}{}", if gloss { "" } else { "_matte" })
}

/// The name of the Cartesian pipeline with one light per surface of this variant.
fn surface(decode: Decode, nearest: bool, gloss: bool) -> String {
    let hemi = if decode == Decode::HemiOct { "_hemi_oct" } else { "" };
    format!("cart_surface{}{hemi}{}", if nearest { "_nearest" } else { "" }, if gloss { "" } else { "_matte" })
}

fn scenes_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes")
}

/// Under the workspace's target folder, where the build's own files go.
fn test_dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/test-files/scene-file");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn parse(text: &str) -> Result<scene_file::SceneSpec, String> {
    scene_file::parse(text, "s.toml", &test_dir())
}

#[test]
fn every_example_scene_reads_and_the_demos_is_the_default_scene() {
    let mut seen = 0;
    for e in std::fs::read_dir(scenes_dir()).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "toml") {
            scene_file::load(&p).unwrap_or_else(|e| panic!("{e}"));
            seen += 1;
        }
    }
    assert!(seen >= 6, "{seen} scenes");
    // scenes/texture_unit/: one scene per pipeline on the texture unit that no scene above shows, named after it
    let mut named = 0;
    for e in std::fs::read_dir(scenes_dir().join("texture_unit")).unwrap() {
        let p = e.unwrap().path();
        let got = scene_file::load(&p).unwrap_or_else(|e| panic!("{e}")).pipeline.name;
        assert_eq!(got, p.file_stem().unwrap().to_str().unwrap(), "{}", p.display());
        named += 1;
    }
    assert_eq!(named, 43);
    // the quad every pipeline is compared on is the default scene; the demo's own is a torus, lit per vertex
    let quad = scene_file::load(&scenes_dir().join("quad.toml")).unwrap();
    let d = Scene::default();
    let s = &quad.scene;
    assert_eq!(
        (s.size, s.tex, s.light_pos, s.conc, s.src, s.dst, s.relief),
        (d.size, d.tex, d.light_pos, d.conc, d.src, d.dst, d.relief)
    );
    // on the texture unit: the quad's map is 128 texels, a power of two the unit's memory holds
    assert_eq!(quad.pipeline.name, "cart_tex_bilinear");
    assert!(!quad.scene.per_surface && quad.scene.curved.is_none());
    let demo = scene_file::load(&scenes_dir().join("demo.toml")).unwrap();
    // C = 0: the per-vertex pipeline without its gloss unit
    assert_eq!(demo.pipeline.name, "cart_tex_bilinear_matte");
    assert!(matches!(demo.scene.curved.map(|c| c.shape), Some(sim::surface::Shape::Torus { .. })));
    // each pipeline has its scene
    let kind = |f: &str| scene_file::load(&scenes_dir().join(f)).unwrap().pipeline.name;
    assert_eq!(kind("hemi_oct.toml"), "cart_tex_bilinear_hemi_oct");
    for (f, want) in [
        ("hemi_oct_matte.toml", "cart_tex_bilinear_hemi_oct_matte"),
        ("torus_nearest_gloss.toml", "cart_tex_nearest"),
        ("torus_nearest_mip_gloss.toml", "cart_tex_nearest_mip"),
        ("torus_trilinear_hemi_oct_matte.toml", "cart_tex_trilinear_hemi_oct_matte"),
        ("torus_trilinear_surface_matte.toml", "cart_tex_trilinear_surface_matte"),
        ("torus_colour_nearest.toml", "cart_tex_nearest_colour"),
        ("torus_colour_nearest_mip.toml", "cart_tex_nearest_mip_colour"),
    ] {
        assert_eq!(kind(f), want, "{f}");
    }
    assert_eq!(kind("polar.toml"), "polar_tex_bilinear");
    assert_eq!(kind("polar_host.toml"), "polar_pipeline");
    assert_eq!(kind("sphere_polar.toml"), "polar_pipeline");
    assert_eq!(scene_file::load(&scenes_dir().join("polar.toml")).unwrap().settings.pw, 16);
    assert_eq!(kind("height.toml"), "height_pipeline");
    assert_eq!(kind("palette.toml"), "palette_pipeline");
    assert_eq!(scene_file::load(&scenes_dir().join("palette.toml")).unwrap().settings.palette, Some(256));
    assert_eq!(kind("palette_nearest_mip.toml"), "palette_tex_nearest_mip");
    // the curved ones
    let torus = scene_file::load(&scenes_dir().join("torus.toml")).unwrap().scene;
    let c = torus.curved.expect("a torus");
    assert_eq!(c.shape, sim::surface::Shape::Torus { minor: 0.32 });
    assert_eq!((c.segments, c.repeat), ([72, 36], [6, 2]));
    assert_eq!(kind("torus.toml"), "cart_tex_bilinear_surface");
    assert!(scene_file::load(&scenes_dir().join("sphere_polar.toml")).unwrap().scene.curved.is_some());
}

#[test]
fn curved_surfaces_take_their_own_fields_and_only_the_pipelines_that_can_draw_them() {
    let base = "size = 64\n[bump]\nsource = \"procedural\"\n";
    let with =
        |surface: &str, rest: &str| format!("size = 64\n[surface]\n{surface}[bump]\nsource = \"procedural\"\n{rest}");
    assert!(parse(base).unwrap().scene.curved.is_none());
    let s = parse(&with("shape = \"sphere\"\n", "")).unwrap().scene;
    assert_eq!(s.light_pos, scene_file::DEFAULT_WORLD_LIGHT, "a curved surface's default light is in the world");
    refused(&with("segments = [8, 8]\n", ""), "s.toml:3:12:", &["the quad is two triangles"]);
    refused(&with("shape = \"sphere\"\nminor = 0.2\n", ""), "s.toml:4:9:", &["only a torus"]);
    refused(&with("shape = \"torus\"\nminor = 0.9\n", ""), "s.toml:4:9:", &["0.05 to 0.5"]);
    refused(&with("shape = \"torus\"\nsegments = [2, 8]\n", ""), "s.toml:4:12:", &["3 to 512"]);
    refused(&with("shape = \"torus\"\nrepeat = [1]\n", ""), "s.toml:4:10:", &["two whole numbers"]);
    refused(&with("shape = \"torus\"\ntilt = nan\n", ""), "s.toml:4:8:", &["finite"]);
    refused(
        &with("shape = \"torus\"\n", "encoding = \"palette\"\npalette = 16\n[light]\nper = \"surface\"\n"),
        "s.toml:6:12:",
        &["renders the quad only"],
    );
    refused(
        &with("shape = \"sphere\"\n", "encoding = \"heights\"\n[light]\nper = \"surface\"\n"),
        "s.toml:6:12:",
        &["renders the quad only"],
    );
}

#[test]
fn a_directional_light_for_the_surface_lights_every_vertex_alike() {
    let s = scene_file::load(&scenes_dir().join("directional.toml")).unwrap().scene;
    let l = s.vertex_lights();
    assert!(l.iter().all(|v| *v == l[0]));
    let d = [-0.8f64, 0.45, 0.3];
    let n = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    assert!((0..3).all(|c| (l[0][c] - d[c] / n).abs() < 1e-12), "{:?}", l[0]);
}

#[test]
fn one_light_per_surface_builds_the_surface_pipeline_with_only_the_units_the_material_and_filter_need() {
    let scene = |enc: &str, filter: &str, per: &str, gloss: &str| {
        format!("size = 64\n[bump]\nsource = \"procedural\"\nencoding = \"{enc}\"\n{filter}[light]\nper = \"{per}\"\n[material]\n{gloss}")
    };
    let kind = |t: String| parse(&t).unwrap_or_else(|e| panic!("{e}")).pipeline.name;
    let v = surface;
    assert_eq!(kind(scene("seed", "", "vertex", "gloss = 0\n")), "cart_tex_bilinear_matte");
    assert_eq!(kind(scene("seed", "", "vertex", "gloss = 1\n")), "cart_tex_bilinear");
    // the host-fed pipelines where the scene asks for them
    assert_eq!(kind(scene("seed", "fetch = \"host\"\n", "vertex", "gloss = 0\n")), cart(Decode::Seed, false));
    assert_eq!(kind(scene("seed", "fetch = \"host\"\n", "vertex", "gloss = 1\n")), cart(Decode::Seed, true));
    // the texture unit's filters: the nearest texel, of level 0 or of the nearest MIP level (matte)
    assert_eq!(kind(scene("seed", "filter = \"nearest\"\n", "vertex", "gloss = 0\n")), "cart_tex_nearest_matte");
    assert_eq!(
        kind(scene("seed", "filter = \"nearest_mip\"\n", "vertex", "gloss = 0\n")),
        "cart_tex_nearest_mip_matte"
    );
    assert_eq!(kind(scene("seed", "filter = \"trilinear\"\n", "vertex", "gloss = 0\n")), "cart_tex_trilinear_matte");
    refused(
        &scene("seed", "filter = \"trilinear\"\nfetch = \"host\"\n", "vertex", "gloss = 0\n"),
        "s.toml:5:10:",
        &["filter = \"trilinear\"", "only the texture unit has MIP levels"],
    );
    assert_eq!(kind(scene("seed", "filter = \"nearest_mip\"\n", "vertex", "gloss = 3\n")), "cart_tex_nearest_mip");
    assert_eq!(
        kind(scene("hemi_oct", "filter = \"nearest_mip\"\n", "vertex", "gloss = 3\n")),
        "cart_tex_nearest_mip_hemi_oct"
    );
    // a MIP filter no pipeline on the unit serves (trilinear in two passes is built matte, seed texels, lights per
    // vertex only): one line at the filter, naming the choices
    refused(
        &scene("hemi_oct", "filter = \"trilinear_two_pass\"\n", "vertex", "gloss = 3\n"),
        "s.toml:5:10:",
        &["trilinear_two_pass", "texture unit", "hemi_oct", "a gloss"],
    );
    refused(
        &scene("seed", "filter = \"nearest_mip\"\nfetch = \"host\"\n", "vertex", "gloss = 0\n"),
        "s.toml:5:10:",
        &["only the texture unit has MIP levels"],
    );
    assert_eq!(
        kind(scene("hemi_oct", "fetch = \"unit\"\n", "vertex", "gloss = 0\n")),
        "cart_tex_bilinear_hemi_oct_matte"
    );
    assert_eq!(
        kind(scene("hemi_oct", "fetch = \"unit\"\n", "surface", "gloss = 3\n")),
        "cart_tex_bilinear_surface_hemi_oct"
    );
    refused(
        &scene("hemi_oct", "filter = \"trilinear_two_pass\"\nfetch = \"unit\"\n", "surface", "gloss = 3\n"),
        "s.toml:6:9:",
        &["fetch = \"unit\"", "hemi_oct", "per = \"surface\"", "a gloss"],
    );
    refused(
        "size = 64\n[bump]\nsource = \"procedural\"\ntexels = 256\nfetch = \"unit\"\n[material]\ngloss = 0\n",
        "s.toml:5:9:",
        &["1, 2, 4 … 128", "256"],
    );
    assert_eq!(kind(scene("hemi_oct", "", "vertex", "")), "cart_tex_bilinear_hemi_oct", "the default gloss is 96");
    let host = "fetch = \"host\"\n";
    assert_eq!(kind(scene("hemi_oct", host, "vertex", "")), cart(Decode::HemiOct, true));
    assert_eq!(kind(scene("hemi_oct", host, "vertex", "gloss = 0\n")), cart(Decode::HemiOct, false));
    // hemi-oct texels on the unit, per vertex and per surface, matte and glossy
    assert_eq!(kind(scene("hemi_oct", "", "vertex", "gloss = 0\n")), "cart_tex_bilinear_hemi_oct_matte");
    assert_eq!(kind(scene("hemi_oct", "", "surface", "gloss = 3\n")), "cart_tex_bilinear_surface_hemi_oct");
    assert_eq!(kind(scene("hemi_oct", host, "surface", "gloss = 3\n")), v(Decode::HemiOct, false, true));
    // one light per surface: on the texture unit where it serves the material, the host's on asking
    assert_eq!(kind(scene("seed", "", "surface", "gloss = 0\n")), "cart_tex_bilinear_surface_matte");
    assert_eq!(kind(scene("seed", "", "surface", "gloss = 12\n")), "cart_tex_bilinear_surface");
    assert_eq!(kind(scene("seed", "", "surface", "")), "cart_tex_bilinear_surface", "the default gloss is 96");
    assert_eq!(kind(scene("seed", host, "surface", "gloss = 0\n")), v(Decode::Seed, false, false));
    assert_eq!(kind(scene("seed", host, "surface", "gloss = 12\n")), v(Decode::Seed, false, true));
    assert_eq!(kind(scene("hemi_oct", "", "surface", "gloss = 12\n")), "cart_tex_bilinear_surface_hemi_oct");
    assert_eq!(kind(scene("hemi_oct", "", "surface", "gloss = 0\n")), "cart_tex_bilinear_surface_hemi_oct_matte");
    let nearest = "filter = \"nearest\"\n";
    assert_eq!(kind(scene("hemi_oct", nearest, "surface", "gloss = 0\n")), "cart_tex_nearest_surface_hemi_oct_matte");
    let nearest_host = format!("{nearest}{host}");
    assert_eq!(kind(scene("hemi_oct", &nearest_host, "surface", "gloss = 0\n")), v(Decode::HemiOct, true, false));
    assert_eq!(kind(scene("seed", "filter = \"bilinear\"\n", "surface", "gloss = 5\n")), "cart_tex_bilinear_surface");
    // lights per vertex: the nearest texel on the texture unit; the host-fed nearest-texel pipelines have one light
    assert_eq!(kind(scene("seed", "filter = \"nearest\"\n", "vertex", "")), "cart_tex_nearest");
    refused(&scene("seed", &nearest_host, "vertex", ""), "s.toml:5:10:", &["one light", "per = \"surface\""]);
    refused(
        &scene("polar", "filter = \"nearest\"\n", "surface", ""),
        "s.toml:5:10:",
        &["only the Cartesian encodings"],
    );
    refused(&scene("seed", "filter = \"cubic\"\n", "surface", ""), "s.toml:5:10:", &["bilinear", "nearest"]);
    // polar texels: on the texture unit where it holds the map, fed by the host on asking, or where the unit has no
    // pipeline for the angle scale or no room for the map
    assert_eq!(kind(scene("polar", "", "surface", "")), "polar_tex_bilinear");
    assert_eq!(kind(scene("polar_dc255", "", "surface", "")), "polar_pipeline_dc");
    assert_eq!(kind(scene("polar", "texels = 256\n", "surface", "")), "polar_pipeline");
    refused(
        &scene("polar", "texels = 256\nfetch = \"unit\"\n", "surface", ""),
        "s.toml:6:9:",
        &["1, 2, 4 … 128", "256"],
    );
    assert_eq!(kind(scene("polar", host, "surface", "")), "polar_pipeline");
    assert_eq!(kind(scene("polar", "fetch = \"unit\"\n", "surface", "")), "polar_tex_bilinear");
    assert_eq!(kind(scene("polar", "filter = \"trilinear\"\n", "surface", "")), "polar_tex_trilinear");
    refused(
        &scene("polar", &format!("filter = \"trilinear\"\n{host}"), "surface", ""),
        "s.toml:",
        &["filters bilinearly"],
    );
    refused(
        &scene("polar_dc255", "fetch = \"unit\"\n", "surface", ""),
        "s.toml:5:9:",
        &["no pipeline on the texture unit"],
    );
    assert_eq!(scene_file::load(&scenes_dir().join("up5k.toml")).unwrap().pipeline.name, v(Decode::Seed, true, false));
    // its map of 128 texels in the texture unit's memory: the nearest texel, one light per surface, matte
    let textured = scene_file::load(&scenes_dir().join("up5k_textured.toml")).unwrap().pipeline.name;
    assert_eq!(textured, "cart_tex_nearest_surface_matte");
    assert_eq!(
        scene_file::load(&scenes_dir().join("directional.toml")).unwrap().pipeline.name,
        "cart_tex_bilinear_surface_matte"
    );
}

#[test]
fn a_palette_scene_is_on_the_texture_unit_where_it_names_a_filter_of_its_and_one_line_where_none_serves() {
    let scene = |bump: &str| {
        format!(
            "size = 64\n[bump]\nsource = \"procedural\"\nencoding = \"palette\"\n{bump}[light]\nper = \"surface\"\n"
        )
    };
    let kind = |t: String| parse(&t).unwrap_or_else(|e| panic!("{e}")).pipeline.name;
    // fed by the host as before, unless the scene names the unit's filters or the unit
    assert_eq!(kind(scene("palette = 256\n")), "palette_pipeline");
    assert_eq!(kind(scene("palette = 256\nfilter = \"bilinear\"\n")), "palette_pipeline");
    assert_eq!(kind(scene("palette = 256\nfetch = \"host\"\n")), "palette_pipeline");
    assert_eq!(kind(scene("palette = 4096\n")), "palette_pipeline_12");
    assert_eq!(kind(scene("palette = 256\nfilter = \"nearest\"\n")), "palette_tex_nearest");
    assert_eq!(kind(scene("palette = 200\nfilter = \"nearest_mip\"\n")), "palette_tex_nearest_mip");
    assert_eq!(kind(scene("palette = 256\nfetch = \"unit\"\n")), "palette_tex_nearest");
    // an index is never blended; the unit's indices are the texel's low byte; the host has no filter
    refused(&scene("palette = 256\nfilter = \"trilinear\"\n"), "s.toml:6:10:", &["cannot be blended", "nearest_mip"]);
    refused(&scene("palette = 300\nfilter = \"nearest\"\n"), "s.toml:6:10:", &["8-bit indices", "300"]);
    refused(
        &scene("palette = 256\nfilter = \"nearest_mip\"\nfetch = \"host\"\n"),
        "s.toml:6:10:",
        &["host-fed palette", "fetch = \"unit\""],
    );
    refused(&scene("palette = 256\ntexels = 256\nfetch = \"unit\"\n"), "s.toml:7:9:", &["1, 2, 4 … 128", "256"]);
    refused(&scene("palette = 256\nfilter = \"nearest\"\nlod_bias = -0.5\n"), "s.toml:7:", &["only a MIP filter"]);
}

const GOOD: &str = "size = 64\n[bump]\nsource = \"procedural\"\ntexels = 16\n[light]\nposition = [0.5, 0.5, 0.5]\n";

/// One line, naming the place, saying the words.
fn refused(text: &str, at: &str, words: &[&str]) {
    let e = match parse(text) {
        Ok(_) => panic!("read:\n{text}"),
        Err(e) => e,
    };
    assert!(!e.contains('\n'), "more than one line: {e}");
    assert!(e.starts_with(at), "{e:?} does not start with {at:?}");
    for w in words {
        assert!(e.contains(w), "{e:?} does not say {w:?}");
    }
}

#[test]
fn bad_scene_text_is_one_line_at_its_line_and_column() {
    assert!(parse(GOOD).is_ok());
    // malformed TOML
    refused("size = \n[bump]\nsource = \"procedural\"\n", "s.toml:1:8:", &[]);
    refused("size = 64\n[bump\nsource = \"procedural\"\n", "s.toml:2:", &[]);
    // unknown fields, at the top and in a table, and unknown choices
    refused(&format!("{GOOD}colour = 3\n"), "s.toml:", &["unknown field `colour`"]);
    refused(
        "size = 64\n[bump]\nsource = \"procedural\"\nrelif = 2\n",
        "s.toml:4:1:",
        &["unknown field `relif`", "relief"],
    );
    refused("size = 64\n[bump]\nsource = \"photo\"\n", "s.toml:3:10:", &["unknown variant `photo`", "height_map"]);
    refused(
        "size = 64\n[surface]\nshape = \"cube\"\n[bump]\nsource = \"procedural\"\n",
        "s.toml:3:9:",
        &["unknown variant `cube`"],
    );
    // missing fields
    refused("[bump]\nsource = \"procedural\"\n", "s.toml:", &["missing field `size`"]);
    // NaN, infinities, out-of-range numbers
    refused("size = 64\n[bump]\nsource = \"procedural\"\nrelief = nan\n", "s.toml:4:10:", &["finite"]);
    refused("size = 64\n[bump]\nsource = \"procedural\"\nrelief = -inf\n", "s.toml:4:10:", &["finite"]);
    refused("size = 5000\n[bump]\nsource = \"procedural\"\n", "s.toml:1:8:", &["16 to 1024", "5000"]);
    refused("size = 64\n[bump]\nsource = \"procedural\"\ntexels = 100\n", "s.toml:4:10:", &["power of two"]);
    refused("size = 64\n[bump]\nsource = \"procedural\"\n[material]\ngloss = 256\n", "s.toml:5:9:", &["0 to 255"]);
    refused("size = 64\n[bump]\nsource = \"procedural\"\n[material]\nsrc = [1, 2]\n", "s.toml:5:", &["length"]);
    refused("size = 64\n[bump]\nsource = \"procedural\"\nencoding = \"polar\"\n[light]\nper = \"surface\"\n[material]\npower = 1.1\n", "s.toml:8:9:", &["multiple of 0.25"]);
    refused("size = 64\n[bump]\nsource = \"procedural\"\n[light]\nposition = [0, 1e400, 0]\n", "s.toml:5:", &[]);
    // a light of zero length
    refused(
        "size = 64\n[bump]\nsource = \"procedural\"\n[light]\nkind = \"directional\"\ndirection = [0, 0, 0]\n",
        "s.toml:6:13:",
        &["zero length"],
    );
    refused(
        "size = 64\n[bump]\nsource = \"procedural\"\n[light]\nkind = \"directional\"\n",
        "s.toml:",
        &["needs direction"],
    );
    // fields the other choices leave no use for
    refused(
        "size = 64\n[bump]\nsource = \"procedural\"\npath = \"a.png\"\n",
        "s.toml:4:8:",
        &["procedural map reads no file"],
    );
    refused(
        "size = 64\n[bump]\nsource = \"procedural\"\nencoding = \"polar\"\n[light]\nper = \"vertex\"\n",
        "s.toml:6:7:",
        &["one light"],
    );
    refused("size = 64\n[bump]\nsource = \"procedural\"\nencoding = \"heights\"\n[light]\nper = \"surface\"\n[material]\ngloss = 4\n", "s.toml:8:9:", &["no gloss"]);
    refused("size = 64\n[bump]\nsource = \"procedural\"\nencoding = \"palette\"\n", "s.toml:", &["palette = s_N"]);
    refused(
        "size = 64\n[bump]\nsource = \"procedural\"\nencoding = \"palette\"\npalette = 16\n[light]\nper = \"vertex\"\n",
        "s.toml:7:7:",
        &["palette pipeline lights a surface with one light"],
    );
    refused(
        "size = 64\n[bump]\nsource = \"procedural\"\nencoding = \"palette\"\npalette = 5000\n",
        "s.toml:5:11:",
        &["1 to 4096"],
    );
    // the LOD bias: past the LOD unit's Sq3.8, off its 1/256 grid, and on a filter that reads no level of detail
    let mip = "size = 64\n[bump]\nsource = \"procedural\"\nfilter = \"trilinear\"\n[material]\ngloss = 0\n";
    let biased =
        |b: &str| mip.replace("filter = \"trilinear\"\n", &format!("filter = \"trilinear\"\nlod_bias = {b}\n"));
    assert_eq!(parse(&biased("-1.25")).unwrap().scene.lod_bias, -1.25);
    assert_eq!(parse(mip).unwrap().scene.lod_bias, 0.0);
    refused(&biased("8.0"), "s.toml:5:12:", &["LOD bias", "-8 to 7.99609375", "not 8"]);
    refused(&biased("0.001"), "s.toml:5:12:", &["multiple of 1/256"]);
    refused(
        "size = 64\n[bump]\nsource = \"procedural\"\nlod_bias = -1.0\n",
        "s.toml:4:12:",
        &["only a MIP filter", "filter = \"bilinear\""],
    );
}

/// A PNG written under the test folder.
fn png(name: &str, img: image::DynamicImage) -> PathBuf {
    let p = test_dir().join(name);
    img.save_with_format(&p, image::ImageFormat::Png).unwrap();
    p
}

fn with_map(source: &str, path: &Path, extra: &str) -> String {
    format!("size = 32\n[bump]\nsource = \"{source}\"\npath = \"{}\"\n{extra}", path.display())
}

#[test]
fn bad_maps_are_one_line_naming_the_scene_line_and_the_map() {
    let dir = test_dir();
    // a good grey map and a good normal map read
    let grey = png("grey8.png", image::GrayImage::from_fn(8, 8, |x, y| image::Luma([(x * 30 + y) as u8])).into());
    assert!(parse(&with_map("height_map", &grey, "")).is_ok());
    let rgb = png("flat-normals.png", image::RgbImage::from_fn(8, 8, |_, _| image::Rgb([128, 128, 255])).into());
    let s = parse(&with_map("normal_map", &rgb, "green = \"directx\"\n")).unwrap();
    assert_eq!(s.scene.tex, 8);
    let n = s.scene.normals();
    assert!(n.iter().all(|v| v[1] > 0.999), "{:?}", n[0]);
    // missing, unreadable, not a PNG, cut short, zero-sized
    let missing = dir.join("absent.png");
    refused(&with_map("height_map", &missing, ""), "s.toml:4:8:", &["absent.png", "cannot read"]);
    let text = dir.join("text.png");
    std::fs::write(&text, b"not an image").unwrap();
    refused(&with_map("normal_map", &text, ""), "s.toml:4:8:", &["text.png", "not a PNG"]);
    let whole = std::fs::read(&grey).unwrap();
    let cut = dir.join("cut.png");
    std::fs::write(&cut, &whole[..whole.len() / 2]).unwrap();
    refused(&with_map("height_map", &cut, ""), "s.toml:4:8:", &["cut.png", "not a readable PNG"]);
    // a zero-width PNG: the grey map's bytes with IHDR's width set to 0 (its CRC left as it was: either refusal is
    // right)
    let mut zero = whole.clone();
    zero[16..20].copy_from_slice(&0u32.to_be_bytes());
    let zp = dir.join("zero.png");
    std::fs::write(&zp, &zero).unwrap();
    refused(&with_map("height_map", &zp, ""), "s.toml:4:8:", &["zero.png"]);
    let empty = dir.join("empty.png");
    std::fs::write(&empty, b"").unwrap();
    refused(&with_map("height_map", &empty, ""), "s.toml:4:8:", &["empty.png", "empty file"]);
    // 16 bits where 8 are required: a normal map, and heights for US 2004/0207631's path
    let rgb16 = image::ImageBuffer::<image::Rgb<u16>, _>::from_fn(4, 4, |_, _| image::Rgb([32768, 32768, 65535]));
    let p16 = png("normals16.png", image::DynamicImage::ImageRgb16(rgb16));
    refused(&with_map("normal_map", &p16, ""), "s.toml:4:8:", &["normals16.png", "16-bit", "8 bits are required"]);
    let g16 = image::ImageBuffer::<image::Luma<u16>, _>::from_fn(4, 4, |x, _| image::Luma([x as u16 * 9000]));
    let h16 = png("heights16.png", image::DynamicImage::ImageLuma16(g16));
    assert!(parse(&with_map("height_map", &h16, "")).is_ok(), "16-bit heights are fine for the Cartesian path");
    refused(
        &with_map("height_map", &h16, "encoding = \"heights\"\n[light]\nper = \"surface\"\n"),
        "s.toml:4:8:",
        &["heights16.png", "16-bit", "8 bits are required"],
    );
    // a grey map named as a normal map
    refused(&with_map("normal_map", &grey, ""), "s.toml:4:8:", &["grey8.png", "height map"]);
    // the scene file itself: missing, not UTF-8
    let e = scene_file::load(&dir.join("no-such-scene.toml")).err().unwrap();
    assert!(e.contains("no-such-scene.toml") && e.contains("cannot read") && !e.contains('\n'), "{e}");
    let bin = dir.join("binary.toml");
    std::fs::write(&bin, [b's', b'i', 0xff, 0xfe]).unwrap();
    let e = scene_file::load(&bin).err().unwrap();
    assert!(e.contains("binary.toml") && e.contains("UTF-8"), "{e}");
}

/// A small deterministic generator (no dependency on the fuzzed code's own randomness).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// Tokens a corrupted scene is made of: the format's own words, numbers at and past every edge, broken syntax.
const TOKENS: &[&str] = &[
    "=",
    "[",
    "]",
    "[[",
    "]]",
    "\"",
    "'",
    "\n",
    "#",
    ",",
    ".",
    "{",
    "}",
    "nan",
    "inf",
    "-inf",
    "+nan",
    "0",
    "-1",
    "1e400",
    "255",
    "256",
    "1024",
    "1025",
    "16",
    "15",
    "4096",
    "4097",
    "63.75",
    "64",
    "0.25",
    "-0.0",
    "9223372036854775808",
    "true",
    "size",
    "bump",
    "light",
    "material",
    "surface",
    "source",
    "path",
    "green",
    "texels",
    "relief",
    "encoding",
    "palette",
    "filter",
    "kind",
    "position",
    "direction",
    "per",
    "gloss",
    "src",
    "dst",
    "power",
    "weight",
    "shape",
    "\"procedural\"",
    "\"height_map\"",
    "\"normal_map\"",
    "\"seed\"",
    "\"hemi_oct\"",
    "\"polar\"",
    "\"polar_dc255\"",
    "\"heights\"",
    "\"palette\"",
    "\"vertex\"",
    "\"surface\"",
    "\"directional\"",
    "\"point\"",
    "\"quad\"",
    "\"bilinear\"",
    "\"directx\"",
    "\"opengl\"",
    "[0, 0, 0]",
    "[1, 2]",
    "[1, 2, 3, 4]",
    "[1e308, 1e308, 1e308]",
    "\"\"",
    "\"a.png\"",
    "1979-05-27",
    "\u{0}",
    "\u{feff}",
    "é",
    "\\u0000",
    "'''",
    "\"\"\"",
];

#[test]
fn the_scene_parser_survives_100000_generated_and_corrupted_scenes() {
    let mut bases: Vec<String> = vec![GOOD.to_string()];
    for e in std::fs::read_dir(scenes_dir()).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "toml") {
            bases.push(std::fs::read_to_string(p).unwrap());
        }
    }
    let mut rng = Lcg(0x5eed);
    let (mut ok, mut refused, mut panics) = (0usize, 0usize, vec![]);
    const N: usize = 100_000;
    for k in 0..N {
        let base = &bases[rng.below(bases.len())];
        let mut b: Vec<u8> = base.as_bytes().to_vec();
        // 1 to 4 edits: a byte flipped, removed or inserted, a token dropped in, a line doubled or cut
        for _ in 0..1 + rng.below(4) {
            let at = rng.below(b.len().max(1));
            match rng.below(6) {
                0 if !b.is_empty() => b[at] ^= 1 << rng.below(8),
                1 if !b.is_empty() => {
                    b.remove(at);
                }
                2 => b.insert(at.min(b.len()), rng.below(256) as u8),
                3 | 4 => {
                    let t = TOKENS[rng.below(TOKENS.len())].as_bytes();
                    let at = at.min(b.len());
                    b.splice(at..at, t.iter().copied());
                }
                _ => b.truncate(at),
            }
        }
        let text = String::from_utf8_lossy(&b).into_owned();
        match std::panic::catch_unwind(|| parse(&text)) {
            Ok(Ok(_)) => ok += 1,
            Ok(Err(e)) => {
                assert!(!e.contains('\n') && e.starts_with("s.toml"), "input {k}: {e:?}\n{text}");
                refused += 1;
            }
            Err(_) => panics.push(text),
        }
    }
    println!("scene parser: {N} inputs, {ok} read, {refused} refused with one line, {} panics", panics.len());
    assert!(panics.is_empty(), "{} inputs panicked; the first:\n{}", panics.len(), panics[0]);
    assert!(ok > 0 && refused > 0);
}

#[test]
fn the_png_loader_survives_100000_corrupted_maps() {
    // three small maps: 8-bit grey, 16-bit grey, 8-bit RGB
    let mut bases = vec![];
    for img in [
        image::DynamicImage::from(image::GrayImage::from_fn(9, 7, |x, y| image::Luma([(x * 25 + y * 3) as u8]))),
        image::DynamicImage::ImageLuma16(image::ImageBuffer::from_fn(6, 6, |x, y| {
            image::Luma([(x * 9000 + y) as u16])
        })),
        image::DynamicImage::from(image::RgbImage::from_fn(8, 5, |x, y| {
            image::Rgb([(x * 30) as u8, (y * 50) as u8, 200])
        })),
    ] {
        let mut bytes = std::io::Cursor::new(vec![]);
        img.write_to(&mut bytes, image::ImageFormat::Png).unwrap();
        bases.push(bytes.into_inner());
    }
    let mut rng = Lcg(0xb17e);
    let (mut ok, mut refused, mut panics) = (0usize, 0usize, 0usize);
    const N: usize = 100_000;
    for _ in 0..N {
        let mut b = bases[rng.below(bases.len())].clone();
        for _ in 0..1 + rng.below(3) {
            let at = rng.below(b.len());
            match rng.below(5) {
                0 | 1 => b[at] ^= 1 << rng.below(8),
                2 => b[at] = [0, 0xff, 0x7f, 0x80][rng.below(4)],
                3 => b.truncate(at.max(1)),
                _ => {
                    // a header field (width, height, depth, colour type) set to an edge
                    if b.len() > 26 {
                        let f = [16, 20, 24, 25][rng.below(4)];
                        b[f] = [0, 0xff, 16, 2, 6][rng.below(5)];
                    }
                }
            }
        }
        let r = std::panic::catch_unwind(|| {
            sim::heightmap::png_from_bytes(&b, "fuzz.png", "map").map(|img| {
                // and what the loaders read off a decoded image
                let _ = (sim::heightmap::depth(&img), sim::heightmap::is_grey(&img));
                if sim::heightmap::is_grey(&img) {
                    sim::heightmap::grey_values(&img).len()
                } else {
                    sim::heightmap::normal_values(&img, false).0.len()
                }
            })
        });
        match r {
            Ok(Ok(_)) => ok += 1,
            Ok(Err(e)) => {
                assert!(!e.contains('\n') && e.starts_with("fuzz.png"), "{e:?}");
                refused += 1;
            }
            Err(_) => panics += 1,
        }
    }
    println!("PNG loader: {N} corrupted maps, {ok} decoded, {refused} refused with one line, {panics} panics");
    assert_eq!(panics, 0);
    assert!(ok > 0 && refused > 0);
}

mod positions {
    use sim::scene_file::*;

    #[test]
    fn line_and_column_count_from_one() {
        let t = "a = 1\nbb = 2\n";
        assert_eq!(line_col(t, 0), (1, 1));
        assert_eq!(line_col(t, 6), (2, 1));
        assert_eq!(line_col(t, 9), (2, 4));
    }
}

#[test]
fn the_wrap_is_one_word_or_one_each_axis_and_not_the_height_pipelines() {
    let with = |bump: &str| format!("size = 64\n[bump]\nsource = \"procedural\"\n{bump}");
    assert_eq!(parse(&with("")).unwrap().scene.wrap, None, "the surface's own");
    assert_eq!(parse(&with("wrap = \"repeat\"\n")).unwrap().scene.wrap, Some([true, true]));
    assert_eq!(parse(&with("wrap = [\"clamp\", \"repeat\"]\n")).unwrap().scene.wrap, Some([false, true]));
    refused(&with("wrap = \"mirror\"\n"), "s.toml:4:8:", &["\"repeat\" or \"clamp\"", "mirror"]);
    refused(&with("wrap = [\"clamp\"]\n"), "s.toml:4:8:", &["two words [u, v], not 1"]);
    refused(&with("wrap = 3\n"), "s.toml:4:8:", &["\"repeat\" or \"clamp\""]);
    refused(&with("encoding = \"heights\"\nwrap = \"clamp\"\n"), "s.toml:5:8:", &["height pipeline", "clamps"]);
}

/// A scene with a procedural 16-texel map and a colour map, the light and material lines after `bump`.
fn with_colour(colour: &Path, bump: &str, rest: &str) -> String {
    format!(
        "size = 32\n[bump]\nsource = \"procedural\"\ntexels = 16\n{bump}[material]\ncolour_map = \"{}\"\n{rest}",
        colour.display()
    )
}

#[test]
fn a_colour_map_picks_the_colour_pipeline_and_bad_ones_are_one_line_at_the_field() {
    let dir = test_dir();
    // 8-bit RGB at the bump map's side: taken as it is, on the colour pipelines (per vertex, per surface)
    let rgb = png(
        "colour16.png",
        image::RgbImage::from_fn(16, 16, |x, y| image::Rgb([x as u8 * 16, y as u8 * 16, 7])).into(),
    );
    let s = parse(&with_colour(&rgb, "", "")).unwrap();
    assert_eq!(s.pipeline.name, "cart_tex_bilinear_colour");
    let c = s.scene.colour_map.as_ref().unwrap();
    assert_eq!((c.side, c.rgb[17]), (16, [16.0, 16.0, 7.0]));
    assert!(s.notes.is_empty(), "{:?}", s.notes);
    let s = parse(&with_colour(&rgb, "", "[light]\nper = \"surface\"\n")).unwrap();
    assert_eq!(s.pipeline.name, "cart_tex_bilinear_surface_colour");
    // RGBA and another size: its alpha dropped and resampled to the bump map's side, each said so
    let rgba = png("colour-rgba.png", image::RgbaImage::from_fn(40, 24, |x, _| image::Rgba([x as u8, 9, 9, 3])).into());
    let s = parse(&with_colour(&rgba, "", "")).unwrap();
    assert_eq!(s.scene.colour_map.as_ref().unwrap().side, 16);
    assert!(s.notes.iter().any(|n| n.contains("alpha")) && s.notes.iter().any(|n| n.contains("40 × 24 resampled")));
    // the colour line's failures: at the field (line 6), naming the file
    let at = "s.toml:6:14:";
    refused(&with_colour(&dir.join("absent.png"), "", ""), at, &["colour_map", "absent.png", "cannot read"]);
    let jpeg = dir.join("photo.jpg");
    std::fs::write(&jpeg, [0xff, 0xd8, 0xff, 0xe0, 0, 16, b'J', b'F', b'I', b'F']).unwrap();
    refused(&with_colour(&jpeg, "", ""), at, &["photo.jpg", "a JPEG", "PNG"]);
    let rgb16 = image::ImageBuffer::<image::Rgb<u16>, _>::from_fn(4, 4, |_, _| image::Rgb([1, 2, 3]));
    let p16 = png("colour16bit.png", image::DynamicImage::ImageRgb16(rgb16));
    refused(&with_colour(&p16, "", ""), at, &["colour16bit.png", "16-bit", "8 bits are required"]);
    // with dst beside it, on a family or a filter with no colour path, host-fed
    refused(&with_colour(&rgb, "", "dst = [1, 2, 3]\n"), at, &["colour_map", "leave dst out"]);
    let at = "s.toml:7:14:"; // one [bump] line more
    refused(&with_colour(&rgb, "encoding = \"polar\"\n", "[light]\nper = \"surface\"\n"), at, &["only the Cartesian"]);
    refused(
        &with_colour(&rgb, "filter = \"trilinear_two_pass\"\n", "gloss = 0\n"),
        at,
        &["no pipeline on the texture unit with a colour map", "no two-pass one"],
    );
    refused(&with_colour(&rgb, "fetch = \"host\"\n", ""), at, &["host-fed"]);
    // the nearest texel, the nearest MIP level's and trilinear, with gloss and lights per vertex, have a colour path
    for (filter, want) in [
        ("nearest", "cart_tex_nearest_colour"),
        ("nearest_mip", "cart_tex_nearest_mip_colour"),
        ("trilinear", "cart_tex_trilinear_colour"),
    ] {
        let s = parse(&with_colour(&rgb, &format!("filter = \"{filter}\"\n"), "")).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(s.pipeline.name, want);
    }
    // a bump map the memory does not hold (256 texels)
    let big = "size = 32\n[bump]\nsource = \"procedural\"\ntexels = 256\n[material]\ncolour_map = \"X\"\n";
    refused(&big.replace('X', &rgb.display().to_string()), "s.toml:6:14:", &["side 1, 2, 4 … 128", "256"]);
}
