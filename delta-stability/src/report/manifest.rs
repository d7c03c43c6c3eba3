//! What a report wrote, so that `report --out DIR` replaces DIR only when
//! nothing in it would be lost: the report writes, beside its files, a
//! manifest ([`MANIFEST`]) listing each one's path, size and hash, and a
//! later report replaces DIR only if everything in it, recursively, is a
//! file of that list, unchanged (or the manifest itself). A file of the
//! user's — under a name the report does not write, under `docs/`, or an
//! `index.html` or `summary.json` of their own or edited — is found, and
//! named, before anything is removed; DIR is checked when the run starts
//! and again at the moment it is replaced.

use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The manifest's name in the report's directory.
pub const MANIFEST: &str = ".report-manifest.json";

/// A file the report wrote: its size and FNV-1a hash (enough to tell the
/// report's file from one the user put or edited there; it guards against
/// mistakes, not against an adversary).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Entry {
    bytes: u64,
    fnv1a64: String,
}

impl Entry {
    fn of(bytes: &[u8]) -> Entry {
        Entry {
            bytes: bytes.len() as u64,
            fnv1a64: format!("{:016x}", stability_io::files::fnv1a64(bytes)),
        }
    }
}

/// The files a report wrote, by their paths relative to its directory
/// (`fig01.svg`, `docs/models.md`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Manifest {
    generator: String,
    files: BTreeMap<String, Entry>,
}

impl Default for Manifest {
    fn default() -> Self {
        Manifest {
            generator: format!("delta-stability {} report", stability_io::VERSION),
            files: BTreeMap::new(),
        }
    }
}

impl Manifest {
    /// Notes that the report wrote `bytes` to `name`.
    pub fn add(&mut self, name: &str, bytes: &[u8]) {
        self.files.insert(name.to_string(), Entry::of(bytes));
    }

    /// The manifest as written into the report's directory.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default() + "\n"
    }

    /// The manifest in `dir`, if it is a regular file that reads as one
    /// (a FIFO or a device in its place is not waited on: it is then
    /// something the report did not write).
    fn read(dir: &Path) -> Option<Manifest> {
        let bytes = stability_io::files::read_regular(&dir.join(MANIFEST)).ok()?;
        serde_json::from_slice(&bytes).ok()
    }

    /// The directories its files lie in (`docs`).
    fn directories(&self) -> BTreeSet<String> {
        let mut out = BTreeSet::new();
        for name in self.files.keys() {
            let mut at = name.as_str();
            while let Some((dir, _)) = at.rsplit_once('/') {
                out.insert(dir.to_string());
                at = dir;
            }
        }
        out
    }
}

/// What in `dir` a report did not write, or changed since (relative paths,
/// each with why), recursively: empty when replacing `dir` loses nothing.
/// Without a manifest every entry is foreign.
pub fn foreign(dir: &Path) -> std::io::Result<Vec<String>> {
    let manifest = Manifest::read(dir);
    let mut out = Vec::new();
    walk(dir, "", manifest.as_ref(), &mut out)?;
    if manifest.is_none() && !out.is_empty() {
        out.push(format!(
            "(no {MANIFEST}: the directory is not a report, or one written before reports listed their files)"
        ));
    }
    Ok(out)
}

fn walk(
    dir: &Path,
    prefix: &str,
    manifest: Option<&Manifest>,
    out: &mut Vec<String>,
) -> std::io::Result<()> {
    let dirs = manifest.map(Manifest::directories).unwrap_or_default();
    let mut entries: Vec<_> = std::fs::read_dir(dir)?.collect::<Result<_, _>>()?;
    entries.sort_by_key(|e| e.file_name());
    for e in entries {
        let name = format!("{prefix}{}", e.file_name().to_string_lossy());
        let kind = e.path().symlink_metadata()?.file_type();
        if kind.is_dir() && dirs.contains(&name) {
            walk(&e.path(), &format!("{name}/"), manifest, out)?;
        } else if kind.is_dir() {
            out.push(format!("{name}/"));
        } else if name == MANIFEST && manifest.is_some() {
            continue;
        } else if !kind.is_file() {
            out.push(format!("{name} (not a regular file)"));
        } else {
            match manifest.and_then(|m| m.files.get(&name)) {
                None => out.push(name),
                Some(written)
                    if *written != Entry::of(&stability_io::files::read_regular(&e.path())?) =>
                {
                    out.push(format!("{name} (changed since the report wrote it)"));
                }
                Some(_) => {}
            }
        }
    }
    Ok(())
}

/// [`foreign`]'s list in a sentence's words: the first few, and how many
/// more.
pub fn describe(foreign: &[String]) -> String {
    const SHOWN: usize = 6;
    let mut s: Vec<String> = foreign
        .iter()
        .take(SHOWN)
        .map(|n| {
            let quote = stability_io::diag::quote;
            match n.split_once(" (") {
                _ if n.starts_with('(') => n.clone(),
                Some((name, why)) => format!("`{}` ({why}", quote(name)),
                None => format!("`{}`", quote(n)),
            }
        })
        .collect();
    if foreign.len() > SHOWN {
        s.push(format!("and {} more", foreign.len() - SHOWN));
    }
    s.join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn report(dir: &Path) -> Manifest {
        let mut m = Manifest::default();
        for (name, text) in [("index.html", "<p>page"), ("docs/models.md", "# models")] {
            let p = dir.join(name);
            std::fs::create_dir_all(p.parent().unwrap()).unwrap();
            std::fs::write(&p, text).unwrap();
            m.add(name, text.as_bytes());
        }
        std::fs::write(dir.join(MANIFEST), m.to_json()).unwrap();
        m
    }

    #[test]
    fn only_what_the_report_wrote_unchanged_may_be_replaced() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        report(d);
        assert!(foreign(d).unwrap().is_empty());
        // a file of the user's under docs/, a directory of theirs, an edit
        std::fs::write(d.join("docs/mine.md"), "mine").unwrap();
        std::fs::create_dir(d.join("data")).unwrap();
        std::fs::write(d.join("index.html"), "<p>my own page").unwrap();
        assert_eq!(
            foreign(d).unwrap(),
            [
                "data/",
                "docs/mine.md",
                "index.html (changed since the report wrote it)"
            ]
        );
        // without a manifest nothing is the report's
        let bare = tempfile::tempdir().unwrap();
        std::fs::write(bare.path().join("summary.json"), "{}").unwrap();
        let f = foreign(bare.path()).unwrap();
        assert_eq!(f[0], "summary.json");
        assert!(describe(&f).contains(MANIFEST), "{}", describe(&f));
        assert!(
            foreign(tempfile::tempdir().unwrap().path())
                .unwrap()
                .is_empty()
        );
    }

    /// A FIFO in the manifest's place (no writer will ever open it) is
    /// named as what the report did not write, at once: reading it would
    /// block forever.
    #[cfg(unix)]
    #[test]
    fn a_fifo_in_the_manifests_place_is_foreign_not_waited_on() {
        let dir = tempfile::tempdir().unwrap();
        report(dir.path());
        let manifest = dir.path().join(MANIFEST);
        std::fs::remove_file(&manifest).unwrap();
        let c = std::ffi::CString::new(manifest.to_str().unwrap()).unwrap();
        // SAFETY: a NUL-terminated path; mkfifo touches no memory of ours
        assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o644) }, 0);
        let f = foreign(dir.path()).unwrap();
        assert!(
            f.contains(&format!("{MANIFEST} (not a regular file)")),
            "{f:?}"
        );
    }
}
