//! The arguments of `gartowen verify`, shared by its modes (the sampled battery in
//! [`super::verify`], the every-word sweep in [`super::sweep`]).

use clap::{Args, ValueEnum};
use gartowen::certificate::{fnv1a64, InputRecord};
use std::path::PathBuf;

/// Battery size.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum LevelArg {
    /// About 6 s for the whole registry on 2 cores (the CI gate).
    Quick,
    /// Larger samples and deeper nets.
    Full,
    /// Long (minutes); split it with --shard and combine with --merge.
    Exhaustive,
}

/// Which bases the nets check uses.
#[derive(Clone, Copy, Debug, clap::ValueEnum, PartialEq, Eq)]
pub enum NetBases {
    /// The base and every base 2^(kq) ≤ 256 it is nested in.
    Nested,
    /// The base alone.
    Own,
}

/// Run the conformance battery. Structure is checked exactly: inverse (injectivity for external
/// programs), nestedness (inspector), net preservation in the scrambling base. Randomness is
/// checked by laws over independent seeds:
///   node-law    each node permutation uniform over the claimed group, depths 0..12 (marginal)
///   pair-law    pairs of nodes (siblings, parent-child, cousins, distant) independent (joint)
///   flip-rank   no exact GF(2) relation among node flips of depths ≤ D, dims 0-1 (joint)
///   collisions  no two subtrees alike within one seed (joint; finite tables show here)
///   pair-lemma  Owen's pair lemma for inputs first differing at digit r (marginal + joint)
///   dimensions  dimensions 0..64 distinct (marginal) and root pairs independent (joint)
///
/// Each implementation is judged only on what it claims (`gartowen list` shows the claims;
/// --claim overrides them): `nested`, `marginal:GROUP` (node permutations uniform over
/// symmetric|affine|translation|cyclic; `per-depth[:GROUP]` says the same), `independent:GROUP`,
/// or `owen` (= independent:symmetric).
/// Unclaimed checks are `measured`. The family-wise false-alarm rate of a run is 1e-3
/// (Bonferroni over implementations and sub-tests); a pass reads "no deviation detected at this
/// power", and each sub-test's power (smallest Cohen's w at power 0.9, or what an exact test
/// detects) is in the JSON. The profile line shows, per family and depth 0, 1, 2, …, where an
/// implementation departs from Owen: `.` nothing detected, `x` deviation, `?` not measured
/// (the program failed, or a sub-test needs a dimension beyond --max-dims), `-` not tested.
///
/// Prints a table (implementation × check). Exit codes: 0 every check passed, 1 a check
/// failed, 2 bad usage or input, 3 the external program failed (crash, exit, hang, garbage).
///
/// Examples:
///   gartowen verify --list-checks       (what the battery runs, and every size per level)
///   gartowen verify --list-requests --level full --base 16   (what a program is asked for)
///   gartowen verify --level quick
///   gartowen verify --impl art-owen-16p --impl lk-hash --json verify.json
///   gartowen verify --level quick --profile     (where the time goes: slowest checks, words)
///   gartowen verify --impl digital-shift --impl lk-hash --claim owen     (imitations fail)
///   gartowen verify --level exhaustive --shard 2/4 --json shard2.json     (one CI job of four)
///   gartowen verify --merge shard1.json shard2.json shard3.json shard4.json --json all.json
///
/// Every word (--level exhaustive --dims A..B): all 2^32 inputs of each dimension, in order,
/// through the batch path, proving bijective and nested at every depth (3-40 s per dimension
/// for built-ins on 2 cores, about 1 min for the C example over pipes; under 50 MB of memory).
/// Scramblers without 32-bit support are swept at 24 bits; 64-bit words are refused (2^64 words
/// cannot be enumerated; the sampled checks apply). --shard I/N cuts the (implementation,
/// dimension, chunk) units into N contiguous runs, so N dividing the dimensions shards by
/// dimension and other N split inside dimensions; --merge joins the shards and refuses a
/// missing, doubled or foreign one:
///   gartowen verify --level exhaustive --dims 0..3 --impl art-owen-2 --impl lk-hash
///   gartowen verify --level exhaustive --dims 0..1023 --impl art-owen-2 --shard 7/32 --json s7.json
///   gartowen verify --level exhaustive --dims 0..3 --external ./lk_hash --base 2 --claim nested
///   gartowen verify --level exhaustive --dims 0..1023 --external ./lk_hash --estimate   (cost first)
///
/// External implementations (the protocol is in docs/external.md):
///   gartowen verify --external './my_scrambler --fast' --base 16 --width 32
///   gartowen verify --external ./owen_per_bit --base 2 --width 64 --expect owen-per-bit-hash
///   gartowen verify --external ./four_dims --base 2 --max-dims 4   (serves dimensions 0..3)
///   gartowen verify --external ./twelve_bits --base 2 --bits 12    (scrambles the top 12 bits)
///
/// Equivalence to Owen (the estimator variance against the exact Owen variance of the base,
/// TOST with a stated margin; the seeds used are printed and in the JSON):
///   gartowen verify --impl art-owen-16p --equivalent-to owen --margin 0.1
///   gartowen verify --external ./owen_nested --base 16 --equivalent-to owen --equivalence-seeds 4000
#[derive(Args, Debug)]
#[command(verbatim_doc_comment)]
#[command(group(clap::ArgGroup::new("program").args(["external", "list_requests"]).multiple(true)))]
pub struct VerifyArgs {
    /// Battery size.
    #[arg(long, value_enum, default_value_t = LevelArg::Quick)]
    pub level: LevelArg,
    /// Implementations to verify (registry names, with options); default: all.
    #[arg(long = "impl")]
    pub implementations: Vec<String>,
    /// Also write the report as JSON to this file.
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Run only shard I of N (1 ≤ I ≤ N): implementation k goes to shard (k mod N) + 1.
    #[arg(long)]
    pub shard: Option<String>,
    /// Combine shard JSON files (from --json) into one report instead of running checks.
    #[arg(long, num_args = 1.., conflicts_with_all = ["shard", "implementations"])]
    pub merge: Vec<PathBuf>,
    /// Verify an external program speaking the gartowen protocol instead of the registry
    /// (the command line is split on spaces; quotes group; no shell is involved).
    #[arg(long, conflicts_with_all = ["implementations", "merge"])]
    pub external: Option<String>,
    /// Every-word sweep of dimensions A..B (both included; or one dimension A) with
    /// --level exhaustive: every 2^32 input word of each dimension (2^24 for scramblers without
    /// 32-bit support) is scrambled and checked for bijectivity and nestedness at every depth,
    /// in one streaming pass. 64-bit words cannot be enumerated (2^64 words) and are refused;
    /// the sampled levels (without --dims) check them.
    #[arg(long, conflicts_with_all = ["merge", "expect"])]
    pub dims: Option<String>,
    /// With --dims: estimate what the every-word sweep will cost instead of running it, from a
    /// timed probe of about a second per implementation (words per second on this machine),
    /// with the time per shard for 1, 4, 16 and 64 shards. Writes nothing; exit 0.
    #[arg(long, requires = "dims", conflicts_with_all = ["json", "junit", "shard"])]
    pub estimate: bool,
    /// Scrambling base of the external program: a power of two 2..=256 (protocol version 1,
    /// digits in the word's bits), or any other base 3..=65535 (version 2, words are base-b
    /// digit integers below b^m; flip-rank then does not apply).
    #[arg(long, default_value_t = 2, requires = "program")]
    pub base: u64,
    /// Word width the external program receives: 32 or 64.
    #[arg(long, default_value_t = 32, requires = "program")]
    pub width: u32,
    /// The external program serves dimensions 0..N only (a sampler with N dimensions per
    /// domain): no check asks for another. Checks choose their dimensions among those served
    /// (`nets` takes the first ones, `dimensions` compares 0..N); a sub-test that needs a
    /// dimension beyond them (root pairs up to (0,63); flip-rank needs 2) reports
    /// "not run: needs dimension D" and `?` in the profile, and counts towards no verdict.
    #[arg(long, value_name = "N", requires = "program",
          value_parser = clap::value_parser!(u32).range(1..))]
    pub max_dims: Option<u32>,
    /// Seed of the external program's main instance (the node law uses seeds 0, 1, 2, …).
    #[arg(long, default_value_t = 0, requires = "external")]
    pub seed: u64,
    /// Require bit-exact agreement with this built-in implementation (registry name).
    #[arg(long, requires = "external")]
    pub expect: Option<String>,
    /// Seconds to wait for each reply before the program is killed.
    #[arg(long, default_value_t = 10.0, requires = "external")]
    pub timeout: f64,
    /// The external program does not claim any law (same as --claim nested).
    #[arg(long, requires = "external", conflicts_with = "claim")]
    pub no_uniform_claim: bool,
    /// Also write JUnit XML (one testsuite per implementation, one testcase per check; for
    /// the every-word sweep, one testcase per dimension piece).
    #[arg(long)]
    pub junit: Option<PathBuf>,
    /// Judge on this claim instead of each implementation's own: nested | owen |
    /// `marginal[:GROUP]` | `per-depth[:GROUP]` (= marginal) | `independent:GROUP` (GROUP:
    /// symmetric, affine, translation, cyclic).
    /// External programs default to owen.
    #[arg(long)]
    pub claim: Option<String>,
    /// Also test equivalence to the full-tree Owen scramble of the implementation's base: the
    /// variance of a box-volume estimator (64 fixed points, boxes of 1, 2 and 3 digits) over
    /// seeds 0..S, divided by its exact Owen value, must have its 90% interval inside
    /// [1 − margin, 1 + margin] at every level (TOST, α = 0.05). Check `equivalent-to-owen`:
    /// pass = equivalent; fail = different, or inconclusive with the seeds that would decide.
    #[arg(long, value_parser = ["owen"], conflicts_with_all = ["merge", "dims"])]
    pub equivalent_to: Option<String>,
    /// Equivalence margin on the variance ratio (0 < margin < 1).
    #[arg(long, default_value_t = gartowen::battery::equivalence::DEFAULT_MARGIN,
          value_parser = super::parse_margin, requires = "equivalent_to")]
    pub margin: f64,
    /// Seeds of the equivalence check (default: 10000 quick, 40000 full, 100000 exhaustive;
    /// at most 1000000).
    #[arg(long, value_parser = clap::value_parser!(u64).range(2..=1_000_000),
          requires = "equivalent_to")]
    pub equivalence_seeds: Option<u64>,
    /// Print what the battery runs and exit: every check in report order with what a claim
    /// must promise for it to be judged, and every size per level. With --json FILE the
    /// listing is written there as JSON instead.
    #[arg(long, conflicts_with_all = ["merge", "external", "dims", "shard", "implementations",
          "junit", "equivalent_to", "claim"])]
    pub list_checks: bool,
    /// Print what the battery would ask an external program for at --level, phase by phase,
    /// and exit: requests (protocol frames), words, dimensions, seeds, widths, instances
    /// alive at once and the most recent seeds a per-seed cache needs (measured on the Owen
    /// oracle of --base at --width, one thread, honouring --max-dims; a failing program may
    /// be asked less). With --json FILE the phases are written there as JSON instead.
    #[arg(long, conflicts_with_all = ["merge", "external", "dims", "shard", "implementations",
          "junit", "equivalent_to", "claim", "list_checks"])]
    pub list_requests: bool,
    /// Bases the nets check uses: `nested` (default), the program's base and every base
    /// 2^(kq) ≤ 256 a nested scramble in it is also nested in (what the claim implies); `own`,
    /// its base only, for a program never meant for the larger bases (no Faure dimensions
    /// up to 255 are then asked for).
    #[arg(long, value_enum, default_value_t = NetBases::Nested, requires = "program")]
    pub net_bases: NetBases,
    /// Judge only the top K bits of each word of the external program (a library that
    /// scrambles the ⌈log2 N⌉ bits its point count needs): requests carry K-bit words in the
    /// top of --width-bit words (zeros below) and only the top K bits of each reply count;
    /// depths below digit K are not tested. K from log2(--base) to --width.
    #[arg(long, value_name = "K", requires = "external",
          conflicts_with_all = ["dims", "expect", "equivalent_to"])]
    pub bits: Option<u32>,
    /// After the table, print where the time went: the 10 slowest (implementation, check)
    /// entries with seconds and words scrambled, then totals per check and per
    /// implementation (the seconds are also in the JSON, per check).
    #[arg(long, conflicts_with_all = ["dims", "list_checks"])]
    pub profile: bool,
}

/// The certificate's record of an external program: its command line and, where the program
/// file can be read, the checksum of its bytes.
pub fn program_record(command: &str) -> InputRecord {
    let program = gartowen::external::split_command(command)
        .ok()
        .and_then(|w| w.into_iter().next());
    let checksum = program
        .as_ref()
        .and_then(|p| std::fs::read(p).ok())
        .map(|bytes| format!("{:016x}", fnv1a64(&bytes)));
    InputRecord {
        kind: "program".into(),
        name: command.into(),
        checksum_fnv1a64: checksum,
        details: serde_json::json!({ "program": program }),
    }
}
