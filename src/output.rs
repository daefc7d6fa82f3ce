//! Where a command writes: its output folder or file, made and tried before any work, refused in one line.

/// A command's output folder, made and tried with a file before any work, refused in one line.
pub fn writable_folder(out: &std::path::Path) -> Result<(), String> {
    std::fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    try_a_file_in(out).map_err(|e| format!("cannot write into {}: {e}", out.display()))
}

/// A file written into `dir` and removed.
fn try_a_file_in(dir: &std::path::Path) -> std::io::Result<()> {
    let probe = dir.join(format!(".{}.write-test", std::process::id()));
    std::fs::write(&probe, b"")?;
    let _ = std::fs::remove_file(&probe);
    Ok(())
}

/// A file can be written at `path`: its folder exists and takes a file (tried with one, removed), and it is not a
/// folder itself.
pub fn writable_file(path: &std::path::Path) -> Result<(), String> {
    if path.is_dir() {
        return Err(format!("{} is a folder; name a file", path.display()));
    }
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => std::path::Path::new("."),
    };
    try_a_file_in(dir).map_err(|e| format!("cannot write {}: {e}", path.display()))
}
