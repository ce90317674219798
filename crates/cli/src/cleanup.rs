//! Temporary output files removed when SIGINT, SIGTERM or SIGHUP ends a command: without it an
//! interrupted `generate` left a 600–730 MB `.NAME.tmp-PID` beside its target.
//!
//! Output sinks register their temporary file while it is being written and unregister it
//! once it is renamed or removed. A watcher thread waits for the signals; on the first one it
//! removes every registered file, kills the process groups of external programs still
//! running (their helpers included), and ends the process as the signal would have.

use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
use signal_hook::iterator::Signals;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Starts the watcher (once, at start-up), and adopts the orphans of the external programs
/// this command starts (see `gartowen::external::orphans`). Without signal support the
/// command still runs; only the cleanup is lost.
pub fn install() {
    gartowen::external::orphans::adopt_orphans();
    let Ok(mut signals) = Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
        return;
    };
    std::thread::spawn(move || {
        if let Some(signal) = signals.forever().next() {
            remove_pending();
            // End as the signal would have (exit status 128 + signal for the shell).
            let _ = signal_hook::low_level::emulate_default_handler(signal);
            std::process::exit(128 + signal);
        }
    });
}

/// Removes every registered file and kills every external program's process group (the
/// signal path).
fn remove_pending() {
    gartowen::external::kill_live_groups();
    end_adopted();
    let mut pending = PENDING.lock().unwrap_or_else(|e| e.into_inner());
    for path in pending.drain(..) {
        if path.is_dir() {
            let _ = std::fs::remove_dir_all(path);
        } else {
            let _ = std::fs::remove_file(path);
        }
    }
}

/// Kills and reaps whatever this process still has as children: at the end of a command the
/// external programs it started are ended, so these are descendants that escaped their
/// process group and pipes (a double fork into a new session). Nothing is left running. A
/// command that started no external program has none, and skips the scan of `/proc`.
pub fn end_adopted() {
    if gartowen::external::any_spawned() {
        gartowen::external::orphans::kill_children(8);
    }
}

/// Registers a temporary file (or a staging folder, removed with its contents) being written.
pub fn register(path: &Path) {
    PENDING
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .push(path.to_path_buf());
}

/// Unregisters it once it has been renamed onto its target or removed.
pub fn unregister(path: &Path) {
    PENDING
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .retain(|p| p != path);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unregistering_one_file_keeps_the_others_pending() {
        let (a, b) = (Path::new("/tmp/.a.tmp-test"), Path::new("/tmp/.b.tmp-test"));
        register(a);
        register(b);
        unregister(a);
        let pending = PENDING.lock().unwrap().clone();
        assert!(pending.iter().any(|p| p == b), "{pending:?}");
        assert!(!pending.iter().any(|p| p == a), "{pending:?}");
        unregister(b);
        assert!(!PENDING.lock().unwrap().iter().any(|p| p == b));
    }
}
