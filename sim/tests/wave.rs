//! The VCD is read back with the `vcd` crate: the outputs in the waveform are the model's.
use std::io::BufReader;
use vectors::gloss::MODEL;

fn value(v: &vcd::Vector) -> u64 {
    v.iter().fold(0, |a, b| (a << 1) | u64::from(b == vcd::Value::V1))
}

#[test]
fn gloss_vcd_outputs_are_the_models() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("bumprtl-wave-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("gloss.vcd");
    let inputs = (MODEL.hard_cases)();
    sim::wave::write_vcd::<rtl::gloss::Gloss>(&MODEL, &inputs, &path).unwrap();
    let mut p = vcd::Parser::new(BufReader::new(std::fs::File::open(&path).unwrap()));
    let header = p.parse_header().unwrap();
    let code = |name: &str| header.find_var(&["uut", name]).unwrap_or_else(|| panic!("no uut.{name} in the VCD")).code;
    let (c_valid, c_p) = (code("valid_out"), code("p"));
    // readable hierarchy: a pipeline register of stage 3 is uut.s3_l.q
    assert!(header.find_var(&["uut", "s3_l", "q"]).is_some());
    let (mut valid, mut pv, mut t) = (false, 0u64, 0u64);
    let mut seen = vec![];
    let flush = |t: u64, valid: bool, pv: u64, seen: &mut Vec<i64>| {
        if t % 10_000 == 5_000 && valid {
            seen.push(pv as i64);
        }
    };
    for cmd in p {
        match cmd.unwrap() {
            vcd::Command::Timestamp(n) => {
                flush(t, valid, pv, &mut seen);
                t = n;
            }
            vcd::Command::ChangeScalar(c, v) if c == c_valid => valid = v == vcd::Value::V1,
            vcd::Command::ChangeVector(c, v) if c == c_p => pv = value(&v),
            vcd::Command::ChangeVector(c, v) if c == c_valid => valid = value(&v) == 1,
            _ => {}
        }
    }
    flush(t, valid, pv, &mut seen);
    let want: Vec<i64> = inputs.iter().map(|i| (MODEL.exact)(i)[0]).collect();
    assert_eq!(seen, want);
    std::fs::remove_dir_all(&dir).ok();
}
