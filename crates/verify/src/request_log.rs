//! What the battery asks of an implementation, measured from the code: every call of a
//! stand-in (the Owen oracle seen as an external program sees it: one width, no inverse) is
//! logged per phase, and summarized as the dimensions, seeds, widths and words requested and
//! the instances alive at once. `verify --list-requests` prints it; the README's table is this
//! function's output (a test keeps it so, and another compares it with what a counting
//! program is sent).
//!
//! The stand-in answers with the words unchanged instead of scrambling them: what the battery
//! asks does not depend on the answers of an implementation that passes the structure checks,
//! and the identity passes every one the oracle passes (nested, injective, a function, nets
//! kept), and costs no evaluation.
//!
//! Instances: the battery builds one instance per seed for the laws and drops it when that
//! seed is done, so with T threads at most T + 1 instances (one per thread and the main
//! probe) are alive. Within each pass a seed's requests are contiguous, so an adapter that
//! keeps only the latest seed's instance builds one per "seed run".

use crate::candidate::Candidate;
use crate::level::Level;
use crate::structure::{Stage, STRUCTURE_CHECKS};
use gartowen_core::{Claim, PowerOfTwoBase, Scrambler, Width};
use std::collections::BTreeSet;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// What one phase of the battery (a structure check, or the law pass) requested.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct PhaseRequests {
    /// The check's name, or `laws` for the shared law pass and the families' own passes.
    pub phase: String,
    /// Calls (one protocol frame each for an external program).
    pub requests: u64,
    /// Words scrambled.
    pub words: u64,
    /// Dimensions requested.
    pub dims: BTreeSet<u32>,
    /// Seeds requested.
    pub seeds: BTreeSet<u64>,
    /// Word widths requested, in bits.
    pub widths: BTreeSet<u32>,
    /// The most instances alive at once (one thread).
    pub most_alive: usize,
    /// Runs of consecutive requests for one seed: the instances an adapter that keeps only
    /// the latest seed's builds (equal to the number of seeds when each seed's requests are
    /// contiguous; more when a later pass revisits seeds).
    pub seed_runs: u64,
}

#[derive(Default)]
struct Log {
    calls: Vec<(u64, u32, u32, u64)>,
    alive: AtomicUsize,
    most_alive: AtomicUsize,
}

impl Log {
    fn born(&self) {
        let now = self.alive.fetch_add(1, Ordering::SeqCst) + 1;
        self.most_alive.fetch_max(now, Ordering::SeqCst);
    }
}

/// One seed's instance of the stand-in, logging every call.
struct Logged<'a> {
    inner: Box<dyn Scrambler + 'a>,
    seed: u64,
    width: Width,
    log: Arc<Mutex<Log>>,
}

impl Drop for Logged<'_> {
    fn drop(&mut self) {
        self.log
            .lock()
            .expect("log")
            .alive
            .fetch_sub(1, Ordering::SeqCst);
    }
}

impl Scrambler for Logged<'_> {
    fn name(&self) -> String {
        self.inner.name()
    }
    fn base(&self) -> PowerOfTwoBase {
        self.inner.base()
    }
    fn claim(&self) -> Claim {
        self.inner.claim()
    }
    fn supports_width(&self, width: Width) -> bool {
        width == self.width
    }
    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        self.log
            .lock()
            .expect("log")
            .calls
            .push((self.seed, dim, width.bits(), 1));
        x
    }
    fn scramble_batch(&self, words: &mut [u64], width: Width, dim: u32) {
        let n = words.len() as u64;
        self.log
            .lock()
            .expect("log")
            .calls
            .push((self.seed, dim, width.bits(), n));
        // The words stay as they are: the identity (see the module doc).
        let _ = words;
    }
}

/// Runs of equal consecutive values.
fn seed_runs(seeds: impl Iterator<Item = u64>) -> u64 {
    let mut last = None;
    let mut runs = 0;
    for s in seeds {
        if last != Some(s) {
            runs += 1;
            last = Some(s);
        }
    }
    runs
}

fn summarize(phase: &str, log: &Mutex<Log>) -> PhaseRequests {
    let mut log = log.lock().expect("log");
    let calls = std::mem::take(&mut log.calls);
    let most_alive = log
        .most_alive
        .swap(log.alive.load(Ordering::SeqCst), Ordering::SeqCst);
    PhaseRequests {
        phase: phase.to_string(),
        requests: calls.len() as u64,
        words: calls.iter().map(|c| c.3).sum(),
        dims: calls.iter().map(|c| c.1).collect(),
        seeds: calls.iter().map(|c| c.0).collect(),
        widths: calls.iter().map(|c| c.2).collect(),
        most_alive,
        seed_runs: seed_runs(calls.iter().map(|c| c.0)),
    }
}

/// The requests of every phase of `verify --level LEVEL` on the candidate `make` builds (its
/// instances are the stand-in: the Owen oracle of the base asked about), seen as an external
/// program of `width`-bit words with no inverse sees them, on one thread (the order is then
/// fixed; with T threads, T seeds are in flight at once). Phases that do not apply (no twin:
/// no `expect`) are left out.
pub fn log_requests<'a>(
    make: impl FnOnce() -> Candidate<'a> + Send,
    level: Level,
    width: Width,
    seed: u64,
) -> Vec<PhaseRequests> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool");
    pool.install(move || {
        let c = make();
        let log = Arc::new(Mutex::new(Log::default()));
        let with_seed = c.with_seed;
        let instance = {
            let log = log.clone();
            move |s: u64| -> Result<Box<dyn Scrambler + 'a>, String> {
                let inner = with_seed(s)?;
                log.lock().expect("log").born();
                Ok(Box::new(Logged {
                    inner,
                    seed: s,
                    width,
                    log: log.clone(),
                }))
            }
        };
        let probe = instance(seed).expect("the stand-in builds");
        let logged = Candidate {
            probe,
            with_seed: Box::new(instance),
            many: None,
            health: Box::new(|| None),
            ..c
        };
        summarize("(probe)", &log);
        let plan = level.plan();
        let mut out = Vec::new();
        let structure = |stage: Stage, out: &mut Vec<PhaseRequests>| {
            for check in STRUCTURE_CHECKS
                .iter()
                .filter(|s| s.stage == stage && (s.applies)(&logged))
            {
                (check.run)(&logged, plan);
                out.push(summarize(check.name, &log));
            }
        };
        structure(Stage::BeforeLaws, &mut out);
        crate::law_runner::run_laws(&logged, level, 0).expect("the stand-in builds");
        out.push(summarize("laws", &log));
        structure(Stage::AfterLaws, &mut out);
        out
    })
}

/// `0..=63, 127, 255`: a set of integers as runs.
pub fn runs<T: Copy + Into<u64>>(set: &BTreeSet<T>) -> String {
    let mut parts: Vec<String> = Vec::new();
    let mut it = set.iter().map(|&x| x.into()).peekable();
    while let Some(first) = it.next() {
        let mut last = first;
        while it.peek() == Some(&(last + 1)) {
            last = it.next().expect("peeked");
        }
        parts.push(match last - first {
            0 => first.to_string(),
            1 => format!("{first}, {last}"),
            _ => format!("{first}..={last}"),
        });
    }
    if parts.is_empty() {
        "-".into()
    } else {
        parts.join(", ")
    }
}

/// The phases as a Markdown table: phase, requests, words, dimensions, seeds, widths,
/// instances alive at once, seed runs.
pub fn markdown(phases: &[PhaseRequests]) -> String {
    let mut out = String::from(
        "| phase | requests | words | dimensions | seeds | widths | alive at once | seed runs |\n\
         |---|---:|---:|---|---|---|---:|---:|\n",
    );
    for p in phases {
        let seeds = if p.seeds.len() > 3 {
            format!("{} ({})", runs(&p.seeds), p.seeds.len())
        } else {
            runs(&p.seeds)
        };
        let widths: Vec<String> = p.widths.iter().map(u32::to_string).collect();
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} |\n",
            p.phase,
            p.requests,
            p.words,
            runs(&p.dims),
            seeds,
            if widths.is_empty() {
                "-".into()
            } else {
                widths.join(", ")
            },
            p.most_alive,
            p.seed_runs,
        ));
    }
    out
}

/// The header of [`level_row`]'s table.
pub const LEVEL_HEADER: &str = "| level | requests | words | dimensions | seeds | widths | \
     alive at once | seed runs |\n|---|---:|---:|---|---|---|---:|---:|\n";

/// One Markdown row for a whole level: `| level | requests | words | dimensions | seeds |
/// widths | alive at once | seed runs |`, summed (or joined) over its phases.
pub fn level_row(level: Level, phases: &[PhaseRequests]) -> String {
    let union = |f: &dyn Fn(&PhaseRequests) -> Vec<u64>| -> BTreeSet<u64> {
        phases.iter().flat_map(f).collect()
    };
    let dims = union(&|p| p.dims.iter().map(|&d| d as u64).collect());
    let seeds = union(&|p| p.seeds.iter().copied().collect());
    let widths: Vec<String> = union(&|p| p.widths.iter().map(|&w| w as u64).collect())
        .iter()
        .map(u64::to_string)
        .collect();
    format!(
        "| {} | {} | {} | {} | {} ({}) | {} | {} | {} |",
        level.name(),
        phases.iter().map(|p| p.requests).sum::<u64>(),
        phases.iter().map(|p| p.words).sum::<u64>(),
        runs(&dims),
        runs(&seeds),
        seeds.len(),
        widths.join(", "),
        phases.iter().map(|p| p.most_alive).max().unwrap_or(0),
        phases.iter().map(|p| p.seed_runs).sum::<u64>(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runs_of_integers_and_of_seeds() {
        let set: BTreeSet<u32> = [0, 1, 2, 3, 5, 7, 8, 127].into_iter().collect();
        assert_eq!(runs(&set), "0..=3, 5, 7, 8, 127");
        assert_eq!(runs(&BTreeSet::<u32>::new()), "-");
        assert_eq!(seed_runs([1, 1, 2, 2, 3].into_iter()), 3);
        assert_eq!(seed_runs([1, 2, 1, 2].into_iter()), 4);
        assert_eq!(seed_runs([7].into_iter()), 1);
        assert_eq!(seed_runs(std::iter::empty()), 0);
    }
}
