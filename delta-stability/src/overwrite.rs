//! No output overwrites an input, nor another output of the same command.
//!
//! A command's inputs are every file it read ([`stability_io::files::recording`]):
//! the derivative file or config and the files that names (CSV tables, an
//! AVL `.st` file). Its outputs are the paths its options give, the
//! python-control and MATLAB scripts written beside `--state-space` among
//! them. Two paths are the same file when their canonical paths agree
//! (symbolic links and `..` resolved; an output not yet written by its
//! directory's) or, on Unix, when they are one file (device and inode: a
//! hard link). An output that is a directory the command replaces whole
//! (`report --out DIR`) must hold no input either, at any depth. Such a
//! command line is bad input (exit status 2), refused before anything is
//! written, and the message names both options.

use crate::Failure;
use stability_io::diag::InputError;
use std::path::{Path, PathBuf};

/// A file a command reads or writes: the option or argument that names it
/// on the command line (`FILE`, `CONFIG`, `--csv`, `-o`, …), what it is in
/// words, and its path.
#[derive(Debug, Clone)]
pub struct Named {
    pub option: String,
    pub what: String,
    pub path: PathBuf,
    /// A directory the command replaces whole: every file in it is lost.
    pub directory: bool,
}

impl Named {
    /// The file `option` names.
    pub fn new(option: impl Into<String>, path: impl Into<PathBuf>) -> Named {
        let option = option.into();
        Named {
            what: option.clone(),
            option,
            path: path.into(),
            directory: false,
        }
    }

    /// The directory `option` names, which the command replaces whole.
    pub fn directory(option: impl Into<String>, path: impl AsRef<Path>) -> Named {
        Named {
            directory: true,
            ..Named::new(option, crate::output::directory_target(path.as_ref()))
        }
    }

    /// A file `option` gives the path of, described as `what`.
    fn described(option: &str, what: String, path: impl Into<PathBuf>) -> Named {
        Named {
            option: option.into(),
            what,
            path: path.into(),
            directory: false,
        }
    }
}

/// Who a file is: its canonical path, and its device and inode when it
/// exists (Unix).
#[derive(Debug, PartialEq)]
struct Identity {
    canonical: PathBuf,
    file: Option<(u64, u64)>,
}

impl Identity {
    fn of(path: &Path) -> Identity {
        Identity {
            canonical: canonical(path),
            file: file_id(path),
        }
    }

    fn same(&self, other: &Identity) -> bool {
        self.canonical == other.canonical || (self.file.is_some() && self.file == other.file)
    }

    /// Whether this file lies in the directory `dir`, at any depth.
    fn within(&self, dir: &Identity) -> bool {
        self.canonical.starts_with(&dir.canonical)
    }
}

/// The canonical path of `path`; of a file that does not exist (yet), its
/// directory's canonical path with its name; else the path made absolute.
fn canonical(path: &Path) -> PathBuf {
    if let Ok(c) = std::fs::canonicalize(path) {
        return c;
    }
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    match (std::fs::canonicalize(parent), path.file_name()) {
        (Ok(dir), Some(name)) => dir.join(name),
        _ => std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf()),
    }
}

#[cfg(unix)]
fn file_id(path: &Path) -> Option<(u64, u64)> {
    use std::os::unix::fs::MetadataExt;
    let m = std::fs::metadata(path).ok()?;
    Some((m.dev(), m.ino()))
}

#[cfg(not(unix))]
fn file_id(_: &Path) -> Option<(u64, u64)> {
    None
}

/// The inputs of a command whose main input (`what`, e.g. `FILE`) is
/// `main`, from the files it read: `main` itself, and each other file as
/// one `main` names.
pub fn inputs(what: &str, main: &str, read: &[PathBuf]) -> Vec<Named> {
    let mut out = vec![Named::new(what, main)];
    let first = Identity::of(Path::new(main));
    for p in read {
        if !Identity::of(p).same(&first) {
            let described = format!("`{}` (named in {what})", p.display());
            out.push(Named::described(what, described, p));
        }
    }
    out
}

/// [`check`] of a command whose main input (`what`) is `main`, which read
/// the files `read` ([`inputs`]).
pub fn refuse(what: &str, main: &str, read: &[PathBuf], outputs: &[Named]) -> Result<(), Failure> {
    check(&inputs(what, main, read), outputs)
}

/// Refuses a command line where an output is an input or another output.
pub fn check(inputs: &[Named], outputs: &[Named]) -> Result<(), Failure> {
    let ins: Vec<Identity> = inputs.iter().map(|n| Identity::of(&n.path)).collect();
    let outs: Vec<Identity> = outputs.iter().map(|n| Identity::of(&n.path)).collect();
    for (k, (o, oid)) in outputs.iter().zip(&outs).enumerate() {
        let bad = |m: String| Failure::Input(InputError::file(&o.path.display().to_string(), m));
        if let Some(i) = ins.iter().position(|id| id.same(oid)) {
            return Err(bad(format!(
                "{} would overwrite {}, which the command reads: give {} another path",
                o.what, inputs[i].what, o.option
            )));
        }
        if o.directory
            && let Some(i) = ins.iter().position(|id| id.within(oid))
        {
            return Err(bad(format!(
                "{} holds {}, which the command reads, and the directory is replaced whole: give {} a directory that holds no input, or move `{}` out of it",
                o.what,
                inputs[i].what,
                o.option,
                inputs[i].path.display()
            )));
        }
        if let Some(j) = outs[..k].iter().position(|id| id.same(oid)) {
            return Err(bad(format!(
                "{} and {} name the same file: each output needs its own path",
                outputs[j].what, o.what
            )));
        }
    }
    Ok(())
}

/// The outputs of `--state-space OUT.json`: the JSON and the scripts
/// written beside it (none without the option).
pub fn state_space(out: Option<&str>) -> Result<Vec<Named>, Failure> {
    let Some(out) = out else {
        return Ok(Vec::new());
    };
    let [json, py, m] = stability_io::state_space::paths(out)?;
    let script = |p: PathBuf| {
        let what = format!(
            "the script {} that --state-space writes beside {out}",
            p.display()
        );
        Named::described("--state-space", what, p)
    };
    Ok(vec![
        Named::new("--state-space", json),
        script(py),
        script(m),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_file_by_another_name_is_the_same_file() {
        let dir = tempfile::tempdir().unwrap();
        let a = dir.path().join("a.toml");
        std::fs::write(&a, "x").unwrap();
        std::fs::create_dir(dir.path().join("sub")).unwrap();
        let by_dots = dir.path().join("sub/../a.toml");
        assert!(Identity::of(&a).same(&Identity::of(&by_dots)));
        // a file not yet written, by its directory
        let new = dir.path().join("sub/new.csv");
        let other = dir.path().join("sub/./new.csv");
        assert!(Identity::of(&new).same(&Identity::of(&other)));
        assert!(!Identity::of(&new).same(&Identity::of(&a)));
        #[cfg(unix)]
        {
            let link = dir.path().join("hard.toml");
            std::fs::hard_link(&a, &link).unwrap();
            assert!(Identity::of(&a).same(&Identity::of(&link)));
        }
        let err = check(
            &[Named::new("FILE", &a)],
            &[Named::new("--csv", &new), Named::new("--svg", &by_dots)],
        )
        .unwrap_err();
        assert!(
            err.to_string().contains("--svg would overwrite FILE"),
            "{err}"
        );
        let err = check(
            &[],
            &[Named::new("--csv", &new), Named::new("--svg", &other)],
        );
        assert!(
            err.unwrap_err()
                .to_string()
                .contains("--csv and --svg name the same file")
        );
    }

    #[test]
    fn a_directory_replaced_whole_holds_no_input() {
        let dir = tempfile::tempdir().unwrap();
        let rep = dir.path().join("rep");
        std::fs::create_dir_all(rep.join("data")).unwrap();
        let table = rep.join("data/lift-slope.csv");
        std::fs::write(&table, "mach,value\n").unwrap();
        let config = dir.path().join("a.toml");
        std::fs::write(&config, "x").unwrap();
        let ins = inputs("CONFIG", config.to_str().unwrap(), &[config.clone(), table]);
        for spelt in ["rep", "rep/.", "rep/", "rep/data/.."] {
            let out = Named::directory("--out", dir.path().join(spelt));
            let e = check(&ins, &[out]).unwrap_err().to_string();
            assert!(
                e.contains("--out holds") && e.contains("lift-slope.csv"),
                "{spelt}: {e}"
            );
        }
        // a directory beside the input's, or one not yet made, is fine
        for other in ["rep2", "new/sub"] {
            let out = Named::directory("--out", dir.path().join(other));
            assert!(check(&ins, &[out]).is_ok(), "{other}");
        }
        // a file output is not a directory: it only must not be an input
        let file = Named::new("-o", dir.path().join("rep/data/out.csv"));
        assert!(check(&ins, &[file]).is_ok());
    }
}
