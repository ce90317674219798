//! Progress of a long computation, the one shape every crate reports through: a stage starts
//! with its number of units, units are done (from any thread), a message names what is being
//! done, the stage finishes. A display (the CLI's bars, Python's callbacks) implements it; the
//! library code only calls it, and [`Silent`] ignores it.

/// Progress of a long computation. Every method has a no-op default, so a display implements
/// only what it shows; calls may come from many threads at once.
///
/// A closure over units done is a `Progress` that counts and ignores the rest:
///
/// ```
/// use gartowen_core::Progress;
/// use std::sync::atomic::{AtomicU64, Ordering};
/// let done = AtomicU64::new(0);
/// let count = |k: u64| {
///     done.fetch_add(k, Ordering::Relaxed);
/// };
/// let progress: &dyn Progress = &count;
/// progress.start(10, "words");
/// progress.advance(4);
/// progress.advance(6);
/// assert_eq!(done.load(Ordering::Relaxed), 10);
/// ```
pub trait Progress: Sync {
    /// A stage begins with `total` units (0 when unknown) of kind `what`.
    fn start(&self, total: u64, what: &str) {
        let _ = (total, what);
    }
    /// `k` more units are done.
    fn advance(&self, k: u64) {
        let _ = k;
    }
    /// What is being done now (a name for the display).
    fn message(&self, what: &str) {
        let _ = what;
    }
    /// The stage is done.
    fn finish(&self) {}
}

/// No progress display.
#[derive(Debug, Clone, Copy, Default)]
pub struct Silent;

impl Progress for Silent {}

impl<F: Fn(u64) + Sync> Progress for F {
    fn advance(&self, k: u64) {
        self(k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicU64, Ordering};

    #[test]
    fn a_closure_counts_the_units_and_ignores_the_rest() {
        let done = AtomicU64::new(0);
        let count = |k: u64| {
            done.fetch_add(k, Ordering::Relaxed);
        };
        let p: &dyn Progress = &count;
        p.start(100, "words");
        p.message("dimension 0");
        p.advance(3);
        p.advance(4);
        p.finish();
        assert_eq!(done.load(Ordering::Relaxed), 7);
        Silent.advance(5); // and Silent ignores everything
    }
}
