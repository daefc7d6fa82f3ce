//! cart_surface and its seven siblings (matte: no gloss unit; hemi_oct: the hemi-octahedral decode; nearest: no
//! bilinear filter): the pipelines a scene with one light per surface is built as, each against its model, three
//! ways, and the hard cases of its light.
use rtl::cart_surface::*;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::cart_surface::{exact_trace, Variant, MODEL, MODEL_HEMI_OCT, MODEL_HEMI_OCT_MATTE, MODEL_MATTE};
use vectors::cart_surface::{MODEL_NEAREST, MODEL_NEAREST_HEMI_OCT, MODEL_NEAREST_HEMI_OCT_MATTE, MODEL_NEAREST_MATTE};

unit_tests!(cart_surface, CartSurface, MODEL);
unit_tests!(cart_surface_matte, CartSurfaceMatte, MODEL_MATTE);
unit_tests!(cart_surface_hemi_oct, CartSurfaceHemiOct, MODEL_HEMI_OCT);
unit_tests!(cart_surface_hemi_oct_matte, CartSurfaceHemiOctMatte, MODEL_HEMI_OCT_MATTE);
unit_tests!(cart_surface_nearest, CartSurfaceNearest, MODEL_NEAREST);
unit_tests!(cart_surface_nearest_matte, CartSurfaceNearestMatte, MODEL_NEAREST_MATTE);
unit_tests!(cart_surface_nearest_hemi_oct, CartSurfaceNearestHemiOct, MODEL_NEAREST_HEMI_OCT);
unit_tests!(cart_surface_nearest_hemi_oct_matte, CartSurfaceNearestHemiOctMatte, MODEL_NEAREST_HEMI_OCT_MATTE);

#[test]
fn random_vs_model_with_bubbles() {
    random_vs_model::<CartSurface>(&MODEL, 12, 500);
    random_vs_model::<CartSurfaceMatte>(&MODEL_MATTE, 13, 500);
    random_vs_model::<CartSurfaceNearestMatte>(&MODEL_NEAREST_MATTE, 14, 500);
    random_vs_model::<CartSurfaceNearestHemiOct>(&MODEL_NEAREST_HEMI_OCT, 15, 500);
}

#[test]
fn random_vs_model_verilator_every_variant() {
    random_vs_model_verilator::<CartSurface>(&MODEL, 50_000, 31);
    random_vs_model_verilator::<CartSurfaceMatte>(&MODEL_MATTE, 50_000, 32);
    random_vs_model_verilator::<CartSurfaceHemiOct>(&MODEL_HEMI_OCT, 50_000, 33);
    random_vs_model_verilator::<CartSurfaceHemiOctMatte>(&MODEL_HEMI_OCT_MATTE, 50_000, 34);
    random_vs_model_verilator::<CartSurfaceNearest>(&MODEL_NEAREST, 50_000, 35);
    random_vs_model_verilator::<CartSurfaceNearestMatte>(&MODEL_NEAREST_MATTE, 50_000, 36);
    random_vs_model_verilator::<CartSurfaceNearestHemiOct>(&MODEL_NEAREST_HEMI_OCT, 50_000, 37);
    random_vs_model_verilator::<CartSurfaceNearestHemiOctMatte>(&MODEL_NEAREST_HEMI_OCT_MATTE, 50_000, 38);
}

/// The light's own hard cases, the last five of every variant's list: straight above a flat texel, straight
/// below it, along +x and along −z at texel 255 (the guard's legal vector leans along +x and +z), and every
/// component at its most negative code.
#[test]
fn the_surface_light_at_its_ends() {
    for v in Variant::ALL {
        let h = (v.model().hard_cases)();
        let n = h.len();
        let t = |k: usize| exact_trace(v, &h[n - 5 + k]);
        match v.decode {
            vectors::cart_pipeline::Decode::Seed => {
                // the flat texel (127, 127) lit from straight above is full; from below, dark
                assert!(t(0).x >= 1020, "{v:?}: {:?}", t(0));
                assert_eq!(t(1).x, 0, "{v:?}");
                // texel 255 is guarded to (127, 1, 127): lit along +x about half, along −z nothing
                assert_eq!(t(2).bump, [127, 1, 127], "{v:?}");
                assert!((700..=730).contains(&t(2).x), "{v:?}: {:?}", t(2));
                assert_eq!(t(3).x, 0, "{v:?}");
            }
            vectors::cart_pipeline::Decode::HemiOct => {
                // the hemi-oct square's centre (127, 127) is straight up (to a code's rounding)
                assert!(t(0).x >= 1015, "{v:?}: {:?}", t(0));
                assert_eq!(t(1).x, 0, "{v:?}");
            }
        }
        // (−2048, −2048, −2048) is no unit vector; the dot product still clamps a negative sum to 0
        assert_eq!(t(4).x, 0, "{v:?}");
    }
    rust_hdl::<CartSurface>(&MODEL, &(MODEL.hard_cases)(), Bubbles::Random { one_in: 2, seed: 5 })
        .assert_clean("hard cases");
    rust_hdl::<CartSurfaceNearestHemiOctMatte>(
        &MODEL_NEAREST_HEMI_OCT_MATTE,
        &(MODEL_NEAREST_HEMI_OCT_MATTE.hard_cases)(),
        Bubbles::Random { one_in: 2, seed: 5 },
    )
    .assert_clean("hard cases");
}
