//! Processes that hold an external program's pipes open after it is gone.
//!
//! An external program runs in its own process group, and the host kills the group. A helper
//! that calls `setsid` leaves the group (and its session) but keeps the pipes it inherited:
//! it survives the group kill, and as long as it holds the program's stdout the host sees no
//! end of file, so a dead program would read as a hung one until the timeout.
//!
//! A pipe is named by its inode. Only processes that inherited (or were handed) a descriptor
//! of the pipes the host created for this program can hold them, so every holder is one of
//! the program's descendants; on Linux they are found by reading `/proc/*/fd`. Elsewhere
//! nothing is found and the behaviour is the group kill alone.

/// The inode of the pipe behind descriptor `fd`, or `None` when it is not a pipe or cannot
/// be inspected.
#[cfg(unix)]
pub fn pipe_inode(fd: std::os::unix::io::RawFd) -> Option<u64> {
    // SAFETY: a zeroed `stat` is a valid value of the plain C struct.
    let mut st: libc::stat = unsafe { std::mem::zeroed() };
    // SAFETY: fstat writes into the stat buffer we own; a bad fd only returns -1.
    let rc = unsafe { libc::fstat(fd, &mut st) };
    (rc == 0 && st.st_mode & libc::S_IFMT == libc::S_IFIFO).then_some(st.st_ino as u64)
}

/// The inode of the pipe behind descriptor `fd` (never found on non-Unix systems).
#[cfg(not(unix))]
pub fn pipe_inode(_fd: i32) -> Option<u64> {
    None
}

/// Pids of the processes other than this one that hold a descriptor of one of `inodes`
/// (pipes), in increasing order. Processes whose descriptors cannot be read (another user's)
/// are skipped.
pub fn holders(inodes: &[u64]) -> Vec<u32> {
    if inodes.is_empty() {
        return Vec::new();
    }
    let names: Vec<String> = inodes.iter().map(|i| format!("pipe:[{i}]")).collect();
    let me = std::process::id();
    let Ok(procs) = std::fs::read_dir("/proc") else {
        return Vec::new();
    };
    let mut out: Vec<u32> = procs
        .flatten()
        .filter_map(|d| d.file_name().to_str()?.parse::<u32>().ok())
        .filter(|&pid| pid != me)
        .filter(|pid| {
            let Ok(fds) = std::fs::read_dir(format!("/proc/{pid}/fd")) else {
                return false;
            };
            fds.flatten().any(|fd| {
                std::fs::read_link(fd.path())
                    .ok()
                    .and_then(|l| l.to_str().map(|s| names.iter().any(|n| n == s)))
                    .unwrap_or(false)
            })
        })
        .collect();
    out.sort_unstable();
    out
}

/// Kills (SIGKILL) every process other than this one that holds one of `inodes`; returns
/// their pids.
pub fn kill_holders(inodes: &[u64]) -> Vec<u32> {
    let pids = holders(inodes);
    #[cfg(unix)]
    for &pid in &pids {
        // SAFETY: kill(2) with a valid signal number has no memory-safety preconditions.
        unsafe {
            libc::kill(pid as i32, libc::SIGKILL);
        }
    }
    pids
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    use super::*;
    use std::os::unix::io::AsRawFd;
    use std::process::{Command, Stdio};

    #[test]
    fn a_child_holding_a_pipe_is_found_and_killed_and_a_file_is_no_pipe() {
        let mut child = Command::new("sleep")
            .arg("30")
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .spawn()
            .unwrap();
        let ino = pipe_inode(child.stdin.as_ref().unwrap().as_raw_fd()).expect("a pipe");
        assert_eq!(holders(&[ino]), vec![child.id()]);
        assert_eq!(holders(&[ino ^ (1 << 40)]), Vec::<u32>::new());
        assert_eq!(holders(&[]), Vec::<u32>::new());
        assert_eq!(kill_holders(&[ino]), vec![child.id()]);
        let status = child.wait().unwrap();
        use std::os::unix::process::ExitStatusExt;
        assert_eq!(status.signal(), Some(libc::SIGKILL));
        let file = std::fs::File::open("/proc/self/stat").unwrap();
        assert_eq!(pipe_inode(file.as_raw_fd()), None);
        assert_eq!(pipe_inode(-1), None);
    }
}
