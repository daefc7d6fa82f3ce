//! `SpRam`: a single-port block RAM, one address a clock for the read and the write, the form of the iCE40 UP5K's
//! SPRAM (SB_SPRAM256KA, 16,384 × 16 bits) and of any block RAM's port in its "no change" mode.
//!
//! Every clock edge either writes `write_data` at `address` (`write_enable` high), while `read_data` keeps the
//! word it last read, or reads the word at `address` into `read_data` (a read sees every write of the clocks
//! before it). A RAM with two address ports (rust-hdl's `RAM`) that reads on a writing clock cannot be mapped to a
//! single-port block: yosys finds no mapping for its read-before-write. `synth_ice40 -spram` maps this one to
//! SPRAM, `synth_ice40` to SB_RAM40_4K, `synth_ecp5` to DP16KD. Until a word is written it reads zero in rust-hdl,
//! the FPGA's block RAM (zero at configuration) and Verilator; Icarus reads x.

use rust_hdl::prelude::*;
use std::collections::BTreeMap;

#[derive(LogicBlock, Default)]
pub struct SpRam<D: Synth, const N: usize> {
    pub address: Signal<In, Bits<N>>,
    pub clock: Signal<In, Clock>,
    pub read_data: Signal<Out, D>,
    pub write_data: Signal<In, D>,
    pub write_enable: Signal<In, bool>,
    _sim: BTreeMap<Bits<N>, D>,
}

impl<D: Synth, const N: usize> Logic for SpRam<D, N> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            if self.write_enable.val() {
                self._sim.insert(self.address.val(), self.write_data.val());
            } else {
                // the word as written (D), an unwritten one zero
                let word = *self._sim.get(&self.address.val()).unwrap_or(&D::default());
                self.read_data.next = word; // D, as stored
            }
        }
    }

    fn connect(&mut self) {
        self.read_data.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "\
reg[{d}:0] mem[{last}:0];

always @(posedge clock) begin
   if (write_enable) begin
      mem[address] <= write_data;
   end else begin
      read_data <= mem[address];
   end
end
",
            d = D::BITS - 1,
            last = (1usize << N) - 1,
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "sp_ram".into(),
            clock: "clock".into(),
            inputs: vec!["address".into(), "write_data".into(), "write_enable".into()],
            outputs: vec!["read_data".into()],
        }]
    }
}
