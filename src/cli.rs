use clap::{Parser, Subcommand};
use std::path::PathBuf;

#[derive(Parser)]
#[command(name = "bumprtl", version, about = "Bump-mapping shading hardware: model, rtl, vectors, waveforms, Verilog, synthesis")]
struct Cli {
    #[command(subcommand)]
    cmd: Cmd,
}

#[derive(Subcommand)]
enum Cmd {
    /// Write a unit's test vectors as CSV (header of port names, decimal values)
    Vectors {
        unit: String,
        /// every input vector (units whose input space is at most 2^20)
        #[arg(long)]
        exhaustive: bool,
        /// random vectors after the hard cases
        #[arg(long, default_value_t = 1000)]
        count: usize,
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// output file (default: standard output)
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

pub fn unit(name: &str) -> Result<&'static vectors::UnitModel, String> {
    vectors::unit::find(name).ok_or_else(|| {
        let names: Vec<&str> = vectors::UNITS.iter().map(|u| u.name).collect();
        format!("unknown unit `{name}`; the units are: {}", names.join(", "))
    })
}

pub fn main() -> Result<(), String> {
    let cli = Cli::parse();
    match cli.cmd {
        Cmd::Vectors { unit: name, exhaustive, count, seed, out } => {
            let u = unit(&name)?;
            let inputs = vectors::unit::generate(u, exhaustive, count, seed)?;
            let command = if exhaustive {
                format!("bumprtl vectors {name} --exhaustive")
            } else {
                format!("bumprtl vectors {name} --count {count} --seed {seed}")
            };
            let text = vectors::csv::render(u, &inputs, &command);
            match out {
                Some(p) => synth::export::write_atomic(&p, text.as_bytes())?,
                None => print!("{text}"),
            }
        }
    }
    Ok(())
}
