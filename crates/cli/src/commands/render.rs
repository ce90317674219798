//! `gartowen render`: the rendering benchmark inside Mitsuba 3, which lives in the Python
//! package (`gartowen.render`, as Mitsuba is a Python package); this command runs it with the
//! arguments given, or says what to install.

use crate::CliError;
use clap::Args;
use std::process::ExitCode;

/// Run the rendering benchmark in Mitsuba 3 (gartowen samplers against Mitsuba's own).
///
/// Runs `python3 -m gartowen.render` with the arguments that follow (GARTOWEN_PYTHON names
/// another interpreter): scenes of Mitsuba 3 rendered with gartowen's samplers (one fixed ART
/// table per render, per-pixel seeds) and Mitsuba's own, RMSE against a converged reference
/// over many seeds, verdicts per method pair and the fixed-table check. Needs the Python
/// package with Mitsuba (`pip install './python[mitsuba]'`) and libLLVM ≥ 16.
///
/// Examples:
///   gartowen render --quick --out out/render
///   gartowen render --out out/render --seeds 32 --sizes 16,64,100,256,1024
///   gartowen render --help          (the benchmark's own options)
#[derive(Args, Debug)]
#[command(verbatim_doc_comment, disable_help_flag = true)]
pub struct RenderArgs {
    /// Arguments of `python -m gartowen.render` (--quick, --out, --seeds, --sizes, --scenes,
    /// --resolution, --margin, --help).
    #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
    pub args: Vec<String>,
}

/// Where the Python package or Mitsuba is missing, the benchmark's own message (exit 2);
/// otherwise its exit code.
const LAUNCH: &str = "import sys\n\
try:\n    import gartowen.render as r\n\
except ImportError as e:\n    \
sys.stderr.write('gartowen render: the Python package is not installed (%s): pip install ./python[mitsuba]\\n' % e)\n    \
sys.exit(2)\n\
sys.exit(r.main(sys.argv[1:]))\n";

/// Runs `render`.
pub fn run(a: RenderArgs) -> Result<ExitCode, CliError> {
    let python = std::env::var("GARTOWEN_PYTHON").unwrap_or_else(|_| "python3".into());
    let status = std::process::Command::new(&python)
        .arg("-c")
        .arg(LAUNCH)
        .args(&a.args)
        .status()
        .map_err(|e| {
            CliError::Usage(format!(
                "cannot run {python} ({e}): the rendering benchmark needs Python with the \
                 gartowen package (pip install './python[mitsuba]'); GARTOWEN_PYTHON names the \
                 interpreter"
            ))
        })?;
    Ok(ExitCode::from(
        status.code().map_or(2, |c| c.clamp(0, 255) as u8),
    ))
}
