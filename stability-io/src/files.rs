//! Reading input files: only regular files (not a FIFO, a device or a
//! directory, which could block forever or never end), of at most
//! [`MAX_INPUT_BYTES`], as UTF-8 text; and saying in words why a path
//! could not be read or written.

use crate::Failure;
use crate::diag::{InputError, IoError};
use std::io::Read;
use std::path::{Path, PathBuf};

/// The largest input file the program reads (a derivative file, a config,
/// an AVL `.st` file or a CSV table): 16 MiB.
pub const MAX_INPUT_BYTES: u64 = 16 * 1024 * 1024;

/// The same limit in words, for messages and `--help`.
pub const MAX_INPUT_TEXT: &str = "16 MiB";

/// An I/O error's reason, without the "(os error N)" suffix.
pub fn reason(e: &std::io::Error) -> String {
    let s = e.to_string();
    match s.find(" (os error") {
        Some(i) => s[..i].to_string(),
        None => s,
    }
}

/// What a non-regular file is, in words.
fn kind_of(t: std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if t.is_char_device() {
            return "a character device";
        }
        if t.is_block_device() {
            return "a block device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if t.is_dir() {
        "a directory"
    } else {
        "not a regular file"
    }
}

fn not_regular(path: &Path, t: std::fs::FileType) -> Failure {
    Failure::Io(IoError::new(
        "cannot read",
        path,
        format!(
            "it is {}; inputs are read only from regular files",
            kind_of(t)
        ),
    ))
}

fn too_large(path: &Path, len: u64) -> Failure {
    Failure::Input(InputError::file(
        &path.display().to_string(),
        format!(
            "the file has {len} bytes; inputs are read up to {MAX_INPUT_TEXT} ({MAX_INPUT_BYTES} bytes)"
        ),
    ))
}

thread_local! {
    /// The input files read on this thread while [`recording`] runs.
    static READ: std::cell::RefCell<Option<Vec<PathBuf>>> = const { std::cell::RefCell::new(None) };
}

/// Runs `f` and returns, with its result, every input file that
/// [`read_input`] read for it on this thread, in order: a derivative file
/// or config, and the files it names (CSV tables, an AVL `.st` file). A
/// front end that writes files checks its outputs against them (an output
/// must not overwrite an input).
pub fn recording<T>(f: impl FnOnce() -> T) -> (T, Vec<PathBuf>) {
    let outer = READ.with(|r| r.borrow_mut().replace(Vec::new()));
    let value = f();
    let read = READ
        .with(|r| std::mem::replace(&mut *r.borrow_mut(), outer))
        .unwrap_or_default();
    READ.with(|r| {
        if let Some(o) = r.borrow_mut().as_mut() {
            o.extend(read.iter().cloned());
        }
    });
    (value, read)
}

/// Notes `path` among the inputs of the run being [`recording`]: a file an
/// input names that this run does not read (a samples file of a config's
/// `[uncertainty]` when the command runs no study) is the user's data all
/// the same, and no output may overwrite it.
pub fn note_input(path: &Path) {
    READ.with(|r| {
        if let Some(read) = r.borrow_mut().as_mut() {
            read.push(path.to_path_buf());
        }
    });
}

/// The flag that opens a file without waiting for a FIFO's writer (or a
/// device): `open(2)` returns at once, and the file's type is then asked
/// of the open file itself, so that nothing swapped in between looking and
/// opening can block the program.
#[cfg(unix)]
fn open_options() -> std::fs::OpenOptions {
    use std::os::unix::fs::OpenOptionsExt;
    let mut o = std::fs::OpenOptions::new();
    o.read(true).custom_flags(libc::O_NONBLOCK);
    o
}

#[cfg(not(unix))]
fn open_options() -> std::fs::OpenOptions {
    let mut o = std::fs::OpenOptions::new();
    o.read(true);
    o
}

/// `path` opened for reading if it is a regular file — never blocking on a
/// FIFO or a device, which is refused ([`Opened::Special`]) — with its
/// size.
fn open_regular(path: &Path) -> std::io::Result<Opened> {
    // a directory opens on Unix; on other systems it is refused here
    if let Ok(m) = std::fs::metadata(path)
        && m.is_dir()
    {
        return Ok(Opened::Special(m.file_type()));
    }
    let file = open_options().open(path)?;
    let meta = file.metadata()?;
    if !meta.is_file() {
        return Ok(Opened::Special(meta.file_type()));
    }
    Ok(Opened::Regular(file, meta.len()))
}

/// What [`open_regular`] found.
enum Opened {
    Regular(std::fs::File, u64),
    Special(std::fs::FileType),
}

/// The bytes of the regular file `path` (a FIFO, a device or a directory
/// is an error of kind `InvalidInput` saying what it is, returned at
/// once): for files the program reads that are not inputs of a
/// computation, such as a report's manifest.
pub fn read_regular(path: &Path) -> std::io::Result<Vec<u8>> {
    match open_regular(path)? {
        Opened::Regular(mut file, len) => {
            let mut bytes = Vec::with_capacity(len as usize);
            file.read_to_end(&mut bytes)?;
            Ok(bytes)
        }
        Opened::Special(t) => Err(std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            format!("it is {}, not a regular file", kind_of(t)),
        )),
    }
}

/// The text of the input file `path`: a regular file of at most
/// [`MAX_INPUT_BYTES`], in UTF-8 (noted for [`recording`]). A FIFO or a
/// device is refused at once, never waited on.
pub fn read_input(path: &Path) -> Result<String, Failure> {
    note_input(path);
    let io = |e: std::io::Error| Failure::Io(IoError::new("cannot read", path, reason(&e)));
    let (file, len) = match open_regular(path).map_err(io)? {
        Opened::Regular(file, len) => (file, len),
        Opened::Special(t) => return Err(not_regular(path, t)),
    };
    if len > MAX_INPUT_BYTES {
        return Err(too_large(path, len));
    }
    let mut bytes = Vec::new();
    file.take(MAX_INPUT_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(too_large(path, bytes.len() as u64));
    }
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let line = bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
        let text = String::from_utf8_lossy(bytes);
        Failure::Input(InputError::at_line(
            &path.display().to_string(),
            &text,
            line,
            format!("not UTF-8 text (byte {at} is not part of a UTF-8 character)"),
        ))
    })
}

/// Why `path` cannot be written, in words: a component of it that is a
/// file rather than a directory, the path itself being a directory, or the
/// system's reason.
pub fn write_error(path: &Path, e: &std::io::Error) -> IoError {
    let mut ancestor = path.parent();
    while let Some(a) = ancestor {
        if !a.as_os_str().is_empty()
            && let Ok(m) = std::fs::metadata(a)
        {
            if !m.is_dir() {
                return IoError::new(
                    "cannot write",
                    path,
                    format!("`{}` is a file, not a directory", a.display()),
                );
            }
            break;
        }
        ancestor = a.parent();
    }
    if std::fs::metadata(path).is_ok_and(|m| m.is_dir()) {
        return IoError::new("cannot write", path, "it is a directory");
    }
    IoError::new("cannot write", path, reason(e))
}

/// The FNV-1a 64-bit hash of `bytes` (enough to tell one file's contents
/// from another's; it guards against mistakes, not against an adversary).
pub fn fnv1a64(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_inputs_read_are_recorded_while_asked_for() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a.toml"), dir.path().join("b.csv"));
        std::fs::write(&a, "x").unwrap();
        std::fs::write(&b, "y").unwrap();
        let _ = read_input(&a);
        let ((inner, _), outer) = recording(|| {
            let _ = read_input(&a);
            recording(|| read_input(&b))
        });
        assert_eq!(inner.unwrap(), "y");
        assert_eq!(outer, [a.clone(), b]);
        // nothing is kept when no one asks
        assert!(recording(|| ()).1.is_empty());
    }

    #[test]
    fn a_directory_is_not_an_input() {
        let dir = tempfile::tempdir().unwrap();
        let e = read_input(dir.path()).unwrap_err();
        assert_eq!(e.status(), Failure::IO_STATUS);
        assert!(e.to_string().contains("it is a directory"), "{e}");
    }

    #[cfg(unix)]
    #[test]
    fn a_fifo_is_refused_at_once_not_waited_on() {
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("pipe.toml");
        let c = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
        // SAFETY: a NUL-terminated path; mkfifo touches no memory of ours
        assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o644) }, 0);
        // no writer ever opens it: a blocking open would never return
        let e = read_input(&fifo).unwrap_err();
        assert_eq!(e.status(), Failure::IO_STATUS);
        assert!(e.to_string().contains("a FIFO (named pipe)"), "{e}");
        let e = read_regular(&fifo).unwrap_err();
        assert_eq!(e.kind(), std::io::ErrorKind::InvalidInput);
        assert!(e.to_string().contains("FIFO"), "{e}");
        assert!(read_regular(dir.path()).is_err());
        let file = dir.path().join("a.json");
        std::fs::write(&file, "{}").unwrap();
        assert_eq!(read_regular(&file).unwrap(), b"{}");
    }

    #[test]
    fn a_file_named_but_not_read_is_an_input() {
        let (_, read) = recording(|| note_input(Path::new("samples.csv")));
        assert_eq!(read, [PathBuf::from("samples.csv")]);
    }

    #[test]
    fn a_path_through_a_file_is_named() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("plain");
        std::fs::write(&file, "x").unwrap();
        let target = file.join("sub/out.csv");
        let e = std::fs::create_dir_all(target.parent().unwrap()).unwrap_err();
        let msg = write_error(&target, &e).to_string();
        assert!(
            msg.contains("plain` is a file, not a directory") && msg.contains("out.csv"),
            "{msg}"
        );
    }

    #[test]
    fn text_that_is_not_utf8_is_located() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("bad.toml");
        std::fs::write(&p, b"a = 1\nb = \"\xff\"\n").unwrap();
        let e = read_input(&p).unwrap_err();
        assert_eq!(e.status(), Failure::INPUT_STATUS);
        assert!(e.to_string().contains("bad.toml:2:1: not UTF-8"), "{e}");
    }
}
