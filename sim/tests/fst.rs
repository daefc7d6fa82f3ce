//! `sim::fst`: a VCD rewritten as an FST holds the same trace. Each FST is read back by `fst-reader` (a reader
//! written apart from the writer) and compared, signal by signal and timestamp by timestamp, with the VCD read by the
//! `vcd` crate.

use fst_reader::{FstFilter, FstHierarchyEntry, FstReader, FstSignalValue};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("fst-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A trace: each variable's dotted path → its width, and its value at each timestamp (the last change at or before
/// it), as `0`/`1`/`x`/`z` characters, most significant first.
#[derive(Debug, PartialEq)]
struct Trace {
    timescale_exponent: i8,
    vars: BTreeMap<String, usize>,
    values: BTreeMap<String, Vec<(u64, String)>>,
}

/// Per variable, its value sampled at every time of `times`, from its changes (time, value) in any order of signals
/// but time order within one.
fn sampled(times: &[u64], changes: &[(u64, String)]) -> Vec<(u64, String)> {
    let mut out = vec![];
    let mut k = 0;
    let mut now: Option<&String> = None;
    for &t in times {
        while k < changes.len() && changes[k].0 <= t {
            now = Some(&changes[k].1);
            k += 1;
        }
        if let Some(v) = now {
            out.push((t, v.clone()));
        }
    }
    out
}

fn read_vcd(path: &Path) -> Trace {
    let mut p = vcd::Parser::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let h = p.parse_header().unwrap();
    let (n, unit) = h.timescale.unwrap();
    let timescale_exponent = (n.ilog10() as i8) - unit.divisor().ilog10() as i8;
    let mut vars = BTreeMap::new();
    let mut names: BTreeMap<vcd::IdCode, Vec<(String, usize)>> = BTreeMap::new();
    fn walk(
        items: &[vcd::ScopeItem],
        at: &str,
        vars: &mut BTreeMap<String, usize>,
        names: &mut BTreeMap<vcd::IdCode, Vec<(String, usize)>>,
    ) {
        for i in items {
            match i {
                vcd::ScopeItem::Scope(s) => walk(&s.items, &format!("{at}{}.", s.identifier), vars, names),
                vcd::ScopeItem::Var(v) => {
                    let name = format!("{at}{}", v.reference);
                    vars.insert(name.clone(), v.size as usize);
                    names.entry(v.code).or_default().push((name, v.size as usize));
                }
                _ => {}
            }
        }
    }
    walk(&h.items, "", &mut vars, &mut names);
    let (mut now, mut times) = (0, vec![]);
    let mut changes: BTreeMap<String, Vec<(u64, String)>> = BTreeMap::new();
    for c in p {
        let (code, bits): (vcd::IdCode, String) = match c.unwrap() {
            vcd::Command::Timestamp(t) => {
                now = t;
                times.push(t);
                continue;
            }
            vcd::Command::ChangeScalar(c, v) => (c, v.to_string()),
            vcd::Command::ChangeVector(c, v) => (c, v.to_string()),
            _ => continue,
        };
        for (name, width) in &names[&code] {
            // VCD's left-extension: 0, or x / z when the value's first bit is one
            let fill = match bits.chars().next() {
                Some('x') => 'x',
                Some('z') => 'z',
                _ => '0',
            };
            let mut v: String = std::iter::repeat_n(fill, width.saturating_sub(bits.len())).collect();
            v.push_str(&bits[bits.len().saturating_sub(*width)..]);
            changes.entry(name.clone()).or_default().push((now, v));
        }
    }
    let values = changes.iter().map(|(k, c)| (k.clone(), sampled(&times, c))).collect();
    Trace { timescale_exponent, vars, values }
}

/// The FST read back, sampled at the VCD's timestamps `times`.
fn read_fst(path: &Path, times: &[u64]) -> Trace {
    let mut r = FstReader::open(std::io::BufReader::new(std::fs::File::open(path).unwrap())).unwrap();
    let timescale_exponent = r.get_header().timescale_exponent;
    let (mut vars, mut by_handle) = (BTreeMap::new(), BTreeMap::<usize, Vec<String>>::new());
    let mut scope: Vec<String> = vec![];
    r.read_hierarchy(|e| match e {
        FstHierarchyEntry::Scope { name, .. } => scope.push(name),
        FstHierarchyEntry::UpScope => {
            scope.pop();
        }
        FstHierarchyEntry::Var { name, length, handle, .. } => {
            let full = scope.iter().map(|s| format!("{s}.")).collect::<String>() + &name;
            vars.insert(full.clone(), length as usize);
            by_handle.entry(handle.get_index()).or_default().push(full);
        }
        _ => {}
    })
    .unwrap();
    let mut changes: BTreeMap<String, Vec<(u64, String)>> = BTreeMap::new();
    r.read_signals(&FstFilter::all(), |t, h, v| {
        let FstSignalValue::String(bytes) = v else { panic!("a real value") };
        for name in &by_handle[&h.get_index()] {
            changes.entry(name.clone()).or_default().push((t, String::from_utf8(bytes.to_vec()).unwrap()));
        }
        Ok::<(), ()>(())
    })
    .unwrap();
    for c in changes.values_mut() {
        c.sort_by_key(|x| x.0); // stable: changes at one time keep their order
    }
    let values = changes.iter().map(|(k, c)| (k.clone(), sampled(times, c))).collect();
    Trace { timescale_exponent, vars, values }
}

fn times_of(vcd: &Path) -> Vec<u64> {
    let mut p = vcd::Parser::new(std::io::BufReader::new(std::fs::File::open(vcd).unwrap()));
    p.parse_header().unwrap();
    p.filter_map(|c| match c.unwrap() {
        vcd::Command::Timestamp(t) => Some(t),
        _ => None,
    })
    .collect()
}

/// A VCD written by hand with what rust-hdl's never has but the format allows: nested scopes, two variables on one
/// code, vectors shorter than their width, x and z, a timescale of 10 ns.
const HAND: &str = "$timescale 10 ns $end
$scope module top $end
$var wire 1 ! clock $end
$scope module uut $end
$var wire 8 \" a $end
$var wire 8 \" a_copy $end
$var wire 4 # b $end
$upscope $end
$upscope $end
$enddefinitions $end
#0
$dumpvars
0!
b101 \"
bx #
$end
#5
1!
b11111111 \"
b1z #
#10
0!
bz #
b0 \"
";

#[test]
fn a_hand_written_vcd_keeps_its_scopes_aliases_widths_and_every_value() {
    let d = scratch("hand");
    let (vcd, fst) = (d.join("hand.vcd"), d.join("hand.fst"));
    std::fs::write(&vcd, HAND).unwrap();
    let changes = sim::fst::vcd_to_fst(&vcd, &fst).unwrap();
    assert_eq!(changes, 9);
    let got = read_fst(&fst, &times_of(&vcd));
    // written out by hand from the VCD above, not from either reader
    let v = |pairs: &[(u64, &str)]| pairs.iter().map(|(t, s)| (*t, s.to_string())).collect::<Vec<_>>();
    assert_eq!(got.timescale_exponent, -8);
    assert_eq!(
        got.vars,
        BTreeMap::from([
            ("top.clock".to_string(), 1),
            ("top.uut.a".into(), 8),
            ("top.uut.a_copy".into(), 8),
            ("top.uut.b".into(), 4)
        ])
    );
    assert_eq!(got.values["top.clock"], v(&[(0, "0"), (5, "1"), (10, "0")]));
    assert_eq!(got.values["top.uut.a"], v(&[(0, "00000101"), (5, "11111111"), (10, "00000000")]));
    assert_eq!(got.values["top.uut.a_copy"], got.values["top.uut.a"]);
    assert_eq!(got.values["top.uut.b"], v(&[(0, "xxxx"), (5, "001z"), (10, "zzzz")]));
    assert_eq!(got, read_vcd(&vcd));
}

#[test]
fn a_units_rust_hdl_vcd_and_its_fst_hold_the_same_trace() {
    for name in ["gloss", "cart_pipeline"] {
        let d = scratch(name);
        let (vcd, fst) = (d.join(format!("{name}.vcd")), d.join(format!("{name}.fst")));
        let unit = sim::units::unit(name).unwrap();
        let inputs = vectors::unit::generate(unit.model, false, 200, 1).unwrap();
        unit.rtl.write_vcd(unit.model, &inputs, &vcd).unwrap();
        sim::fst::vcd_to_fst(&vcd, &fst).unwrap();
        let want = read_vcd(&vcd);
        assert!(want.vars.len() > 20 && want.values.values().any(|v| v.len() > 200), "{name}: a trace this short?");
        assert_eq!(read_fst(&fst, &times_of(&vcd)), want, "{name}");
        // and the FST is the smaller file
        let size = |p: &Path| std::fs::metadata(p).unwrap().len();
        assert!(size(&fst) * 3 < size(&vcd), "{name}: FST {} bytes, VCD {}", size(&fst), size(&vcd));
    }
}

#[test]
fn an_unreadable_vcd_is_an_error_naming_it_and_leaves_no_fst() {
    let d = scratch("bad");
    let (vcd, fst) = (d.join("bad.vcd"), d.join("bad.fst"));
    std::fs::write(&vcd, "$timescale 1 ps $end\n$scope module top $end\n$var wire 1 ! c $end\n$upscope $end\n$enddefinitions $end\n#0\n1?\n").unwrap();
    let e = sim::fst::vcd_to_fst(&vcd, &fst).unwrap_err();
    assert!(e.starts_with(&vcd.display().to_string()) && !e.contains('\n'), "{e}");
    assert!(!fst.exists());
    assert_eq!(std::fs::read_dir(&d).unwrap().count(), 1, "a partial file left behind");
}
