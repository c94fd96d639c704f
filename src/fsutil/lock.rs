//! The lock on an output folder ([`DirLock`]): an advisory `flock` on `.viscoroll.lock`, which the
//! OS releases when its process ends, however it ends. The file's content (the holder's pid and
//! start time) only informs a waiting run; an empty, garbage or stale file never blocks, because
//! only the `flock` counts. While held, the folder is a [`Jail`].
//!
//! Input: a folder, a longest wait and a callback told once, at once, who holds the lock; output:
//! the lock, or an error of kind `WouldBlock` naming the holder and the lock's age.

use super::Jail;
use rustix::fs::{FlockOperation, Mode, OFlags, CWD};
use rustix::io::Errno;
use std::io::{self, Read as _, Write as _};
use std::os::fd::AsFd as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant, SystemTime};

/// The lock file's name inside the output folder.
pub(crate) const LOCK_FILE: &str = ".viscoroll.lock";

/// What a waiting run can tell about the holder: its pid and how long it has held the lock, as far
/// as the lock file tells (`None` when it does not).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LockHolder {
    /// The holder's process id, as written in the lock file.
    pub pid: Option<u32>,
    /// Time since the holder took the lock (the file's modification time).
    pub age: Option<Duration>,
}

impl std::fmt::Display for LockHolder {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.pid {
            Some(p) => write!(f, "process {p}")?,
            None => write!(f, "a process that did not write its id")?,
        }
        match self.age {
            Some(a) => write!(f, ", holding it for {} s", a.as_secs()),
            None => Ok(()),
        }
    }
}

/// A held lock on an output folder; released (and its file removed) when dropped.
#[derive(Debug)]
pub struct DirLock {
    file: std::fs::File,
    path: PathBuf,
    _jail: Jail,
}

/// Open (creating) the lock file: never through a symlink, never blocking on a FIFO, and only a
/// regular file.
fn open_lock_file(path: &Path) -> io::Result<std::fs::File> {
    let flags =
        OFlags::RDWR | OFlags::CREATE | OFlags::NOFOLLOW | OFlags::NONBLOCK | OFlags::CLOEXEC;
    let fd = rustix::fs::openat(CWD, path, flags, Mode::from_raw_mode(0o666)).map_err(|e| {
        if e == Errno::LOOP {
            io::Error::new(
                io::ErrorKind::PermissionDenied,
                format!("{} is a symbolic link; remove it", path.display()),
            )
        } else {
            e.into()
        }
    })?;
    let st = rustix::fs::fstat(&fd)?;
    if rustix::fs::FileType::from_raw_mode(st.st_mode) != rustix::fs::FileType::RegularFile {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{} is not a regular file; remove it", path.display()),
        ));
    }
    Ok(std::fs::File::from(fd))
}

/// Whether `file` is still the file at `path` (a holder that finished removed the name; a lock on
/// the removed file would lock nothing).
fn still_linked(file: &std::fs::File, path: &Path) -> bool {
    let (Ok(a), Ok(b)) = (
        rustix::fs::fstat(file.as_fd()),
        rustix::fs::statat(CWD, path, rustix::fs::AtFlags::SYMLINK_NOFOLLOW),
    ) else {
        return false;
    };
    a.st_dev == b.st_dev && a.st_ino == b.st_ino
}

/// What the lock file says about its holder.
fn holder(file: &mut std::fs::File) -> LockHolder {
    let mut text = String::new();
    let _ = (&*file).take(256).read_to_string(&mut text);
    let pid = text
        .split_whitespace()
        .find_map(|w| w.parse::<u32>().ok())
        .filter(|&p| p > 0);
    let age = file
        .metadata()
        .and_then(|m| m.modified())
        .ok()
        .and_then(|t| SystemTime::now().duration_since(t).ok());
    LockHolder { pid, age }
}

impl DirLock {
    /// Lock `dir` (creating it), waiting up to `timeout` for another process that holds it;
    /// `waiting` is called once, at once, with what is known of the holder, if we have to wait.
    pub fn acquire(
        dir: &Path,
        timeout: Duration,
        waiting: &dyn Fn(&LockHolder),
    ) -> io::Result<DirLock> {
        std::fs::create_dir_all(dir)?;
        let path = dir.join(LOCK_FILE);
        let start = Instant::now();
        let mut told = false;
        loop {
            let mut file = open_lock_file(&path)?;
            match rustix::fs::flock(file.as_fd(), FlockOperation::NonBlockingLockExclusive) {
                Ok(()) if still_linked(&file, &path) => {
                    // Informative only: a full disk here leaves an empty file, which blocks nobody.
                    let _ = file
                        .set_len(0)
                        .and_then(|()| writeln!(file, "{}", std::process::id()));
                    let _jail = Jail::enter(dir)?;
                    return Ok(DirLock { file, path, _jail });
                }
                Ok(()) => continue,
                Err(Errno::WOULDBLOCK) => {
                    let h = holder(&mut file);
                    if !told {
                        waiting(&h);
                        told = true;
                    }
                    if start.elapsed() >= timeout {
                        return Err(io::Error::new(
                            io::ErrorKind::WouldBlock,
                            format!(
                                "{} is locked by another viscoroll run ({h}); waited {} s (--wait)",
                                dir.display(),
                                timeout.as_secs()
                            ),
                        ));
                    }
                    std::thread::sleep(Duration::from_millis(100).min(timeout));
                }
                Err(e) => return Err(e.into()),
            }
        }
    }
}

impl Drop for DirLock {
    fn drop(&mut self) {
        // Remove the name while still holding the lock; a waiter that opened it sees it unlinked
        // (`still_linked`) and opens the new one. The lock goes with the file descriptor.
        let _ = std::fs::remove_file(&self.path);
        let _ = &self.file;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exclusive_released_on_drop_and_the_file_content_never_blocks() {
        let dir = std::env::temp_dir().join(format!("viscoroll-lock-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let short = Duration::from_millis(300);
        let held = DirLock::acquire(&dir, short, &|_| {}).unwrap();
        let waited = std::cell::Cell::new(None);
        let e = DirLock::acquire(&dir, short, &|h| waited.set(Some(*h))).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::WouldBlock);
        assert_eq!(waited.get().unwrap().pid, Some(std::process::id()));
        assert!(
            e.to_string()
                .contains(&format!("process {}", std::process::id())),
            "{e}"
        );
        drop(held);
        assert!(!dir.join(LOCK_FILE).exists());
        // Whatever a lock file holds, nobody holds its flock: taken at once.
        for content in ["", "hello", "-5", "1", "4294967", "\0\0\0"] {
            std::fs::write(dir.join(LOCK_FILE), content).unwrap();
            let l = DirLock::acquire(&dir, short, &|_| panic!("waited on {content:?}")).unwrap();
            drop(l);
        }
    }
}
