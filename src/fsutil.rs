//! Atomic file writes, shared by every stage and the CLI: write a temporary file in the target's
//! folder, flush it to disk, then move it into place, so a reader never sees a half-written file
//! and a crash leaves either the old file or the new one.
//!
//! Input: a path and bytes (or a finished temporary file); output: the file, or an
//! [`std::io::Error`] (kind `AlreadyExists` when `replace` is false and the file exists). Callers wrap
//! the error in their stage's enum.

use std::io::{self, Write as _};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// A fresh temporary path beside `path`: `.NAME.tmp-PID-N.EXT`, keeping the extension (the bitmap
/// encoder picks the image format from it). Unique within the process and across processes.
pub fn temp_path(path: &Path) -> PathBuf {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let ext = path
        .extension()
        .map(|e| format!(".{}", e.to_string_lossy()))
        .unwrap_or_default();
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    dir.join(format!(".{stem}.tmp-{}-{n}{ext}", std::process::id()))
}

/// Move a finished temporary file `tmp` to `path`. With `replace` false an existing `path` is
/// never replaced, not even one that appears meanwhile (a hard link fails if the name exists; on
/// file systems without hard links, check then rename). `tmp` is removed in every case.
pub fn commit(tmp: &Path, path: &Path, replace: bool) -> io::Result<()> {
    let result = if replace {
        std::fs::rename(tmp, path)
    } else {
        std::fs::hard_link(tmp, path).or_else(|e| {
            if e.kind() == io::ErrorKind::AlreadyExists || path.exists() {
                Err(io::ErrorKind::AlreadyExists.into())
            } else {
                std::fs::rename(tmp, path)
            }
        })
    };
    let _ = std::fs::remove_file(tmp);
    result
}

/// Write `bytes` to `path` atomically (creating its folder): temp file, rename. With `replace`
/// false, fails with `AlreadyExists` if `path` exists.
pub fn write_atomic(path: &Path, bytes: &[u8], replace: bool) -> io::Result<()> {
    write(path, bytes, replace, false)
}

/// As [`write_atomic`], and the data reach the disk (`fsync`) before the rename, so the file
/// survives a power loss whole (for files that later runs trust, like fit files). Costs a disk
/// round trip per file.
pub fn write_atomic_durable(path: &Path, bytes: &[u8], replace: bool) -> io::Result<()> {
    write(path, bytes, replace, true)
}

fn write(path: &Path, bytes: &[u8], replace: bool, sync: bool) -> io::Result<()> {
    if !replace && path.exists() {
        return Err(io::ErrorKind::AlreadyExists.into());
    }
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    let tmp = temp_path(path);
    let written = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        if sync {
            f.sync_all()?;
        }
        Ok(())
    })();
    if let Err(e) = written {
        let _ = std::fs::remove_file(&tmp);
        return Err(e);
    }
    commit(&tmp, path, replace)
}

/// Whether process `pid` is alive (Linux: `/proc/PID` exists; elsewhere assumed alive, so nothing
/// of a possibly running process is ever removed).
pub fn process_alive(pid: u32) -> bool {
    if pid == std::process::id() {
        return true;
    }
    if cfg!(target_os = "linux") {
        Path::new(&format!("/proc/{pid}")).exists()
    } else {
        true
    }
}

/// The process id in a temporary name made by [`temp_path`] (`.NAME.tmp-PID-N.EXT`).
fn temp_owner(name: &str) -> Option<u32> {
    if !name.starts_with('.') {
        return None;
    }
    let rest = &name[name.rfind(".tmp-")? + 5..];
    rest.split('-').next()?.parse().ok()
}

/// Remove the temporary files that a killed process left in `dir` and its sub-folders (down to
/// `depth` levels): names made by [`temp_path`] whose process is no longer alive. Returns how many
/// were removed.
pub fn remove_stale_temps(dir: &Path, depth: usize) -> usize {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return 0;
    };
    let mut n = 0;
    for e in entries.flatten() {
        let path = e.path();
        let Ok(kind) = e.file_type() else { continue };
        if kind.is_dir() && depth > 0 {
            n += remove_stale_temps(&path, depth - 1);
        } else if kind.is_file() {
            let name = e.file_name().to_string_lossy().into_owned();
            if temp_owner(&name).is_some_and(|pid| !process_alive(pid))
                && std::fs::remove_file(&path).is_ok()
            {
                n += 1;
            }
        }
    }
    n
}

/// A lock on an output folder (`.viscoroll.lock`, holding the owner's process id), released when
/// dropped. Two runs on one folder take turns instead of failing each other; a lock left by a
/// killed process is taken over.
#[derive(Debug)]
pub struct DirLock {
    path: PathBuf,
}

impl DirLock {
    /// Lock `dir` (creating it), waiting up to `timeout` for another process that holds it;
    /// `waiting` is called once, with the holder's pid, if we have to wait.
    pub fn acquire(
        dir: &Path,
        timeout: std::time::Duration,
        waiting: &dyn Fn(u32),
    ) -> io::Result<DirLock> {
        std::fs::create_dir_all(dir)?;
        let path = dir.join(".viscoroll.lock");
        let start = std::time::Instant::now();
        let mut told = false;
        loop {
            match std::fs::OpenOptions::new()
                .write(true)
                .create_new(true)
                .open(&path)
            {
                Ok(mut f) => {
                    write!(f, "{}", std::process::id())?;
                    return Ok(DirLock { path });
                }
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {
                    let holder = std::fs::read_to_string(&path)
                        .ok()
                        .and_then(|s| s.trim().parse::<u32>().ok());
                    if let Some(pid) = holder {
                        if !process_alive(pid) {
                            let _ = std::fs::remove_file(&path);
                            continue;
                        }
                        if !told {
                            waiting(pid);
                            told = true;
                        }
                    }
                    if start.elapsed() > timeout {
                        return Err(io::Error::new(
                            io::ErrorKind::WouldBlock,
                            format!(
                                "{} is locked by another viscoroll run (process {}); waited {} s",
                                dir.display(),
                                holder.map_or("?".into(), |p| p.to_string()),
                                timeout.as_secs()
                            ),
                        ));
                    }
                    std::thread::sleep(std::time::Duration::from_millis(100));
                }
                Err(e) => return Err(e),
            }
        }
    }
}

impl Drop for DirLock {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_replaces_and_refuses() {
        let dir = std::env::temp_dir().join(format!("viscoroll-fsutil-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let p = dir.join("sub").join("a.txt");
        write_atomic(&p, b"one", false).unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"one");
        let e = write_atomic(&p, b"two", false).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::AlreadyExists);
        assert_eq!(std::fs::read(&p).unwrap(), b"one");
        write_atomic_durable(&p, b"two", true).unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"two");
        // no temporary file left behind
        let left: Vec<_> = std::fs::read_dir(p.parent().unwrap()).unwrap().collect();
        assert_eq!(left.len(), 1);
        let t = temp_path(Path::new("x/plot.png"));
        assert_eq!(t.extension().unwrap(), "png");
        assert_ne!(t, temp_path(Path::new("x/plot.png")));
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn stale_temps_go_live_ones_stay() {
        let dir = std::env::temp_dir().join(format!("viscoroll-stale-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("reports/a")).unwrap();
        // pid 4294967 is above Linux's pid_max (4194304), so never alive.
        let dead = dir.join("reports/a/.friction.tmp-4294967-0.csv");
        let mine = dir.join(format!(".x.tmp-{}-0.json", std::process::id()));
        let user = dir.join("notes.tmp-1-0.txt");
        for p in [&dead, &mine, &user] {
            std::fs::write(p, b"x").unwrap();
        }
        assert_eq!(remove_stale_temps(&dir, 2), 1);
        assert!(!dead.exists() && mine.exists() && user.exists());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_lock_is_exclusive_released_on_drop_and_taken_over_when_stale() {
        let dir = std::env::temp_dir().join(format!("viscoroll-lock-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let short = std::time::Duration::from_millis(300);
        let held = DirLock::acquire(&dir, short, &|_| {}).unwrap();
        let waited = std::cell::Cell::new(None);
        let e = DirLock::acquire(&dir, short, &|pid| waited.set(Some(pid))).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::WouldBlock);
        assert_eq!(waited.get(), Some(std::process::id()));
        drop(held);
        let again = DirLock::acquire(&dir, short, &|_| {}).unwrap();
        drop(again);
        // A lock left by a dead process is taken over at once.
        std::fs::write(dir.join(".viscoroll.lock"), "4294967").unwrap();
        let _l = DirLock::acquire(&dir, short, &|_| panic!("should not wait")).unwrap();
    }
}
