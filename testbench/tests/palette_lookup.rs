//! palette_lookup: the two-table colour RAM, against the model's stream: golden vectors three ways, random streams
//! through rust-hdl and (after the hard cases have written the entries they read) Verilator, and the other index
//! widths a palette of 2, 16, 4096 and 16,384 normals needs, three ways.
use rtl::palette_lookup::PaletteLookup;
use testbench::{external, random_vs_model, unit_tests, Bubbles};
use vectors::palette_lookup::{self as pl, MODEL};
use vectors::{Port, UnitModel};

unit_tests!(palette_lookup, PaletteLookup<8, 9>, MODEL);

#[test]
fn palette_lookup_random_vs_model() {
    random_vs_model::<PaletteLookup<8, 9>>(&MODEL, 30, 2_000);
}

#[test]
fn palette_lookup_random_after_the_hard_cases_verilator() {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(19);
    let mut inputs = (MODEL.hard_cases)();
    inputs.extend((0..50_000).map(|_| (MODEL.random)(&mut rng)));
    external::<PaletteLookup<8, 9>>(
        synth::cosim::Simulator::Verilator,
        &MODEL,
        &inputs,
        Bubbles::Random { one_in: 3, seed: 19 },
    )
    .assert_clean("verilator, random");
}

fn exact_sized<const B: u32>(v: &[i64]) -> Vec<i64> {
    vectors::unit::run_machine::<pl::Tables<B>>(&[v.to_vec()]).remove(0)
}
fn random_sized<const B: u32>(rng: &mut dyn rand::RngCore) -> Vec<i64> {
    pl::random_with(rng, B)
}
fn hard_sized<const B: u32>() -> Vec<Vec<i64>> {
    pl::hard_cases_with(B)
}

macro_rules! sized {
    ($name:ident, $b:literal, $ins:ident) => {
        const $ins: &[Port] =
            &[Port::u("frame", 1), Port::u("idx", $b), Port::u("we", 1), Port::u("waddr", $b), Port::u("wdata", 32)];
        static $name: UnitModel = UnitModel::new(
            "palette_lookup",
            ($ins, pl::OUTPUTS),
            exact_sized::<$b>,
            random_sized::<$b>,
            hard_sized::<$b>,
        )
        .with_stream::<pl::Tables<$b>>();
    };
}

sized!(M1, 1, IN1);
sized!(M4, 4, IN4);
sized!(M12, 12, IN12);
sized!(M14, 14, IN14);

fn stream(m: &UnitModel) -> Vec<Vec<i64>> {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(23);
    let mut v = (m.hard_cases)();
    v.extend((0..3_000).map(|_| (m.random)(&mut rng)));
    v
}

#[test]
fn other_index_widths_three_ways() {
    testbench::three_ways::<PaletteLookup<1, 2>>(&M1, &stream(&M1), "palette_lookup_a1");
    testbench::three_ways::<PaletteLookup<4, 5>>(&M4, &stream(&M4), "palette_lookup_a4");
    testbench::three_ways::<PaletteLookup<12, 13>>(&M12, &stream(&M12), "palette_lookup_a12");
    testbench::three_ways::<PaletteLookup<14, 15>>(&M14, &stream(&M14), "palette_lookup_a14");
}
