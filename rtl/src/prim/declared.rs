//! What the compiler records of each block's declaration, for the width report: rust-hdl keeps only widths
//! (`Sq1_10` and `Uq2_10` are both `Bits<12>` to it), while the project's fixed-point formats live in the type names
//! the source writes (`rtl::prim::q`). Every block is declared through a macro (`crate::block!`, or `crate::stream_block!`
//! for a unit) that writes the struct once and, beside it, an implementation of `Declared`: the struct's name, its
//! generic parameters with their defaults, and each field's name and type as written (`stringify!`), together with
//! the declaration of that field's own type. The compiler thus walks from a top block to every block it holds,
//! generic arguments and all, and no list of blocks or reading of source text is needed.
//!
//! A field's type text is the source's (`Signal<In, T>`, `Delay<Sq7_2, LIGHT_DELAY>`): the reader substitutes the
//! enclosing block's generic arguments along a path. A signal or constant also carries the width the compiler gives
//! it (`Synth::BITS`), exact whatever names its type was written with (`Bits<ANGLE_BITS>`).

use crate::prim::sp_ram::SpRam;
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::{RAM, ROM};

/// A type as the compiler knows it: a block with its declaration, one signal or constant, or an array of either.
#[derive(Clone, Debug)]
pub enum Declaration {
    Block(Block),
    /// a `Signal` or a `Constant` of this many bits
    Wire {
        bits: usize,
    },
    /// `[T; N]`: the element's declaration
    Array(Box<Declaration>),
}

/// A block's struct as its source declares it.
#[derive(Clone, Debug)]
pub struct Block {
    /// the struct's name (`Delay`)
    pub name: &'static str,
    /// its generic parameters in order (`T`, `N`), each with its default as written (`const D: usize = 0`)
    pub generics: Vec<Generic>,
    pub fields: Vec<Field>,
    /// one of rust-hdl's own blocks (`DFF`, `ROM`, `RAM`), declared here as rust-hdl 0.46 declares them
    pub library: bool,
}

#[derive(Clone, Debug)]
pub struct Generic {
    pub name: &'static str,
    pub default: Option<&'static str>,
}

/// One field: its name, its type as the source writes it, and that type's declaration.
#[derive(Clone, Debug)]
pub struct Field {
    pub name: &'static str,
    pub ty: &'static str,
    pub decl: Declaration,
}

impl Field {
    pub fn of<T: Declared>(name: &'static str, ty: &'static str) -> Field {
        Field { name, ty, decl: T::declaration() }
    }
}

/// Every type a block holds: blocks (through `crate::block!` or `crate::stream_block!`), rust-hdl's signals,
/// constants, registers and memories, and arrays of them.
pub trait Declared {
    fn declaration() -> Declaration;
}

impl<D: Direction, T: Synth> Declared for Signal<D, T> {
    fn declaration() -> Declaration {
        Declaration::Wire { bits: T::BITS }
    }
}

impl<T: Synth> Declared for Constant<T> {
    fn declaration() -> Declaration {
        Declaration::Wire { bits: T::BITS }
    }
}

impl<T: Declared, const N: usize> Declared for [T; N] {
    fn declaration() -> Declaration {
        Declaration::Array(Box::new(T::declaration()))
    }
}

/// rust-hdl's own blocks, their signals as rust-hdl 0.46 declares them (`rust-hdl-widgets`: `dff.rs`,
/// `ramrom/rom.rs`, `ramrom/ram.rs`), and `SpRam`, a memory with its own Verilog as those are; the width tests hold every signal of every unit to a declared format, so a
/// field missing here fails them.
macro_rules! library {
    ($t:ident < $($p:ident),* > where [$($bounds:tt)*] { $($f:ident : $ft:ty),* $(,)? }) => {
        impl<$($bounds)*> Declared for $t<$($p),*> {
            fn declaration() -> Declaration {
                Declaration::Block(Block {
                    name: stringify!($t),
                    generics: vec![$(Generic { name: stringify!($p), default: None }),*],
                    fields: vec![$(Field::of::<$ft>(stringify!($f), stringify!($ft))),*],
                    library: true,
                })
            }
        }
    };
}

library!(DFF<T> where [T: Synth] { d: Signal<In, T>, q: Signal<Out, T>, clock: Signal<In, Clock> });
library!(ROM<D, N> where [D: Synth, const N: usize] { address: Signal<In, Bits<N>>, data: Signal<Out, D> });
library!(SpRam<D, N> where [D: Synth, const N: usize] {
    address: Signal<In, Bits<N>>,
    clock: Signal<In, Clock>,
    read_data: Signal<Out, D>,
    write_data: Signal<In, D>,
    write_enable: Signal<In, bool>,
});
library!(RAM<D, N> where [D: Synth, const N: usize] {
    read_address: Signal<In, Bits<N>>,
    read_clock: Signal<In, Clock>,
    read_data: Signal<Out, D>,
    write_address: Signal<In, Bits<N>>,
    write_clock: Signal<In, Clock>,
    write_data: Signal<In, D>,
    write_enable: Signal<In, bool>,
});

/// Declares a block once: writes the struct with `#[derive(LogicBlock)]` and its attributes, and implements
/// `Declared` from the same field list. Generic parameters are `const` ones (with literal defaults), or one type
/// parameter with a bound followed by `const` ones.
/// ```ignore
/// crate::block! {
///     /// A delay line.
///     pub struct Delay<T: Synth, const N: usize> {
///         pub clock: Signal<In, Clock>,
///         pub d: Signal<In, T>,
///         pub q: Signal<Out, T>,
///         line: [DFF<T>; N],
///     }
/// }
/// ```
#[macro_export]
macro_rules! block {
    (
        $(#[$attr:meta])*
        pub struct $t:ident $(< $(const $g:ident : $gt:ty $(= $gd:literal)?),* >)? {
            $($(#[$fa:meta])* $fv:vis $f:ident : $ft:ty),* $(,)?
        }
    ) => {
        #[derive(LogicBlock)]
        $(#[$attr])*
        pub struct $t $(< $(const $g: $gt $(= $gd)?),* >)? {
            $($(#[$fa])* $fv $f: $ft,)*
        }

        impl $(< $(const $g: $gt),* >)? $crate::prim::declared::Declared for $t $(< $($g),* >)? {
            fn declaration() -> $crate::prim::declared::Declaration {
                $crate::prim::declared::Declaration::Block($crate::prim::declared::Block {
                    name: stringify!($t),
                    generics: vec![$($($crate::prim::declared::Generic {
                        name: stringify!($g),
                        default: [$(stringify!($gd))?].first().copied(),
                    }),*)?],
                    fields: vec![$($crate::prim::declared::Field::of::<$ft>(stringify!($f), stringify!($ft))),*],
                    library: false,
                })
            }
        }
    };
    (
        $(#[$attr:meta])*
        pub struct $t:ident < $p:ident : $pb:path $(, const $g:ident : $gt:ty)* > {
            $($(#[$fa:meta])* $fv:vis $f:ident : $ft:ty),* $(,)?
        }
    ) => {
        #[derive(LogicBlock)]
        $(#[$attr])*
        pub struct $t < $p: $pb $(, const $g: $gt)* > {
            $($(#[$fa])* $fv $f: $ft,)*
        }

        impl < $p: $pb $(, const $g: $gt)* > $crate::prim::declared::Declared for $t < $p $(, $g)* > {
            fn declaration() -> $crate::prim::declared::Declaration {
                $crate::prim::declared::Declaration::Block($crate::prim::declared::Block {
                    name: stringify!($t),
                    generics: vec![
                        $crate::prim::declared::Generic { name: stringify!($p), default: None },
                        $($crate::prim::declared::Generic { name: stringify!($g), default: None },)*
                    ],
                    fields: vec![$($crate::prim::declared::Field::of::<$ft>(stringify!($f), stringify!($ft))),*],
                    library: false,
                })
            }
        }
    };
}
