//! The demo's hardware-cost figures, run beside its rendering: the scene's own pipeline placed on the ECP5-45F, every
//! pipeline's cells from yosys alone there; cached (the first run synthesises, later runs read the figures while the
//! Verilog is unchanged).

use indicatif::ProgressBar;
use synth::fpga::{Fit, Part};

/// The demo's placements: one, at seed 1, on a cold cache (its first run must stay short), and the median of every
/// other of seeds 1 … 5 the cache holds (`synth` and `report` place all five).
pub const DEMO_SEEDS: synth::fpga::Seeds = synth::fpga::Seeds { n: 5, least: 1 };

/// What one of the demo's synthesis jobs gives: a pipeline placed on parts, its cells from yosys alone, or why it
/// gave neither (the demo goes on without its figures).
pub enum Cost {
    Placed(Vec<(Part, Fit)>),
    Cells(synth::fpga::Cells),
    Failed(String),
}

/// A job for one of the demo's synthesis threads.
pub type Job<'a> = Box<dyn FnOnce(&dyn Fn(String)) -> Result<Cost, String> + Send + 'a>;

/// Synthesis jobs run beside other work, on two threads (the machine's two cores) at the lowest priority (nice 19,
/// which the tools they start inherit): the work beside them, whose speed the demo reports, keeps its cores, and the
/// synthesis takes what it leaves. The jobs are taken from one queue in order, each by whichever thread is free:
/// give the longest first. Each thread shows a progress line on a terminal, and a line a job otherwise.
pub struct Pool {
    queue: std::sync::Arc<std::sync::Mutex<std::collections::VecDeque<(usize, (String, Job<'static>))>>>,
    threads: Vec<std::thread::JoinHandle<Vec<(usize, Result<Cost, String>)>>>,
    n: usize,
}

impl Pool {
    /// The jobs, named, taken by two threads.
    pub fn start(jobs: Vec<(String, Job<'static>)>) -> Pool {
        let n = jobs.len();
        let queue = std::sync::Arc::new(std::sync::Mutex::new(jobs.into_iter().enumerate().collect()));
        let threads = (0..2)
            .map(|_| {
                let bar = crate::progress::bars().add(ProgressBar::new_spinner());
                bar.enable_steady_tick(std::time::Duration::from_millis(200));
                let queue: std::sync::Arc<std::sync::Mutex<std::collections::VecDeque<_>>> =
                    std::sync::Arc::clone(&queue);
                // a job builds its block on this thread's stack (rust-hdl's `Default`): room for the largest
                std::thread::Builder::new()
                    .stack_size(16 << 20)
                    .spawn(move || {
                        // this thread's nice value (Linux keeps one a thread), inherited by the tools it starts; a
                        // machine that refuses it runs the jobs at the usual priority
                        // SAFETY: setpriority and gettid read and write no memory of this process
                        unsafe {
                            libc::setpriority(libc::PRIO_PROCESS, libc::gettid() as libc::id_t, 19);
                        }
                        let t = std::time::Instant::now();
                        let say = |m: String| bar.set_message(format!("{m} [{:.0} s]", t.elapsed().as_secs_f64()));
                        let mut out = Vec::new();
                        loop {
                            let next = queue.lock().unwrap_or_else(|e| e.into_inner()).pop_front();
                            let Some((k, (name, job))) = next else { break };
                            let t = std::time::Instant::now();
                            let r = job(&say);
                            if !crate::progress::drawn() {
                                let what = match &r {
                                    Ok(Cost::Placed(p)) => {
                                        let parts: Vec<&str> = p.iter().map(|x| x.0.name).collect();
                                        format!("placed on {}", parts.join(", "))
                                    }
                                    Ok(Cost::Cells(_)) => "yosys alone".into(),
                                    Ok(Cost::Failed(e)) | Err(e) => format!("failed: {e}"),
                                };
                                eprintln!("synthesis, {name}: {what}, {:.1} s", t.elapsed().as_secs_f64());
                            }
                            out.push((k, r));
                        }
                        bar.finish_and_clear();
                        out
                    })
                    .expect("a synthesis thread")
            })
            .collect();
        Pool { queue, threads, n }
    }

    /// No more jobs taken: those under way finish, the rest are dropped (the work they were for failed).
    pub fn cancel(&self) {
        self.queue.lock().unwrap_or_else(|e| e.into_inner()).clear();
    }

    /// Every job's result, in job order: a job that failed, or was cancelled before it ran, as `Cost::Failed`.
    pub fn join(mut self) -> Vec<Cost> {
        let mut results: Vec<Cost> = (0..self.n).map(|_| Cost::Failed("not run (cancelled)".into())).collect();
        for h in std::mem::take(&mut self.threads) {
            for (k, r) in h.join().expect("a synthesis thread panicked") {
                results[k] = r.unwrap_or_else(Cost::Failed);
            }
        }
        results
    }
}

/// A pool dropped on an error path takes no more jobs and waits for those under way (their tools are not left
/// running behind the program).
impl Drop for Pool {
    fn drop(&mut self) {
        self.cancel();
        for h in std::mem::take(&mut self.threads) {
            let _ = h.join();
        }
    }
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
