//! Inputs are never outputs: before a command reads or writes anything, every output path is
//! compared with every input and every other output. Two paths name one file when they reach
//! the same device and inode (through symbolic and hard links), or, for an output that does
//! not exist yet, the same resolved path. Special files (`/dev/null`, a FIFO, standard output
//! as `-`) are never files a command could eat and are left out.

use crate::CliError;
use std::path::{Path, PathBuf};

/// One path a command reads or writes, with the option that named it (for the message).
#[derive(Debug, Clone, Copy)]
pub struct Named<'a> {
    /// The option or argument that named the path (`--junit`, `FILE`).
    pub flag: &'a str,
    /// The path as given.
    pub path: &'a Path,
}

/// `flag` naming `path`.
pub fn named<'a>(flag: &'a str, path: &'a Path) -> Named<'a> {
    Named { flag, path }
}

/// What identifies a file: its device and inode when it exists, else its resolved path.
#[derive(Debug, Clone, PartialEq, Eq)]
enum FileId {
    Inode(u64, u64),
    Path(PathBuf),
}

/// The identity of `path`, or None for standard output (`-`) and existing special files.
fn identity(path: &Path) -> Option<FileId> {
    if path.as_os_str() == "-" {
        return None;
    }
    match std::fs::metadata(path) {
        Ok(meta) if !meta.is_file() && !meta.is_dir() => None,
        Ok(meta) => Some(inode(&meta).unwrap_or_else(|| FileId::Path(resolved(path)))),
        Err(_) => Some(FileId::Path(resolved(path))),
    }
}

#[cfg(unix)]
fn inode(meta: &std::fs::Metadata) -> Option<FileId> {
    use std::os::unix::fs::MetadataExt;
    Some(FileId::Inode(meta.dev(), meta.ino()))
}

#[cfg(not(unix))]
fn inode(_meta: &std::fs::Metadata) -> Option<FileId> {
    None
}

/// `path` made absolute with its existing parent resolved (links followed), so that `a/x` and
/// `./a/../a/x` agree before `x` exists.
fn resolved(path: &Path) -> PathBuf {
    let absolute = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    match (absolute.parent(), absolute.file_name()) {
        (Some(parent), Some(name)) => std::fs::canonicalize(parent)
            .map(|p| p.join(name))
            .unwrap_or(absolute),
        _ => absolute,
    }
}

/// Refuses (usage error, exit 2) an output that is the same file as an input or as another
/// output, naming both options and paths.
pub fn refuse_clobbering(inputs: &[Named], outputs: &[Named]) -> Result<(), CliError> {
    let ids =
        |list: &[Named]| -> Vec<Option<FileId>> { list.iter().map(|n| identity(n.path)).collect() };
    let (input_ids, output_ids) = (ids(inputs), ids(outputs));
    for (k, out) in outputs.iter().enumerate() {
        let Some(id) = &output_ids[k] else { continue };
        if let Some(i) = (0..inputs.len()).find(|&i| input_ids[i].as_ref() == Some(id)) {
            return Err(CliError::Usage(format!(
                "{} {} is the input {} {}: writing it would destroy the input; choose another path",
                out.flag,
                out.path.display(),
                inputs[i].flag,
                inputs[i].path.display()
            )));
        }
        if let Some(j) = (0..k).find(|&j| output_ids[j].as_ref() == Some(id)) {
            return Err(CliError::Usage(format!(
                "{} {} and {} {} are one file: each output needs its own path",
                outputs[j].flag,
                outputs[j].path.display(),
                out.flag,
                out.path.display()
            )));
        }
    }
    Ok(())
}

/// The program file of an external command line (its first word), as an input a command must
/// not overwrite.
pub fn program_path(command: &str) -> Option<PathBuf> {
    gartowen::external::split_command(command)
        .ok()
        .and_then(|w| w.into_iter().next())
        .map(PathBuf::from)
}

/// Refuses an input that lies in the folder `dir` a command rewrites (`report --out`,
/// `scene --out`): the next run would replace it.
pub fn refuse_input_inside(input: Named, dir: Named) -> Result<(), CliError> {
    let (Some(parent_id), Some(dir_id)) = (
        input
            .path
            .parent()
            .map(|p| {
                if p.as_os_str().is_empty() {
                    Path::new(".")
                } else {
                    p
                }
            })
            .and_then(identity),
        identity(dir.path),
    ) else {
        return Ok(());
    };
    if parent_id == dir_id {
        return Err(CliError::Usage(format!(
            "{} {} lies in the folder {} {} that this run rewrites; copy it elsewhere first",
            input.flag,
            input.path.display(),
            dir.flag,
            dir.path.display()
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn links_and_spellings_of_one_file_are_one_file() {
        let dir = tempfile::tempdir().unwrap();
        let a = dir.path().join("a.npy");
        std::fs::write(&a, b"x").unwrap();
        let hard = dir.path().join("hard.npy");
        std::fs::hard_link(&a, &hard).unwrap();
        let dotted = dir.path().join(".").join("a.npy");
        for other in [&a, &hard, &dotted] {
            let e = refuse_clobbering(&[named("FILE", &a)], &[named("--junit", other)]);
            assert!(
                matches!(e, Err(CliError::Usage(m)) if m.contains("--junit") && m.contains("FILE"))
            );
        }
        #[cfg(unix)]
        {
            let soft = dir.path().join("soft.npy");
            std::os::unix::fs::symlink(&a, &soft).unwrap();
            assert!(refuse_clobbering(&[named("FILE", &soft)], &[named("-o", &a)]).is_err());
        }
        let b = dir.path().join("b.xml");
        assert!(refuse_clobbering(&[named("FILE", &a)], &[named("--junit", &b)]).is_ok());
    }

    #[test]
    fn two_outputs_on_one_new_path_are_refused_and_special_files_are_not() {
        let dir = tempfile::tempdir().unwrap();
        let new = dir.path().join("out.json");
        let same = dir.path().join("sub").join("..").join("out.json");
        std::fs::create_dir(dir.path().join("sub")).unwrap();
        let e = refuse_clobbering(&[], &[named("--json", &new), named("--junit", &same)]);
        assert!(matches!(e, Err(CliError::Usage(m)) if m.contains("one file")));
        let null = Path::new("/dev/null");
        if null.exists() {
            assert!(refuse_clobbering(
                &[named("FILE", null)],
                &[named("--json", null), named("--junit", null)]
            )
            .is_ok());
        }
        let dash = Path::new("-");
        assert!(refuse_clobbering(&[], &[named("-o", dash), named("--junit", dash)]).is_ok());
    }

    #[test]
    fn an_input_inside_the_rewritten_folder_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        std::fs::create_dir(&out).unwrap();
        let baseline = out.join("report.json");
        std::fs::write(&baseline, b"{}").unwrap();
        let e = refuse_input_inside(named("--baseline", &baseline), named("--out", &out));
        assert!(matches!(e, Err(CliError::Usage(m)) if m.contains("rewrites")));
        let elsewhere = dir.path().join("old.json");
        assert!(refuse_input_inside(named("--baseline", &elsewhere), named("--out", &out)).is_ok());
        // A folder that does not exist yet holds nothing.
        let fresh = dir.path().join("fresh");
        assert!(
            refuse_input_inside(named("--baseline", &baseline), named("--out", &fresh)).is_ok()
        );
    }
}
