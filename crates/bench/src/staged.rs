//! Writing a folder's files all or nothing: each file is staged in a folder of its own and
//! moved into place only when every one is complete.

use std::path::{Path, PathBuf};

/// Creates `dir`, lets `stage` write files into [`staging_dir`] (returning their names), and
/// moves them into `dir` only when all are complete, so a write error (a full disk) leaves
/// `dir` as it was, an earlier report in it intact, and no staging folder behind.
pub fn write_staged(
    dir: &Path,
    stage: impl FnOnce(&Path) -> Result<Vec<String>, String>,
) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let staging = staging_dir(dir);
    // A staging folder left by a killed run of this pid would only hold stale files.
    let _ = std::fs::remove_dir_all(&staging);
    std::fs::create_dir(&staging)
        .map_err(|e| format!("cannot create {}: {e}", staging.display()))?;
    let moved = stage(&staging).and_then(|names| {
        // Renames within one folder need no space: once every file is staged, the report
        // cannot stop half-written.
        for name in &names {
            std::fs::rename(staging.join(name), dir.join(name))
                .map_err(|e| format!("cannot write {}: {e}", dir.join(name).display()))?;
        }
        Ok(())
    });
    let _ = std::fs::remove_dir_all(&staging);
    moved
}

/// The folder inside `dir` where [`write_staged`] (and so `write_report`) writes every file before moving them into
/// place (named by the process id, so two runs into one folder do not share it).
pub fn staging_dir(dir: &Path) -> PathBuf {
    dir.join(format!(".report-staging-{}", std::process::id()))
}
