//! What can go wrong with an external program, in words a user can act on.

use std::fmt;

/// A failure of the external program, in words a user can act on.
#[derive(Debug, Clone, PartialEq)]
pub enum ExternalError {
    /// The command line is empty or has an unbalanced quote.
    BadCommand(String),
    /// The program could not be started.
    Spawn {
        /// The program.
        program: String,
        /// The OS error.
        reason: String,
    },
    /// The program exited (or was killed by a signal) before answering request `batch`.
    Exited {
        /// 1-based request number.
        batch: u64,
        /// Exit status in words.
        status: String,
        /// Bytes of the reply that did arrive.
        received: usize,
        /// Bytes the reply needed.
        expected: usize,
        /// The end of the program's stderr.
        stderr: String,
    },
    /// No complete answer to request `batch` within the timeout; the program was killed.
    Timeout {
        /// 1-based request number.
        batch: u64,
        /// The timeout.
        seconds: f64,
        /// Bytes of the reply that did arrive.
        received: usize,
        /// Bytes the reply needed.
        expected: usize,
    },
    /// The program did not take the whole request `batch` within the timeout (it stopped
    /// reading its stdin, or was stopped); the program was killed.
    WriteTimeout {
        /// 1-based request number.
        batch: u64,
        /// The timeout.
        seconds: f64,
        /// Bytes of the request the program did take.
        written: usize,
        /// Bytes of the whole request.
        total: usize,
    },
    /// The reply is not a reply: wrong magic or wrong count.
    Garbage {
        /// 1-based request number.
        batch: u64,
        /// What was wrong.
        detail: String,
    },
    /// Writing the request failed (the program closed its stdin).
    WriteFailed {
        /// 1-based request number.
        batch: u64,
        /// The OS error.
        reason: String,
        /// The end of the program's stderr.
        stderr: String,
    },
    /// A request the host refuses to send (empty or too large).
    BadRequest(String),
}

impl fmt::Display for ExternalError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let tail = |s: &str| {
            if s.trim().is_empty() {
                String::new()
            } else {
                format!("; its stderr ends: {}", printable(s.trim()))
            }
        };
        match self {
            ExternalError::BadCommand(c) => write!(f, "bad --external command: {c}"),
            ExternalError::Spawn { program, reason } => {
                write!(f, "cannot start '{program}': {reason}")
            }
            ExternalError::Exited {
                batch,
                status,
                received,
                expected,
                stderr,
            } => write!(
                f,
                "the program {status} during request {batch} after {received} of {expected} reply bytes{}",
                tail(stderr)
            ),
            ExternalError::Timeout {
                batch,
                seconds,
                received,
                expected,
            } => write!(
                f,
                "no complete reply to request {batch} within {seconds} s ({received} of {expected} bytes); the program was killed"
            ),
            ExternalError::WriteTimeout {
                batch,
                seconds,
                written,
                total,
            } => write!(
                f,
                "request {batch} not taken within {seconds} s (the program read {written} of its {total} bytes, then stopped reading); the program was killed"
            ),
            ExternalError::Garbage { batch, detail } => {
                write!(f, "garbage reply to request {batch}: {detail}")
            }
            ExternalError::WriteFailed {
                batch,
                reason,
                stderr,
            } => write!(
                f,
                "cannot send request {batch}: {reason}{}",
                tail(stderr)
            ),
            ExternalError::BadRequest(r) => write!(f, "bad request: {r}"),
        }
    }
}

impl std::error::Error for ExternalError {}

/// `text` with every control character but line feed and tab written as a `\u{..}` escape, so
/// that a program's stderr cannot drive the user's terminal (colours, cursor moves, titles).
pub fn printable(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() && c != '\n' && c != '\t' {
            out.push_str(&c.escape_unicode().to_string());
        } else {
            out.push(c);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn terminal_escapes_in_a_programs_stderr_are_written_out_not_sent() {
        assert_eq!(
            printable("\u{1b}[31mred\u{7}\r\nok\tdone"),
            "\\u{1b}[31mred\\u{7}\\u{d}\nok\tdone"
        );
        let e = ExternalError::WriteFailed {
            batch: 1,
            reason: "broken pipe".into(),
            stderr: "\u{1b}]0;owned\u{7}".into(),
        };
        assert!(!e.to_string().contains('\u{1b}'), "{e}");
        assert!(e.to_string().contains("\\u{1b}]0;owned"), "{e}");
    }
}
