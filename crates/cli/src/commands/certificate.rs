//! `gartowen certificate check`: a certificate checked, not trusted.

use crate::CliError;
use clap::{Args, Subcommand};
use gartowen::audit::Content;
use std::path::PathBuf;
use std::process::ExitCode;

/// Check certificates written by `verify`, `check` or `discrepancy`.
///
/// `certificate check FILE...` reads each certificate and checks it field by field: the schema
/// and tool version, and for a verify report every implementation's name, base and claim
/// against the registry (or the external program's record), the seeds and sizes against the
/// level, every law verdict, p-value, per-test level and profile recomputed from the sub-test
/// statistics it records, and the overall verdict. Last, the content digest: a file edited
/// after it was written is refused even when the edit kept every field consistent. The digest
/// is an unkeyed SHA-256, not a signature: it cannot tell who wrote a file.
///
/// Exit 0 when every file is consistent; 2 naming the file and the field otherwise.
#[derive(Args)]
pub struct CertificateArgs {
    #[command(subcommand)]
    command: CertificateCommand,
}

#[derive(Subcommand)]
enum CertificateCommand {
    /// Check each certificate: fields, recomputed verdicts, digest.
    Check {
        /// Certificate files (JSON).
        #[arg(required = true)]
        files: Vec<PathBuf>,
    },
}

/// Runs `certificate check`.
pub fn run(a: CertificateArgs) -> Result<ExitCode, CliError> {
    let CertificateCommand::Check { files } = a.command;
    let registry = gartowen::registry();
    for p in &files {
        let (cert, text) = super::shards::read_certificate(p)?;
        let refuse = |e: gartowen::audit::AuditError| super::shards::refuse(p, e);
        // What the file is comes from its fields, not its `command` label: a verify report
        // relabelled `check` is refused, not read as a check.
        let what = match gartowen::audit::content_of(&cert).map_err(refuse)? {
            Content::Sweep => {
                super::sweep::audit(&cert).map_err(|e| super::shards::refuse(p, e))?
            }
            Content::Verify => {
                let run = gartowen::audit::audit_verify(&cert, &registry).map_err(refuse)?;
                let (i, n) = run.shard;
                format!(
                    "verify, {} level, {} implementation(s){}, verdicts recomputed",
                    run.level.name(),
                    run.reports.len(),
                    if n > 1 {
                        format!(", shard {i}/{n}")
                    } else {
                        String::new()
                    }
                )
            }
            Content::Check => gartowen::audit::audit_check(&cert).map_err(refuse)?,
            Content::Discrepancy => gartowen::audit::audit_discrepancy(&cert).map_err(refuse)?,
        };
        super::shards::check_digest(p, &text)?;
        crate::outln!(
            "{}: consistent ({what}; verdict {}; digest matches)",
            p.display(),
            serde_json::to_value(cert.verdict)
                .ok()
                .and_then(|v| v.as_str().map(str::to_string))
                .unwrap_or_default()
        );
    }
    Ok(ExitCode::SUCCESS)
}
