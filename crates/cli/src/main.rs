//! The `gartowen` command-line tool.

mod cleanup;
mod commands;
mod error;
mod input;
mod output;
mod paths;
mod progress;

use clap::{Parser, Subcommand};
use error::CliError;
use std::process::ExitCode;

/// gartowen: generate, scramble and verify quasi-Monte Carlo point sets in bases 2^q.
///
/// Points are W-bit words x with value x·2^-W in [0,1). Sequences are digital: point n of
/// dimension j XORs the generator columns at the set bits of n.
#[derive(Parser)]
#[command(name = "gartowen", version, about, long_about = None, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    Generate(commands::generate::GenerateArgs),
    Scramble(commands::scramble::ScrambleArgs),
    Check(commands::check::CheckArgs),
    Inspect(commands::inspect::InspectArgs),
    Discrepancy(commands::discrepancy::DiscrepancyArgs),
    Verify(commands::verify::VerifyArgs),
    Matrices(commands::matrices::MatricesArgs),
    List(commands::list::ListArgs),
    Report(commands::report::ReportArgs),
    Certificate(commands::certificate::CertificateArgs),
    Scene(commands::scene::SceneArgs),
    Render(commands::render::RenderArgs),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_exit(e),
    };
    cleanup::install();
    let result = match cli.command {
        Command::Generate(a) => commands::generate::run(a),
        Command::Scramble(a) => commands::scramble::run(a),
        Command::Check(a) => commands::check::run(a),
        Command::Inspect(a) => commands::inspect::run(a),
        Command::Discrepancy(a) => commands::discrepancy::run(a),
        Command::Verify(a) => commands::verify::run(a),
        Command::Matrices(a) => commands::matrices::run(a),
        Command::List(a) => commands::list::run(a),
        Command::Report(a) => commands::report::run(a),
        Command::Certificate(a) => commands::certificate::run(a),
        Command::Scene(a) => commands::scene::run(a),
        Command::Render(a) => commands::render::run(a),
    };
    cleanup::end_adopted();
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("gartowen: error: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}

/// Prints what clap has to say (help, version, a usage error) and the exit code: 0 for help
/// and version, 2 otherwise. Help that cannot be written (a full disk) is an error, exit 2.
fn clap_exit(e: clap::Error) -> ExitCode {
    use std::io::Write;
    let informational = matches!(
        e.kind(),
        clap::error::ErrorKind::DisplayHelp | clap::error::ErrorKind::DisplayVersion
    );
    if !informational {
        let _ = e.print();
        return ExitCode::from(error::EXIT_USAGE);
    }
    let text = e.render().to_string();
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(err) => {
            eprintln!("gartowen: error: cannot write the help to standard output: {err}");
            ExitCode::from(error::EXIT_USAGE)
        }
    }
}
