//! One module per subcommand.

pub mod certificate;
pub mod check;
pub mod discrepancy;
pub mod estimate;
pub mod generate;
pub mod inspect;
pub mod list;
pub mod matrices;
pub mod render;
pub mod report;
pub mod scene;
pub mod scramble;
pub mod shards;
pub mod sweep;
pub mod verify;
pub mod verify_args;

use crate::CliError;
use gartowen::core::{Claim, Width};
use gartowen::external::ExternalProcess;

/// The word width from `--bits` (32 or 64).
pub fn width_from_bits(bits: u32) -> Result<Width, CliError> {
    match bits {
        32 | 64 => Ok(Width::new(bits)?),
        _ => Err(CliError::Usage(format!(
            "--bits must be 32 or 64, not {bits}"
        ))),
    }
}

/// An equivalence margin δ on a ratio (`--margin` of `verify` and `report`), 0 < δ < 1.
pub fn parse_margin(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(m) if m > 0.0 && m < 1.0 => Ok(m),
        _ => Err(format!(
            "'{s}' is not a margin in (0, 1), e.g. 0.1 for ±10%"
        )),
    }
}

/// The `--claim` option, parsed (None when absent).
pub fn parse_claim(text: &Option<String>) -> Result<Option<Claim>, CliError> {
    text.as_deref()
        .map(|t| Claim::parse(t).map_err(|e| CliError::Usage(format!("--claim {t}: {e}"))))
        .transpose()
}

/// The longest `--timeout` accepted: one day per reply.
pub const MAX_TIMEOUT_SECONDS: f64 = 86_400.0;

/// Starts an external program speaking the protocol, after checking the width (32 or 64 bits)
/// and `--timeout` (finite, positive seconds, at most [`MAX_TIMEOUT_SECONDS`]).
pub fn spawn_external(
    command: &str,
    base: impl Into<gartowen::external::ProtocolBase>,
    width: Width,
    timeout: f64,
) -> Result<ExternalProcess, CliError> {
    if width != Width::W32 && width != Width::W64 {
        return Err(CliError::Usage(format!(
            "--width {}: the protocol carries 32- or 64-bit words",
            width.bits()
        )));
    }
    if !(timeout.is_finite() && timeout > 0.0) {
        return Err(CliError::Usage(format!(
            "--timeout {timeout} is not a positive number of seconds"
        )));
    }
    if timeout > MAX_TIMEOUT_SECONDS {
        return Err(CliError::Usage(format!(
            "--timeout {timeout} exceeds the maximum of {MAX_TIMEOUT_SECONDS} seconds (one day)"
        )));
    }
    ExternalProcess::spawn(
        command,
        base,
        width,
        std::time::Duration::from_secs_f64(timeout),
    )
    .map_err(|e| CliError::Usage(e.to_string()))
}
