//! Finding and running the external tools, with one-line errors that say which tool failed and why.

use std::path::Path;
use std::process::{Command, Output};

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
