//! One module per subcommand.

pub mod check;
pub mod discrepancy;
pub mod generate;
pub mod inspect;
pub mod list;
pub mod matrices;
pub mod report;
pub mod scramble;
pub mod verify;

use crate::CliError;
use gartowen::core::Width;

/// The word width from `--bits` (32 or 64).
pub fn width_from_bits(bits: u32) -> Result<Width, CliError> {
    match bits {
        32 | 64 => Ok(Width::new(bits)?),
        _ => Err(CliError::Usage(format!(
            "--bits must be 32 or 64, not {bits}"
        ))),
    }
}
