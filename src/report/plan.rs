//! `--plan`: the points as commands for GNU parallel, ssh or a Slurm array.

use super::points::{points, Point};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// `bumprtl report --plan FILE`: one command per point in FILE (for `parallel < FILE`, or over ssh with
/// `parallel -S`), the merge step in FILE.merge, and a Slurm job array in FILE.slurm that runs line
/// `$SLURM_ARRAY_TASK_ID` of FILE.
pub fn plan(
    scenes: &[String],
    file: &Path,
    out: &Path,
    budgets: &[f64],
    place: Option<u32>,
    only: Option<&str>,
) -> Result<(), String> {
    let pts: Vec<Point> = points(scenes)?.into_iter().filter(|p| only.is_none_or(|o| p.id.contains(o))).collect();
    let exe = std::env::current_exe().map_err(|e| format!("cannot name this program: {e}"))?;
    let q = |p: &Path| shell_quote(&p.to_string_lossy());
    let common = {
        let mut c = String::new();
        for s in scenes {
            let _ = write!(c, " --scene {}", shell_quote(s));
        }
        let _ = write!(c, " --out {}", q(out));
        // the points synthesise with this process's toolchain, as the merge names it
        let _ = write!(c, " --toolchain {}", synth::tools::toolchain().name());
        c
    };
    let mut lines = String::new();
    for p in &pts {
        let _ = writeln!(
            lines,
            "{} report{common} --point {}{}",
            q(&exe),
            shell_quote(&p.id),
            match place {
                Some(n) => format!(" --seeds {n}"),
                None => " --no-place".into(),
            }
        );
    }
    let mut merge = format!("{} report{common} --merge", q(&exe));
    if let Some(o) = only {
        let _ = write!(merge, " --only {}", shell_quote(o));
    }
    for b in budgets {
        let _ = write!(merge, " --budget {b}");
    }
    merge.push('\n');
    let with = |ext: &str| PathBuf::from(format!("{}.{ext}", file.display()));
    let slurm = format!(
        "#!/usr/bin/env bash\n#SBATCH --job-name=bumprtl-report\n#SBATCH --array=1-{}\n# then, once the array is done: bash {}\nsed -n \"${{SLURM_ARRAY_TASK_ID}}p\" {} | bash\n",
        pts.len(), q(&with("merge")), q(file)
    );
    synth::export::write_atomic(file, lines.as_bytes())?;
    synth::export::write_atomic(&with("merge"), merge.as_bytes())?;
    synth::export::write_atomic(&with("slurm"), slurm.as_bytes())?;
    println!(
        "{} points: {} (parallel < {0}), then {}; a Slurm array: sbatch {}",
        pts.len(),
        file.display(),
        with("merge").display(),
        with("slurm").display()
    );
    Ok(())
}

pub(super) fn shell_quote(s: &str) -> String {
    if !s.is_empty() && s.chars().all(|c| c.is_ascii_alphanumeric() || "-_./=:,+".contains(c)) {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', "'\\''"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plan_arguments_are_quoted_for_the_shell() {
        assert_eq!(shell_quote("scenes/up5k.toml"), "scenes/up5k.toml");
        assert_eq!(shell_quote("my scene's.toml"), "'my scene'\\''s.toml'");
    }
}
