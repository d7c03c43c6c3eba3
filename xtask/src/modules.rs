//! `cargo xtask modules [CRATE_SRC]`: the module graph of a library crate,
//! checked for cycles at every level of its folders.
//!
//! A module's children (its files and folders) are the nodes of one level;
//! child A points at child B when code anywhere under A names a path under
//! B (`use crate::…`, `super::…`, a path in an expression or a type; test
//! code, `#[cfg(test)]`, left out). A name that a folder's `mod.rs` hands
//! on (`pub use child::X`) counts as the child's. The rule: at every level
//! the arrows form no circle — no module imports one that imports it back —
//! so that each folder reads as layers, lower ones never naming higher.
//! `xtask`'s test `stability_core_has_no_module_cycles` holds
//! `stability-core` to it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use syn::visit::Visit;

/// A module's path from the crate root: `["aerodynamics", "solvers"]`.
pub type ModPath = Vec<String>;

/// One arrow, and the first file and path that drew it.
#[derive(Debug, Clone)]
pub struct Edge {
    pub from: ModPath,
    pub to: ModPath,
    pub file: PathBuf,
    pub named: String,
}

/// The crate's modules (each with its file) and every reference between
/// them, resolved to the module named.
pub struct Graph {
    pub modules: BTreeMap<ModPath, PathBuf>,
    pub references: Vec<Edge>,
}

fn module_files(src: &Path) -> Result<BTreeMap<ModPath, PathBuf>, String> {
    let mut out = BTreeMap::new();
    fn walk(
        dir: &Path,
        prefix: &ModPath,
        out: &mut BTreeMap<ModPath, PathBuf>,
    ) -> Result<(), String> {
        let mut entries: Vec<_> = std::fs::read_dir(dir)
            .map_err(|e| format!("{}: {e}", dir.display()))?
            .filter_map(Result::ok)
            .map(|e| e.path())
            .collect();
        entries.sort();
        for path in entries {
            let name = path
                .file_stem()
                .and_then(|s| s.to_str())
                .unwrap_or("")
                .to_string();
            if path.is_dir() {
                let mut p = prefix.clone();
                p.push(name);
                walk(&path, &p, out)?;
            } else if path.extension().is_some_and(|e| e == "rs") {
                let p = match name.as_str() {
                    "lib" | "main" if prefix.is_empty() => prefix.clone(),
                    "mod" => prefix.clone(),
                    _ => {
                        let mut p = prefix.clone();
                        p.push(name);
                        p
                    }
                };
                out.insert(p, path);
            }
        }
        Ok(())
    }
    walk(src, &Vec::new(), &mut out)?;
    Ok(out)
}

fn is_test(attrs: &[syn::Attribute]) -> bool {
    attrs.iter().any(|a| {
        a.path().is_ident("cfg")
            && a.parse_args::<syn::Meta>()
                .is_ok_and(|m| m.path().is_ident("test") || quote_contains_test(&m))
    })
}

fn quote_contains_test(m: &syn::Meta) -> bool {
    // cfg(any(test, …)) and the like
    match m {
        syn::Meta::List(l) => l
            .tokens
            .to_string()
            .split(|c: char| !c.is_alphanumeric() && c != '_')
            .any(|t| t == "test"),
        _ => false,
    }
}

/// The paths a file names, as written (each a list of segments), and the
/// names its `pub use` items hand on: (name, path).
#[derive(Default)]
struct Names {
    paths: Vec<Vec<String>>,
    reexports: Vec<(String, Vec<String>)>,
}

impl<'ast> Visit<'ast> for Names {
    fn visit_item_mod(&mut self, m: &'ast syn::ItemMod) {
        if !is_test(&m.attrs) {
            syn::visit::visit_item_mod(self, m);
        }
    }
    fn visit_item_fn(&mut self, f: &'ast syn::ItemFn) {
        if !is_test(&f.attrs) {
            syn::visit::visit_item_fn(self, f);
        }
    }
    fn visit_item_impl(&mut self, i: &'ast syn::ItemImpl) {
        if !is_test(&i.attrs) {
            syn::visit::visit_item_impl(self, i);
        }
    }
    fn visit_item_use(&mut self, u: &'ast syn::ItemUse) {
        if is_test(&u.attrs) {
            return;
        }
        let public = !matches!(u.vis, syn::Visibility::Inherited);
        let mut leaves = Vec::new();
        flatten(&u.tree, &mut Vec::new(), &mut leaves);
        for (path, name) in leaves {
            if public && let Some(name) = name {
                self.reexports.push((name, path.clone()));
            }
            self.paths.push(path);
        }
    }
    fn visit_path(&mut self, p: &'ast syn::Path) {
        let segs: Vec<String> = p.segments.iter().map(|s| s.ident.to_string()).collect();
        if matches!(
            segs.first().map(String::as_str),
            Some("crate" | "super" | "self")
        ) && segs.len() > 1
        {
            self.paths.push(segs);
        }
        syn::visit::visit_path(self, p);
    }
}

/// Each leaf of a use tree: its whole path and the name it binds (None
/// for a glob).
fn flatten(
    tree: &syn::UseTree,
    prefix: &mut Vec<String>,
    out: &mut Vec<(Vec<String>, Option<String>)>,
) {
    match tree {
        syn::UseTree::Path(p) => {
            prefix.push(p.ident.to_string());
            flatten(&p.tree, prefix, out);
            prefix.pop();
        }
        syn::UseTree::Name(n) => {
            let mut path = prefix.clone();
            let name = n.ident.to_string();
            if name != "self" {
                path.push(name.clone());
            }
            let bound = if name == "self" {
                prefix.last().cloned()
            } else {
                Some(name)
            };
            out.push((path, bound));
        }
        syn::UseTree::Rename(r) => {
            let mut path = prefix.clone();
            path.push(r.ident.to_string());
            out.push((path, Some(r.rename.to_string())));
        }
        syn::UseTree::Glob(_) => out.push((prefix.clone(), None)),
        syn::UseTree::Group(g) => {
            for t in &g.items {
                flatten(t, prefix, out);
            }
        }
    }
}

/// `path` as written in module `at`, made absolute (from the crate root),
/// or None when it leaves the crate.
fn absolute(
    at: &ModPath,
    path: &[String],
    modules: &BTreeMap<ModPath, PathBuf>,
) -> Option<Vec<String>> {
    let mut out: Vec<String>;
    let mut rest = path;
    match path.first().map(String::as_str) {
        Some("crate") => {
            out = Vec::new();
            rest = &path[1..];
        }
        Some("self") => {
            out = at.clone();
            rest = &path[1..];
        }
        Some("super") => {
            out = at.clone();
            while rest.first().map(String::as_str) == Some("super") {
                out.pop()?;
                rest = &rest[1..];
            }
        }
        // a child module of this one (`use child::X` in a mod.rs)
        Some(first) => {
            let mut child = at.clone();
            child.push(first.to_string());
            if !modules.contains_key(&child) {
                return None;
            }
            out = at.clone();
        }
        None => return None,
    }
    out.extend(rest.iter().cloned());
    Some(out)
}

impl Graph {
    /// The graph of the crate whose source folder is `src`.
    pub fn of(src: &Path) -> Result<Graph, String> {
        let modules = module_files(src)?;
        let mut names: BTreeMap<ModPath, Names> = BTreeMap::new();
        for (m, file) in &modules {
            let text =
                std::fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
            let ast = syn::parse_file(&text).map_err(|e| format!("{}: {e}", file.display()))?;
            let mut n = Names::default();
            n.visit_file(&ast);
            names.insert(m.clone(), n);
        }
        // (module, name) → the absolute path it hands on
        let mut reexports: BTreeMap<(ModPath, String), Vec<String>> = BTreeMap::new();
        for (m, n) in &names {
            for (name, path) in &n.reexports {
                if let Some(abs) = absolute(m, path, &modules) {
                    reexports.insert((m.clone(), name.clone()), abs);
                }
            }
        }
        let mut references = Vec::new();
        for (m, n) in &names {
            for path in &n.paths {
                let Some(abs) = absolute(m, path, &modules) else {
                    continue;
                };
                let to = resolve(&abs, &modules, &reexports, 0);
                references.push(Edge {
                    from: m.clone(),
                    to,
                    file: modules[m].clone(),
                    named: path.join("::"),
                });
            }
        }
        Ok(Graph {
            modules,
            references,
        })
    }

    /// Every circle at every level: for each module, the circles among its
    /// children (each circle as its children's names, with one arrow per
    /// step and what drew it).
    pub fn cycles(&self) -> Vec<(ModPath, Vec<Edge>)> {
        let mut out = Vec::new();
        for parent in self.modules.keys() {
            let children: BTreeSet<String> = self
                .modules
                .keys()
                .filter(|m| m.len() == parent.len() + 1 && m.starts_with(parent))
                .map(|m| m[parent.len()].clone())
                .collect();
            if children.len() < 2 {
                continue;
            }
            let mut arrows: BTreeMap<(String, String), Edge> = BTreeMap::new();
            for e in &self.references {
                let (Some(a), Some(b)) = (child_of(parent, &e.from), child_of(parent, &e.to))
                else {
                    continue;
                };
                if a != b {
                    arrows.entry((a, b)).or_insert_with(|| e.clone());
                }
            }
            for cycle in circles(&children, &arrows) {
                out.push((parent.clone(), cycle));
            }
        }
        out
    }
}

/// The child of `parent` that `m` lies in, if any (not `parent` itself).
fn child_of(parent: &ModPath, m: &ModPath) -> Option<String> {
    (m.len() > parent.len() && m.starts_with(parent)).then(|| m[parent.len()].clone())
}

/// The module an absolute path names: its longest prefix that is a
/// module, followed through a `pub use` there when the next segment is a
/// name that module hands on.
fn resolve(
    abs: &[String],
    modules: &BTreeMap<ModPath, PathBuf>,
    reexports: &BTreeMap<(ModPath, String), Vec<String>>,
    depth: usize,
) -> ModPath {
    let mut n = abs.len();
    while n > 0 && !modules.contains_key(&abs[..n].to_vec()) {
        n -= 1;
    }
    let m = abs[..n].to_vec();
    if depth < 8
        && let Some(name) = abs.get(n)
        && let Some(target) = reexports.get(&(m.clone(), name.clone()))
    {
        let mut t = target.clone();
        t.extend(abs[n + 1..].iter().cloned());
        return resolve(&t, modules, reexports, depth + 1);
    }
    m
}

/// The strongly connected components of more than one node, each as a
/// circle of arrows (Tarjan's algorithm, then one circle through each
/// component found by a walk).
fn circles(nodes: &BTreeSet<String>, arrows: &BTreeMap<(String, String), Edge>) -> Vec<Vec<Edge>> {
    let index: BTreeMap<&String, usize> = nodes.iter().enumerate().map(|(i, n)| (n, i)).collect();
    let names: Vec<&String> = nodes.iter().collect();
    let mut adj = vec![Vec::new(); nodes.len()];
    for (a, b) in arrows.keys() {
        adj[index[a]].push(index[b]);
    }
    let comps = tarjan(&adj);
    let mut out = Vec::new();
    for comp in comps.into_iter().filter(|c| c.len() > 1) {
        let inside: BTreeSet<usize> = comp.iter().copied().collect();
        // a circle: BFS from the first node back to itself within the component
        let start = comp[0];
        let mut prev = vec![usize::MAX; nodes.len()];
        let mut queue = std::collections::VecDeque::from([start]);
        let mut end = None;
        'bfs: while let Some(u) = queue.pop_front() {
            for &v in &adj[u] {
                if !inside.contains(&v) {
                    continue;
                }
                if v == start {
                    end = Some(u);
                    break 'bfs;
                }
                if prev[v] == usize::MAX {
                    prev[v] = u;
                    queue.push_back(v);
                }
            }
        }
        let Some(mut u) = end else { continue };
        let mut path = vec![start];
        while u != start {
            path.push(u);
            u = prev[u];
        }
        path.push(start);
        path.reverse();
        let edges = path
            .windows(2)
            .map(|w| arrows[&(names[w[0]].clone(), names[w[1]].clone())].clone())
            .collect();
        out.push(edges);
    }
    out
}

fn tarjan(adj: &[Vec<usize>]) -> Vec<Vec<usize>> {
    struct S<'a> {
        adj: &'a [Vec<usize>],
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        on: Vec<bool>,
        stack: Vec<usize>,
        next: usize,
        out: Vec<Vec<usize>>,
    }
    fn visit(s: &mut S, v: usize) {
        s.index[v] = Some(s.next);
        s.low[v] = s.next;
        s.next += 1;
        s.stack.push(v);
        s.on[v] = true;
        for &w in &s.adj[v] {
            match s.index[w] {
                None => {
                    visit(s, w);
                    s.low[v] = s.low[v].min(s.low[w]);
                }
                Some(i) if s.on[w] => s.low[v] = s.low[v].min(i),
                _ => {}
            }
        }
        if Some(s.low[v]) == s.index[v] {
            let mut comp = Vec::new();
            while let Some(w) = s.stack.pop() {
                s.on[w] = false;
                comp.push(w);
                if w == v {
                    break;
                }
            }
            s.out.push(comp);
        }
    }
    let n = adj.len();
    let mut s = S {
        adj,
        index: vec![None; n],
        low: vec![0; n],
        on: vec![false; n],
        stack: Vec::new(),
        next: 0,
        out: Vec::new(),
    };
    for v in 0..n {
        if s.index[v].is_none() {
            visit(&mut s, v);
        }
    }
    s.out
}

/// The circles as text, one block each: the level, then each arrow with
/// the file and the path that drew it.
pub fn describe(root: &Path, cycles: &[(ModPath, Vec<Edge>)]) -> String {
    let name = |m: &ModPath| {
        if m.is_empty() {
            "crate".to_string()
        } else {
            m.join("::")
        }
    };
    let mut out = String::new();
    for (parent, edges) in cycles {
        out.push_str(&format!(
            "a circle among the modules of {}:\n",
            name(parent)
        ));
        for e in edges {
            let file = e.file.strip_prefix(root).unwrap_or(&e.file);
            out.push_str(&format!(
                "  {} -> {}  ({}: {})\n",
                name(&e.from),
                name(&e.to),
                file.display(),
                e.named
            ));
        }
    }
    out
}

/// `cargo xtask modules [SRC]`: print the circles of the crate at `src`
/// (stability-core's by default); fail when there is one.
pub fn check(root: &Path, src: Option<&str>) -> Result<(), String> {
    let src = root.join(src.unwrap_or("stability-core/src"));
    let g = Graph::of(&src)?;
    let cycles = g.cycles();
    if cycles.is_empty() {
        println!(
            "{}: {} modules, no circle at any level",
            src.display(),
            g.modules.len()
        );
        Ok(())
    } else {
        Err(format!(
            "{} circle(s):\n{}",
            cycles.len(),
            describe(root, &cycles)
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stability_core_has_no_module_cycles() {
        let root = crate::root();
        let g = Graph::of(&root.join("stability-core/src")).unwrap();
        assert!(g.modules.len() > 50, "{} modules", g.modules.len());
        let cycles = g.cycles();
        assert!(cycles.is_empty(), "{}", describe(&root, &cycles));
    }

    /// The check finds a circle where one is: two files of a scratch
    /// crate that name each other, and one through a name a `mod.rs` hands
    /// on.
    #[test]
    fn a_circle_is_found_and_named() {
        let dir = std::env::temp_dir().join(format!("xtask-modules-{}", std::process::id()));
        let src = dir.join("src");
        std::fs::create_dir_all(src.join("b")).unwrap();
        std::fs::write(src.join("lib.rs"), "mod a;\nmod b;\nmod c;\n").unwrap();
        std::fs::write(src.join("a.rs"), "use crate::b::Thing;\npub struct A;\n").unwrap();
        std::fs::write(src.join("b/mod.rs"), "mod inner;\npub use inner::Thing;\n").unwrap();
        std::fs::write(src.join("b/inner.rs"), "pub struct Thing(crate::c::C);\n").unwrap();
        std::fs::write(
            src.join("c.rs"),
            "pub struct C;\n#[cfg(test)]\nmod tests { use crate::a::A; }\n",
        )
        .unwrap();
        let g = Graph::of(&src).unwrap();
        assert!(g.cycles().is_empty(), "a test module draws no arrow");
        std::fs::write(src.join("c.rs"), "pub struct C(crate::a::A);\n").unwrap();
        let cycles = Graph::of(&src).unwrap().cycles();
        let text = describe(&dir, &cycles);
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(cycles.len(), 1, "{text}");
        assert!(
            text.contains("a -> b::inner")
                && text.contains("b::inner -> c")
                && text.contains("c -> a"),
            "{text}"
        );
    }
}
