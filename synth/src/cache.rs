//! Synthesis results kept under a content hash of everything that made them: the Verilog (with its wrapper), the
//! target part and clock, the flow's own settings, and the tools' versions as the tools print them. A rerun, another
//! output folder, or another worker of a sweep sharing the folder reuses a result whose inputs have not changed (and
//! waits for one another process is making); a new yosys or nextpnr makes a new key rather than a stale hit.
//!
//! The store is a folder of files `<hash>.<kind>`, written whole or not at all: `$BUMPRTL_SYNTH_CACHE`, else the
//! workspace's `target/synth-cache`. Its `locks/` folder holds a lock file per result ever made (see `making`).

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Mutex;

/// FNV-1a, 128 bits, as 32 hex digits: stable across builds and machines (the standard's offset and prime).
pub fn hash(text: &str) -> String {
    const OFFSET: u128 = 0x6c62272e07bb014262b821756295c58d;
    const PRIME: u128 = 0x0000000001000000000000000000013b;
    let h = text.bytes().fold(OFFSET, |h, b| (h ^ b as u128).wrapping_mul(PRIME));
    format!("{h:032x}")
}

/// The folder of the store.
pub fn root() -> PathBuf {
    match std::env::var_os("BUMPRTL_SYNTH_CACHE") {
        Some(p) => PathBuf::from(p),
        None => PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..").join("target").join("synth-cache"),
    }
}

/// The first line a tool prints of its version (`yosys -V`, `nextpnr-ice40 --version`), asked once a process;
/// "unknown" when it cannot be run, so that a missing tool never matches a result a real one made.
pub fn version(tool: &str) -> String {
    static SEEN: Mutex<Option<HashMap<String, String>>> = Mutex::new(None);
    let mut seen = SEEN.lock().unwrap_or_else(|e| e.into_inner());
    let map = seen.get_or_insert_with(HashMap::new);
    if let Some(v) = map.get(tool) {
        return v.clone();
    }
    let yosys = std::path::Path::new(tool).file_name().is_some_and(|n| n.to_string_lossy().ends_with("yosys"));
    let flag = if yosys { "-V" } else { "--version" };
    let v = std::process::Command::new(tool)
        .arg(flag)
        .output()
        .ok()
        .map(|o| {
            let text = String::from_utf8_lossy(&o.stdout).into_owned() + &String::from_utf8_lossy(&o.stderr);
            text.lines().map(str::trim).find(|l| !l.is_empty()).unwrap_or("").to_string()
        })
        .filter(|l| !l.is_empty())
        .unwrap_or_else(|| format!("{tool}: unknown"));
    map.insert(tool.to_string(), v.clone());
    v
}

/// The key of a result: the hash of its inputs' text and the tools' versions.
pub fn key(inputs: &str, tools: &[&str]) -> String {
    let versions: Vec<String> = tools.iter().map(|t| version(t)).collect();
    hash(&format!("{inputs}\n--\n{}", versions.join("\n")))
}

/// A kept result of `kind` under `key`, if there is one.
pub fn get(key: &str, kind: &str) -> Option<String> {
    get_in(&root(), key, kind)
}

/// Keep a result (whole or not at all).
pub fn put(key: &str, kind: &str, value: &str) -> Result<(), String> {
    put_in(&root(), key, kind, value)
}

/// Held while the result of `kind` under `key` is made: another process that wants the same result (a test beside
/// this one, a worker of the same sweep) waits for it and then reads it, rather than running the tools again
/// alongside. A lock file of the same name in the store's `locks/` folder, released when dropped or when the process
/// dies.
pub fn making(key: &str, kind: &str) -> Result<crate::export::FolderLock, String> {
    let dir = root().join("locks");
    std::fs::create_dir_all(&dir).map_err(|e| format!("cannot create the synthesis cache {}: {e}", dir.display()))?;
    crate::export::FolderLock::take_file(&dir.join(format!("{key}.{kind}")))
}

fn get_in(dir: &std::path::Path, key: &str, kind: &str) -> Option<String> {
    std::fs::read_to_string(dir.join(format!("{key}.{kind}"))).ok()
}

fn put_in(dir: &std::path::Path, key: &str, kind: &str, value: &str) -> Result<(), String> {
    static NEXT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create the synthesis cache {}: {e}", dir.display()))?;
    // written beside it under a name of its own, then renamed: two workers keeping the same result at once each
    // rename a whole file, and either one is the result
    let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let tmp = dir.join(format!(".{key}.{kind}.{}.{n}.partial", std::process::id()));
    let path = dir.join(format!("{key}.{kind}"));
    std::fs::write(&tmp, value).and_then(|_| std::fs::rename(&tmp, &path)).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        format!("cannot write {}: {e}", path.display())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_result_being_made_keeps_another_process_waiting_until_the_maker_is_done() {
        let key = hash("a result being made, in the cache's own test");
        let lock = root().join("locks").join(format!("{key}.cells"));
        // whether another process (util-linux's `flock -n`) could take the lock now
        let free = || match std::process::Command::new("flock").args(["-n", "-E", "3"]).arg(&lock).arg("true").status()
        {
            Ok(s) if s.code() == Some(0) => true,
            Ok(s) if s.code() == Some(3) => false,
            other => panic!("flock: {other:?}"),
        };
        let making = making(&key, "cells").unwrap();
        assert!(!free(), "another process could make the result while this one was making it");
        drop(making);
        assert!(free(), "the lock outlived its maker");
    }

    #[test]
    fn the_hash_is_fnv_1a_128() {
        // the empty text hashes to the offset basis; "a" to the published FNV-1a 128 value
        assert_eq!(hash(""), "6c62272e07bb014262b821756295c58d");
        assert_eq!(hash("a"), "d228cb696f1a8caf78912b704e4a8964");
        assert_eq!(hash("foobar"), "343e1662793c64bf6f0d3597ba446f18");
        assert_ne!(hash("ab"), hash("ba"));
    }

    #[test]
    fn a_result_is_kept_whole_under_its_key_and_kind() {
        let dir = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/test-files/synth-cache");
        let _ = std::fs::remove_dir_all(&dir);
        let k = key("module m; endmodule", &[]);
        assert_eq!(get_in(&dir, &k, "cells"), None);
        put_in(&dir, &k, "cells", "1 2 3 4 5").unwrap();
        assert_eq!(get_in(&dir, &k, "cells").as_deref(), Some("1 2 3 4 5"));
        assert_eq!(get_in(&dir, &k, "report"), None);
        assert_eq!(get_in(&dir, &key("module m2; endmodule", &[]), "cells"), None);
        // nothing half-written left beside it
        assert!(std::fs::read_dir(&dir).unwrap().all(|e| !e
            .unwrap()
            .file_name()
            .to_string_lossy()
            .contains("partial")));
        // two writers of one result at once: one whole file
        std::thread::scope(|s| {
            for v in ["a b", "a b"] {
                s.spawn(|| put_in(&dir, &k, "report", v).unwrap());
            }
        });
        assert_eq!(get_in(&dir, &k, "report").as_deref(), Some("a b"));
    }

    #[test]
    fn a_tool_that_cannot_run_has_a_version_no_real_one_prints() {
        assert_eq!(version("/no/such/tool-bumprtl"), "/no/such/tool-bumprtl: unknown");
        assert_ne!(key("x", &["/no/such/tool-bumprtl"]), key("x", &["/no/such/other-bumprtl"]));
        assert_ne!(key("x", &[]), key("y", &[]));
    }
}
