//! `bumprtl`: the command line over the bumprtl crates. Every failure is one line on stderr and a non-zero exit.

mod cli;
mod demo;
mod hardware;
mod palette_table;
mod quantize;
mod report;

fn main() {
    if let Err(e) = cli::main() {
        eprintln!("bumprtl: {e}");
        std::process::exit(1);
    }
}
