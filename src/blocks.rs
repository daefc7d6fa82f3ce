//! The rtl blocks of the swept table sizes, each as the function that has yosys count its cells: the sine/cosine
//! units' LUT sizes (for `accuracy --lut-cost`, `widths --budget` and the report's table-size points).

pub type SynthFn = fn(&std::path::Path, synth::fpga::Family) -> Result<synth::fpga::Cells, String>;

macro_rules! sincos_blocks {
    ($(($tb:literal, $w:literal)),* $(,)?) => {
        &[$(($tb, $w, synth::fpga::synth_unit::<rtl::sincos::SinCos<$tb, $w>> as SynthFn)),*]
    };
}

macro_rules! cos_sign_blocks {
    ($(($tb:literal, $w:literal)),* $(,)?) => {
        &[$(($tb, $w, synth::fpga::synth_unit::<rtl::cos_sign::CosSign<$tb, $w>> as SynthFn)),*]
    };
}

/// The rtl block of every size of each LUT-size table, from the same list as the model's `LUT_SIZES`.
pub const SINCOS_BLOCKS: &[(u32, u32, SynthFn)] = vectors::sincos_lut_sizes!(sincos_blocks);
pub const COS_SIGN_BLOCKS: &[(u32, u32, SynthFn)] = vectors::cos_sign_lut_sizes!(cos_sign_blocks);
