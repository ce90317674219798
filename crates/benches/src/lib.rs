//! gartowen's criterion benchmarks, in `benches/`: `cargo bench -p gartowen-benches` runs them
//! all, `--bench scramblers` every scrambler and sequence side by side (the table of
//! docs/performance.md). The library is empty: Cargo needs a target besides the benchmarks.
