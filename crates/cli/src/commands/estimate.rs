//! `verify --level exhaustive --dims A..B --estimate`: what the every-word sweep will cost, said
//! before a CI matrix or a job array is sized. Each implementation is timed on whole chunks of
//! its first dimension for about a second (an external program through its pipes, as the run
//! will be), and the words of the whole run are divided by that rate. A shard takes a contiguous
//! run of chunks, so N shards each take about the run's time / N on a machine like this one.

use super::sweep::{targets, DimRange};
use super::verify_args::{LevelArg, VerifyArgs};
use crate::CliError;
use gartowen::word_sweep::sweep;
use std::process::ExitCode;
use std::time::Instant;

/// How long the probe of each implementation runs, at least one chunk.
const PROBE_SECONDS: f64 = 1.0;

/// Shard counts the estimate is printed for.
const SHARDS: [u64; 4] = [1, 4, 16, 64];

/// The cost of one implementation's part of the sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// Words the probe scrambled and checked.
    pub probe_words: u64,
    /// Seconds the probe took.
    pub probe_seconds: f64,
    /// Words of the whole run (every word of every dimension).
    pub run_words: u64,
}

impl Estimate {
    /// Words per second in the probe.
    pub fn rate(&self) -> f64 {
        self.probe_words as f64 / self.probe_seconds.max(1e-9)
    }

    /// Seconds of the whole run at the probe's rate.
    pub fn seconds(&self) -> f64 {
        self.run_words as f64 / self.rate()
    }
}

/// A duration for people: seconds, minutes or hours with 2–3 significant digits.
pub fn duration_words(seconds: f64) -> String {
    if seconds < 120.0 {
        format!("{seconds:.1} s")
    } else if seconds < 7200.0 {
        format!("{:.1} min", seconds / 60.0)
    } else {
        format!("{:.1} h", seconds / 3600.0)
    }
}

/// Runs the probes and prints the estimate.
pub fn run(a: &VerifyArgs, dims_text: &str) -> Result<ExitCode, CliError> {
    if a.level != LevelArg::Exhaustive {
        return Err(CliError::Usage(
            "--estimate sizes the every-word sweep, which is --level exhaustive --dims A..B".into(),
        ));
    }
    let dims = DimRange::parse(dims_text)?;
    let threads = rayon::current_num_threads();
    crate::outln!(
        "estimate of `verify --level exhaustive --dims {dims_text}` on this machine ({threads} threads), from a probe of about {PROBE_SECONDS} s per implementation:"
    );
    let mut total = 0.0;
    for t in targets(a)? {
        let started = Instant::now();
        let mut chunks = 0;
        while chunks < t.plan.chunks()
            && (chunks == 0 || started.elapsed().as_secs_f64() < PROBE_SECONDS)
        {
            sweep(
                t.scrambler.as_ref(),
                &t.plan,
                dims.first,
                chunks..chunks + 1,
                &|_| {},
            )
            .map_err(|e| CliError::Usage(e.to_string()))?;
            if let Some(e) = t.pool.as_ref().and_then(|p| p.failure()) {
                return Err(CliError::External(e.to_string()));
            }
            chunks += 1;
        }
        let e = Estimate {
            probe_words: chunks * t.plan.chunk_words(),
            probe_seconds: started.elapsed().as_secs_f64(),
            run_words: t.plan.words().saturating_mul(dims.count()),
        };
        total += e.seconds();
        let shards: Vec<String> = SHARDS
            .iter()
            .map(|&n| format!("{n}: {}", duration_words(e.seconds() / n as f64)))
            .collect();
        crate::outln!(
            "  {}: {:.3e} words/s ({} words in {:.2} s); {} dimension(s) × {} words = {:.3e} words ≈ {}; per shard ({})",
            t.name,
            e.rate(),
            e.probe_words,
            e.probe_seconds,
            dims.count(),
            t.plan.words(),
            e.run_words as f64,
            duration_words(e.seconds()),
            shards.join(", ")
        );
    }
    crate::outln!(
        "  in all ≈ {} with {threads} threads; a shard on a machine with other cores scales with them (the sweep is CPU-bound), plus a second or two of scheduler per job",
        duration_words(total)
    );
    Ok(ExitCode::SUCCESS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rates_and_durations_are_what_they_say() {
        let e = Estimate {
            probe_words: 1 << 24,
            probe_seconds: 0.5,
            run_words: 4 << 32,
        };
        assert_eq!(e.rate(), 2.0 * (1u64 << 24) as f64);
        // 2^34 words at 2^25 per second: 512 s.
        assert_eq!(e.seconds(), 512.0);
        assert_eq!(duration_words(59.94), "59.9 s");
        assert_eq!(duration_words(512.0), "8.5 min");
        assert_eq!(duration_words(9000.0), "2.5 h");
        // The boundaries belong to the larger unit.
        assert_eq!(duration_words(120.0), "2.0 min");
        assert_eq!(duration_words(7200.0), "2.0 h");
    }
}
