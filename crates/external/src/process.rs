//! The child program: its command line, process group, pipes, timeouts and exit status.

use crate::deadline_write::{make_non_blocking, write_before, WriteStop};
use crate::error::ExternalError;
use crate::protocol::ProtocolBase;
use crate::protocol::*;
use gartowen_core::Width;
use std::io::Read;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Splits a command line into words: whitespace separates, single or double quotes group
/// (no escapes, no variables; the program is run directly, not through a shell).
pub fn split_command(line: &str) -> Result<Vec<String>, ExternalError> {
    let mut words = Vec::new();
    let mut word = String::new();
    let mut in_word = false;
    let mut quote: Option<char> = None;
    for c in line.chars() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), c) => word.push(c),
            (None, '\'' | '"') => {
                quote = Some(c);
                in_word = true;
            }
            (None, c) if c.is_whitespace() => {
                if in_word {
                    words.push(std::mem::take(&mut word));
                    in_word = false;
                }
            }
            (None, c) => {
                word.push(c);
                in_word = true;
            }
        }
    }
    if let Some(q) = quote {
        return Err(ExternalError::BadCommand(format!(
            "unbalanced {q} in '{line}'"
        )));
    }
    if in_word {
        words.push(word);
    }
    if words.is_empty() {
        return Err(ExternalError::BadCommand("empty command".into()));
    }
    Ok(words)
}

struct Session {
    child: Child,
    stdin: Option<ChildStdin>,
    stdout: Receiver<Vec<u8>>,
    pending: Vec<u8>,
    /// The request frame of the 32-bit path, reused from request to request.
    frame: Vec<u8>,
    batches: u64,
    failure: Option<ExternalError>,
}

/// One running external program (one session of the protocol).
pub struct ExternalProcess {
    command: String,
    width: Width,
    base: ProtocolBase,
    timeout: Duration,
    stderr: Arc<Mutex<Vec<u8>>>,
    /// Inodes of the pipes to the child's stdin, stdout and stderr.
    pipes: Vec<u64>,
    session: Mutex<Session>,
}

const STDERR_KEEP: usize = 4096;

/// How often a wait for a reply looks at whether the child is still alive.
const EXIT_POLL: Duration = Duration::from_millis(50);

/// Process groups (leader pids) of the external programs still running, with the inodes of
/// their pipes, so that a signal handler can end them: a process killed by a signal runs no
/// `Drop`.
static LIVE_GROUPS: Mutex<Vec<(u32, Vec<u64>)>> = Mutex::new(Vec::new());

/// Whether this process has started an external program (only then can it have orphans of
/// one to end).
static SPAWNED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Whether [`ExternalProcess::spawn`] has started a program in this process.
pub fn any_spawned() -> bool {
    SPAWNED.load(std::sync::atomic::Ordering::SeqCst)
}

/// Kills the process group of every external program still running (with its helpers), and
/// every process still holding one of their pipes (helpers that left the group with
/// `setsid`). Meant for a signal handler's last act before the process ends.
pub fn kill_live_groups() {
    let groups: Vec<(u32, Vec<u64>)> = LIVE_GROUPS
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .drain(..)
        .collect();
    #[cfg(unix)]
    for (pid, _) in &groups {
        // SAFETY: kill(2) with a valid signal number has no memory-safety preconditions.
        unsafe {
            libc::kill(-(*pid as i32), libc::SIGKILL);
        }
    }
    let pipes: Vec<u64> = groups.into_iter().flat_map(|(_, p)| p).collect();
    crate::pipe_holders::kill_holders(&pipes);
}

/// Kills the child's process group, reaps the child, then kills whatever still holds its
/// pipes (a helper that escaped the group).
fn kill_group(child: &mut Child, pipes: &[u64]) {
    LIVE_GROUPS
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .retain(|(p, _)| *p != child.id());
    #[cfg(unix)]
    {
        // The child leads its own process group; a negative pid signals the whole group, so
        // helpers it started (e.g. a shell's children) die with it.
        // SAFETY: kill(2) with a valid signal number has no memory-safety preconditions.
        unsafe {
            libc::kill(-(child.id() as i32), libc::SIGKILL);
        }
    }
    let _ = child.kill();
    let _ = child.wait();
    crate::pipe_holders::kill_holders(pipes);
}

/// The inodes of the pipes behind the child's standard streams.
fn child_pipes(child: &Child) -> Vec<u64> {
    #[cfg(unix)]
    {
        use std::os::unix::io::AsRawFd;
        let fds = [
            child.stdin.as_ref().map(|x| x.as_raw_fd()),
            child.stdout.as_ref().map(|x| x.as_raw_fd()),
            child.stderr.as_ref().map(|x| x.as_raw_fd()),
        ];
        fds.into_iter()
            .flatten()
            .filter_map(crate::pipe_holders::pipe_inode)
            .collect()
    }
    #[cfg(not(unix))]
    {
        let _ = child;
        Vec::new()
    }
}

impl ExternalProcess {
    /// Starts `command` (split by [`split_command`]) for words of `width` bits in `base`;
    /// each reply must arrive within `timeout`.
    pub fn spawn(
        command: &str,
        base: impl Into<ProtocolBase>,
        width: Width,
        timeout: Duration,
    ) -> Result<ExternalProcess, ExternalError> {
        let base = base.into();
        if width != Width::W32 && width != Width::W64 {
            return Err(ExternalError::BadRequest(format!(
                "width {} (the protocol carries 32- or 64-bit words)",
                width.bits()
            )));
        }
        let words = split_command(command)?;
        let mut cmd = Command::new(&words[0]);
        cmd.args(&words[1..])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped());
        #[cfg(unix)]
        std::os::unix::process::CommandExt::process_group(&mut cmd, 0);
        let mut child = cmd.spawn().map_err(|e| ExternalError::Spawn {
            program: words[0].clone(),
            reason: e.to_string(),
        })?;
        SPAWNED.store(true, std::sync::atomic::Ordering::SeqCst);
        let pipes = child_pipes(&child);
        LIVE_GROUPS
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .push((child.id(), pipes.clone()));
        let stdin = child.stdin.take();
        if let Some(pipe) = &stdin {
            if let Err(e) = make_non_blocking(pipe) {
                kill_group(&mut child, &pipes);
                return Err(ExternalError::Spawn {
                    program: words[0].clone(),
                    reason: format!("cannot make its stdin non-blocking: {e}"),
                });
            }
        }
        let mut out = child.stdout.take().expect("piped stdout");
        let mut err = child.stderr.take().expect("piped stderr");
        // Reader threads turn blocking pipes into a channel the host can wait on with a
        // deadline; they end at EOF, which the kill in Drop guarantees.
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            let mut buf = vec![0u8; 1 << 16];
            while let Ok(n) = out.read(&mut buf) {
                if n == 0 || tx.send(buf[..n].to_vec()).is_err() {
                    break;
                }
            }
        });
        let stderr = Arc::new(Mutex::new(Vec::new()));
        let sink = Arc::clone(&stderr);
        std::thread::spawn(move || {
            let mut buf = [0u8; 4096];
            while let Ok(n) = err.read(&mut buf) {
                if n == 0 {
                    break;
                }
                let mut s = sink.lock().expect("stderr buffer");
                s.extend_from_slice(&buf[..n]);
                let excess = s.len().saturating_sub(STDERR_KEEP);
                s.drain(..excess);
            }
        });
        Ok(ExternalProcess {
            command: command.to_string(),
            width,
            base,
            timeout,
            stderr,
            pipes,
            session: Mutex::new(Session {
                child,
                stdin,
                stdout: rx,
                pending: Vec::new(),
                frame: Vec::new(),
                batches: 0,
                failure: None,
            }),
        })
    }

    /// The command line.
    pub fn command(&self) -> &str {
        &self.command
    }

    /// The word width requests carry.
    pub fn width(&self) -> Width {
        self.width
    }

    /// The scrambling base the program was started for.
    pub fn base(&self) -> ProtocolBase {
        self.base
    }

    /// The child's process id (its process group id too).
    pub fn pid(&self) -> u32 {
        self.session.lock().expect("session").child.id()
    }

    /// The first failure of this session, if any.
    pub fn failure(&self) -> Option<ExternalError> {
        self.session.lock().expect("session").failure.clone()
    }

    fn stderr_tail(&self) -> String {
        // Let the stderr thread drain what a dying child wrote.
        std::thread::sleep(Duration::from_millis(50));
        String::from_utf8_lossy(&self.stderr.lock().expect("stderr")).into_owned()
    }

    /// Scrambles `words` (dimension `dim`, seed `seed`) in one request.
    pub fn scramble_batch(
        &self,
        seed: u64,
        dim: u32,
        words: &[u64],
    ) -> Result<Vec<u64>, ExternalError> {
        self.with_session(|s| {
            let frame = encode_request(&self.header(seed, dim), words)?;
            let need = self.exchange(s, &frame, words.len())?;
            let out = decode_reply(
                &s.pending[..need],
                words.len(),
                self.width,
                self.base,
                s.batches,
            );
            s.pending.clear();
            out
        })
    }

    /// Scrambles 32-bit `words` in place in one request (the session must carry 32-bit words);
    /// the request frame and the reply buffer are reused, so a long run allocates nothing per
    /// request.
    pub fn scramble_batch_u32(
        &self,
        seed: u64,
        dim: u32,
        words: &mut [u32],
    ) -> Result<(), ExternalError> {
        if self.width != Width::W32 || words.is_empty() || words.len() > MAX_BATCH {
            return Err(ExternalError::BadRequest(format!(
                "{} 32-bit words for a {}-bit session (1..={MAX_BATCH} allowed)",
                words.len(),
                self.width.bits()
            )));
        }
        self.with_session(|s| {
            let mut frame = std::mem::take(&mut s.frame);
            frame.clear();
            push_header(&mut frame, &self.header(seed, dim), words.len());
            for &w in words.iter() {
                frame.extend_from_slice(&w.to_le_bytes());
            }
            let result = self.exchange(s, &frame, words.len());
            s.frame = frame;
            let need = result?;
            check_reply(
                &s.pending[..need],
                words.len(),
                self.width,
                self.base,
                s.batches,
            )?;
            for (w, b) in words.iter_mut().zip(s.pending[8..need].chunks_exact(4)) {
                *w = u32::from_le_bytes(b.try_into().expect("4 bytes"));
            }
            s.pending.clear();
            Ok(())
        })
    }

    fn header(&self, seed: u64, dim: u32) -> RequestHeader {
        RequestHeader {
            width: self.width,
            base: self.base,
            dim,
            seed,
        }
    }

    /// Runs `f` on the session unless it has failed; a failure of `f` (other than a refused
    /// request) poisons the session and kills the program.
    fn with_session<R>(
        &self,
        f: impl FnOnce(&mut Session) -> Result<R, ExternalError>,
    ) -> Result<R, ExternalError> {
        let mut s = self.session.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(f) = &s.failure {
            return Err(f.clone());
        }
        let result = f(&mut s);
        if let Err(e) = &result {
            if !matches!(e, ExternalError::BadRequest(_)) {
                s.failure = Some(e.clone());
                s.stdin = None;
                kill_group(&mut s.child, &self.pipes);
            }
        }
        result
    }

    /// Sends one request frame of `count` words and waits for the whole reply, which then
    /// starts `s.pending`; returns the reply's length in bytes.
    fn exchange(
        &self,
        s: &mut Session,
        frame: &[u8],
        count: usize,
    ) -> Result<usize, ExternalError> {
        s.batches += 1;
        let batch = s.batches;
        let need = 8 + count * self.width.bits() as usize / 8;
        // One deadline for the whole request, write and reply. A timeout past what Instant can
        // represent waits "forever" instead of panicking.
        let now = Instant::now();
        let deadline = now
            .checked_add(self.timeout)
            .unwrap_or_else(|| now + Duration::from_secs(365 * 86_400));
        let Session { stdin, child, .. } = s;
        let stdin = stdin.as_mut().expect("open until failure");
        let write = write_before(stdin, frame, deadline, || {
            matches!(child.try_wait(), Ok(Some(_)))
        });
        match write {
            Ok(()) => {}
            Err(WriteStop::Deadline { written }) => {
                return Err(ExternalError::WriteTimeout {
                    batch,
                    seconds: self.timeout.as_secs_f64(),
                    written,
                    total: frame.len(),
                })
            }
            Err(WriteStop::Io(e)) => {
                return Err(
                    self.exited_or(s, batch, need, |stderr| ExternalError::WriteFailed {
                        batch,
                        reason: e.to_string(),
                        stderr,
                    }),
                )
            }
        }
        // Set once the child is seen to have exited while its stdout stays open.
        let mut exited_at: Option<Instant> = None;
        while s.pending.len() < need {
            let now = Instant::now();
            let left = deadline.saturating_duration_since(now);
            match s.stdout.recv_timeout(left.min(EXIT_POLL)) {
                Ok(chunk) => {
                    s.pending.extend_from_slice(&chunk);
                    // A reply that starts wrong is garbage now; do not wait for more bytes.
                    let k = s.pending.len().min(4);
                    if s.pending[..k] != REPLY_MAGIC[..k] {
                        return Err(ExternalError::Garbage {
                            batch,
                            detail: format!(
                                "starts with {:?} ({:02x?}), not the reply magic GOWR",
                                String::from_utf8_lossy(&s.pending[..k]),
                                &s.pending[..k]
                            ),
                        });
                    }
                }
                Err(RecvTimeoutError::Timeout) if left > EXIT_POLL => {
                    // A dead child whose stdout is held open by a helper outside its group
                    // never sends end of file: look at the child itself. Bytes it wrote
                    // before exiting get one more poll to arrive.
                    match exited_at {
                        Some(t) if t.elapsed() >= EXIT_POLL => {
                            let received = s.pending.len();
                            return Err(self.exited_or(s, batch, need, |stderr| {
                                ExternalError::Exited {
                                    batch,
                                    status: "exited".into(),
                                    received,
                                    expected: need,
                                    stderr,
                                }
                            }));
                        }
                        Some(_) => {}
                        None => {
                            if let Ok(Some(_)) = s.child.try_wait() {
                                exited_at = Some(Instant::now());
                            }
                        }
                    }
                }
                Err(RecvTimeoutError::Timeout) => {
                    return Err(ExternalError::Timeout {
                        batch,
                        seconds: self.timeout.as_secs_f64(),
                        received: s.pending.len(),
                        expected: need,
                    })
                }
                Err(RecvTimeoutError::Disconnected) => {
                    let received = s.pending.len();
                    return Err(
                        self.exited_or(s, batch, need, |stderr| ExternalError::Exited {
                            batch,
                            status: "closed its stdout".into(),
                            received,
                            expected: need,
                            stderr,
                        }),
                    );
                }
            }
        }
        if s.pending.len() > need {
            return Err(ExternalError::Garbage {
                batch,
                detail: format!("{} bytes beyond the reply", s.pending.len() - need),
            });
        }
        Ok(need)
    }

    /// The child's exit as an error if it has exited (waiting briefly), else `otherwise`.
    fn exited_or(
        &self,
        s: &mut Session,
        batch: u64,
        need: usize,
        otherwise: impl FnOnce(String) -> ExternalError,
    ) -> ExternalError {
        let start = Instant::now();
        while start.elapsed() < Duration::from_millis(500) {
            if let Ok(Some(status)) = s.child.try_wait() {
                let mut status = describe_status(status);
                let held = crate::pipe_holders::holders(&self.pipes);
                if !held.is_empty() {
                    let pids: Vec<String> = held.iter().map(|p| p.to_string()).collect();
                    status += &format!(
                        "; its pipes are still held open by pid {}, started outside its \
                         process group (killed with the program)",
                        pids.join(", ")
                    );
                }
                return ExternalError::Exited {
                    batch,
                    status,
                    received: s.pending.len(),
                    expected: need,
                    stderr: self.stderr_tail(),
                };
            }
            std::thread::sleep(Duration::from_millis(5));
        }
        otherwise(self.stderr_tail())
    }
}

fn describe_status(status: std::process::ExitStatus) -> String {
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(sig) = status.signal() {
            return format!("was killed by signal {sig}");
        }
    }
    match status.code() {
        Some(c) => format!("exited with status {c}"),
        None => "exited".into(),
    }
}

impl Drop for ExternalProcess {
    fn drop(&mut self) {
        // A poisoned session (a panic elsewhere) must still end the child.
        let s = self.session.get_mut().unwrap_or_else(|e| e.into_inner());
        // Closing stdin asks a well-behaved child to exit; give it a moment, then kill the group.
        s.stdin = None;
        let start = Instant::now();
        while start.elapsed() < Duration::from_millis(200) {
            if let Ok(Some(_)) = s.child.try_wait() {
                break;
            }
            std::thread::sleep(Duration::from_millis(2));
        }
        kill_group(&mut s.child, &self.pipes);
    }
}
