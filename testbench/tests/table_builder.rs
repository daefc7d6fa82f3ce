//! table_builder: the colour table's entries from the shared normaliser, dot3 and gloss blocks, random vectors
//! through rust-hdl and Verilator, hard cases (a zero-length normal, normals on and below the horizon, the light on
//! and below it, the index's ends).
use rtl::table_builder::TableBuilder;
use testbench::{random_vs_model, random_vs_model_verilator, rust_hdl, unit_tests, Bubbles};
use vectors::table_builder::MODEL;

unit_tests!(table_builder, TableBuilder, MODEL);

#[test]
fn table_builder_random_vs_model() {
    random_vs_model::<TableBuilder>(&MODEL, 20, 1_000);
}

#[test]
fn table_builder_random_vs_model_verilator() {
    random_vs_model_verilator::<TableBuilder>(&MODEL, 100_000, 29);
}

#[test]
fn table_builder_hard_cases() {
    rust_hdl::<TableBuilder>(&MODEL, &(MODEL.hard_cases)(), Bubbles::BackToBack).assert_clean("hard cases");
}
