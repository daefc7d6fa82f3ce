//! `palette_tex_*`: Tarini et al.'s palette pipeline on the texture unit: `palette_pipeline` with the texture unit's
//! front in place of the index the host fetched (`texture::textured`: the model is the two wired, the palette
//! pipeline's colour tables its state). The texel's low byte is the index; an index is never filtered, so the
//! front is the nearest texel of level 0 (`nearest`) or of the nearest level ⌊λ + ½⌋ (`nearest_mip`, the levels
//! §5.2's: each texel the palette index nearest the average of the four normals below it, made by
//! `quantize::mip_chain` and written through the map port like any level).

use crate::texture::front::Filter;
use crate::texture::textured::{hard_cases, random, textured, Sweep, Textured};
use crate::unit::{Machine, UnitModel};

textured!(nearest, "palette_tex_nearest", Filter::Nearest, crate::palette_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    frame: u 1, build: u 1, b_idx: u 8, n_x: s 10, n_y: s 10, n_z: s 10, l_x: s 12, l_y: s 12, l_z: s 12,
    h_x: s 12, h_y: s 12, h_z: s 12, conc: u 8, spec_r: u 8, spec_g: u 8, spec_b: u 8,
], outputs: [out_r: u 8, out_g: u 8, out_b: u 8, out_a: u 8]);

textured!(nearest_mip, "palette_tex_nearest_mip", Filter::NearestMip, crate::palette_pipeline::MODEL, inputs: [
    u: s 20, v: s 20, log_side: u 4, uwrap: u 1, vwrap: u 1, we: u 1, w_log2: u 4, wx: u 8, wy: u 8, wdata: u 16,
    du_dx: s 17, dv_dx: s 17, du_dy: s 17, dv_dy: s 17, lod_bias: s 12,
    frame: u 1, build: u 1, b_idx: u 8, n_x: s 10, n_y: s 10, n_z: s 10, l_x: s 12, l_y: s 12, l_z: s 12,
    h_x: s 12, h_y: s 12, h_z: s 12, conc: u 8, spec_r: u 8, spec_g: u 8, spec_b: u 8,
], outputs: [out_r: u 8, out_g: u 8, out_b: u 8, out_a: u 8]);

/// Every palette pipeline on the texture unit: its model, its filter and its host.
pub fn all() -> Vec<(&'static UnitModel, Filter, &'static UnitModel)> {
    vec![
        (&nearest::MODEL, nearest::FILTER, nearest::host()),
        (&nearest_mip::MODEL, nearest_mip::FILTER, nearest_mip::host()),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::palette_pipeline::{build, pixel};
    use crate::texture::front::{self, At};
    use crate::texture::textured::{expected_ports, from_host};

    #[test]
    fn each_pipeline_has_the_fronts_ports_then_its_hosts_others() {
        for (m, f, h) in all() {
            let want = expected_ports(f, h, false);
            let got: Vec<_> = m.inputs.iter().map(|p| (p.name, p.bits, p.signed)).collect();
            assert_eq!(got, want.iter().map(|p| (p.name, p.bits, p.signed)).collect::<Vec<_>>(), "{}", m.name);
        }
    }

    /// The texel's low byte is the index the palette pipeline reads, and its tables carry over from vector to
    /// vector: entries 5 and 200 of table 1 built (while frame 0 shows table 0), texels 5 and 200 (a high byte of
    /// 0xab, which must not count) written into the 2 × 1 rows of a 2 × 2 map; frame 1 reading at each texel's
    /// centre gives the entries the palette pipeline alone gives for pixels 5 and 200.
    #[test]
    fn the_texels_low_byte_indexes_the_tables_the_builder_wrote() {
        for (m, f, h) in all() {
            let at = At::of(m.inputs, f.mip());
            let (b5, b200) = (build(0, 0, 5, [100, 300, -50], 96), build(0, 0, 200, [-200, 250, 90], 40));
            let mut host_stream = vec![b5.clone(), b200.clone()];
            let mut stream = vec![from_host(h, m.inputs, &b5), from_host(h, m.inputs, &b200)];
            for (x, t) in [(0, 5), (1, 200)] {
                let mut w = from_host(h, m.inputs, &pixel(0, 0));
                front::put_write(&mut w, &at, 1, x, 0, t | 0xab << 8);
                stream.push(w);
                host_stream.push(pixel(0, 0));
            }
            for (x, t) in [(0, 5), (1, 200)] {
                let mut r = from_host(h, m.inputs, &pixel(1, 0));
                front::put_read(&mut r, &at, [128 + 256 * x, 128], 1, [true, true], [256, 0, 0, 256]);
                stream.push(r);
                host_stream.push(pixel(1, t));
            }
            let (got, want) = (m.run(&stream), h.run(&host_stream));
            assert_eq!(got[4..], want[4..], "{}", m.name);
            assert_ne!(got[4], got[5], "{}: two entries of one colour prove nothing", m.name);
            assert_ne!(got[4], vec![0; 4], "{}", m.name);
        }
    }

    /// With MIP levels the level is the LOD unit's: a map of side 2 whose level 0 holds index 5 everywhere and
    /// whose 1 × 1 level holds 200 reads entry 5 at one texel a pixel and entry 200 at two (λ = 1).
    #[test]
    fn the_mip_pipeline_reads_the_level_the_derivatives_name() {
        let (m, h) = (&nearest_mip::MODEL, nearest_mip::host());
        let at = At::of(m.inputs, true);
        let b = |e, n| from_host(h, m.inputs, &build(0, 0, e, n, 96));
        let mut stream = vec![b(5, [100, 300, -50]), b(200, [-200, 250, 90])];
        for (lvl, x, y, t) in [(1, 0, 0, 5), (1, 1, 0, 5), (1, 0, 1, 5), (1, 1, 1, 5), (0, 0, 0, 200)] {
            let mut w = from_host(h, m.inputs, &pixel(0, 0));
            front::put_write(&mut w, &at, lvl, x, y, t);
            stream.push(w);
        }
        for d in [[256, 0, 0, 256], [512, 0, 0, 512]] {
            let mut r = from_host(h, m.inputs, &pixel(1, 0));
            front::put_read(&mut r, &at, [200, 300], 1, [true, true], d);
            stream.push(r);
        }
        let got = m.run(&stream);
        let want = h.run(&[
            build(0, 0, 5, [100, 300, -50], 96),
            build(0, 0, 200, [-200, 250, 90], 96),
            pixel(1, 5),
            pixel(1, 200),
        ]);
        assert_eq!(got[got.len() - 2..], want[2..]);
    }
}
