//! Exact, readable reference implementations that the fast paths are judged against.
