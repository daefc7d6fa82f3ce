//! Waveforms: a unit run in rust-hdl with every signal traced to a VCD (hierarchical names: `uut.s3_l.q`, ...).

use rtl::stream::Runner;
use rtl::StreamUnit;
use std::path::Path;
use vectors::UnitModel;

/// Trace `inputs` through the unit into `path` (written whole, or not at all), with its GTKWave save file beside it
/// (`crate::gtkw`). Returns the outputs seen.
pub fn write_vcd<U: StreamUnit>(model: &UnitModel, inputs: &[Vec<i64>], path: &Path) -> Result<Vec<Vec<u64>>, String> {
    let tmp = path.with_extension("vcd.partial");
    let file = std::fs::File::create(&tmp).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    let got = match trace::<U>(model, inputs, Box::new(std::io::BufWriter::new(file))) {
        Ok(g) => g,
        Err(e) => {
            let _ = std::fs::remove_file(&tmp);
            return Err(format!("cannot write {}: {e}", path.display()));
        }
    };
    std::fs::rename(&tmp, path).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    crate::gtkw::write_beside(path, &widths::Formats::of::<U>())?;
    Ok(got)
}

/// Trace `inputs` through the unit into any writer (standard output, say); Err when a write failed.
pub fn trace<U: StreamUnit>(
    model: &UnitModel,
    inputs: &[Vec<i64>],
    w: Box<dyn std::io::Write>,
) -> std::io::Result<Vec<Vec<u64>>> {
    let mut r = Runner::<U>::with_vcd(Some(w));
    let slots = rtl::stream::paced::<U>(inputs.iter().map(|v| vectors::unit::to_patterns(v, model.inputs)));
    let got = r.run(slots);
    r.finish()?;
    Ok(got.outputs)
}
