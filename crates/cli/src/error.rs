//! CLI errors: bad input exits 2, I/O failures exit 2 too (nothing partial is left behind).

use std::fmt;

/// An error that ends a command.
#[derive(Debug)]
pub enum CliError {
    /// Invalid arguments or input data.
    Usage(String),
    /// A file could not be read or written.
    Io(String),
}

impl CliError {
    /// The process exit code.
    pub fn exit_code(&self) -> u8 {
        2
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Usage(m) | CliError::Io(m) => write!(f, "{m}"),
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
