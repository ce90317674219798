//! Descendants that leave both the program's process group and its pipes: a program that
//! forks twice, calls `setsid` in the grandchild and closes every descriptor. No group kill and
//! no pipe scan reaches such a process, and its parent is gone.
//!
//! On Linux a process that declares itself a child subreaper (`PR_SET_CHILD_SUBREAPER`) gets
//! every orphan among its descendants as its own child instead of init's. A host whose only
//! children are external programs (the `gartowen` command) adopts them so, and at its end
//! kills every child it still has: by then the programs it started are ended and reaped, so
//! what remains are their escaped descendants. A library host (a Python session, a test
//! harness) has children of its own and does not adopt.

/// Makes this process the reaper of its orphaned descendants; `false` where the system has
/// no such thing (not Linux) or refuses.
pub fn adopt_orphans() -> bool {
    #[cfg(target_os = "linux")]
    {
        // SAFETY: prctl with PR_SET_CHILD_SUBREAPER takes an integer flag and touches no memory.
        unsafe { libc::prctl(libc::PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0 }
    }
    #[cfg(not(target_os = "linux"))]
    {
        false
    }
}

/// The pids of this process's live children, read from `/proc` (none elsewhere).
pub fn children() -> Vec<u32> {
    let me = std::process::id();
    let Ok(procs) = std::fs::read_dir("/proc") else {
        return Vec::new();
    };
    let mut out: Vec<u32> = procs
        .flatten()
        .filter_map(|d| {
            let pid: u32 = d.file_name().to_str()?.parse().ok()?;
            let stat = std::fs::read_to_string(d.path().join("stat")).ok()?;
            // After the command name: state, ppid, ...
            let rest: Vec<&str> = stat.rsplit_once(") ")?.1.split(' ').collect();
            (rest.get(1)?.parse::<u32>().ok()? == me).then_some(pid)
        })
        .collect();
    out.sort_unstable();
    out
}

/// Kills (SIGKILL, with its process group) and reaps every child this process still has,
/// again for those their deaths hand over, at most `rounds` times; returns the pids killed.
pub fn kill_children(rounds: usize) -> Vec<u32> {
    let mut killed = Vec::new();
    for _ in 0..rounds {
        let pids = children();
        if pids.is_empty() {
            break;
        }
        #[cfg(unix)]
        for &pid in &pids {
            // SAFETY: kill(2) and waitpid(2) on a pid, with a valid signal and a null status
            // pointer, have no memory-safety preconditions.
            unsafe {
                libc::kill(-(pid as i32), libc::SIGKILL);
                libc::kill(pid as i32, libc::SIGKILL);
                libc::waitpid(pid as i32, std::ptr::null_mut(), 0);
            }
        }
        killed.extend(pids);
    }
    killed
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    use super::*;

    #[test]
    fn a_child_is_listed_until_it_is_reaped() {
        // kill_children is exercised by the CLI's containment test: here other test threads
        // have children of their own, which it would kill.
        let mut child = std::process::Command::new("sleep")
            .arg("30")
            .spawn()
            .unwrap();
        let pid = child.id();
        assert!(children().contains(&pid));
        child.kill().unwrap();
        child.wait().unwrap();
        assert!(!children().contains(&pid));
    }
}
