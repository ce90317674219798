//! CLI errors: bad input exits 2, I/O failures exit 2 too (nothing partial is left behind), a
//! failing external program exits 3. A failed check is not an error: commands exit 1 then.

use std::fmt;

/// An error that ends a command.
#[derive(Debug)]
pub enum CliError {
    /// Invalid arguments or input data.
    Usage(String),
    /// A file could not be read or written.
    Io(String),
    /// An external program started but failed (crash, exit, hang, garbage reply).
    External(String),
}

/// Exit code: every check passed.
pub const EXIT_PASS: u8 = 0;
/// Exit code: a check failed.
pub const EXIT_FAIL: u8 = 1;
/// Exit code: bad usage or input (nothing was judged, nothing partial written).
pub const EXIT_USAGE: u8 = 2;
/// Exit code: the external program failed.
pub const EXIT_EXTERNAL: u8 = 3;

impl CliError {
    /// The process exit code.
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::Usage(_) | CliError::Io(_) => EXIT_USAGE,
            CliError::External(_) => EXIT_EXTERNAL,
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Usage(m) | CliError::Io(m) => write!(f, "{m}"),
            CliError::External(m) => write!(f, "external program failed: {m}"),
        }
    }
}

impl From<gartowen::seq::SeqError> for CliError {
    fn from(e: gartowen::seq::SeqError) -> Self {
        CliError::Usage(e.to_string())
    }
}

impl From<gartowen::core::CoreError> for CliError {
    fn from(e: gartowen::core::CoreError) -> Self {
        CliError::Usage(e.to_string())
    }
}

impl From<gartowen::generate::RequestError> for CliError {
    fn from(e: gartowen::generate::RequestError) -> Self {
        CliError::Usage(e.to_string())
    }
}
