//! Safe file access, shared by every stage and the CLI.
//!
//! - Atomic writes (`write_atomic`, `TempFile`): a temporary file with an unpredictable name,
//!   created exclusively (`O_EXCL | O_NOFOLLOW`) in an open handle on the target's folder, flushed,
//!   then renamed within that handle, so a reader never sees a half-written file, a crash leaves
//!   the old file or the new one, and no symlink planted at a temporary or final name is followed.
//! - The output folder as a jail (`jail`): below a folder held by a [`DirLock`], folders are walked
//!   without following symlinks, and a symlinked sub-folder is refused.
//! - The folder lock (`lock`): an advisory `flock` that the OS releases with its process.
//! - Reading inputs (`read`): regular files only, within a size limit, never blocking on a FIFO.
//!
//! Errors are [`std::io::Error`]s (kind `AlreadyExists` when `replace` is false and the file
//! exists); callers wrap them in their stage's enum.

pub(crate) mod jail;
pub(crate) mod lock;
pub(crate) mod read;

pub(crate) use jail::Jail;
pub use lock::DirLock;
pub(crate) use read::{read_regular, read_regular_to_string};

use rustix::fs::{AtFlags, Mode, OFlags};
use rustix::io::Errno;
use std::ffi::{OsStr, OsString};
use std::hash::{BuildHasher as _, Hasher as _};
use std::io::{self, Write as _};
use std::os::fd::OwnedFd;
use std::path::{Path, PathBuf};

/// 64 unpredictable bits: std's randomly keyed SipHash over a counter, the time and the pid.
fn random_u64() -> u64 {
    use std::sync::atomic::{AtomicU64, Ordering};
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let mut h = std::collections::hash_map::RandomState::new().build_hasher();
    h.write_u64(COUNTER.fetch_add(1, Ordering::Relaxed));
    h.write_u32(std::process::id());
    if let Ok(t) = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH) {
        h.write_u128(t.as_nanos());
    }
    h.finish()
}

/// A temporary name for `name`: `.STEM.tmp-PID-RANDOM.EXT`, keeping the extension (the bitmap
/// encoder picks the image format from it); the stem is cut so the name fits any file system.
fn temp_name(name: &OsStr) -> String {
    let p = Path::new(name);
    let stem: String = p
        .file_stem()
        .map(|s| s.to_string_lossy().chars().take(64).collect())
        .unwrap_or_default();
    let ext: String = p
        .extension()
        .map(|e| {
            format!(
                ".{}",
                e.to_string_lossy().chars().take(16).collect::<String>()
            )
        })
        .unwrap_or_default();
    format!(
        ".{stem}.tmp-{}-{:016x}{ext}",
        std::process::id(),
        random_u64()
    )
}

/// A temporary file beside a target path, created exclusively and never through a symlink;
/// removed when dropped unless [`TempFile::commit`]ted.
#[derive(Debug)]
pub(crate) struct TempFile {
    dir: OwnedFd,
    name: OsString,
    tmp: String,
    path: PathBuf,
    file: Option<std::fs::File>,
}

impl TempFile {
    /// Create an empty temporary file beside `path` (inside a jail, see [`jail`]).
    pub fn beside(path: &Path) -> io::Result<TempFile> {
        let (dir, name) = jail::open_parent(path)?;
        let flags =
            OFlags::WRONLY | OFlags::CREATE | OFlags::EXCL | OFlags::NOFOLLOW | OFlags::CLOEXEC;
        for _ in 0..16 {
            let tmp = temp_name(&name);
            match rustix::fs::openat(&dir, tmp.as_str(), flags, Mode::from_raw_mode(0o666)) {
                Ok(fd) => {
                    let path = path.with_file_name(&tmp);
                    let file = Some(std::fs::File::from(fd));
                    return Ok(TempFile {
                        dir,
                        name,
                        tmp,
                        path,
                        file,
                    });
                }
                Err(Errno::EXIST) => continue,
                Err(e) => return Err(e.into()),
            }
        }
        Err(io::Error::new(
            io::ErrorKind::AlreadyExists,
            "no free temporary name",
        ))
    }

    /// The temporary file's path, for writers that open by path (the plot backends).
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Write `bytes` into the temporary file (and `fsync` them with `sync`).
    pub fn write_all(&mut self, bytes: &[u8], sync: bool) -> io::Result<()> {
        let f = self
            .file
            .as_mut()
            .ok_or_else(|| io::Error::other("temporary file closed"))?;
        f.write_all(bytes)?;
        if sync {
            f.sync_all()?;
        }
        Ok(())
    }

    /// Move the temporary file to the target name. With `replace` false an existing target (even a
    /// dangling symlink, even one that appears meanwhile) is never replaced: a hard link fails if
    /// the name exists; on file systems without hard links, check then rename. A symlink at the
    /// target is replaced, never followed. With `sync` the folder is flushed too.
    pub fn commit(mut self, replace: bool, sync: bool) -> io::Result<()> {
        self.file = None;
        let (dir, tmp, name) = (&self.dir, self.tmp.as_str(), self.name.as_os_str());
        if replace {
            rustix::fs::renameat(dir, tmp, dir, name)?;
        } else {
            match rustix::fs::linkat(dir, tmp, dir, name, AtFlags::empty()) {
                Ok(()) => {}
                Err(Errno::EXIST) => return Err(io::ErrorKind::AlreadyExists.into()),
                Err(_) => {
                    if rustix::fs::statat(dir, name, AtFlags::SYMLINK_NOFOLLOW).is_ok() {
                        return Err(io::ErrorKind::AlreadyExists.into());
                    }
                    rustix::fs::renameat(dir, tmp, dir, name)?;
                }
            }
        }
        if sync {
            rustix::fs::fsync(dir)?;
        }
        Ok(())
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        // After a rename this finds nothing; after a link it removes the temporary name.
        let _ = rustix::fs::unlinkat(&self.dir, self.tmp.as_str(), AtFlags::empty());
    }
}

/// Write `bytes` to `path` atomically (creating its folder): temp file, rename. With `replace`
/// false, fails with `AlreadyExists` if `path` exists.
pub(crate) fn write_atomic(path: &Path, bytes: &[u8], replace: bool) -> io::Result<()> {
    write(path, bytes, replace, false)
}

/// As [`write_atomic`], and the data reach the disk (`fsync`) before the rename, so the file
/// survives a power loss whole (for files that later runs trust, like fit files). Costs a disk
/// round trip per file.
pub(crate) fn write_atomic_durable(path: &Path, bytes: &[u8], replace: bool) -> io::Result<()> {
    write(path, bytes, replace, true)
}

fn write(path: &Path, bytes: &[u8], replace: bool, sync: bool) -> io::Result<()> {
    let mut t = TempFile::beside(path)?;
    t.write_all(bytes, sync)?;
    t.commit(replace, sync)
}

/// Whether process `pid` is alive (Linux: `/proc/PID` exists; elsewhere assumed alive, so nothing
/// of a possibly running process is ever removed).
pub(crate) fn process_alive(pid: u32) -> bool {
    if pid == std::process::id() {
        return true;
    }
    if cfg!(target_os = "linux") {
        Path::new(&format!("/proc/{pid}")).exists()
    } else {
        true
    }
}

/// The process id in a temporary name made by [`TempFile`] (`.NAME.tmp-PID-RANDOM.EXT`).
fn temp_owner(name: &str) -> Option<u32> {
    if !name.starts_with('.') {
        return None;
    }
    let rest = &name[name.rfind(".tmp-")? + 5..];
    rest.split('-').next()?.parse().ok()
}

/// Remove the temporary files that a killed process left in `dir` and its sub-folders (down to
/// `depth` levels): names made by [`TempFile`] whose process is no longer alive. Returns how many
/// were removed.
pub(crate) fn remove_stale_temps(dir: &Path, depth: usize) -> usize {
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
        let t = temp_name(OsStr::new("plot.png"));
        assert!(t.ends_with(".png") && t.starts_with(".plot.tmp-"), "{t}");
        assert_ne!(t, temp_name(OsStr::new("plot.png")));
        assert_eq!(temp_owner(&t), Some(std::process::id()));
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
    fn a_symlink_at_the_target_is_replaced_not_followed() {
        let dir = std::env::temp_dir().join(format!("viscoroll-plant-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let victim = dir.join("victim.txt");
        std::fs::write(&victim, b"keep").unwrap();
        let target = dir.join("ranking.csv");
        std::os::unix::fs::symlink(&victim, &target).unwrap();
        // not replacing: the (symlink) name exists
        let e = write_atomic(&target, b"new", false).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::AlreadyExists);
        write_atomic(&target, b"new", true).unwrap();
        assert_eq!(std::fs::read(&victim).unwrap(), b"keep");
        assert!(!std::fs::symlink_metadata(&target)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read(&target).unwrap(), b"new");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
