//! The output folder as a jail: while a [`Jail`] on a folder lives (the main job holds one with its
//! [`super::DirLock`]), every write of this module below that folder walks down from the folder
//! itself with `openat(…, O_NOFOLLOW | O_DIRECTORY)`, creating missing folders with `mkdirat`, and
//! refuses a symbolic link (or anything that is not a folder) on the way. Writes elsewhere (the
//! single output file of `export`, `ingest`, …) open their parent folder as named by the user.
//!
//! Input: a path; output: an open handle on its parent folder (`open_parent`) that the atomic
//! writer creates its temporary file in and renames within, so no later path lookup can be
//! redirected by a symlink planted meanwhile.

use rustix::fs::{Mode, OFlags, CWD};
use rustix::io::Errno;
use std::ffi::OsString;
use std::io;
use std::os::fd::OwnedFd;
use std::path::{Component, Path, PathBuf};
use std::sync::Mutex;

/// The folders that are jails now (a folder may be entered more than once, so this is a list).
static ROOTS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// A folder treated as a jail while this value lives (see the module doc).
#[derive(Debug)]
pub struct Jail {
    root: PathBuf,
}

impl Jail {
    /// Make `root` (created if missing) a jail until the value is dropped.
    pub(crate) fn enter(root: &Path) -> io::Result<Jail> {
        std::fs::create_dir_all(root)?;
        lock_roots().push(root.to_path_buf());
        Ok(Jail {
            root: root.to_path_buf(),
        })
    }
}

impl Drop for Jail {
    fn drop(&mut self) {
        let mut roots = lock_roots();
        if let Some(i) = roots.iter().position(|r| *r == self.root) {
            roots.swap_remove(i);
        }
    }
}

fn lock_roots() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    // A panic while holding the lock cannot leave the list half-changed (push/swap_remove).
    ROOTS.lock().unwrap_or_else(|p| p.into_inner())
}

/// The innermost jail that holds `path`, if any.
fn jail_of(path: &Path) -> Option<PathBuf> {
    lock_roots()
        .iter()
        .filter(|r| path.starts_with(r))
        .max_by_key(|r| r.components().count())
        .cloned()
}

/// The error for a path that leaves a jail through a symlink, a non-folder or `..`.
fn refused(root: &Path, at: &Path, what: &str) -> io::Error {
    io::Error::new(
        io::ErrorKind::PermissionDenied,
        format!(
            "{} {what} inside the output folder {}; viscoroll writes there only into real folders \
             (remove it, or choose another output folder)",
            at.display(),
            root.display()
        ),
    )
}

/// Open folder `name` inside `dir`, creating it, never following a symlink.
fn step_into(dir: &OwnedFd, name: &std::ffi::OsStr, root: &Path, at: &Path) -> io::Result<OwnedFd> {
    match rustix::fs::mkdirat(dir, name, Mode::from_raw_mode(0o777)) {
        Ok(()) | Err(Errno::EXIST) => {}
        Err(e) => return Err(e.into()),
    }
    let flags = OFlags::RDONLY | OFlags::DIRECTORY | OFlags::NOFOLLOW | OFlags::CLOEXEC;
    match rustix::fs::openat(dir, name, flags, Mode::empty()) {
        Ok(fd) => Ok(fd),
        Err(Errno::LOOP | Errno::NOTDIR | Errno::MLINK) => {
            Err(refused(root, at, "is a symbolic link or not a folder"))
        }
        Err(e) => Err(e.into()),
    }
}

/// Create folder `dir` and its parents (inside a jail without following symlinks, as
/// `open_parent` does).
pub fn create_dir_all(dir: &Path) -> io::Result<()> {
    open_parent(&dir.join("_")).map(drop)
}

/// The open parent folder of `path` and the file name within it. Inside a jail the folders are
/// walked from the jail's root without following symlinks; outside, the parent is created and
/// opened as named.
pub(crate) fn open_parent(path: &Path) -> io::Result<(OwnedFd, OsString)> {
    let name = path
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "not a file path"))?
        .to_os_string();
    let parent = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let dir_flags = OFlags::RDONLY | OFlags::DIRECTORY | OFlags::CLOEXEC;
    let Some(root) = jail_of(path) else {
        std::fs::create_dir_all(parent)?;
        return Ok((
            rustix::fs::openat(CWD, parent, dir_flags, Mode::empty())?,
            name,
        ));
    };
    let mut dir = rustix::fs::openat(CWD, &root, dir_flags, Mode::empty())?;
    let mut at = root.clone();
    let rel = parent.strip_prefix(&root).unwrap_or(Path::new(""));
    for c in rel.components() {
        match c {
            Component::Normal(s) => {
                at.push(s);
                dir = step_into(&dir, s, &root, &at)?;
            }
            Component::CurDir => {}
            _ => return Err(refused(&root, path, "leaves the folder (`..`)")),
        }
    }
    Ok((dir, name))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inside_a_jail_a_symlinked_folder_is_refused_outside_it_is_followed() {
        let base = std::env::temp_dir().join(format!("viscoroll-jail-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&base);
        let (out, elsewhere) = (base.join("out"), base.join("elsewhere"));
        std::fs::create_dir_all(&elsewhere).unwrap();
        std::fs::create_dir_all(&out).unwrap();
        std::os::unix::fs::symlink(&elsewhere, out.join("fits")).unwrap();
        let target = out.join("fits").join("a.json");
        // not a jail yet: the symlink is followed (a user's own layout)
        assert!(open_parent(&target).is_ok());
        let jail = Jail::enter(&out).unwrap();
        let e = open_parent(&target).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::PermissionDenied);
        assert!(e.to_string().contains("symbolic link"), "{e}");
        // a real sub-folder is created on the way
        assert!(open_parent(&out.join("reports/x/y.csv")).is_ok());
        assert!(out.join("reports/x").is_dir());
        drop(jail);
        assert!(jail_of(&target).is_none());
        let _ = std::fs::remove_dir_all(&base);
    }
}
