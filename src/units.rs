//! A unit's figures by its name in the table of units (`sim::units`): its iCE40 cells and its placement, for the
//! report; the rtl block of a swept setting, for the width sweep, the report and the LUT-size tables.

use sim::rtl_paths::RtlBlock;

/// A unit's iCE40 cells from yosys (cached), by name.
pub fn synth_cells(name: &str, dir: &std::path::Path) -> Result<synth::fpga::Cells, String> {
    sim::units::unit(name)?.rtl.synth_unit(dir, synth::fpga::Family::Ice40)
}

/// A unit placed on the smallest part it fits at that part's default clock target at `seeds` (each placement
/// cached); None where that part is an ECP5 and nextpnr-ecp5 is not installed.
pub fn place_cached(
    name: &str,
    dir: &std::path::Path,
    seeds: synth::fpga::Seeds,
) -> Result<Option<synth::fpga::SynthReport>, String> {
    let rtl = sim::units::unit(name)?.rtl;
    let (part, _, _) = rtl.choose(dir)?;
    if part.family == synth::fpga::Family::Ecp5 && synth::tools::nextpnr_ecp5().is_none() {
        Ok(None)
    } else {
        rtl.synth_and_place(dir, part, part.default_freq(), "", seeds).map(Some)
    }
}

/// The rtl block of `unit` at the swept setting `params`, or a one-line error naming the setting.
pub fn block(unit: &str, params: (u32, u32)) -> Result<&'static dyn RtlBlock, String> {
    sim::units::setting(unit, params)
        .map(|s| s.rtl)
        .ok_or_else(|| format!("`{unit}` has no swept setting {params:?} in the table of units"))
}
