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
}
