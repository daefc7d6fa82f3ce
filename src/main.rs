//! `bumprtl`: the command line over the bumprtl crates. Every failure is one line on stderr and a non-zero exit.

mod accuracy;
mod cli;
mod demo;
mod fonts;
mod hardcases;
mod hardware;
mod minify;
mod output;
mod page;
mod palette_table;
mod progress;
mod prove;
mod quantize;
mod render;
mod report;
mod synth_figures;
mod unit_commands;
mod units;
mod widths;

fn main() {
    // a closed pipe (`bumprtl widths cart_pipeline | head`) ends the program quietly, as it does any Unix tool,
    // instead of a panic in the next print
    #[cfg(unix)]
    // SAFETY: restoring the default action of a signal, before any thread starts
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    if let Err(e) = cli::main() {
        eprintln!("bumprtl: {e}");
        std::process::exit(1);
    }
}
