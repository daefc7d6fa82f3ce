//! `polar_tex_*`: US 6,819,319's polar pipeline on the texture unit: `polar_pipeline` with the texture unit's front
//! in place of the S and R the host filtered (`texture::textured`: the model is the two wired). The texel's low byte
//! is S, its high byte R, and the front's bilinear units (and trilinear's blend of two levels) filter each as a
//! plain number, as the seed's colour filter would: across R's 255 → 0 wrap the filtered R is wrong (the seed's
//! shortcoming 2), now in the hardware that makes it.

use crate::texture::front::Filter;
use crate::texture::textured::{hard_cases, random, textured, Sweep, Textured};
use crate::unit::{Machine, UnitModel};

textured!(bilinear, "polar_tex_bilinear", Filter::Bilinear, crate::polar_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    q: u 8, k1: u 8, k2: u 8, k3: u 8, pw: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
], outputs: [alpha: u 8, out_r: u 8, out_g: u 8, out_b: u 8]);

textured!(trilinear, "polar_tex_trilinear", Filter::Trilinear, crate::polar_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    q: u 8, k1: u 8, k2: u 8, k3: u 8, pw: u 8, mode: u 1,
    src_r: u 8, src_g: u 8, src_b: u 8, dst_r: u 8, dst_g: u 8, dst_b: u 8,
], outputs: [alpha: u 8, out_r: u 8, out_g: u 8, out_b: u 8]);

/// Every polar pipeline on the texture unit: its model, its filter and its host.
pub fn all() -> Vec<(&'static UnitModel, Filter, &'static UnitModel)> {
    vec![
        (&bilinear::MODEL, bilinear::FILTER, bilinear::host()),
        (&trilinear::MODEL, trilinear::FILTER, trilinear::host()),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::front::{self, At};
    use crate::texture::textured::expected_ports;

    #[test]
    fn each_pipeline_has_the_fronts_ports_then_its_hosts_others() {
        for (m, f, h) in all() {
            let want = expected_ports(f, h, false);
            let got: Vec<_> = m.inputs.iter().map(|p| (p.name, p.bits, p.signed)).collect();
            assert_eq!(got, want.iter().map(|p| (p.name, p.bits, p.signed)).collect::<Vec<_>>(), "{}", m.name);
        }
    }

    /// S and R written as one texel come back as the host's S and R: the texel (S, R) = (37, 250) written into the
    /// 1 × 1 map and read at its centre shades as the polar pipeline given S = 37 and R = 250.
    #[test]
    fn the_front_gives_the_host_s_in_the_low_byte_and_r_in_the_high_one() {
        for (m, f, h) in all() {
            let at = At::of(m.inputs, f.mip());
            let hv = (h.hard_cases)()[0].clone();
            let mut hv2 = hv.clone();
            (hv2[crate::polar_pipeline::input::s], hv2[crate::polar_pipeline::input::r]) = (37, 250);
            let base = crate::texture::textured::from_host(h, m.inputs, &hv);
            let mut write = base.clone();
            front::put_write(&mut write, &at, 0, 0, 0, 37 | (250 << 8));
            let mut read = base.clone();
            front::put_read(&mut read, &at, [128, 128], 0, [true, true], [256, 0, 0, 256]);
            let out = m.run(&[write, read]);
            assert_eq!(out[1], (h.exact)(&hv2), "{}", m.name);
        }
    }

    /// Across R's wrap the front blends R as a number: texels R = 250 and R = 6 side by side, read half way, give
    /// R = 128 (the seed's shortcoming 2), not 0 (the nearer angle).
    #[test]
    fn r_is_blended_across_its_wrap_as_a_number() {
        let m = &bilinear::MODEL;
        let at = At::of(m.inputs, false);
        let mut f = front::Front::new(Filter::Bilinear);
        let blank = vec![0; m.inputs.len()];
        for (x, r) in [(0, 250), (1, 6)] {
            for y in 0..2 {
                let mut w = blank.clone();
                front::put_write(&mut w, &at, 1, x, y, 100 | (r << 8));
                f.step(&w, &at);
            }
        }
        let mut read = blank.clone();
        // the centre between the two columns' texel centres (x = 1.0 texels), clamped: an even blend
        front::put_read(&mut read, &at, [256, 128], 1, [false, false], [0; 4]);
        let [s, r] = f.step(&read, &at);
        assert_eq!((s, r), (100, 128));
    }

    /// The hard cases' reads of R across its wrap, at every level: the front gives R = (250 + 6) / 2 = 128 half way
    /// between columns 0 and 1 and, repeating, between the last column and column 0; clamped at x = 0, column 0's
    /// R = 6 alone. S = 100 throughout. (The MIP reads past the level are the model's to give: not checked here.)
    #[test]
    fn the_hard_cases_read_r_across_its_wrap_at_every_level() {
        use crate::texture::textured::r_wrap_seams;
        let m = &bilinear::MODEL;
        let at = At::of(m.inputs, false);
        let mut f = front::Front::new(Filter::Bilinear);
        let levels = r_wrap_seams(Filter::Bilinear, &at, &vec![0; m.inputs.len()]);
        for w in &levels[0] {
            f.step(w, &at);
        }
        assert_eq!(levels.len(), 5);
        for (k, level) in levels[1..].iter().enumerate() {
            let got: Vec<[i64; 2]> = level.iter().map(|v| f.step(v, &at)).collect();
            // x = 0 repeating, x = 0 clamped, x = 1 texel repeating, clamped
            assert_eq!(got, [[100, 128], [100, 6], [100, 128], [100, 128]], "level of side 2^{}", k + 1);
        }
        // and the pipeline's hard cases hold them, for each filter
        for (m, filt, h) in all() {
            let at = At::of(m.inputs, filt.mip());
            let hard = (m.hard_cases)();
            let base = crate::texture::textured::from_host(h, m.inputs, &(h.hard_cases)()[0]);
            let seams: Vec<Vec<i64>> = r_wrap_seams(filt, &at, &base).into_iter().flatten().collect();
            assert!(hard.ends_with(&seams), "{}", m.name);
        }
    }
}
