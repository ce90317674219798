//! `gartowen inspect`: is a registered scrambler a nested scramble in base B?

use crate::CliError;
use clap::Args;
use gartowen::core::{BuildContext, PowerOfTwoBase, Width};
use gartowen::oracles::inspector::{inspect_exhaustive, inspect_probes, InspectReport};
use std::process::ExitCode;

/// Decide from black-box evaluations whether a scrambler is a nested scramble in base B.
///
/// Nested: output digit k depends only on input digits 0..k, and every node's map on digit k is
/// a bijection. Widths ≤ 16 are checked exhaustively; 32 and 64 bits by seeded node probes
/// (each probe evaluates all B digits of one node with two random tails). The report gives the
/// first violation (node, two inputs, two outputs) and the law of reconstructed node
/// permutations against uniform S_B. Exit 0 when nested, 1 when not, 2 on bad usage.
///
/// Examples:
///   gartowen inspect --scramble owen-oracle --base 4 --width 16
///   gartowen inspect --scramble owen-oracle:base=16 --base 2 --width 16      (exit 1)
///   gartowen inspect --scramble owen-oracle:xor --base 16 --width 64 --probes 5000 --json
#[derive(Args, Debug)]
#[command(verbatim_doc_comment)]
pub struct InspectArgs {
    /// Scrambler from the registry, NAME[:OPTION...].
    #[arg(long)]
    pub scramble: String,
    /// Base B = 2^q in which to test nestedness (also the default base of the scrambler).
    #[arg(long)]
    pub base: u64,
    /// Word width in bits (≤ 16 exhaustive; 32 or 64 by probes).
    #[arg(long, default_value_t = 16)]
    pub width: u32,
    /// Depth K (digits) to which node permutations are reconstructed (default: all).
    #[arg(long)]
    pub depth: Option<u32>,
    /// Number of node probes for widths above 16.
    #[arg(long, default_value_t = 2000)]
    pub probes: u64,
    /// Seed of the scrambler.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Seed of the probe generator.
    #[arg(long, default_value_t = 1)]
    pub probe_seed: u64,
    /// Dimension to inspect.
    #[arg(long, default_value_t = 0)]
    pub dim: u32,
    /// Print the report as JSON.
    #[arg(long)]
    pub json: bool,
}

fn text(r: &InspectReport, name: &str) -> String {
    let mut out = format!(
        "{name}: {} in base {} ({}-bit words, {:?}, {} evaluations, {} nodes)\n",
        if r.nested_scramble {
            "nested scramble"
        } else {
            "NOT a nested scramble"
        },
        r.base,
        r.width,
        r.mode,
        r.evaluations,
        r.nodes_checked
    );
    if let Some(v) = &r.first_violation {
        out += &format!(
            "  first violation: {:?} at depth {}, prefix {:#x}: inputs {:#x}, {:#x} -> outputs {:#x}, {:#x}\n",
            v.kind, v.depth, v.prefix, v.inputs[0], v.inputs[1], v.outputs[0], v.outputs[1]
        );
    } else {
        out += &format!(
            "  node permutations ({} cells = {}): chi-square {:.1} on {} dof, total variation {:.4}\n",
            r.node_law.counts.len(),
            r.node_law.cells_are,
            r.node_law.chi_square,
            r.node_law.dof,
            r.node_law.total_variation
        );
    }
    out
}

/// Runs `inspect`.
pub fn run(a: InspectArgs) -> Result<ExitCode, CliError> {
    let base = PowerOfTwoBase::from_base(a.base)?;
    let width = Width::new(a.width)?;
    let ctx = BuildContext {
        seed: a.seed,
        default_base: base,
    };
    let s = gartowen::registry().build_with(&a.scramble, &ctx)?;
    if !s.supports_width(width) {
        return Err(CliError::Usage(format!(
            "{} does not support {}-bit words",
            s.name(),
            a.width
        )));
    }
    let depth = a.depth.unwrap_or(u32::MAX);
    let f = |x: u64| s.scramble(x, width, a.dim);
    let report = if a.width <= 16 {
        inspect_exhaustive(&f, width, base, depth)
    } else {
        if a.probes == 0 {
            return Err(CliError::Usage("--probes must be at least 1".into()));
        }
        inspect_probes(&f, width, base, depth, a.probes, a.probe_seed)
    };
    if a.json {
        let doc = serde_json::json!({
            "tool": "gartowen", "version": env!("CARGO_PKG_VERSION"), "command": "inspect",
            "scrambler": s.name(), "seed": a.seed, "dim": a.dim, "report": report,
        });
        println!("{}", serde_json::to_string_pretty(&doc).expect("json"));
    } else {
        print!("{}", text(&report, &s.name()));
    }
    Ok(if report.nested_scramble {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
