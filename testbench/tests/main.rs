//! The testbench's tests, one module a file (`<unit>.rs` for a unit, and the project-wide ones), linked into one
//! binary: forty test binaries each linking the simulators cost the cold build minutes; one costs one link. A file
//! in this folder that is not a module here is not compiled, so `every_test_file_is_a_module_here` checks the list.
mod architecture;
mod axis;
mod bilinear;
mod blend;
mod blend_adjust;
mod blinn_pipeline;
mod cart_decode;
mod cart_decode_hemi_oct;
mod cart_pipeline;
mod cart_pipeline_hemi_oct;
mod cart_pipeline_matte;
mod cart_surface;
mod cart_tex;
mod cos_sign;
mod docs;
mod dot3;
mod gloss;
mod height_addr;
mod height_chain;
mod height_fetch;
mod height_normal;
mod height_pipeline;
mod light_iter;
mod lod;
mod normalise;
mod palette_lookup;
mod palette_pipeline;
mod palette_pipeline_12;
mod palette_pipeline_shared;
mod palette_tex;
mod polar_pipeline;
mod polar_shade;
mod polar_shade_dc;
mod polar_tex;
mod power;
mod replicate;
mod sincos;
mod table_builder;
mod tangent;
mod tex_addr;
mod tex_fetch;
mod texture_filter;

#[test]
fn every_test_file_is_a_module_here() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let here = std::fs::read_to_string(dir.join("main.rs")).unwrap();
    let mut missing = Vec::new();
    for entry in std::fs::read_dir(&dir).unwrap() {
        let name = entry.unwrap().file_name().into_string().unwrap();
        if let Some(stem) = name.strip_suffix(".rs").filter(|s| *s != "main") {
            if !here.lines().any(|l| l == format!("mod {stem};")) {
                missing.push(name);
            }
        }
    }
    assert!(missing.is_empty(), "tests/main.rs has no `mod` line for {missing:?}: they are not compiled");
}
