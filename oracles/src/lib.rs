//! Exact, readable reference implementations that the fast paths are judged against.
//! Readable before fast: each one is the definition, written out.

pub mod box_counting;
