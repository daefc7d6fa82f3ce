//! Finding and running the external tools, with one-line errors that say which tool failed and why.

use std::path::Path;
use std::process::{Command, Output};

/// The tools of `names` that are not on the PATH (so that a caller can skip what needs them and say why).
pub fn missing(names: &[&'static str]) -> Vec<&'static str> {
    let path = std::env::var_os("PATH").unwrap_or_default();
    names.iter().copied().filter(|n| !std::env::split_paths(&path).any(|d| d.join(n).is_file())).collect()
}

/// Run a command in `dir`; Err carries the tool name and the last lines of its output.
pub fn run(dir: &Path, prog: &str, args: &[&str]) -> Result<Output, String> {
    let out = Command::new(prog)
        .args(args)
        .current_dir(dir)
        .output()
        .map_err(|e| format!("cannot run {prog}: {e} (is it installed? the README's test command installs it)"))?;
    if !out.status.success() {
        let text = String::from_utf8_lossy(&out.stderr).to_string() + &String::from_utf8_lossy(&out.stdout);
        let tail: Vec<&str> = text.lines().rev().take(12).collect();
        let tail: Vec<&str> = tail.into_iter().rev().collect();
        return Err(format!("{prog} failed in {}:\n{}", dir.display(), tail.join("\n")));
    }
    Ok(out)
}
