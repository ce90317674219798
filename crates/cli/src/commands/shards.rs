//! The bookkeeping both merges share (`verify --merge` of battery shards and of sweep shards):
//! certificates read and parsed, each shard I of N given once, all from one tool version, none
//! missing; anything else refused with the file named.

use crate::CliError;
use gartowen::certificate::Certificate;
use std::path::{Path, PathBuf};

/// The shards admitted so far.
#[derive(Default)]
pub struct ShardSet {
    first: Option<(PathBuf, String)>,
    count: u64,
    seen: Vec<u64>,
}

/// A usage error naming the file.
pub fn refuse(p: &Path, m: impl std::fmt::Display) -> CliError {
    CliError::Usage(format!("{}: {m}", p.display()))
}

/// Reads and parses the certificate at `p`, with its text (for [`check_digest`]).
pub fn read_certificate(p: &Path) -> Result<(Certificate, String), CliError> {
    let text = crate::input::read_text_bounded(p, MAX_CERTIFICATE_BYTES)?;
    let cert = Certificate::parse(&text).map_err(|e| refuse(p, e))?;
    Ok((cert, text))
}

/// The largest certificate read (a full-level registry certificate is about 30 MB).
pub const MAX_CERTIFICATE_BYTES: u64 = 1 << 30;

/// Refuses a certificate whose content does not match its digest (an edit that kept every
/// field consistent); run after the field checks, which name what was edited when they can.
pub fn check_digest(p: &Path, text: &str) -> Result<(), CliError> {
    gartowen::certificate::check_digest(text).map_err(|e| refuse(p, e))
}

impl ShardSet {
    /// Admits `cert` read from `p`: its shard record, tool version and shard count must agree
    /// with the first file's, and its index must be new. Returns the path of the first file
    /// when this is not the first (for the caller's own comparisons).
    pub fn admit(&mut self, p: &Path, cert: &Certificate) -> Result<Option<PathBuf>, CliError> {
        let shard = &cert.parameters["shard"];
        let (Some(index), Some(n)) = (shard["index"].as_u64(), shard["count"].as_u64()) else {
            return Err(refuse(
                p,
                "no shard record (parameters.shard): not written by `verify --shard --json`",
            ));
        };
        let earlier = match &self.first {
            Some((fp, version)) => {
                if *version != cert.tool_version {
                    return Err(refuse(
                        p,
                        format!(
                            "made by gartowen {}, {} by {version}",
                            cert.tool_version,
                            fp.display()
                        ),
                    ));
                }
                if n != self.count {
                    return Err(refuse(
                        p,
                        format!(
                            "is shard {index}/{n}, {} one of {}",
                            fp.display(),
                            self.count
                        ),
                    ));
                }
                Some(fp.clone())
            }
            None => {
                self.first = Some((p.to_path_buf(), cert.tool_version.clone()));
                self.count = n;
                None
            }
        };
        if self.seen.contains(&index) {
            return Err(refuse(p, format!("shard {index}/{n} is given twice")));
        }
        self.seen.push(index);
        Ok(earlier)
    }

    /// Refuses a set with a shard missing.
    pub fn complete(&self) -> Result<(), CliError> {
        if let Some(missing) = (1..=self.count).find(|i| !self.seen.contains(i)) {
            return Err(CliError::Usage(format!(
                "shard {missing}/{} is missing ({} of {} given)",
                self.count,
                self.seen.len(),
                self.count
            )));
        }
        Ok(())
    }
}
