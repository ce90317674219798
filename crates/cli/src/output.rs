//! Output files written atomically: into a temporary file beside the target, renamed on
//! success and removed on failure, so an error never leaves a partial or clobbered file.
//!
//! The target is respected: a regular file keeps its permissions, and a read-only one is
//! refused; a device, FIFO or socket (`/dev/null`, a named pipe) is written in place, never
//! replaced; a symbolic link is refused (name its target instead), so `-o` never redirects
//! a write through a link or turns a special file into a regular one.

use crate::CliError;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

/// Where output goes: a file (atomic) or standard output.
pub enum Sink {
    File {
        tmp: PathBuf,
        target: PathBuf,
        writer: BufWriter<File>,
    },
    /// A special file (device, FIFO, socket) written in place.
    InPlace {
        target: PathBuf,
        writer: BufWriter<File>,
    },
    Stdout(BufWriter<io::Stdout>),
}

impl Sink {
    /// Opens `path`, or standard output when `None` or `-`.
    pub fn open(path: Option<&Path>) -> Result<Sink, CliError> {
        match path {
            None => Ok(Sink::Stdout(BufWriter::new(io::stdout()))),
            Some(p) if p.as_os_str() == "-" => Ok(Sink::Stdout(BufWriter::new(io::stdout()))),
            Some(p) => {
                let name = p.file_name().ok_or_else(|| {
                    CliError::Usage(format!("{} is not a file path", p.display()))
                })?;
                let existing = match std::fs::symlink_metadata(p) {
                    Ok(m) => Some(m),
                    Err(e) if e.kind() == io::ErrorKind::NotFound => None,
                    Err(e) => {
                        return Err(CliError::Io(format!("cannot inspect {}: {e}", p.display())))
                    }
                };
                if let Some(m) = &existing {
                    let kind = m.file_type();
                    if kind.is_symlink() {
                        return Err(CliError::Usage(format!(
                            "{} is a symbolic link: gartowen does not write through links; \
                             give the file it points to",
                            p.display()
                        )));
                    }
                    if kind.is_dir() {
                        return Err(CliError::Usage(format!("{} is a directory", p.display())));
                    }
                    if !kind.is_file() {
                        // A device, FIFO or socket: write into it, never replace it.
                        let file =
                            std::fs::OpenOptions::new()
                                .write(true)
                                .open(p)
                                .map_err(|e| {
                                    CliError::Io(format!("cannot open {}: {e}", p.display()))
                                })?;
                        return Ok(Sink::InPlace {
                            target: p.to_path_buf(),
                            writer: BufWriter::new(file),
                        });
                    }
                    if m.permissions().readonly() {
                        return Err(CliError::Usage(format!(
                            "{} is read-only: gartowen does not replace it",
                            p.display()
                        )));
                    }
                }
                let mut tmp_name = std::ffi::OsString::from(".");
                tmp_name.push(name);
                tmp_name.push(format!(".tmp-{}", std::process::id()));
                let tmp = p.with_file_name(tmp_name);
                // Registered before it exists, so no signal can fall between the two.
                crate::cleanup::register(&tmp);
                let file = std::fs::OpenOptions::new()
                    .write(true)
                    .create_new(true)
                    .open(&tmp)
                    .map_err(|e| {
                        crate::cleanup::unregister(&tmp);
                        CliError::Io(format!("cannot create {}: {e}", p.display()))
                    })?;
                if let Some(m) = &existing {
                    // The replacement keeps the target's permissions (a 0600 file stays 0600).
                    file.set_permissions(m.permissions()).map_err(|e| {
                        let _ = std::fs::remove_file(&tmp);
                        crate::cleanup::unregister(&tmp);
                        CliError::Io(format!("cannot keep the mode of {}: {e}", p.display()))
                    })?;
                }
                Ok(Sink::File {
                    tmp,
                    target: p.to_path_buf(),
                    writer: BufWriter::new(file),
                })
            }
        }
    }

    /// The writer to write into.
    pub fn writer(&mut self) -> &mut dyn Write {
        match self {
            Sink::File { writer, .. } | Sink::InPlace { writer, .. } => writer,
            Sink::Stdout(w) => w,
        }
    }

    /// Flushes and, for files, renames the temporary file onto the target.
    pub fn commit(self) -> Result<(), CliError> {
        match self {
            Sink::Stdout(mut w) => w
                .flush()
                .map_err(|e| CliError::Io(format!("cannot write to standard output: {e}"))),
            Sink::InPlace { target, mut writer } => writer
                .flush()
                .map_err(|e| CliError::Io(format!("cannot write {}: {e}", target.display()))),
            Sink::File {
                tmp,
                target,
                writer,
            } => {
                let result = writer
                    .into_inner()
                    .map_err(|e| e.into_error())
                    .and_then(|f| f.sync_all())
                    .and_then(|_| std::fs::rename(&tmp, &target));
                crate::cleanup::unregister(&tmp);
                if let Err(e) = result {
                    let _ = std::fs::remove_file(&tmp);
                    return Err(CliError::Io(format!(
                        "cannot write {}: {e}",
                        target.display()
                    )));
                }
                Ok(())
            }
        }
    }

    /// Discards the output (removes the temporary file).
    pub fn abort(self) {
        if let Sink::File { tmp, writer, .. } = self {
            drop(writer);
            let _ = std::fs::remove_file(&tmp);
            crate::cleanup::unregister(&tmp);
        }
    }
}

/// Runs `body` against a sink, committing on success and aborting on error.
pub fn write_atomically(
    path: Option<&Path>,
    body: impl FnOnce(&mut dyn Write) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let mut sink = Sink::open(path)?;
    match body(sink.writer()) {
        Ok(()) => sink.commit(),
        Err(e) => {
            sink.abort();
            Err(e)
        }
    }
}

/// Converts an I/O error while writing into a CLI error.
pub fn io_err(e: io::Error) -> CliError {
    CliError::Io(format!("write failed: {e}"))
}

/// Writes JUnit XML (`--junit`) atomically.
pub fn write_junit(
    path: &Path,
    run: &str,
    suites: &[gartowen::battery::junit::JunitSuite],
) -> Result<(), CliError> {
    let xml = gartowen::battery::junit::to_xml(run, suites);
    write_atomically(Some(path), |out| {
        out.write_all(xml.as_bytes()).map_err(io_err)
    })
}

/// Writes `text` to standard output and flushes it: a full disk or a closed pipe is an error
/// with a message (exit 2), never a panic as `println!` would give.
pub fn emit(text: &str) -> Result<(), CliError> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| CliError::Io(format!("cannot write to standard output: {e}")))
}

/// `println!` that returns a [`CliError`] from the enclosing function instead of panicking.
#[macro_export]
macro_rules! outln {
    ($($arg:tt)*) => {
        $crate::output::emit(&format!("{}\n", format_args!($($arg)*)))?
    };
}

/// `print!` that returns a [`CliError`] from the enclosing function instead of panicking.
#[macro_export]
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::output::emit(&format!($($arg)*))?
    };
}
