//! Reading an input file safely ([`read_regular`]): only a regular file (a symlink to one is
//! fine), opened with `O_NONBLOCK` so a FIFO never blocks the open, checked with `fstat` on the
//! open descriptor (no race with a swap of the name), and read up to a size limit (the caller's, from
//! `crate::limits`), so `/dev/zero`, a FIFO, a socket or a device is refused at once.
//!
//! Input: a path and a byte limit; output: the bytes (or text), or an [`std::io::Error`] whose
//! message names the file and what it is.

use rustix::fs::{FileType, Mode, OFlags, CWD};
use std::io::{self, Read as _};
use std::path::Path;

/// What a file type is called in an error.
fn type_name(t: FileType) -> &'static str {
    match t {
        FileType::Directory => "a folder",
        FileType::Fifo => "a FIFO (named pipe)",
        FileType::Socket => "a socket",
        FileType::CharacterDevice => "a character device",
        FileType::BlockDevice => "a block device",
        FileType::Symlink => "a symbolic link",
        _ => "not a regular file",
    }
}

/// The bytes of the regular file at `path`, at most `max_bytes` of them (more is an error).
pub fn read_regular(path: &Path, max_bytes: u64) -> io::Result<Vec<u8>> {
    let flags = OFlags::RDONLY | OFlags::NONBLOCK | OFlags::CLOEXEC | OFlags::NOCTTY;
    let fd = rustix::fs::openat(CWD, path, flags, Mode::empty())?;
    let st = rustix::fs::fstat(&fd)?;
    let t = FileType::from_raw_mode(st.st_mode);
    if t != FileType::RegularFile {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!(
                "{} is {}; only regular files are read",
                path.display(),
                type_name(t)
            ),
        ));
    }
    let too_big = || {
        io::Error::new(
            io::ErrorKind::InvalidData,
            format!(
                "{} is larger than {} MiB, the limit of an input file",
                path.display(),
                max_bytes >> 20
            ),
        )
    };
    if st.st_size as u64 > max_bytes {
        return Err(too_big());
    }
    let mut bytes = Vec::with_capacity(st.st_size as usize);
    std::fs::File::from(fd)
        .take(max_bytes + 1)
        .read_to_end(&mut bytes)?;
    if bytes.len() as u64 > max_bytes {
        return Err(too_big());
    }
    Ok(bytes)
}

/// [`read_regular`] as UTF-8 text.
pub fn read_regular_to_string(path: &Path, max_bytes: u64) -> io::Result<String> {
    String::from_utf8(read_regular(path, max_bytes)?).map_err(|_| {
        io::Error::new(
            io::ErrorKind::InvalidData,
            format!("{} is not UTF-8 text", path.display()),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn special_files_are_refused_without_blocking_and_sizes_are_capped() {
        let dir = std::env::temp_dir().join(format!("viscoroll-read-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        // a FIFO with no writer: a blocking open would hang here
        let fifo = dir.join("a.csv");
        assert!(std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success());
        let e = read_regular(&fifo, 100).unwrap_err();
        assert!(e.to_string().contains("FIFO"), "{e}");
        // /dev/zero behind a symlink
        let z = dir.join("z.csv");
        std::os::unix::fs::symlink("/dev/zero", &z).unwrap();
        assert!(read_regular(&z, 100)
            .unwrap_err()
            .to_string()
            .contains("character device"));
        assert!(read_regular(&dir, 100)
            .unwrap_err()
            .to_string()
            .contains("folder"));
        let f = dir.join("f.csv");
        std::fs::write(&f, vec![b'x'; 101]).unwrap();
        assert_eq!(read_regular(&f, 101).unwrap().len(), 101);
        assert_eq!(
            read_regular(&f, 100).unwrap_err().kind(),
            io::ErrorKind::InvalidData
        );
        let _ = std::fs::remove_dir_all(&dir);
    }
}
