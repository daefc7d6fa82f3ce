//! A unit by its name in the unit table: its model (`unit`), and its rtl block's type for code that needs it
//! (`with_unit!`); a unit's yosys cells and placement by name, for the
//! report.

/// Defines `with_unit!(name, U => body)`: run `body` with `U` bound to the rtl block of the unit called `name`,
/// for every unit of `vectors::unit_table!` (the `$` passed through lets this macro write one of its own).
macro_rules! define_with_unit {
    ([$d:tt] rtl { $($name:ident: $model:expr, $block:ty, [$($waiver:tt)*];)* } software { $($soft:ident),* }) => {
        macro_rules! with_unit {
            ($d unit:expr, $d u:ident => $d body:expr) => {
                match $d unit {
                    $(stringify!($name) => {
                        type $d u = $block;
                        $d body
                    })*
                    other => Err(format!("`{other}` has no rtl block")),
                }
            };
        }
    };
}
vectors::unit_table!(define_with_unit, $);

/// The unit called `name`, or a one-line error listing the units.
pub fn unit(name: &str) -> Result<&'static vectors::UnitModel, String> {
    if vectors::unit::SOFTWARE_ONLY.contains(&name) {
        return Err(format!(
            "`{name}` is software only (no rtl block, no vectors): its errors are in `bumprtl accuracy`"
        ));
    }
    vectors::unit::find(name).ok_or_else(|| {
        let names: Vec<&str> = vectors::UNITS.iter().map(|u| u.name).collect();
        format!("unknown unit `{name}`; the units are: {}", names.join(", "))
    })
}

/// A unit's iCE40 cells from yosys (cached), by name.
pub fn synth_cells(name: &str, dir: &std::path::Path) -> Result<synth::fpga::Cells, String> {
    with_unit!(name, U => synth::fpga::synth_unit::<U>(dir, synth::fpga::Family::Ice40))
}

/// A unit placed on the smallest part it fits at that part's default clock target (cached); None where that part
/// is an ECP5 and nextpnr-ecp5 is not installed.
pub fn place_cached(name: &str, dir: &std::path::Path) -> Result<Option<synth::fpga::SynthReport>, String> {
    with_unit!(name, U => {
        let (part, _, _) = synth::fpga::choose::<U>(dir)?;
        if part.family == synth::fpga::Family::Ecp5 && synth::tools::nextpnr_ecp5().is_none() {
            Ok(None)
        } else {
            synth::fpga::synth_and_place_cached::<U>(dir, part, part.default_freq()).map(Some)
        }
    })
}
