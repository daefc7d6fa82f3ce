//! The demo's hardware-cost figures: each pipeline on the iCE40 UP5K and on the ECP5-45F, cached beside the
//! demo's output (the first run places every pipeline; later runs read the figures while the Verilog is unchanged).

use indicatif::{MultiProgress, ProgressBar};
use synth::fpga::{Fit, Part, ECP5_45F, UP5K};

/// The parts the demo reports, smallest first.
pub const DEMO_PARTS: [Part; 2] = [UP5K, ECP5_45F];

/// The demo's placements: one, at seed 1, on a cold cache (its first run must stay short), and the median of every
/// other of seeds 1 … 5 the cache holds (`synth` and `report` place all five).
pub const DEMO_SEEDS: synth::fpga::Seeds = synth::fpga::Seeds { n: 5, least: 1 };

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
                // a job builds its block on this thread's stack (rust-hdl's `Default`): room for the largest
                let thread = std::thread::Builder::new().stack_size(16 << 20);
                thread
                    .spawn_scoped(s, move || {
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
                    .expect("a synthesis thread")
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

/// A unit with a mode input, synthesised as a design that needs only one mode would hold it (the mode tied, the other
/// mode's outputs left open), beside the unit with both: what sharing one set of blocks between the modes saves.
/// `texture_filter`'s colour and height modes share its four bilinear units.
const MODE_VIEWS: &[(&str, &[(&str, &[(&str, u64)], &[&str])])] = &[(
    "texture_filter",
    &[
        ("colour", &[("mode", 0)], &["out_r", "out_g", "out_b", "out_a"]),
        ("height", &[("mode", 1)], &["norm_x", "norm_y", "norm_z"]),
        ("both", &[], &["out_r", "out_g", "out_b", "out_a", "norm_x", "norm_y", "norm_z"]),
    ],
)];

/// The mode views of a unit, if it has any: yosys figures of each, printed under the unit's report.
pub type TiedSynth<'a> =
    &'a dyn Fn(&str, &[(&str, u64)], &[&str]) -> Result<(synth::fpga::Cells, synth::fpga::Blocks), String>;

pub fn mode_views(unit: &str, family: synth::fpga::Family, synth_tied: TiedSynth) -> Result<(), String> {
    let Some((_, views)) = MODE_VIEWS.iter().find(|(u, _)| *u == unit) else { return Ok(()) };
    let [lut, ff, dsp, bram, _] = family.cells();
    println!("  each mode alone (the mode tied, the other mode's outputs open) and both, yosys alone, operand copies not kept:");
    let mut sum = synth::fpga::Cells::default();
    for (tag, ties, keep) in views.iter() {
        let (c, b) = synth_tied(tag, ties, keep)?;
        println!("    {tag:<8} {lut} {:>6}  {ff} {:>6}  {dsp} {:>3}  {bram} {:>3}", c.lut4, c.ff, c.dsp, c.bram);
        crate::synth_figures::blocks_line(&b, family, 13);
        if !ties.is_empty() {
            sum = synth::fpga::Cells {
                lut4: sum.lut4 + c.lut4,
                ff: sum.ff + c.ff,
                dsp: sum.dsp + c.dsp,
                bram: sum.bram + c.bram,
                carry: sum.carry + c.carry,
                soft: sum.soft + c.soft,
                spram: sum.spram + c.spram,
            };
        }
    }
    println!(
        "    {:<8} {lut} {:>6}  {ff} {:>6}  {dsp} {:>3}  {bram} {:>3}   (one block per mode)",
        "sum", sum.lut4, sum.ff, sum.dsp, sum.bram
    );
    Ok(())
}
