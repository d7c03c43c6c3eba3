//! What every test of the program as a user runs it shares: the binary, the
//! repository root, running a command and checking its exit status.

use stability_study::Report;
use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

/// The program, run from the repository root (so that `examples/…` paths
/// resolve). `DELTA_STABILITY_BIN` runs another build of it instead (to see
/// a regression test fail on the program before its fix).
pub fn bin() -> Command {
    let exe = std::env::var_os("DELTA_STABILITY_BIN").map_or_else(
        || env!("CARGO_BIN_EXE_delta-stability").into(),
        PathBuf::from,
    );
    let mut c = Command::new(exe);
    c.current_dir(root());
    c
}

/// The repository root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The program's standard error, as text.
pub fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// The program's standard output, as text.
pub fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Runs the program with `args`, which must succeed.
pub fn run_ok<S: AsRef<OsStr>>(args: &[S]) -> Output {
    let out = bin().args(args).output().expect("the program runs");
    assert!(
        out.status.success(),
        "{:?} failed ({:?}):\n{}",
        args.iter().map(|a| a.as_ref()).collect::<Vec<_>>(),
        out.status,
        stderr(&out)
    );
    out
}

/// Runs the program with `args`, which must fail with exit status `code`
/// (2: bad input, 3: a file could not be read or written), without a panic
/// and with a message on standard error.
pub fn run_err<S: AsRef<OsStr>>(args: &[S], code: i32) -> Output {
    let out = bin().args(args).output().expect("the program runs");
    let err = stderr(&out);
    assert_eq!(
        out.status.code(),
        Some(code),
        "{:?}: expected exit status {code}:\n{err}",
        args.iter().map(|a| a.as_ref()).collect::<Vec<_>>()
    );
    assert!(!err.contains("panicked"), "{err}");
    assert!(!err.trim().is_empty(), "no message on standard error");
    out
}

/// The JSON object a command printed.
pub fn json(out: &Output) -> serde_json::Value {
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

/// An example file's text.
pub fn example(name: &str) -> String {
    std::fs::read_to_string(root().join("examples").join(name)).expect("example")
}

/// A temporary directory for a test's files.
pub struct Scratch(pub tempfile::TempDir);

impl Scratch {
    pub fn new() -> Scratch {
        Scratch(tempfile::tempdir().expect("temp dir"))
    }
    pub fn path(&self) -> &Path {
        self.0.path()
    }
    /// Writes `contents` to `name` in the directory and returns its path.
    pub fn write(&self, name: &str, contents: impl AsRef<[u8]>) -> PathBuf {
        let p = self.0.path().join(name);
        std::fs::write(&p, contents).expect("write");
        p
    }
}

/// A path as a command-line argument (the tests' paths are UTF-8).
pub fn path(p: &Path) -> &str {
    p.to_str().expect("a UTF-8 path")
}

/// The mode `name` (`short_period`, `phugoid`) of a `--json` output, as
/// (re, im) in 1/s.
pub fn mode_s(v: &serde_json::Value, name: &str) -> (f64, f64) {
    let m = v["modes"]
        .as_array()
        .expect("modes")
        .iter()
        .find(|m| m["name"] == name)
        .unwrap_or_else(|| panic!("no {name} in {v}"));
    (m["re_s"].as_f64().unwrap(), m["im_s"].as_f64().unwrap())
}

/// The note's study computed whole by the library ([`Report::compute`],
/// what `delta-stability report` writes), once for the test binary.
pub fn report() -> &'static Report {
    static REPORT: OnceLock<Report> = OnceLock::new();
    REPORT.get_or_init(|| Report::quietly().unwrap_or_else(|e| panic!("{e:?}")))
}

/// `delta-stability report --out DIR`, run once for the test binary — the
/// one run of the whole report end to end: DIR, under the target
/// directory's scratch space (each run replaces it, as a report replaces a
/// report).
pub fn note_report() -> &'static Path {
    static OUT: OnceLock<PathBuf> = OnceLock::new();
    OUT.get_or_init(|| {
        let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("note-report/somewhere/report");
        run_ok(&["report", "--out", path(&out)]);
        out
    })
}

/// Copies the directory `from`, whole, to `to` (which must not exist).
pub fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).expect("create");
    for entry in std::fs::read_dir(from).expect("read") {
        let entry = entry.expect("entry");
        let target = to.join(entry.file_name());
        if entry.file_type().expect("type").is_dir() {
            copy_dir(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), target).expect("copy");
        }
    }
}

/// Polls `ready` (what the program has written) until it holds — true —
/// or `child` has ended without it — false. No time limit: the test waits
/// on the program, however loaded the machine (a program that hangs is
/// caught by the run's own limit).
pub fn wait_while_running(
    child: &mut std::process::Child,
    mut ready: impl FnMut() -> bool,
) -> bool {
    loop {
        if ready() {
            return true;
        }
        if child.try_wait().expect("wait").is_some() {
            return ready();
        }
        std::thread::sleep(std::time::Duration::from_millis(2));
    }
}
