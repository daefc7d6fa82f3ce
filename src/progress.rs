//! Progress for the steps a command takes: on a terminal (standard error) a bar, or a spinner where the step has no
//! count; otherwise, in a CI log or through `| tee`, one line a step of a second or more when it ends: what, how
//! many, how long (every step with `BUMPRTL_PROGRESS=every`).

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

/// The shortest step that says a line off a terminal, seconds: 1, or 0 with `BUMPRTL_PROGRESS=every` (a log of
/// every step, whatever its length; the tests read the lines this way).
fn shortest_line() -> f64 {
    match std::env::var("BUMPRTL_PROGRESS") {
        Ok(v) if v == "every" => 0.0,
        _ => 1.0,
    }
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
        if !drawn() && self.start.elapsed().as_secs_f64() >= shortest_line() {
            eprintln!("{}: {how_many}, {:.1} s", self.what, self.start.elapsed().as_secs_f64());
        }
    }
}

/// A step left unfinished (an error returned through it) clears its bar and says no line, as `failed` does.
impl Drop for Step {
    fn drop(&mut self) {
        if !self.bar.is_finished() {
            self.bar.finish_and_clear();
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

/// Steps told one after another by a callee that only says what it begins (`say("miter a = b …")`): each step ends
/// when the next begins, and the last at `end`.
#[derive(Default)]
pub struct Chain(std::cell::RefCell<Option<Step>>);

impl Chain {
    /// The step under way ends (`how_many` its line's count) and `what` begins.
    pub fn next(&self, what: &str, how_many: &str) {
        if let Some(done) = self.0.borrow_mut().replace(Step::new(what.trim_end_matches(" …"), None)) {
            done.done(how_many);
        }
    }

    /// The last step ends: its line where it succeeded, none where the command fails with it.
    pub fn end<T, E>(self, how_many: &str, r: &Result<T, E>) {
        if let Some(s) = self.0.into_inner() {
            match r {
                Ok(_) => s.done(how_many),
                Err(_) => s.failed(),
            }
        }
    }
}
