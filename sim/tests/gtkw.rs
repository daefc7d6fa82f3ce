//! Every VCD the program writes gets a GTKWave save file beside it: every trace in it is a variable of the VCD
//! (under the name GTKWave gives it), the valid flags come first, signed signals are flagged signed, and each
//! block's registers are grouped stage by stage in order.
use std::collections::HashSet;
use std::path::PathBuf;

fn test_dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/test-files/gtkw");
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn a_pipelines_vcd_gets_a_save_file_gtkwave_can_follow() {
    let m = &vectors::cart_pipeline::MODEL;
    let inputs = vectors::unit::generate(m, false, 20, 3).unwrap();
    let vcd = test_dir().join("cart_pipeline.vcd");
    sim::wave::write_vcd::<rtl::cart_pipeline::CartPipeline>(m, &inputs, &vcd).unwrap();
    let gtkw = std::fs::read_to_string(vcd.with_extension("gtkw")).expect("the save file beside the VCD");
    let head = std::fs::read_to_string(&vcd).unwrap();
    let vars = sim::gtkw::header_vars(&head);
    let names: HashSet<String> =
        vars.iter().map(|v| if v.bits > 1 { format!("{}[{}:0]", v.name(), v.bits - 1) } else { v.name() }).collect();
    assert!(gtkw.contains("[dumpfile] \"cart_pipeline.vcd\""));
    let lines: Vec<&str> = gtkw.lines().collect();
    let mut traces = vec![];
    let mut groups = vec![];
    for w in lines.windows(2) {
        if let (Some(flags), next) = (w[0].strip_prefix('@'), w[1]) {
            let f = u32::from_str_radix(flags, 16).unwrap();
            if let Some(title) = next.strip_prefix('-') {
                if f & 0x80_0000 != 0 {
                    groups.push(title.to_string());
                }
            } else {
                traces.push((next.to_string(), f));
            }
        }
    }
    // every trace is a variable of the VCD, none twice, and there are many
    assert!(traces.len() > 500, "{} traces", traces.len());
    for (t, _) in &traces {
        assert!(names.contains(t), "{t} is not in the VCD");
    }
    assert_eq!(traces.iter().map(|t| &t.0).collect::<HashSet<_>>().len(), traces.len());
    // the valid flags first, binary; then the ports
    assert_eq!(groups[0], "valid flags");
    assert_eq!(groups[1], "uut ports");
    assert_eq!(traces[0], ("uut.valid_in".into(), 0x28));
    // signed signals signed (the S8 vertex lights, the normaliser's Sq1.10 outputs), unsigned buses decimal
    let flag = |n: &str| traces.iter().find(|t| t.0 == n).unwrap_or_else(|| panic!("{n}")).1;
    assert_eq!(flag("uut.l0_x[7:0]"), 0x424);
    assert_eq!(flag("uut.bump_norm.norm_x[11:0]") & 0x400, 0x400);
    assert_eq!(flag("uut.conc[7:0]"), 0x24);
    // the normaliser's registers in its stages, in order
    let stages: Vec<u32> =
        groups.iter().filter_map(|g| g.strip_prefix("uut.bump_norm stage ").map(|s| s.parse().unwrap())).collect();
    assert!(stages.len() >= 8 && stages.windows(2).all(|w| w[0] < w[1]), "{stages:?}");
    let at = |n: &str| traces.iter().position(|t| t.0 == n).unwrap_or_else(|| panic!("{n}"));
    assert!(at("uut.bump_norm.s3_s.q[19:0]") < at("uut.bump_norm.s7_p$0.q[22:0]"));
}

mod reading {
    use sim::gtkw::*;

    #[test]
    fn stages_are_read_off_register_names() {
        assert_eq!(stage_of("s7_p$0"), Some(7));
        assert_eq!(stage_of("s6b_c$1"), Some(6));
        assert_eq!(stage_of("s12_x"), Some(12));
        for f in ["mop_r$0", "sum", "s_x", "shift_f", "sb_x"] {
            assert_eq!(stage_of(f), None, "{f}");
        }
    }

    #[test]
    fn the_header_is_read_scope_by_scope() {
        let v = header_vars("$scope module uut $end $var wire 1 ! clock $end $scope module s1_a $end $var wire 12 # q $end $upscope $end $var wire 3 $ w $end $upscope $end $enddefinitions $end");
        assert_eq!(v.len(), 3);
        assert_eq!(v[1], Var { path: vec!["uut".into(), "s1_a".into(), "q".into()], bits: 12 });
        assert_eq!(v[2].name(), "uut.w");
        assert_eq!(facility(&v[1]), "uut.s1_a.q[11:0]");
    }
}
