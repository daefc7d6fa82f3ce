use std::fmt::Debug;

use crate::ast::VerilogLiteral;
use crate::bits::{Bit, Bits};
use crate::clock::Clock;
use crate::signed::Signed;
use crate::type_descriptor::{TypeDescriptor, TypeKind};

#[derive(Clone, PartialEq, Debug)]
pub enum VCDValue {
    Single(vcd::Value),
    Vector(Vec<vcd::Value>),
    String(String),
    Composite(Vec<Box<VCDValue>>),
}

impl From<bool> for VCDValue {
    fn from(x: bool) -> Self {
        if x {
            VCDValue::Single(vcd::Value::V1)
        } else {
            VCDValue::Single(vcd::Value::V0)
        }
    }
}

pub trait Synth: Default + Copy + PartialEq + Debug {
    const BITS: usize;
    fn descriptor() -> TypeDescriptor;
    fn vcd(self) -> VCDValue;
    fn verilog(self) -> VerilogLiteral;
    fn bits(self) -> usize {
        Self::BITS
    }
    /// bumprtl: the value as one word, bit i of the value in bit i of the word (`V1` a one, any other bit a zero),
    /// when `vcd` gives it as at most 64 bits; `None` otherwise. A probe reads it every clock: the default goes
    /// through `vcd`, which builds a vector a call; a bit vector answers without one.
    fn short_word(self) -> Option<u64> {
        short_word_of(&self.vcd())
    }
}

/// bumprtl: `Synth::short_word` from a VCD value: a single bit, or a vector of at most 64 bits, most significant
/// first.
pub fn short_word_of(v: &VCDValue) -> Option<u64> {
    match v {
        VCDValue::Single(b) => Some((*b == vcd::Value::V1) as u64),
        VCDValue::Vector(bits) if bits.len() <= 64 => {
            Some(bits.iter().fold(0u64, |acc, b| acc << 1 | (*b == vcd::Value::V1) as u64))
        }
        _ => None,
    }
}

impl<const N: usize> Synth for Bits<N> {
    const BITS: usize = N;

    fn descriptor() -> TypeDescriptor {
        TypeDescriptor {
            name: format!("Bits::<{}>", Self::BITS),
            kind: TypeKind::Bits(Self::BITS),
        }
    }

    fn vcd(self) -> VCDValue {
        self.into()
    }

    fn verilog(self) -> VerilogLiteral {
        self.into()
    }

    // bumprtl: the bits themselves, as `vcd` gives them
    fn short_word(self) -> Option<u64> {
        (N <= 64).then(|| self.to_u64())
    }
}

impl Synth for Bit {
    const BITS: usize = 1;

    fn descriptor() -> TypeDescriptor {
        TypeDescriptor {
            name: "Bit".to_string(),
            kind: TypeKind::Bits(1),
        }
    }

    fn vcd(self) -> VCDValue {
        if self {
            VCDValue::Single(vcd::Value::V1)
        } else {
            VCDValue::Single(vcd::Value::V0)
        }
    }

    fn verilog(self) -> VerilogLiteral {
        self.into()
    }

    // bumprtl: the bit itself, as `vcd` gives it
    fn short_word(self) -> Option<u64> {
        Some(self as u64)
    }
}

impl Synth for Clock {
    const BITS: usize = 1;

    fn descriptor() -> TypeDescriptor {
        TypeDescriptor {
            name: "clock".to_string(),
            kind: TypeKind::Bits(1),
        }
    }

    fn vcd(self) -> VCDValue {
        self.clk.into()
    }

    fn verilog(self) -> VerilogLiteral {
        self.clk.into()
    }
}

impl<const N: usize> Synth for Signed<N> {
    const BITS: usize = N;
    fn descriptor() -> TypeDescriptor {
        TypeDescriptor {
            name: format!("Signed::<{}>", Self::BITS),
            kind: TypeKind::Signed(Self::BITS),
        }
    }
    fn vcd(self) -> VCDValue {
        self.inner().vcd()
    }
    fn verilog(self) -> VerilogLiteral {
        self.inner().into()
    }
}
