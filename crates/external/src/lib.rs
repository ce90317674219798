//! External scramblers: a child program that speaks the gartowen scrambling protocol on its
//! stdin and stdout, wrapped as a [`Scrambler`](gartowen_core::Scrambler) so the verify battery judges it like a built-in.
//!
//! # Protocol (version 1, every integer little-endian)
//!
//! The host sends request frames and the child answers each one before the next is sent:
//!
//! | offset | size | request field                                     |
//! |--------|------|---------------------------------------------------|
//! | 0      | 4    | magic `GOWQ` (bytes 0x47 0x4F 0x57 0x51)          |
//! | 4      | 2    | protocol version: 1 (b = 2^q) or 2 (other b)      |
//! | 6      | 2    | word width in bits, 32 or 64                      |
//! | 8      | 4    | base b                                            |
//! | 12     | 4    | dimension (selects the independent scramble)      |
//! | 16     | 4    | count n of words that follow (1 ≤ n ≤ 2^20)       |
//! | 20     | 4    | reserved, 0                                       |
//! | 24     | 8    | seed                                              |
//! | 32     | n·w/8| the input words                                   |
//!
//! The reply is the magic `GOWR`, the count n again (u32), then the n scrambled words in order.
//!
//! In version 1 (b = 2^q, q = 1..8) a word is a W-bit binary fraction, value x·2^-W, base-b
//! digit k in its bits. Version 2 (b in 3..=65535, not a power of two) has the same framing,
//! but a word is an integer below b^m of m base-b digits, value x·b^-m, m the most digits with
//! b^m ≤ 2^W (base 3: 20 digits in 32 bits, 40 in 64); replies stay below b^m. A program that
//! knows only version 1 refuses version 2 requests by exiting non-zero, as above.
//! The child exits with status 0 when its stdin closes. A child that cannot serve a request
//! (unknown base or width) writes a reason to stderr and exits non-zero; the host reports the
//! stderr text. Every request names its seed, so one process serves every seed the battery
//! needs.
//!
//! Failures the host detects and names: the program cannot start, exits or dies by a signal,
//! does not answer within the timeout (it is killed), answers with too few bytes, or answers
//! with garbage (wrong magic or count). After the first failure the session is poisoned: every
//! later call returns 0 without talking to the child, and [`ExternalProcess::failure`] names the
//! first failure. The child runs in its own process group, and the whole group is killed when
//! the session ends, so nothing is left running.

//!
//! The parts: [`protocol`] (frames, bytes only), [`error`] (what went wrong, in words),
//! [`process`] (the child, its process group and its pipes; [`pipe_holders`] finds processes
//! that still hold them), [`adapter`] (one seed's view as a [`gartowen_core::Scrambler`]) and
//! [`pool`] (several processes serving parallel workers).

pub mod adapter;
mod deadline_write;
pub mod error;
pub mod orphans;
pub mod pipe_holders;
pub mod pool;
pub mod process;
pub mod protocol;

pub use adapter::{ExternalRadixScrambler, ExternalScrambler};
pub use error::ExternalError;
pub use process::{any_spawned, kill_live_groups, split_command, ExternalProcess};
pub use protocol::{
    decode_reply, decode_request, encode_request, ProtocolBase, RequestHeader, HEADER_BYTES,
    MAX_BATCH, PROTOCOL_VERSION, RADIX_PROTOCOL_VERSION, REPLY_MAGIC, REQUEST_MAGIC,
};
