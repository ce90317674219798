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
    let moved = stage(&staging).and_then(|names| move_into_place(dir, &staging, &names));
    let _ = std::fs::remove_dir_all(&staging);
    moved
}

/// Moves the staged files into `dir`, all or none: a target that cannot be replaced (a
/// folder of that name, a file it may not overwrite) fails before any file moves, and a
/// failure midway puts back what was there. Renames within one folder need no space.
fn move_into_place(dir: &Path, staging: &Path, names: &[String]) -> Result<(), String> {
    let target = |name: &str| dir.join(name);
    if let Some(name) = names
        .iter()
        .find(|n| target(n).symlink_metadata().is_ok_and(|m| m.is_dir()))
    {
        return Err(format!(
            "cannot write {}: a folder of that name is in the way",
            target(name).display()
        ));
    }
    // The files being replaced go aside first (into the staging folder), so that they can
    // be put back.
    let aside = |name: &str| staging.join(format!(".previous-{name}"));
    let mut set_aside: Vec<&str> = Vec::new();
    let mut placed: Vec<&str> = Vec::new();
    let undo = |set_aside: &[&str], placed: &[&str]| {
        for name in placed {
            let _ = std::fs::remove_file(target(name));
        }
        for name in set_aside {
            let _ = std::fs::rename(aside(name), target(name));
        }
    };
    for name in names {
        if target(name).symlink_metadata().is_ok() {
            if let Err(e) = std::fs::rename(target(name), aside(name)) {
                undo(&set_aside, &[]);
                return Err(format!("cannot replace {}: {e}", target(name).display()));
            }
            set_aside.push(name);
        }
    }
    for name in names {
        if let Err(e) = std::fs::rename(staging.join(name), target(name)) {
            undo(&set_aside, &placed);
            return Err(format!("cannot write {}: {e}", target(name).display()));
        }
        placed.push(name);
    }
    Ok(())
}

/// The folder inside `dir` where [`write_staged`] (and so `write_report`) writes every file before moving them into
/// place (named by the process id, so two runs into one folder do not share it).
pub fn staging_dir(dir: &Path) -> PathBuf {
    dir.join(format!(".report-staging-{}", std::process::id()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stage_files(
        files: &'static [(&'static str, &'static str)],
    ) -> impl FnOnce(&Path) -> Result<Vec<String>, String> {
        move |staging| {
            for (name, text) in files {
                std::fs::write(staging.join(name), text).map_err(|e| e.to_string())?;
            }
            Ok(files.iter().map(|(n, _)| n.to_string()).collect())
        }
    }

    fn listing(dir: &Path) -> Vec<(String, String)> {
        let mut out: Vec<(String, String)> = std::fs::read_dir(dir)
            .unwrap()
            .flatten()
            .map(|e| {
                let name = e.file_name().to_string_lossy().to_string();
                let text = std::fs::read_to_string(e.path()).unwrap_or_else(|_| "<dir>".into());
                (name, text)
            })
            .collect();
        out.sort();
        out
    }

    #[test]
    fn a_report_replaces_the_earlier_one_whole() {
        let dir = tempfile::tempdir().unwrap();
        write_staged(dir.path(), stage_files(&[("a.png", "1"), ("r.md", "1")])).unwrap();
        write_staged(dir.path(), stage_files(&[("a.png", "2"), ("r.md", "2")])).unwrap();
        let want = vec![("a.png".into(), "2".into()), ("r.md".into(), "2".into())];
        assert_eq!(listing(dir.path()), want);
    }

    #[test]
    fn a_folder_in_the_way_or_a_failed_move_leaves_the_earlier_report_as_it_was() {
        let dir = tempfile::tempdir().unwrap();
        write_staged(dir.path(), stage_files(&[("a.png", "1"), ("b.png", "1")])).unwrap();
        std::fs::create_dir(dir.path().join("r.md")).unwrap();
        let before = listing(dir.path());
        // Before: the figures were moved in, then r.md failed, and exit 2 left them behind.
        let e = write_staged(
            dir.path(),
            stage_files(&[("a.png", "2"), ("c.png", "2"), ("r.md", "2")]),
        )
        .unwrap_err();
        assert!(e.contains("r.md") && e.contains("folder"), "{e}");
        assert_eq!(listing(dir.path()), before);
        // A move that fails midway (the last name's folder does not exist) is undone.
        std::fs::remove_dir(dir.path().join("r.md")).unwrap();
        let before = listing(dir.path());
        let e = write_staged(dir.path(), |staging| {
            std::fs::write(staging.join("a.png"), "3").unwrap();
            std::fs::create_dir(staging.join("sub")).unwrap();
            std::fs::write(staging.join("sub/x"), "3").unwrap();
            Ok(vec!["a.png".into(), "missing/x".into()])
        })
        .unwrap_err();
        assert!(e.contains("missing"), "{e}");
        assert_eq!(listing(dir.path()), before);
    }
}
