//! cart_tex_*: the Cartesian pipelines on the texture unit, each the front (position → [level →] address → memory
//! → texel) and the host-fed pipeline's units, against the composed model three ways: golden vectors (the map
//! loaded first); random streams through rust-hdl, and through Verilator after the hard cases have loaded the chain
//! they read.
use rtl::cart_tex::{
    CartTexBilinear, CartTexBilinearColour, CartTexBilinearHemiOct, CartTexBilinearHemiOctColour,
    CartTexBilinearHemiOctMatte, CartTexBilinearHemiOctMatteColour, CartTexBilinearMatte, CartTexBilinearMatteColour,
    CartTexBilinearSurface, CartTexBilinearSurfaceColour, CartTexBilinearSurfaceHemiOct,
    CartTexBilinearSurfaceHemiOctColour, CartTexBilinearSurfaceHemiOctMatte, CartTexBilinearSurfaceHemiOctMatteColour,
    CartTexBilinearSurfaceMatte, CartTexBilinearSurfaceMatteColour, CartTexNearest, CartTexNearestColour,
    CartTexNearestHemiOct, CartTexNearestHemiOctColour, CartTexNearestHemiOctMatte, CartTexNearestHemiOctMatteColour,
    CartTexNearestMatte, CartTexNearestMatteColour, CartTexNearestMip, CartTexNearestMipColour,
    CartTexNearestMipHemiOct, CartTexNearestMipHemiOctColour, CartTexNearestMipHemiOctMatte,
    CartTexNearestMipHemiOctMatteColour, CartTexNearestMipMatte, CartTexNearestMipMatteColour,
    CartTexNearestMipSurface, CartTexNearestMipSurfaceColour, CartTexNearestMipSurfaceHemiOct,
    CartTexNearestMipSurfaceHemiOctColour, CartTexNearestMipSurfaceHemiOctMatte,
    CartTexNearestMipSurfaceHemiOctMatteColour, CartTexNearestMipSurfaceMatte, CartTexNearestMipSurfaceMatteColour,
    CartTexNearestSurface, CartTexNearestSurfaceColour, CartTexNearestSurfaceHemiOct,
    CartTexNearestSurfaceHemiOctColour, CartTexNearestSurfaceHemiOctMatte, CartTexNearestSurfaceHemiOctMatteColour,
    CartTexNearestSurfaceMatte, CartTexNearestSurfaceMatteColour, CartTexTrilinear, CartTexTrilinearColour,
    CartTexTrilinearHemiOct, CartTexTrilinearHemiOctColour, CartTexTrilinearHemiOctMatte,
    CartTexTrilinearHemiOctMatteColour, CartTexTrilinearMatte, CartTexTrilinearMatteColour, CartTexTrilinearSurface,
    CartTexTrilinearSurfaceColour, CartTexTrilinearSurfaceHemiOct, CartTexTrilinearSurfaceHemiOctColour,
    CartTexTrilinearSurfaceHemiOctMatte, CartTexTrilinearSurfaceHemiOctMatteColour, CartTexTrilinearSurfaceMatte,
    CartTexTrilinearSurfaceMatteColour, CartTexTrilinearTwoPassMatte,
};
use rtl::StreamUnit;
use testbench::{three_streams, unit_tests};
use vectors::cart_tex::{
    bilinear, bilinear_colour, bilinear_hemi_oct, bilinear_hemi_oct_colour, bilinear_hemi_oct_matte,
    bilinear_hemi_oct_matte_colour, bilinear_matte, bilinear_matte_colour, bilinear_surface, bilinear_surface_colour,
    bilinear_surface_hemi_oct, bilinear_surface_hemi_oct_colour, bilinear_surface_hemi_oct_matte,
    bilinear_surface_hemi_oct_matte_colour, bilinear_surface_matte, bilinear_surface_matte_colour, nearest,
    nearest_colour, nearest_hemi_oct, nearest_hemi_oct_colour, nearest_hemi_oct_matte, nearest_hemi_oct_matte_colour,
    nearest_matte, nearest_matte_colour, nearest_mip, nearest_mip_colour, nearest_mip_hemi_oct,
    nearest_mip_hemi_oct_colour, nearest_mip_hemi_oct_matte, nearest_mip_hemi_oct_matte_colour, nearest_mip_matte,
    nearest_mip_matte_colour, nearest_mip_surface, nearest_mip_surface_colour, nearest_mip_surface_hemi_oct,
    nearest_mip_surface_hemi_oct_colour, nearest_mip_surface_hemi_oct_matte, nearest_mip_surface_hemi_oct_matte_colour,
    nearest_mip_surface_matte, nearest_mip_surface_matte_colour, nearest_surface, nearest_surface_colour,
    nearest_surface_hemi_oct, nearest_surface_hemi_oct_colour, nearest_surface_hemi_oct_matte,
    nearest_surface_hemi_oct_matte_colour, nearest_surface_matte, nearest_surface_matte_colour, trilinear,
    trilinear_colour, trilinear_hemi_oct, trilinear_hemi_oct_colour, trilinear_hemi_oct_matte,
    trilinear_hemi_oct_matte_colour, trilinear_matte, trilinear_matte_colour, trilinear_surface,
    trilinear_surface_colour, trilinear_surface_hemi_oct, trilinear_surface_hemi_oct_colour,
    trilinear_surface_hemi_oct_matte, trilinear_surface_hemi_oct_matte_colour, trilinear_surface_matte,
    trilinear_surface_matte_colour, trilinear_two_pass_matte,
};

unit_tests!(cart_tex_bilinear, CartTexBilinear, bilinear::MODEL);
unit_tests!(cart_tex_bilinear_matte, CartTexBilinearMatte, bilinear_matte::MODEL);
unit_tests!(cart_tex_nearest_matte, CartTexNearestMatte, nearest_matte::MODEL);
unit_tests!(cart_tex_nearest_mip_matte, CartTexNearestMipMatte, nearest_mip_matte::MODEL);
unit_tests!(cart_tex_trilinear_matte, CartTexTrilinearMatte, trilinear_matte::MODEL);
unit_tests!(cart_tex_trilinear, CartTexTrilinear, trilinear::MODEL);
unit_tests!(cart_tex_trilinear_hemi_oct, CartTexTrilinearHemiOct, trilinear_hemi_oct::MODEL);
unit_tests!(cart_tex_trilinear_surface, CartTexTrilinearSurface, trilinear_surface::MODEL);
unit_tests!(cart_tex_trilinear_two_pass_matte, CartTexTrilinearTwoPassMatte, trilinear_two_pass_matte::MODEL);
unit_tests!(cart_tex_bilinear_hemi_oct, CartTexBilinearHemiOct, bilinear_hemi_oct::MODEL);
unit_tests!(cart_tex_bilinear_surface, CartTexBilinearSurface, bilinear_surface::MODEL);
unit_tests!(cart_tex_bilinear_surface_matte, CartTexBilinearSurfaceMatte, bilinear_surface_matte::MODEL);
unit_tests!(cart_tex_nearest_surface_matte, CartTexNearestSurfaceMatte, nearest_surface_matte::MODEL);
unit_tests!(cart_tex_bilinear_colour, CartTexBilinearColour, bilinear_colour::MODEL);
unit_tests!(cart_tex_bilinear_surface_colour, CartTexBilinearSurfaceColour, bilinear_surface_colour::MODEL);
unit_tests!(cart_tex_nearest_colour, CartTexNearestColour, nearest_colour::MODEL);
unit_tests!(cart_tex_nearest_mip_colour, CartTexNearestMipColour, nearest_mip_colour::MODEL);
unit_tests!(cart_tex_nearest, CartTexNearest, nearest::MODEL);
unit_tests!(cart_tex_nearest_mip, CartTexNearestMip, nearest_mip::MODEL);
unit_tests!(cart_tex_bilinear_hemi_oct_matte, CartTexBilinearHemiOctMatte, bilinear_hemi_oct_matte::MODEL);
unit_tests!(cart_tex_trilinear_hemi_oct_matte, CartTexTrilinearHemiOctMatte, trilinear_hemi_oct_matte::MODEL);
unit_tests!(cart_tex_trilinear_surface_matte, CartTexTrilinearSurfaceMatte, trilinear_surface_matte::MODEL);
unit_tests!(
    cart_tex_nearest_surface_hemi_oct_matte,
    CartTexNearestSurfaceHemiOctMatte,
    nearest_surface_hemi_oct_matte::MODEL
);
unit_tests!(cart_tex_nearest_hemi_oct, CartTexNearestHemiOct, nearest_hemi_oct::MODEL);
unit_tests!(cart_tex_nearest_hemi_oct_matte, CartTexNearestHemiOctMatte, nearest_hemi_oct_matte::MODEL);
unit_tests!(cart_tex_nearest_surface, CartTexNearestSurface, nearest_surface::MODEL);
unit_tests!(cart_tex_nearest_surface_hemi_oct, CartTexNearestSurfaceHemiOct, nearest_surface_hemi_oct::MODEL);
unit_tests!(cart_tex_nearest_mip_hemi_oct, CartTexNearestMipHemiOct, nearest_mip_hemi_oct::MODEL);
unit_tests!(cart_tex_nearest_mip_hemi_oct_matte, CartTexNearestMipHemiOctMatte, nearest_mip_hemi_oct_matte::MODEL);
unit_tests!(cart_tex_nearest_mip_surface, CartTexNearestMipSurface, nearest_mip_surface::MODEL);
unit_tests!(cart_tex_nearest_mip_surface_matte, CartTexNearestMipSurfaceMatte, nearest_mip_surface_matte::MODEL);
unit_tests!(
    cart_tex_nearest_mip_surface_hemi_oct,
    CartTexNearestMipSurfaceHemiOct,
    nearest_mip_surface_hemi_oct::MODEL
);
unit_tests!(
    cart_tex_nearest_mip_surface_hemi_oct_matte,
    CartTexNearestMipSurfaceHemiOctMatte,
    nearest_mip_surface_hemi_oct_matte::MODEL
);
unit_tests!(cart_tex_bilinear_surface_hemi_oct, CartTexBilinearSurfaceHemiOct, bilinear_surface_hemi_oct::MODEL);
unit_tests!(
    cart_tex_bilinear_surface_hemi_oct_matte,
    CartTexBilinearSurfaceHemiOctMatte,
    bilinear_surface_hemi_oct_matte::MODEL
);
unit_tests!(cart_tex_trilinear_surface_hemi_oct, CartTexTrilinearSurfaceHemiOct, trilinear_surface_hemi_oct::MODEL);
unit_tests!(
    cart_tex_trilinear_surface_hemi_oct_matte,
    CartTexTrilinearSurfaceHemiOctMatte,
    trilinear_surface_hemi_oct_matte::MODEL
);
unit_tests!(cart_tex_nearest_matte_colour, CartTexNearestMatteColour, nearest_matte_colour::MODEL);
unit_tests!(cart_tex_nearest_hemi_oct_colour, CartTexNearestHemiOctColour, nearest_hemi_oct_colour::MODEL);
unit_tests!(
    cart_tex_nearest_hemi_oct_matte_colour,
    CartTexNearestHemiOctMatteColour,
    nearest_hemi_oct_matte_colour::MODEL
);
unit_tests!(cart_tex_nearest_surface_colour, CartTexNearestSurfaceColour, nearest_surface_colour::MODEL);
unit_tests!(
    cart_tex_nearest_surface_matte_colour,
    CartTexNearestSurfaceMatteColour,
    nearest_surface_matte_colour::MODEL
);
unit_tests!(
    cart_tex_nearest_surface_hemi_oct_colour,
    CartTexNearestSurfaceHemiOctColour,
    nearest_surface_hemi_oct_colour::MODEL
);
unit_tests!(
    cart_tex_nearest_surface_hemi_oct_matte_colour,
    CartTexNearestSurfaceHemiOctMatteColour,
    nearest_surface_hemi_oct_matte_colour::MODEL
);
unit_tests!(cart_tex_nearest_mip_matte_colour, CartTexNearestMipMatteColour, nearest_mip_matte_colour::MODEL);
unit_tests!(cart_tex_nearest_mip_hemi_oct_colour, CartTexNearestMipHemiOctColour, nearest_mip_hemi_oct_colour::MODEL);
unit_tests!(
    cart_tex_nearest_mip_hemi_oct_matte_colour,
    CartTexNearestMipHemiOctMatteColour,
    nearest_mip_hemi_oct_matte_colour::MODEL
);
unit_tests!(cart_tex_nearest_mip_surface_colour, CartTexNearestMipSurfaceColour, nearest_mip_surface_colour::MODEL);
unit_tests!(
    cart_tex_nearest_mip_surface_matte_colour,
    CartTexNearestMipSurfaceMatteColour,
    nearest_mip_surface_matte_colour::MODEL
);
unit_tests!(
    cart_tex_nearest_mip_surface_hemi_oct_colour,
    CartTexNearestMipSurfaceHemiOctColour,
    nearest_mip_surface_hemi_oct_colour::MODEL
);
unit_tests!(
    cart_tex_nearest_mip_surface_hemi_oct_matte_colour,
    CartTexNearestMipSurfaceHemiOctMatteColour,
    nearest_mip_surface_hemi_oct_matte_colour::MODEL
);
unit_tests!(cart_tex_bilinear_matte_colour, CartTexBilinearMatteColour, bilinear_matte_colour::MODEL);
unit_tests!(cart_tex_bilinear_hemi_oct_colour, CartTexBilinearHemiOctColour, bilinear_hemi_oct_colour::MODEL);
unit_tests!(
    cart_tex_bilinear_hemi_oct_matte_colour,
    CartTexBilinearHemiOctMatteColour,
    bilinear_hemi_oct_matte_colour::MODEL
);
unit_tests!(
    cart_tex_bilinear_surface_matte_colour,
    CartTexBilinearSurfaceMatteColour,
    bilinear_surface_matte_colour::MODEL
);
unit_tests!(
    cart_tex_bilinear_surface_hemi_oct_colour,
    CartTexBilinearSurfaceHemiOctColour,
    bilinear_surface_hemi_oct_colour::MODEL
);
unit_tests!(
    cart_tex_bilinear_surface_hemi_oct_matte_colour,
    CartTexBilinearSurfaceHemiOctMatteColour,
    bilinear_surface_hemi_oct_matte_colour::MODEL
);
unit_tests!(cart_tex_trilinear_colour, CartTexTrilinearColour, trilinear_colour::MODEL);
unit_tests!(cart_tex_trilinear_matte_colour, CartTexTrilinearMatteColour, trilinear_matte_colour::MODEL);
unit_tests!(cart_tex_trilinear_hemi_oct_colour, CartTexTrilinearHemiOctColour, trilinear_hemi_oct_colour::MODEL);
unit_tests!(
    cart_tex_trilinear_hemi_oct_matte_colour,
    CartTexTrilinearHemiOctMatteColour,
    trilinear_hemi_oct_matte_colour::MODEL
);
unit_tests!(cart_tex_trilinear_surface_colour, CartTexTrilinearSurfaceColour, trilinear_surface_colour::MODEL);
unit_tests!(
    cart_tex_trilinear_surface_matte_colour,
    CartTexTrilinearSurfaceMatteColour,
    trilinear_surface_matte_colour::MODEL
);
unit_tests!(
    cart_tex_trilinear_surface_hemi_oct_colour,
    CartTexTrilinearSurfaceHemiOctColour,
    trilinear_surface_hemi_oct_colour::MODEL
);
unit_tests!(
    cart_tex_trilinear_surface_hemi_oct_matte_colour,
    CartTexTrilinearSurfaceHemiOctMatteColour,
    trilinear_surface_hemi_oct_matte_colour::MODEL
);

#[test]
fn cart_tex_bilinear_streams() {
    three_streams::<CartTexBilinear>(&bilinear::MODEL, 23);
}

#[test]
fn cart_tex_bilinear_matte_streams() {
    three_streams::<CartTexBilinearMatte>(&bilinear_matte::MODEL, 24);
}

#[test]
fn cart_tex_nearest_matte_streams() {
    three_streams::<CartTexNearestMatte>(&nearest_matte::MODEL, 25);
}

#[test]
fn cart_tex_nearest_mip_matte_streams() {
    three_streams::<CartTexNearestMipMatte>(&nearest_mip_matte::MODEL, 26);
}

#[test]
fn cart_tex_trilinear_matte_streams() {
    three_streams::<CartTexTrilinearMatte>(&trilinear_matte::MODEL, 27);
}

#[test]
fn cart_tex_trilinear_streams() {
    three_streams::<CartTexTrilinear>(&trilinear::MODEL, 37);
}

#[test]
fn cart_tex_trilinear_hemi_oct_streams() {
    three_streams::<CartTexTrilinearHemiOct>(&trilinear_hemi_oct::MODEL, 38);
}

#[test]
fn cart_tex_trilinear_surface_streams() {
    three_streams::<CartTexTrilinearSurface>(&trilinear_surface::MODEL, 39);
}

#[test]
fn cart_tex_trilinear_two_pass_matte_streams() {
    three_streams::<CartTexTrilinearTwoPassMatte>(&trilinear_two_pass_matte::MODEL, 35);
}

#[test]
fn cart_tex_bilinear_hemi_oct_streams() {
    three_streams::<CartTexBilinearHemiOct>(&bilinear_hemi_oct::MODEL, 28);
}

#[test]
fn cart_tex_bilinear_surface_streams() {
    three_streams::<CartTexBilinearSurface>(&bilinear_surface::MODEL, 29);
}

#[test]
fn cart_tex_bilinear_surface_matte_streams() {
    three_streams::<CartTexBilinearSurfaceMatte>(&bilinear_surface_matte::MODEL, 30);
}

#[test]
fn cart_tex_nearest_surface_matte_streams() {
    three_streams::<CartTexNearestSurfaceMatte>(&nearest_surface_matte::MODEL, 31);
}

#[test]
fn cart_tex_nearest_surface_hemi_oct_matte_streams() {
    three_streams::<CartTexNearestSurfaceHemiOctMatte>(&nearest_surface_hemi_oct_matte::MODEL, 32);
}

#[test]
fn cart_tex_bilinear_colour_streams() {
    three_streams::<CartTexBilinearColour>(&bilinear_colour::MODEL, 33);
}

#[test]
fn cart_tex_bilinear_surface_colour_streams() {
    three_streams::<CartTexBilinearSurfaceColour>(&bilinear_surface_colour::MODEL, 34);
}

/// The two-pass front takes a vector every other clock and reads nothing of the clock between: the hard cases with
/// random bits on every input but `valid_in` in each gap (writes among them) give the model's outputs; the same
/// vectors back to back (no gap) do not, so the gap is what the harnesses keep, not a formality.
#[test]
fn the_two_pass_trilinear_reads_nothing_of_the_clock_between_two_vectors_and_needs_it() {
    use rand::{Rng, SeedableRng};
    use rtl::stream::Runner;
    type U = CartTexTrilinearTwoPassMatte;
    let m = &trilinear_two_pass_matte::MODEL;
    assert_eq!(<U as StreamUnit>::INTERVAL, 2);
    let inputs = (m.hard_cases)();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(36);
    let mut runner = Runner::<U>::new();
    let mut slots = vec![];
    let mut got = rtl::stream::Collected::default();
    let keep = |out: Option<Vec<u64>>, cycle: usize, got: &mut rtl::stream::Collected| {
        if let Some(o) = out {
            got.cycles.push(cycle as u64);
            got.outputs.push(o);
        }
    };
    for v in &inputs {
        let pattern = vectors::unit::to_patterns(v, m.inputs);
        keep(runner.step(true, &pattern), slots.len(), &mut got);
        slots.push(Some(pattern));
        let garbage: Vec<u64> = <U as StreamUnit>::INPUTS.iter().map(|&(_, w)| rng.gen::<u64>() >> (64 - w)).collect();
        keep(runner.step(false, &garbage), slots.len(), &mut got);
        slots.push(None);
    }
    for _ in 0..=<U as StreamUnit>::LATENCY {
        keep(runner.step(false, &vec![0; m.inputs.len()]), slots.len(), &mut got);
        slots.push(None);
    }
    testbench::check(m, <U as StreamUnit>::LATENCY, &inputs, &slots, &got)
        .assert_clean("hard cases, random bits between the vectors");
    let back_to_back: Vec<Option<Vec<u64>>> =
        inputs.iter().map(|v| Some(vectors::unit::to_patterns(v, m.inputs))).collect();
    let got = Runner::<U>::new().run(back_to_back.iter().cloned());
    let r = testbench::check(m, <U as StreamUnit>::LATENCY, &inputs, &back_to_back, &got);
    assert!(r.mismatches > 0, "back to back the second passes would be lost: {r:?}");
}

#[test]
fn cart_tex_nearest_streams() {
    three_streams::<CartTexNearest>(&nearest::MODEL, 40);
}

#[test]
fn cart_tex_nearest_mip_streams() {
    three_streams::<CartTexNearestMip>(&nearest_mip::MODEL, 41);
}

#[test]
fn cart_tex_bilinear_hemi_oct_matte_streams() {
    three_streams::<CartTexBilinearHemiOctMatte>(&bilinear_hemi_oct_matte::MODEL, 42);
}

#[test]
fn cart_tex_trilinear_hemi_oct_matte_streams() {
    three_streams::<CartTexTrilinearHemiOctMatte>(&trilinear_hemi_oct_matte::MODEL, 43);
}

#[test]
fn cart_tex_trilinear_surface_matte_streams() {
    three_streams::<CartTexTrilinearSurfaceMatte>(&trilinear_surface_matte::MODEL, 44);
}

#[test]
fn cart_tex_nearest_colour_streams() {
    three_streams::<CartTexNearestColour>(&nearest_colour::MODEL, 45);
}

#[test]
fn cart_tex_nearest_mip_colour_streams() {
    three_streams::<CartTexNearestMipColour>(&nearest_mip_colour::MODEL, 46);
}

#[test]
fn cart_tex_nearest_hemi_oct_streams() {
    three_streams::<CartTexNearestHemiOct>(&nearest_hemi_oct::MODEL, 47);
}

#[test]
fn cart_tex_nearest_hemi_oct_matte_streams() {
    three_streams::<CartTexNearestHemiOctMatte>(&nearest_hemi_oct_matte::MODEL, 48);
}

#[test]
fn cart_tex_nearest_surface_streams() {
    three_streams::<CartTexNearestSurface>(&nearest_surface::MODEL, 49);
}

#[test]
fn cart_tex_nearest_surface_hemi_oct_streams() {
    three_streams::<CartTexNearestSurfaceHemiOct>(&nearest_surface_hemi_oct::MODEL, 50);
}

#[test]
fn cart_tex_nearest_mip_hemi_oct_streams() {
    three_streams::<CartTexNearestMipHemiOct>(&nearest_mip_hemi_oct::MODEL, 51);
}

#[test]
fn cart_tex_nearest_mip_hemi_oct_matte_streams() {
    three_streams::<CartTexNearestMipHemiOctMatte>(&nearest_mip_hemi_oct_matte::MODEL, 52);
}

#[test]
fn cart_tex_nearest_mip_surface_streams() {
    three_streams::<CartTexNearestMipSurface>(&nearest_mip_surface::MODEL, 53);
}

#[test]
fn cart_tex_nearest_mip_surface_matte_streams() {
    three_streams::<CartTexNearestMipSurfaceMatte>(&nearest_mip_surface_matte::MODEL, 54);
}

#[test]
fn cart_tex_nearest_mip_surface_hemi_oct_streams() {
    three_streams::<CartTexNearestMipSurfaceHemiOct>(&nearest_mip_surface_hemi_oct::MODEL, 55);
}

#[test]
fn cart_tex_nearest_mip_surface_hemi_oct_matte_streams() {
    three_streams::<CartTexNearestMipSurfaceHemiOctMatte>(&nearest_mip_surface_hemi_oct_matte::MODEL, 56);
}

#[test]
fn cart_tex_bilinear_surface_hemi_oct_streams() {
    three_streams::<CartTexBilinearSurfaceHemiOct>(&bilinear_surface_hemi_oct::MODEL, 57);
}

#[test]
fn cart_tex_bilinear_surface_hemi_oct_matte_streams() {
    three_streams::<CartTexBilinearSurfaceHemiOctMatte>(&bilinear_surface_hemi_oct_matte::MODEL, 58);
}

#[test]
fn cart_tex_trilinear_surface_hemi_oct_streams() {
    three_streams::<CartTexTrilinearSurfaceHemiOct>(&trilinear_surface_hemi_oct::MODEL, 59);
}

#[test]
fn cart_tex_trilinear_surface_hemi_oct_matte_streams() {
    three_streams::<CartTexTrilinearSurfaceHemiOctMatte>(&trilinear_surface_hemi_oct_matte::MODEL, 60);
}

#[test]
fn cart_tex_nearest_matte_colour_streams() {
    three_streams::<CartTexNearestMatteColour>(&nearest_matte_colour::MODEL, 61);
}

#[test]
fn cart_tex_nearest_hemi_oct_colour_streams() {
    three_streams::<CartTexNearestHemiOctColour>(&nearest_hemi_oct_colour::MODEL, 62);
}

#[test]
fn cart_tex_nearest_hemi_oct_matte_colour_streams() {
    three_streams::<CartTexNearestHemiOctMatteColour>(&nearest_hemi_oct_matte_colour::MODEL, 63);
}

#[test]
fn cart_tex_nearest_surface_colour_streams() {
    three_streams::<CartTexNearestSurfaceColour>(&nearest_surface_colour::MODEL, 64);
}

#[test]
fn cart_tex_nearest_surface_matte_colour_streams() {
    three_streams::<CartTexNearestSurfaceMatteColour>(&nearest_surface_matte_colour::MODEL, 65);
}

#[test]
fn cart_tex_nearest_surface_hemi_oct_colour_streams() {
    three_streams::<CartTexNearestSurfaceHemiOctColour>(&nearest_surface_hemi_oct_colour::MODEL, 66);
}

#[test]
fn cart_tex_nearest_surface_hemi_oct_matte_colour_streams() {
    three_streams::<CartTexNearestSurfaceHemiOctMatteColour>(&nearest_surface_hemi_oct_matte_colour::MODEL, 67);
}

#[test]
fn cart_tex_nearest_mip_matte_colour_streams() {
    three_streams::<CartTexNearestMipMatteColour>(&nearest_mip_matte_colour::MODEL, 68);
}

#[test]
fn cart_tex_nearest_mip_hemi_oct_colour_streams() {
    three_streams::<CartTexNearestMipHemiOctColour>(&nearest_mip_hemi_oct_colour::MODEL, 69);
}

#[test]
fn cart_tex_nearest_mip_hemi_oct_matte_colour_streams() {
    three_streams::<CartTexNearestMipHemiOctMatteColour>(&nearest_mip_hemi_oct_matte_colour::MODEL, 70);
}

#[test]
fn cart_tex_nearest_mip_surface_colour_streams() {
    three_streams::<CartTexNearestMipSurfaceColour>(&nearest_mip_surface_colour::MODEL, 71);
}

#[test]
fn cart_tex_nearest_mip_surface_matte_colour_streams() {
    three_streams::<CartTexNearestMipSurfaceMatteColour>(&nearest_mip_surface_matte_colour::MODEL, 72);
}

#[test]
fn cart_tex_nearest_mip_surface_hemi_oct_colour_streams() {
    three_streams::<CartTexNearestMipSurfaceHemiOctColour>(&nearest_mip_surface_hemi_oct_colour::MODEL, 73);
}

#[test]
fn cart_tex_nearest_mip_surface_hemi_oct_matte_colour_streams() {
    three_streams::<CartTexNearestMipSurfaceHemiOctMatteColour>(&nearest_mip_surface_hemi_oct_matte_colour::MODEL, 74);
}

#[test]
fn cart_tex_bilinear_matte_colour_streams() {
    three_streams::<CartTexBilinearMatteColour>(&bilinear_matte_colour::MODEL, 75);
}

#[test]
fn cart_tex_bilinear_hemi_oct_colour_streams() {
    three_streams::<CartTexBilinearHemiOctColour>(&bilinear_hemi_oct_colour::MODEL, 76);
}

#[test]
fn cart_tex_bilinear_hemi_oct_matte_colour_streams() {
    three_streams::<CartTexBilinearHemiOctMatteColour>(&bilinear_hemi_oct_matte_colour::MODEL, 77);
}

#[test]
fn cart_tex_bilinear_surface_matte_colour_streams() {
    three_streams::<CartTexBilinearSurfaceMatteColour>(&bilinear_surface_matte_colour::MODEL, 78);
}

#[test]
fn cart_tex_bilinear_surface_hemi_oct_colour_streams() {
    three_streams::<CartTexBilinearSurfaceHemiOctColour>(&bilinear_surface_hemi_oct_colour::MODEL, 79);
}

#[test]
fn cart_tex_bilinear_surface_hemi_oct_matte_colour_streams() {
    three_streams::<CartTexBilinearSurfaceHemiOctMatteColour>(&bilinear_surface_hemi_oct_matte_colour::MODEL, 80);
}

#[test]
fn cart_tex_trilinear_colour_streams() {
    three_streams::<CartTexTrilinearColour>(&trilinear_colour::MODEL, 81);
}

#[test]
fn cart_tex_trilinear_matte_colour_streams() {
    three_streams::<CartTexTrilinearMatteColour>(&trilinear_matte_colour::MODEL, 82);
}

#[test]
fn cart_tex_trilinear_hemi_oct_colour_streams() {
    three_streams::<CartTexTrilinearHemiOctColour>(&trilinear_hemi_oct_colour::MODEL, 83);
}

#[test]
fn cart_tex_trilinear_hemi_oct_matte_colour_streams() {
    three_streams::<CartTexTrilinearHemiOctMatteColour>(&trilinear_hemi_oct_matte_colour::MODEL, 84);
}

#[test]
fn cart_tex_trilinear_surface_colour_streams() {
    three_streams::<CartTexTrilinearSurfaceColour>(&trilinear_surface_colour::MODEL, 85);
}

#[test]
fn cart_tex_trilinear_surface_matte_colour_streams() {
    three_streams::<CartTexTrilinearSurfaceMatteColour>(&trilinear_surface_matte_colour::MODEL, 86);
}

#[test]
fn cart_tex_trilinear_surface_hemi_oct_colour_streams() {
    three_streams::<CartTexTrilinearSurfaceHemiOctColour>(&trilinear_surface_hemi_oct_colour::MODEL, 87);
}

#[test]
fn cart_tex_trilinear_surface_hemi_oct_matte_colour_streams() {
    three_streams::<CartTexTrilinearSurfaceHemiOctMatteColour>(&trilinear_surface_hemi_oct_matte_colour::MODEL, 88);
}
