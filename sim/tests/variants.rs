//! The height-map variants of US 2004/0207631: the colour filters against their own method and the picture, and
//! FIG. 8's pictures.
use sim::variants::*;

#[test]
fn both_colour_filters_are_within_a_rounding_of_their_own_method() {
    let c = colour(64);
    assert!(c.bilinear_vs_own.max <= 0.5 + 1e-9, "{}", c.bilinear_vs_own.max);
    assert!(c.bspline_vs_own.max <= 0.5 + 1.0 / 64.0, "{}", c.bspline_vs_own.max); // the height's own floors, then a rounding

    // against the picture sampled, both err by a few LSB: the texture is coarse
    assert!(c.bilinear_vs_reference.mean() < 8.0 && c.bspline_vs_reference.mean() < 12.0);
}

#[test]
fn fig8_pictures_differ_and_the_cross_tangent_jumps_only_for_blinn() {
    let f = fig8(32, 6.0);
    assert_ne!(f.blinn, f.bspline);
    assert!(f.jumps.blinn.1 > 100.0 * f.jumps.bspline.1.max(1e-6), "{:?}", f.jumps);
}
