//! `Delay`: N DFFs in a chain, to keep side-band values beside the pipeline stages they skip.

use rust_hdl::prelude::*;

crate::block! {
    pub struct Delay<T: Synth, const N: usize> {
        pub clock: Signal<In, Clock>,
        pub d: Signal<In, T>,
        pub q: Signal<Out, T>,
        line: [DFF<T>; N],
    }
}

impl<T: Synth, const N: usize> Default for Delay<T, N> {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            d: Default::default(),
            q: Default::default(),
            line: std::array::from_fn(|_| DFF::default()),
        }
    }
}

impl<T: Synth, const N: usize> Logic for Delay<T, N> {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..N {
            self.line[i].clock.next = self.clock.val();
        }
        self.line[0].d.next = self.d.val();
        for i in 1..N {
            self.line[i].d.next = self.line[i - 1].q.val();
        }
        // the last element, written as a loop: rust-hdl's Verilog export cannot index with `N - 1`
        // (it evaluates indices knowing only loop variables); the last assignment wins in both
        self.q.next = self.line[0].q.val();
        for i in 1..N {
            self.q.next = self.line[i].q.val();
        }
    }
}
