//! Progress for the steps a command takes: on a terminal (standard error) a bar, or a spinner where the step has no
//! count; otherwise, in a CI log or through `| tee`, one line a step of a second or more when it ends: what, how
//! many, how long.

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::time::Instant;

/// Every bar and spinner of the process, drawn together (two drawn apart overwrite each other's lines).
pub fn bars() -> &'static indicatif::MultiProgress {
    static BARS: std::sync::OnceLock<indicatif::MultiProgress> = std::sync::OnceLock::new();
    BARS.get_or_init(indicatif::MultiProgress::new)
}

/// Whether progress is drawn (standard error is a terminal) rather than written a line a step.
pub fn drawn() -> bool {
    std::io::stderr().is_terminal()
}

/// One step under way.
pub struct Step {
    what: String,
    start: Instant,
    bar: ProgressBar,
}

impl Step {
    /// A step of `len` items (a bar), or of unknown length (a spinner).
    pub fn new(what: &str, len: Option<u64>) -> Step {
        let bar = match len {
            Some(n) => {
                let b = ProgressBar::new(n);
                b.set_style(
                    ProgressStyle::with_template("{msg:<40} [{bar:30}] {pos}/{len} {eta}")
                        .expect("a template")
                        .progress_chars("=> "),
                );
                b
            }
            None => {
                let b = ProgressBar::new_spinner();
                b.enable_steady_tick(std::time::Duration::from_millis(200));
                b
            }
        };
        let bar = bars().add(bar);
        bar.set_message(what.to_string());
        Step { what: what.to_string(), start: Instant::now(), bar }
    }

    pub fn tick(&self, k: u64) {
        self.bar.set_position(k);
    }

    /// A step that failed: the bar cleared and no line (the error is the command's one line).
    pub fn failed(self) {
        self.bar.finish_and_clear();
    }

    /// The step's end: the bar cleared, or, for a step that took a second or more, its line written (`how_many`:
    /// "65,536 px", "2 parts"). A quick step says nothing: a command refused after it still says one line.
    pub fn done(self, how_many: &str) {
        self.bar.finish_and_clear();
        if !drawn() && self.start.elapsed().as_secs_f64() >= 1.0 {
            eprintln!("{}: {how_many}, {:.1} s", self.what, self.start.elapsed().as_secs_f64());
        }
    }
}

/// `f` run as one step: its count from what it returns, or, where `how_many` gives none (an error), no line.
pub fn step<T>(what: &str, how_many: impl Fn(&T) -> Option<String>, f: impl FnOnce() -> T) -> T {
    let s = Step::new(what, None);
    let t = f();
    match how_many(&t) {
        Some(n) => s.done(&n),
        None => s.failed(),
    }
    t
}
