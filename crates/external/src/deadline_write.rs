//! Writing a request to the child's stdin within a deadline.
//!
//! A pipe holds 64 KiB; a blocking write of a larger request waits for as long as the child
//! does not read, so a child that never reads, stops reading or is stopped (SIGSTOP) would hold
//! the host past any timeout. The host's end of the pipe is made non-blocking and each write
//! waits with `poll(2)` for room, never past the request's deadline.

use std::io::{self, Write};
use std::process::ChildStdin;
use std::time::{Duration, Instant};

/// Why a request was not written whole.
#[derive(Debug)]
pub enum WriteStop {
    /// The deadline passed with `written` bytes of the request taken.
    Deadline {
        /// Bytes of the request the child did read.
        written: usize,
    },
    /// The pipe failed (the child closed its stdin or exited).
    Io(io::Error),
}

/// Makes the host's end of the child's stdin non-blocking (the child's end is another open
/// file description and keeps blocking).
pub fn make_non_blocking(stdin: &ChildStdin) -> io::Result<()> {
    #[cfg(unix)]
    {
        use std::os::unix::io::AsRawFd;
        let fd = stdin.as_raw_fd();
        // SAFETY: fcntl(2) on a descriptor this process owns; F_GETFL/F_SETFL touch only flags.
        let flags = unsafe { libc::fcntl(fd, libc::F_GETFL) };
        if flags < 0 {
            return Err(io::Error::last_os_error());
        }
        // SAFETY: as above.
        if unsafe { libc::fcntl(fd, libc::F_SETFL, flags | libc::O_NONBLOCK) } < 0 {
            return Err(io::Error::last_os_error());
        }
    }
    #[cfg(not(unix))]
    let _ = stdin;
    Ok(())
}

/// Writes all of `frame` before `deadline`, calling `gone` between waits: when it says the
/// child has exited, the write stops with a broken pipe instead of waiting out the deadline
/// (a helper may hold the pipe open after the child's exit).
pub fn write_before(
    stdin: &mut ChildStdin,
    frame: &[u8],
    deadline: Instant,
    mut gone: impl FnMut() -> bool,
) -> Result<(), WriteStop> {
    let mut written = 0;
    while written < frame.len() {
        match stdin.write(&frame[written..]) {
            Ok(0) => {
                return Err(WriteStop::Io(io::Error::new(
                    io::ErrorKind::WriteZero,
                    "the pipe took no bytes",
                )))
            }
            Ok(n) => written += n,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) if e.kind() == io::ErrorKind::WouldBlock => {
                let left = deadline.saturating_duration_since(Instant::now());
                if left.is_zero() {
                    return Err(WriteStop::Deadline { written });
                }
                if gone() {
                    return Err(WriteStop::Io(io::Error::new(
                        io::ErrorKind::BrokenPipe,
                        "the program exited without reading the request",
                    )));
                }
                wait_for_room(stdin, left.min(POLL))?;
            }
            Err(e) => return Err(WriteStop::Io(e)),
        }
    }
    Ok(())
}

/// How long one wait for room lasts before the deadline and the child are looked at again.
const POLL: Duration = Duration::from_millis(50);

/// Waits at most `wait` for room in the pipe (or its closing).
fn wait_for_room(stdin: &ChildStdin, wait: Duration) -> Result<(), WriteStop> {
    #[cfg(unix)]
    {
        use std::os::unix::io::AsRawFd;
        let mut fd = libc::pollfd {
            fd: stdin.as_raw_fd(),
            events: libc::POLLOUT,
            revents: 0,
        };
        // At least 1 ms, so that a sub-millisecond remainder does not spin.
        let ms = wait.as_millis().clamp(1, i32::MAX as u128) as libc::c_int;
        // SAFETY: one valid pollfd, count 1, a bounded timeout.
        let r = unsafe { libc::poll(&mut fd, 1, ms) };
        if r < 0 {
            let e = io::Error::last_os_error();
            if e.kind() != io::ErrorKind::Interrupted {
                return Err(WriteStop::Io(e));
            }
        }
    }
    #[cfg(not(unix))]
    {
        let _ = stdin;
        std::thread::sleep(wait);
    }
    Ok(())
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;
    use std::process::{Command, Stdio};

    fn child(script: &str) -> std::process::Child {
        Command::new("sh")
            .args(["-c", script])
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .spawn()
            .unwrap()
    }

    #[test]
    fn a_child_that_never_reads_stops_the_write_at_the_deadline() {
        let mut c = child("exec sleep 30");
        let mut stdin = c.stdin.take().unwrap();
        make_non_blocking(&stdin).unwrap();
        let frame = vec![7u8; 1 << 20];
        let start = Instant::now();
        let r = write_before(
            &mut stdin,
            &frame,
            start + Duration::from_millis(300),
            || false,
        );
        let took = start.elapsed();
        let _ = c.kill();
        let _ = c.wait();
        match r {
            // The pipe took its buffer's worth and no more.
            Err(WriteStop::Deadline { written }) => {
                assert!(written > 0 && written < frame.len(), "{written}")
            }
            other => panic!("expected the deadline, got {other:?}"),
        }
        assert!(took >= Duration::from_millis(300), "{took:?}");
        assert!(took < Duration::from_secs(5), "{took:?}");
    }

    #[test]
    fn a_reading_child_takes_a_request_larger_than_the_pipe() {
        let mut c = child("cat >/dev/null");
        let mut stdin = c.stdin.take().unwrap();
        make_non_blocking(&stdin).unwrap();
        let frame = vec![1u8; 4 << 20];
        let r = write_before(
            &mut stdin,
            &frame,
            Instant::now() + Duration::from_secs(60),
            || false,
        );
        assert!(r.is_ok(), "{r:?}");
        drop(stdin);
        assert!(c.wait().unwrap().success());
    }

    #[test]
    fn a_child_that_closed_its_stdin_fails_the_write_at_once_not_at_the_deadline() {
        // The child closes its end of the pipe, then lives on: the write must fail with the
        // pipe's own error (a broken pipe), not wait for room until the deadline.
        let mut c = child("exec 0<&-; exec sleep 30");
        let mut stdin = c.stdin.take().unwrap();
        make_non_blocking(&stdin).unwrap();
        std::thread::sleep(Duration::from_millis(200));
        let frame = vec![0u8; 1 << 20];
        let start = Instant::now();
        let r = write_before(&mut stdin, &frame, start + Duration::from_secs(30), || {
            false
        });
        let _ = c.kill();
        let _ = c.wait();
        assert!(
            matches!(&r, Err(WriteStop::Io(e)) if e.kind() == io::ErrorKind::BrokenPipe),
            "{r:?}"
        );
        assert!(start.elapsed() < Duration::from_secs(5));
    }

    #[test]
    fn a_child_seen_gone_ends_the_wait_before_the_deadline() {
        let mut c = child("exec sleep 30");
        let mut stdin = c.stdin.take().unwrap();
        make_non_blocking(&stdin).unwrap();
        let frame = vec![0u8; 1 << 20];
        let start = Instant::now();
        let r = write_before(&mut stdin, &frame, start + Duration::from_secs(30), || true);
        let _ = c.kill();
        let _ = c.wait();
        assert!(
            matches!(&r, Err(WriteStop::Io(e)) if e.kind() == io::ErrorKind::BrokenPipe),
            "{r:?}"
        );
        assert!(start.elapsed() < Duration::from_secs(5));
    }
}
