//! The demo's hardware-cost figures: each pipeline on the iCE40 UP5K and on the ECP5-45F, cached beside the
//! demo's output (the first run places every pipeline; later runs read the figures while the Verilog is unchanged).

use indicatif::{MultiProgress, ProgressBar};
use synth::fpga::{Fit, Part, ECP5_45F, UP5K};

/// The parts the demo reports, smallest first.
pub const DEMO_PARTS: [Part; 2] = [UP5K, ECP5_45F];

/// A job for one of the demo's synthesis threads.
pub type Job<'a> = Box<dyn FnOnce(&dyn Fn(String)) -> Result<Vec<(Part, Fit)>, String> + Send + 'a>;

/// Run the jobs on two threads (the machine's two cores), each with its own progress line; results in job order.
/// The jobs are taken from one queue in order, each by whichever thread is free: give the longest first.
pub fn run_jobs(jobs: Vec<Job<'_>>) -> Result<Vec<Vec<(Part, Fit)>>, String> {
    let multi = MultiProgress::new();
    let n = jobs.len();
    let queue = std::sync::Mutex::new(jobs.into_iter().enumerate().collect::<std::collections::VecDeque<_>>());
    let mut results: Vec<Option<Result<Vec<(Part, Fit)>, String>>> = (0..n).map(|_| None).collect();
    std::thread::scope(|s| {
        let handles: Vec<_> = (0..2)
            .map(|_| {
                let bar = multi.add(ProgressBar::new_spinner());
                bar.enable_steady_tick(std::time::Duration::from_millis(200));
                let queue = &queue;
                s.spawn(move || {
                    let t = std::time::Instant::now();
                    let say = |m: String| bar.set_message(format!("{m} [{:.0} s]", t.elapsed().as_secs_f64()));
                    let mut out = Vec::new();
                    loop {
                        let next = queue.lock().unwrap_or_else(|e| e.into_inner()).pop_front();
                        let Some((k, job)) = next else { break };
                        out.push((k, job(&say)));
                    }
                    bar.finish_and_clear();
                    out
                })
            })
            .collect();
        for h in handles {
            for (k, r) in h.join().expect("a synthesis thread panicked") {
                results[k] = Some(r);
            }
        }
    });
    results.into_iter().map(|r| r.expect("every job ran")).collect()
}
