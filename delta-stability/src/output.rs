//! Writing results atomically: a file ([`AtomicFile`]) or a directory
//! ([`AtomicDir`]) is written under a temporary name beside its target and
//! renamed into place when complete, so that a killed run leaves the
//! previous result whole, never a half-written file or a mix of old and new.
//!
//! A run killed before it finishes leaves its temporary file or directory
//! behind. Those are named `.delta-stability-<pid>-<random>`, and a later
//! run that writes into the same directory removes them ([`remove_stale`])
//! once it can tell they are stale: their process no longer runs and they
//! have not changed for [`STALE_AFTER`]. Nothing else is touched.
//!
//! Interrupted by SIGINT or SIGTERM, a run removes its own temporaries
//! before it exits (status 130 or 143, 128 + the signal):
//! [`remove_temporaries_on_signals`].

use stability_io::format::Format;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

/// The prefix of every temporary file and directory the program makes.
pub const TEMP_PREFIX: &str = ".delta-stability-";

/// How long a dead run's temporary file must have been unchanged before a
/// later run removes it (a live run writes into its file continuously).
pub const STALE_AFTER: Duration = Duration::from_secs(10 * 60);

/// Temporary files of versions before the pid was in the name
/// (`.delta-stability-XXXXXX`) are removed after this long unchanged.
const LEGACY_STALE_AFTER: Duration = Duration::from_secs(60 * 60);

/// Where the process cannot be checked, a temporary file is removed only
/// after this long unchanged.
const UNCHECKED_STALE_AFTER: Duration = Duration::from_secs(24 * 60 * 60);

/// The temporaries this run has made and neither committed nor removed:
/// what [`remove_temporaries`] removes.
static LIVE: std::sync::Mutex<Vec<PathBuf>> = std::sync::Mutex::new(Vec::new());

/// A temporary file or directory of this run, listed in [`LIVE`] while
/// this lives.
struct Live(PathBuf);

impl Live {
    fn new(path: &Path) -> Live {
        let path = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
        LIVE.lock()
            .unwrap_or_else(|e| e.into_inner())
            .push(path.clone());
        Live(path)
    }
}

impl Drop for Live {
    fn drop(&mut self) {
        let mut live = LIVE.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(k) = live.iter().position(|p| *p == self.0) {
            live.swap_remove(k);
        }
    }
}

/// Removes every temporary file and directory of this run not yet
/// committed ([`AtomicFile`], [`AtomicDir`]); returns how many it removed.
/// A directory being filled is not made again after this: its writes
/// fail.
pub fn remove_temporaries() -> usize {
    let live = LIVE.lock().unwrap_or_else(|e| e.into_inner());
    let mut removed = 0;
    for p in live.iter() {
        // a file written into a directory while it is removed: try again
        for _ in 0..3 {
            let gone = match p.symlink_metadata() {
                Ok(m) if m.is_dir() => std::fs::remove_dir_all(p),
                Ok(_) => std::fs::remove_file(p),
                Err(_) => break,
            };
            if gone.is_ok() {
                removed += 1;
                break;
            }
        }
    }
    removed
}

/// On SIGINT or SIGTERM, removes this run's temporaries
/// ([`remove_temporaries`]) and exits with status 128 + the signal (130,
/// 143). To be called first in `main`, before any other thread starts: the
/// two signals are blocked in every thread, and one thread waits for them.
/// (Not on Windows, where a killed run's temporaries are left to a later
/// run, [`remove_stale`].)
pub fn remove_temporaries_on_signals() {
    #[cfg(unix)]
    {
        // SAFETY: plain libc calls on a local, initialised signal set; the
        // mask is set before any other thread exists, so every thread
        // inherits it and the signals go only to the waiting thread.
        unsafe {
            let mut set: libc::sigset_t = std::mem::zeroed();
            libc::sigemptyset(&mut set);
            libc::sigaddset(&mut set, libc::SIGINT);
            libc::sigaddset(&mut set, libc::SIGTERM);
            if libc::pthread_sigmask(libc::SIG_BLOCK, &set, std::ptr::null_mut()) != 0 {
                return;
            }
            std::thread::spawn(move || {
                let mut signal: libc::c_int = 0;
                // SAFETY: waits on the signal set above, blocked in this thread
                while libc::sigwait(&set, &mut signal) != 0 {}
                remove_temporaries();
                // SAFETY: ends the process at once, without running
                // destructors or flushing buffers another thread may hold
                libc::_exit(128 + signal);
            });
        }
    }
}

/// The path of a directory to be replaced, spelt as the directory itself:
/// `rep/.` and `rep/` are `rep` (a rename cannot take a path whose last
/// component is `.`), and a path ending in `..` (or `.` alone) is the
/// directory it resolves to. Anything else is as given.
pub fn directory_target(path: &Path) -> PathBuf {
    let lexical: PathBuf = path.components().collect();
    match lexical.components().next_back() {
        Some(std::path::Component::Normal(_)) => lexical,
        _ => std::fs::canonicalize(&lexical).unwrap_or(lexical),
    }
}

/// The directory a target path is written in.
fn parent_of(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

fn temp_builder(prefix: &str) -> tempfile::Builder<'_, 'static> {
    let mut b = tempfile::Builder::new();
    b.prefix(prefix).rand_bytes(6);
    b
}

fn our_prefix() -> String {
    format!("{TEMP_PREFIX}{}-", std::process::id())
}

/// Whether process `pid` runs; `None` where that cannot be checked.
fn process_runs(pid: u32) -> Option<bool> {
    #[cfg(unix)]
    {
        let pid = libc::pid_t::try_from(pid).ok()?;
        // SAFETY: signal 0 sends nothing; kill only checks that the process
        // exists (ESRCH if not, EPERM if it is another user's).
        let r = unsafe { libc::kill(pid, 0) };
        let errno = std::io::Error::last_os_error().raw_os_error();
        Some(r == 0 || errno != Some(libc::ESRCH))
    }
    #[cfg(not(unix))]
    {
        let _ = pid;
        None
    }
}

/// How long an entry of `name` must have been unchanged to be stale, or
/// `None` if it is not a stale temporary of this program.
fn stale_after(name: &str) -> Option<Duration> {
    let rest = name.strip_prefix(TEMP_PREFIX)?;
    let alnum = |s: &str| s.len() == 6 && s.bytes().all(|b| b.is_ascii_alphanumeric());
    if alnum(rest) {
        return Some(LEGACY_STALE_AFTER);
    }
    let (pid, random) = rest.split_once('-')?;
    if !alnum(random) || pid.is_empty() || !pid.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let pid: u32 = pid.parse().ok()?;
    if pid == std::process::id() {
        return None;
    }
    match process_runs(pid) {
        Some(true) => None,
        Some(false) => Some(STALE_AFTER),
        None => Some(UNCHECKED_STALE_AFTER),
    }
}

/// Removes from `dir` the temporary files and directories that killed runs
/// of this program left (see the module's documentation); returns how many.
/// Errors are ignored: this is housekeeping.
pub fn remove_stale(dir: &Path) -> usize {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return 0;
    };
    let now = SystemTime::now();
    let mut removed = 0;
    for e in entries.flatten() {
        let name = e.file_name();
        let Some(after) = name.to_str().and_then(stale_after) else {
            continue;
        };
        let Ok(meta) = e.path().symlink_metadata() else {
            continue;
        };
        let unchanged = meta
            .modified()
            .ok()
            .and_then(|m| now.duration_since(m).ok());
        if unchanged.is_none_or(|d| d < after) {
            continue;
        }
        let gone = if meta.is_dir() {
            std::fs::remove_dir_all(e.path())
        } else {
            std::fs::remove_file(e.path())
        };
        removed += usize::from(gone.is_ok());
    }
    removed
}

/// How much this process may write on a file system, and what bounds it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Room {
    pub bytes: u64,
    /// In words: "free space on its file system", or "file-size limit
    /// (ulimit -f)".
    pub limited_by: &'static str,
}

/// The room for a file in directory `dir`: the space its file system has
/// free for an unprivileged process (statvfs), and no more than the
/// process's file-size limit (RLIMIT_FSIZE, `ulimit -f`, beyond which
/// writing kills it). `None` where neither can be told.
#[allow(clippy::unnecessary_cast)] // the fields' types differ between systems
pub fn room(dir: &Path) -> Option<Room> {
    #[cfg(unix)]
    {
        use std::os::unix::ffi::OsStrExt;
        let path = std::ffi::CString::new(dir.as_os_str().as_bytes()).ok()?;
        // SAFETY: statvfs fills the zeroed struct from a NUL-terminated
        // path; getrlimit fills the zeroed rlimit.
        let (free, limit) = unsafe {
            let mut st: libc::statvfs = std::mem::zeroed();
            let free = (libc::statvfs(path.as_ptr(), &mut st) == 0)
                .then(|| (st.f_bavail as u64).saturating_mul(st.f_frsize as u64));
            let mut lim: libc::rlimit = std::mem::zeroed();
            let limit = (libc::getrlimit(libc::RLIMIT_FSIZE, &mut lim) == 0
                && lim.rlim_cur != libc::RLIM_INFINITY)
                .then_some(lim.rlim_cur as u64);
            (free, limit)
        };
        let free = free.map(|bytes| Room {
            bytes,
            limited_by: "free space on its file system",
        });
        let limit = limit.map(|bytes| Room {
            bytes,
            limited_by: "file-size limit (ulimit -f)",
        });
        [free, limit].into_iter().flatten().min_by_key(|r| r.bytes)
    }
    #[cfg(not(unix))]
    {
        let _ = dir;
        None
    }
}

/// A number of bytes in words: `44.0 GB`, `812 bytes`.
pub fn bytes(n: f64) -> String {
    match [(1e12, "TB"), (1e9, "GB"), (1e6, "MB"), (1e3, "kB")]
        .into_iter()
        .find(|(unit, _)| n >= *unit)
    {
        Some((unit, name)) => format!("{:.1} {name}", n / unit),
        None => format!("{n:.0} bytes"),
    }
}

/// Prints `text` on standard output. A reader that stops reading (`| head`)
/// ends the output quietly, not with a panic; any other failure (a full
/// disk) is an I/O failure naming standard output.
pub fn print(text: &str) -> Result<(), crate::Failure> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            Err(crate::Failure::Io(stability_io::diag::IoError::new(
                "cannot write",
                Path::new("standard output"),
                stability_io::files::reason(&e),
            )))
        }
        _ => Ok(()),
    }
}

/// Prints a warning (or an error) on standard error; where standard error
/// cannot be written, there is no one to tell, and nothing else is done.
pub fn warn(text: &str) {
    let _ = writeln!(std::io::stderr().lock(), "{text}");
}

/// Prints each of a reader's warnings, `warning: ` before each.
pub fn warn_all(warnings: &[String]) {
    for w in warnings {
        warn(&format!("warning: {w}"));
    }
}

/// Checks that every number of a result is finite (the guard of every
/// writer, [`stability_io::finite`]): the error names the field and the
/// input file `source` the result is of.
pub fn finite(source: &str, value: &impl serde::Serialize) -> Result<(), crate::Failure> {
    Ok(stability_io::finite::guard(source, value)?)
}

/// Prints a result of the input file `source` in `format`, the one its
/// command's options chose ([`Format::document`]): its view as JSON (the
/// `--json` of every command), every number in it finite, or `text()`,
/// the command's own page.
pub fn print_as(
    format: Format,
    source: &str,
    view: &impl serde::Serialize,
    text: impl FnOnce() -> Result<String, crate::Failure>,
) -> Result<(), crate::Failure> {
    print(&format.document(source, view, text)?)
}

/// Write `bytes` to `path` through a temporary file in the same directory,
/// renamed into place when complete.
pub fn atomic_write(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut f = AtomicFile::create(path)?;
    f.write_all(bytes)?;
    f.commit()
}

/// Writes files as a set: every one into its temporary file first, then
/// all renamed into place, so that a failure while writing (a full disk)
/// leaves none of them changed, never a mix of old and new. The error
/// names the file that failed.
pub fn write_set(files: &[(PathBuf, Vec<u8>)]) -> Result<(), (PathBuf, std::io::Error)> {
    // a directory in a file's place would fail its rename, after the others'
    for (path, _) in files {
        if path.symlink_metadata().is_ok_and(|m| m.is_dir()) {
            let e = std::io::Error::new(std::io::ErrorKind::IsADirectory, "it is a directory");
            return Err((path.clone(), e));
        }
    }
    let mut written = Vec::with_capacity(files.len());
    for (path, bytes) in files {
        let at = |e| (path.clone(), e);
        let mut f = AtomicFile::create(path).map_err(at)?;
        f.write_all(bytes).map_err(at)?;
        f.tmp.as_file().sync_all().map_err(at)?;
        written.push(f);
    }
    for f in written {
        let path = f.path.clone();
        f.tmp.persist(&path).map_err(|e| (path, e.error))?;
    }
    Ok(())
}

/// Makes a private (0700/0600) temporary readable by others, as a result
/// should be.
fn make_public(path: &Path, mode: u32) -> std::io::Result<()> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(path, std::fs::Permissions::from_mode(mode))?;
    }
    let _ = (path, mode);
    Ok(())
}

/// A file written in pieces that appears at its path, whole, only on
/// [`AtomicFile::commit`]; dropped uncommitted it leaves nothing behind,
/// and killed it leaves a temporary file that a later run removes.
pub struct AtomicFile {
    tmp: tempfile::NamedTempFile,
    path: PathBuf,
    _live: Live,
}

impl AtomicFile {
    pub fn create(path: &Path) -> std::io::Result<AtomicFile> {
        let dir = parent_of(path);
        std::fs::create_dir_all(dir)?;
        remove_stale(dir);
        let tmp = temp_builder(&our_prefix()).tempfile_in(dir)?;
        let _live = Live::new(tmp.path());
        make_public(tmp.path(), 0o644)?;
        Ok(AtomicFile {
            tmp,
            path: path.to_path_buf(),
            _live,
        })
    }

    pub fn commit(self) -> std::io::Result<()> {
        self.tmp.as_file().sync_all()?;
        self.tmp.persist(&self.path).map_err(|e| e.error)?;
        Ok(())
    }
}

impl Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.tmp.write(buf)
    }
    fn write_all(&mut self, buf: &[u8]) -> std::io::Result<()> {
        self.tmp.write_all(buf)
    }
    fn flush(&mut self) -> std::io::Result<()> {
        self.tmp.flush()
    }
}

/// A directory filled file by file that replaces its target, whole, only on
/// [`AtomicDir::commit`].
pub struct AtomicDir {
    tmp: tempfile::TempDir,
    target: PathBuf,
    live: Live,
}

impl AtomicDir {
    /// A new, empty temporary directory beside `target` (however spelt:
    /// [`directory_target`]).
    pub fn create(target: &Path) -> std::io::Result<AtomicDir> {
        let target = &directory_target(target);
        let dir = parent_of(target);
        std::fs::create_dir_all(dir)?;
        remove_stale(dir);
        let tmp = temp_builder(&our_prefix()).tempdir_in(dir)?;
        let live = Live::new(tmp.path());
        make_public(tmp.path(), 0o755)?;
        Ok(AtomicDir {
            tmp,
            target: target.to_path_buf(),
            live,
        })
    }

    /// The temporary directory being filled.
    pub fn path(&self) -> &Path {
        self.tmp.path()
    }

    /// Writes the file `name` (a relative path) into the directory. Its
    /// subdirectories are made as needed, never the directory itself (gone,
    /// it stays gone: see [`remove_temporaries`]).
    pub fn write(&self, name: &str, bytes: &[u8]) -> std::io::Result<()> {
        let root = self.tmp.path();
        let path = root.join(name);
        let mut missing = Vec::new();
        let mut at = path.parent();
        while let Some(d) = at.filter(|d| *d != root && !d.is_dir()) {
            missing.push(d);
            at = d.parent();
        }
        for d in missing.into_iter().rev() {
            std::fs::create_dir(d)?;
        }
        std::fs::write(path, bytes)
    }

    /// Puts the directory in the target's place; a previous target (a
    /// directory) is removed.
    pub fn commit(self) -> Result<(), Refused> {
        self.commit_if(|_| Ok(()))
    }

    /// Puts the directory in the target's place if `may_replace` allows
    /// the previous target (a directory), which is then removed: asked just
    /// before the swap, and again of the previous directory just after it
    /// (something saved into it in between would otherwise be lost), when a
    /// refusal swaps them back. A refusal is `Refused::Not(why)`.
    pub fn commit_if(
        self,
        may_replace: impl Fn(&Path) -> Result<(), String>,
    ) -> Result<(), Refused> {
        let AtomicDir { tmp, target, live } = self;
        if target.symlink_metadata().is_err() {
            // rename(2) replaces only an empty directory made meanwhile
            std::fs::rename(tmp.path(), &target)?;
            let _ = tmp.keep();
            return Ok(());
        }
        may_replace(&target).map_err(Refused::Not)?;
        // from the swap on, the temporary path may hold the previous
        // directory: no signal removes it then
        drop(live);
        exchange(tmp.path(), &target)?;
        // the previous result is now at the temporary path
        if let Err(why) = may_replace(tmp.path()) {
            if let Err(e) = exchange(tmp.path(), &target) {
                // never remove what may not be replaced: keep it, and say where
                let kept = tmp.keep();
                let m = format!("{e}; the previous directory is kept at {}", kept.display());
                return Err(Refused::Io(std::io::Error::new(e.kind(), m)));
            }
            return Err(Refused::Not(why));
        }
        drop(tmp);
        Ok(())
    }
}

/// Why [`AtomicDir::commit_if`] did not replace its target.
#[derive(Debug)]
pub enum Refused {
    /// The target may not be replaced: why.
    Not(String),
    Io(std::io::Error),
}

impl From<std::io::Error> for Refused {
    fn from(e: std::io::Error) -> Self {
        Refused::Io(e)
    }
}

/// Swaps two directories: atomically where the system can (Linux), else
/// by two renames through a third name (a run killed between them leaves
/// the target missing, both versions whole under temporary names).
fn exchange(a: &Path, b: &Path) -> std::io::Result<()> {
    #[cfg(target_os = "linux")]
    {
        use std::ffi::CString;
        use std::os::unix::ffi::OsStrExt;
        let c = |p: &Path| CString::new(p.as_os_str().as_bytes()).map_err(std::io::Error::other);
        let (ca, cb) = (c(a)?, c(b)?);
        // SAFETY: two valid NUL-terminated paths, relative to the working
        // directory; renameat2 reads them and touches no memory of ours.
        let r = unsafe {
            libc::renameat2(
                libc::AT_FDCWD,
                ca.as_ptr(),
                libc::AT_FDCWD,
                cb.as_ptr(),
                libc::RENAME_EXCHANGE,
            )
        };
        if r == 0 {
            return Ok(());
        }
        let e = std::io::Error::last_os_error();
        // a file system without RENAME_EXCHANGE: fall through
        if !matches!(e.raw_os_error(), Some(libc::EINVAL) | Some(libc::ENOSYS)) {
            return Err(e);
        }
    }
    let via = temp_builder(&our_prefix()).tempdir_in(parent_of(b))?.keep();
    std::fs::remove_dir(&via)?;
    std::fs::rename(b, &via)?;
    std::fs::rename(a, b)?;
    std::fs::rename(&via, a)
}

/// How long a computation runs before [`while_running`] shows its spinner.
pub const SPINNER_AFTER: std::time::Duration = std::time::Duration::from_secs(1);

/// `work()`, and — once it has run [`SPINNER_AFTER`] — a spinner on stderr
/// that says `what` and the seconds elapsed until it ends (a solve near
/// M = 1 or a sizing takes seconds; a quick one shows nothing). Drawn only
/// where stderr is a terminal (indicatif's own test): piped or redirected
/// output carries none of it.
pub fn while_running<T>(what: &str, work: impl FnOnce() -> T) -> T {
    use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
    let (done, ended) = std::sync::mpsc::channel::<()>();
    std::thread::scope(|scope| {
        scope.spawn(move || {
            if ended.recv_timeout(SPINNER_AFTER).is_ok() {
                return;
            }
            let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr())
                .with_elapsed(SPINNER_AFTER);
            bar.set_style(
                ProgressStyle::with_template("{spinner} {msg} ({elapsed})")
                    .unwrap_or_else(|_| ProgressStyle::default_spinner()),
            );
            bar.set_message(what.to_string());
            bar.enable_steady_tick(std::time::Duration::from_millis(120));
            let _ = ended.recv();
            bar.finish_and_clear();
        });
        let out = work();
        let _ = done.send(());
        out
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The work's value comes back, and the spinner's thread ends with the
    /// work whether it ended before the spinner showed or after (the work
    /// here waits for the spinner's delay to pass; nothing is timed).
    #[test]
    fn while_running_returns_the_work_and_ends_its_spinner() {
        assert_eq!(while_running("quick", || 7), 7);
        let slow = while_running("slow", || {
            std::thread::sleep(SPINNER_AFTER + std::time::Duration::from_millis(200));
            "done"
        });
        assert_eq!(slow, "done");
    }

    #[test]
    fn writes_whole_files_and_replaces_old_ones() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("sub/out.csv");
        atomic_write(&p, b"a,b\n1,2\n").unwrap();
        atomic_write(&p, b"new\n").unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "new\n");
        assert_eq!(std::fs::read_dir(p.parent().unwrap()).unwrap().count(), 1);
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let mode = std::fs::metadata(&p).unwrap().permissions().mode();
            assert_eq!(mode & 0o777, 0o644);
        }
    }

    #[test]
    fn a_set_is_written_whole_or_not_at_all() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("x.json"), dir.path().join("x.py"));
        std::fs::write(&a, "old").unwrap();
        // the second file's directory cannot be made: the first is untouched
        let plain = dir.path().join("plain");
        std::fs::write(&plain, "a file").unwrap();
        let bad = plain.join("x.m");
        let (at, _) =
            write_set(&[(a.clone(), b"new".to_vec()), (bad.clone(), b"m".to_vec())]).unwrap_err();
        assert_eq!(at, bad);
        assert_eq!(std::fs::read_to_string(&a).unwrap(), "old");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
        // nor when a directory stands where the last file goes
        std::fs::create_dir(&b).unwrap();
        let set = [(a.clone(), b"new".to_vec()), (b.clone(), b"py".to_vec())];
        assert_eq!(write_set(&set).unwrap_err().0, b);
        assert_eq!(std::fs::read_to_string(&a).unwrap(), "old");
        std::fs::remove_dir(&b).unwrap();
        write_set(&[(a.clone(), b"new".to_vec()), (b.clone(), b"py".to_vec())]).unwrap();
        assert_eq!(std::fs::read_to_string(&a).unwrap(), "new");
        assert_eq!(std::fs::read_to_string(&b).unwrap(), "py");
    }

    #[test]
    fn an_uncommitted_file_leaves_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("out.csv");
        {
            let mut f = AtomicFile::create(&p).unwrap();
            f.write_all(b"half a ro").unwrap();
        }
        assert!(!p.exists());
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    }

    #[test]
    fn a_directory_replaces_its_target_whole() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("report");
        for (k, names) in [["a", "b"], ["b", "c"]].iter().enumerate() {
            let d = AtomicDir::create(&target).unwrap();
            for n in names {
                d.write(n, format!("{k}").as_bytes()).unwrap();
            }
            d.commit().unwrap();
        }
        let mut now: Vec<String> = std::fs::read_dir(&target)
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        now.sort();
        assert_eq!(now, ["b", "c"]);
        assert_eq!(std::fs::read_to_string(target.join("b")).unwrap(), "1");
        // nothing left beside it
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn a_directory_is_replaced_only_if_it_may_be_at_the_swap() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("report");
        std::fs::create_dir(&target).unwrap();
        std::fs::write(target.join("mine.txt"), "mine").unwrap();
        let d = AtomicDir::create(&target).unwrap();
        d.write("docs/a.md", b"new").unwrap();
        // refused before the swap
        let no = |p: &Path| match p.join("mine.txt").exists() {
            true => Err("mine.txt".to_string()),
            false => Ok(()),
        };
        assert!(matches!(d.commit_if(no), Err(Refused::Not(w)) if w == "mine.txt"));
        assert_eq!(
            std::fs::read_to_string(target.join("mine.txt")).unwrap(),
            "mine"
        );
        // allowed before the swap, refused after it (a file saved meanwhile):
        // swapped back, nothing lost, nothing left beside it
        let d = AtomicDir::create(&target).unwrap();
        d.write("a", b"new").unwrap();
        let calls = std::cell::Cell::new(0);
        let second = |_: &Path| {
            calls.set(calls.get() + 1);
            if calls.get() == 1 {
                Ok(())
            } else {
                Err("saved meanwhile".to_string())
            }
        };
        assert!(matches!(d.commit_if(second), Err(Refused::Not(_))));
        assert_eq!(
            std::fs::read_to_string(target.join("mine.txt")).unwrap(),
            "mine"
        );
        assert!(!target.join("a").exists());
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn a_directory_spelt_with_a_trailing_dot_is_replaced_as_itself() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("rep");
        for (k, spelt) in ["rep", "rep/.", "rep/", "rep/./", "rep/sub/.."]
            .iter()
            .enumerate()
        {
            if k == 4 {
                std::fs::create_dir(target.join("sub")).unwrap();
            }
            let d = AtomicDir::create(&dir.path().join(spelt)).unwrap();
            d.write("index.html", format!("{k}").as_bytes()).unwrap();
            d.commit().unwrap();
            let read = std::fs::read_to_string(target.join("index.html")).unwrap();
            assert_eq!(read, format!("{k}"), "{spelt}");
        }
        assert_eq!(directory_target(Path::new("a/b/.")), Path::new("a/b"));
        assert_eq!(directory_target(Path::new("./a/")), Path::new("./a"));
        // nothing left beside it
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn the_room_for_a_file_is_known_and_said_in_words() {
        let dir = tempfile::tempdir().unwrap();
        #[cfg(unix)]
        {
            let r = room(dir.path()).unwrap();
            assert!(r.bytes > 0, "{r:?}");
        }
        assert_eq!(bytes(4.4e10), "44.0 GB");
        assert_eq!(bytes(812.0), "812 bytes");
        assert_eq!(bytes(1500.0), "1.5 kB");
    }

    #[test]
    fn only_stale_temporaries_of_dead_runs_are_stale() {
        assert_eq!(
            stale_after(".delta-stability-AbC123"),
            Some(LEGACY_STALE_AFTER)
        );
        let me = format!(".delta-stability-{}-AbC123", std::process::id());
        assert_eq!(stale_after(&me), None);
        for other in [
            ".delta-stability-notes",
            ".delta-stability-12-abc",
            "delta-stability-AbC123",
            ".delta-stability-x1-AbC123",
        ] {
            assert_eq!(stale_after(other), None, "{other}");
        }
    }
}
