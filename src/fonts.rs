//! A TrueType font for the report's plot, found where the system keeps its fonts (the XDG data folders'
//! `fonts/`, then `/usr/local/share/fonts` and `/usr/share/fonts`), DejaVu Sans or Liberation Sans first, else any
//! `.ttf`; registered once with plotters as `sans-serif`.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

const PREFERRED: [&str; 3] = ["DejaVuSans.ttf", "LiberationSans-Regular.ttf", "FreeSans.ttf"];

fn font_dirs() -> Vec<PathBuf> {
    let mut dirs = vec![];
    if let Some(home) = std::env::var_os("HOME") {
        dirs.push(Path::new(&home).join(".local/share/fonts"));
    }
    let data = std::env::var("XDG_DATA_DIRS").unwrap_or_default();
    dirs.extend(data.split(':').filter(|d| !d.is_empty()).map(|d| Path::new(d).join("fonts")));
    dirs.extend([PathBuf::from("/usr/local/share/fonts"), PathBuf::from("/usr/share/fonts")]);
    dirs
}

/// Every `.ttf` under a folder, depth first, in name order.
fn ttf_files(dir: &Path, out: &mut Vec<PathBuf>, depth: usize) {
    let Ok(rd) = std::fs::read_dir(dir) else { return };
    let mut entries: Vec<PathBuf> = rd.filter_map(|e| e.ok().map(|e| e.path())).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() && depth < 6 {
            ttf_files(&p, out, depth + 1);
        } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("ttf")) {
            out.push(p);
        }
    }
}

/// The family name to draw with, after registering a system font under it.
pub fn sans() -> Result<&'static str, String> {
    static DONE: OnceLock<Result<(), String>> = OnceLock::new();
    DONE.get_or_init(|| {
        let mut all = vec![];
        for d in font_dirs() {
            ttf_files(&d, &mut all, 0);
        }
        let pick = PREFERRED.iter().find_map(|name| all.iter().find(|p| p.file_name().is_some_and(|f| f == *name))).or(all.first());
        let Some(path) = pick else {
            return Err("no TrueType font for the plot's labels in the system's font folders (on Debian: apt-get install fonts-dejavu-core)".into());
        };
        let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
        plotters::style::register_font("sans-serif", plotters::style::FontStyle::Normal, Box::leak(bytes.into_boxed_slice()))
            .map_err(|_| format!("{}: not a font plotters can read", path.display()))
    })
    .clone()
    .map(|_| "sans-serif")
}
