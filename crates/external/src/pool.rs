//! Several instances of one external program behind one [`Scrambler`], so that parallel work
//! (the every-word sweep runs one chunk per thread) keeps every instance busy: each batch goes
//! to an idle instance, and waits for one when all are busy.

use crate::{ExternalError, ExternalProcess, ExternalScrambler};
use gartowen_core::{Claim, PowerOfTwoBase, Scrambler, Width};
use std::sync::{Arc, Condvar, Mutex};

/// A pool of instances of one external program, all with the same seed.
pub struct ExternalPool {
    members: Vec<ExternalScrambler>,
    processes: Vec<Arc<ExternalProcess>>,
    idle: Mutex<Vec<usize>>,
    freed: Condvar,
}

impl ExternalPool {
    /// The pool over `processes` (at least one, same program, base and width), each answering
    /// for `seed`, judged on `claim`.
    pub fn new(processes: Vec<Arc<ExternalProcess>>, seed: u64, claim: Claim) -> ExternalPool {
        assert!(!processes.is_empty(), "a pool needs an instance");
        ExternalPool {
            members: processes
                .iter()
                .map(|p| ExternalScrambler::new(p.clone(), seed, claim))
                .collect(),
            idle: Mutex::new((0..processes.len()).rev().collect()),
            processes,
            freed: Condvar::new(),
        }
    }

    /// Instances in the pool.
    pub fn len(&self) -> usize {
        self.members.len()
    }

    /// Always false: a pool has at least one instance.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The first failure of any instance (they share the program, so one failure condemns it).
    pub fn failure(&self) -> Option<ExternalError> {
        self.processes.iter().find_map(|p| p.failure())
    }

    /// Runs `f` on an idle instance, waiting for one if all are busy.
    fn with_member<R>(&self, f: impl FnOnce(&ExternalScrambler) -> R) -> R {
        let k = {
            let mut idle = self.idle.lock().unwrap_or_else(|e| e.into_inner());
            loop {
                if let Some(k) = idle.pop() {
                    break k;
                }
                idle = self.freed.wait(idle).unwrap_or_else(|e| e.into_inner());
            }
        };
        // Returned to the idle list even if `f` panics, so other threads never wait forever.
        struct Release<'a>(&'a ExternalPool, usize);
        impl Drop for Release<'_> {
            fn drop(&mut self) {
                self.0
                    .idle
                    .lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .push(self.1);
                self.0.freed.notify_one();
            }
        }
        let _release = Release(self, k);
        f(&self.members[k])
    }
}

impl Scrambler for ExternalPool {
    fn name(&self) -> String {
        self.members[0].name()
    }
    fn base(&self) -> PowerOfTwoBase {
        self.members[0].base()
    }
    fn claim(&self) -> Claim {
        self.members[0].claim()
    }
    fn supports_width(&self, width: Width) -> bool {
        self.members[0].supports_width(width)
    }
    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        self.with_member(|m| m.scramble(x, width, dim))
    }
    fn scramble_batch(&self, words: &mut [u64], width: Width, dim: u32) {
        self.with_member(|m| m.scramble_batch(words, width, dim))
    }
    fn scramble_batch_u32(&self, words: &mut [u32], dim: u32) {
        self.with_member(|m| m.scramble_batch_u32(words, dim))
    }
}
