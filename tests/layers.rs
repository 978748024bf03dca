//! The source layout shows the architecture: every module imports only
//! from its own layer or the layers below it, and no two files import each
//! other in a cycle.
//!
//! The layers, bottom first (`src/<folder>/` or `src/<file>.rs`):
//!
//! | layer | modules |
//! |---|---|
//! | 0 | `float`, `error`, `rounding` |
//! | 1 | `math` (vectors, points, directions, rotations, placements) |
//! | 2 | `motion` (rigid motion, interval, swept arc) |
//! | 3 | `shape` (vertex sets, bounding balls) |
//! | 4 | `bound` (NEVQ, EVQ, one-sided rates, the probe) |
//! | 5 | `geometry` (closest points, predicates, GJK) |
//! | 6 | `mesh` (triangle meshes and their files) |
//! | 7 | `bvh` (ball trees) |
//! | 8 | `ca` (conservative advancement) |
//! | 9 | `scenes`, `reference`, `testkit`, `features`, `proofs` (documents only) |
//!
//! How it checks: every `crate::...` path in the code (comments and doc
//! comments stripped, so doc links and doctests do not count) is resolved to
//! the file it names, through `lib.rs`'s `pub use` re-exports for names
//! taken from the crate root. A path into a higher layer fails the test, and
//! so does a cycle among the files.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

const LAYERS: [(&str, u32); 19] = [
    ("float", 0),
    ("error", 0),
    ("rounding", 0),
    ("math", 1),
    ("motion", 2),
    ("shape", 3),
    ("bound", 4),
    ("geometry", 5),
    ("mesh", 6),
    ("bvh", 7),
    ("ca", 8),
    ("scene", 9),
    ("chain", 9),
    ("bodies", 9),
    ("reference", 9),
    ("testkit", 9),
    ("features", 9),
    ("proofs", 9),
    ("lib", 10),
];

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Every `.rs` file under `src/`, as a module path (`["bound", "probe"]`;
/// `mod.rs` names its folder).
fn files() -> BTreeMap<Vec<String>, PathBuf> {
    fn walk(dir: &Path, prefix: &[String], out: &mut BTreeMap<Vec<String>, PathBuf>) {
        for entry in fs::read_dir(dir).expect("src is readable") {
            let path = entry.expect("entry").path();
            let name = path
                .file_stem()
                .and_then(|s| s.to_str())
                .expect("utf-8 name")
                .to_owned();
            if path.is_dir() {
                let mut p = prefix.to_vec();
                p.push(name);
                walk(&path, &p, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let mut p = prefix.to_vec();
                if name != "mod" {
                    p.push(name);
                }
                out.insert(p, path);
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(&src(), &[], &mut out);
    out
}

/// The code of a file without comments (line comments, doc comments and
/// block comments) and without string literals' contents.
fn code(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let b = text.as_bytes();
    let mut i = 0;
    while i < b.len() {
        if b[i..].starts_with(b"//") {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i..].starts_with(b"/*") {
            while i < b.len() && !b[i..].starts_with(b"*/") {
                i += 1;
            }
            i += 2;
        } else if b[i] == b'"' {
            out.push('"');
            i += 1;
            while i < b.len() && b[i] != b'"' {
                if b[i] == b'\\' {
                    i += 1;
                }
                i += 1;
            }
            out.push('"');
            i += 1;
        } else {
            out.push(b[i] as char);
            i += 1;
        }
    }
    out
}

/// `crate::` paths in `code`, each as its segments; a brace group
/// `crate::{a::b, c}` gives one path per item (nested groups flattened one
/// level, which is all this crate uses).
fn crate_paths(code: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find("crate::") {
        // Not part of a longer identifier (`my_crate::`).
        let before = rest[..at].chars().next_back();
        rest = &rest[at + "crate::".len()..];
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
            continue;
        }
        out.extend(parse_tree(&mut rest, &[]));
    }
    out
}

fn ident(rest: &mut &str) -> Option<String> {
    let s = rest.trim_start();
    let len = s
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(s.len());
    if len == 0 {
        return None;
    }
    let id = s[..len].to_owned();
    *rest = &s[len..];
    Some(id)
}

/// Parses `a::b::{c, d::e}` after `crate::`.
fn parse_tree(rest: &mut &str, prefix: &[String]) -> Vec<Vec<String>> {
    let mut path = prefix.to_vec();
    loop {
        let s = rest.trim_start();
        if let Some(group) = s.strip_prefix('{') {
            *rest = group;
            let mut out = Vec::new();
            loop {
                out.extend(parse_tree(rest, &path));
                // Skip a rename (`X as Y`) up to the next `,` or `}`.
                let s = rest.trim_start();
                let s = &s[s.find([',', '}']).unwrap_or(s.len())..];
                if let Some(next) = s.strip_prefix(',') {
                    *rest = next;
                    if rest.trim_start().starts_with('}') {
                        *rest = &rest.trim_start()[1..];
                        return out;
                    }
                } else if let Some(next) = s.strip_prefix('}') {
                    *rest = next;
                    return out;
                } else {
                    return out;
                }
            }
        }
        match ident(rest) {
            Some(id) => path.push(id),
            None => return vec![path],
        }
        let s = rest.trim_start();
        if let Some(next) = s.strip_prefix("::") {
            *rest = next;
        } else {
            return vec![path];
        }
    }
}

/// Root names re-exported by `lib.rs` (`pub use a::b::{X, Y}`), mapped to
/// the module path they come from.
fn root_exports(lib: &str) -> BTreeMap<String, Vec<String>> {
    let mut out = BTreeMap::new();
    let code = code(lib);
    for stmt in code.split(';') {
        let Some(at) = stmt.find("pub use ") else {
            continue;
        };
        let mut rest = &stmt[at + "pub use ".len()..];
        for path in parse_tree(&mut rest, &[]) {
            if let Some((name, module)) = path.split_last() {
                out.insert(name.clone(), module.to_vec());
            }
        }
    }
    out
}

fn layer(module: &[String]) -> u32 {
    let top = module.first().map_or("lib", String::as_str);
    LAYERS
        .iter()
        .find(|(m, _)| *m == top)
        .map(|&(_, l)| l)
        .unwrap_or_else(|| panic!("module `{top}` has no layer in this test's table"))
}

/// The file a path names: the longest prefix that is a file's module path.
fn resolve(
    path: &[String],
    files: &BTreeMap<Vec<String>, PathBuf>,
    exports: &BTreeMap<String, Vec<String>>,
) -> Option<Vec<String>> {
    let path: Vec<String> = match path.first() {
        Some(first) if !files.keys().any(|k| k.first() == Some(first)) => {
            let mut p = exports.get(first)?.clone();
            p.extend_from_slice(&path[1..]);
            p
        }
        _ => path.to_vec(),
    };
    (1..=path.len())
        .rev()
        .map(|n| path[..n].to_vec())
        .find(|p| files.contains_key(p))
}

#[test]
fn every_module_imports_only_downwards_and_no_files_form_a_cycle() {
    let files = files();
    let lib = fs::read_to_string(src().join("lib.rs")).expect("lib.rs");
    let exports = root_exports(&lib);
    assert!(
        exports.contains_key("Vec3") && exports.contains_key("RigidMotion"),
        "the re-export parser found the root names: {:?}",
        exports.keys().take(5).collect::<Vec<_>>()
    );
    let mut edges: BTreeMap<Vec<String>, BTreeSet<Vec<String>>> = BTreeMap::new();
    let mut upward = Vec::new();
    for (module, path) in &files {
        if module.is_empty() {
            continue; // lib.rs re-exports everything
        }
        let text = fs::read_to_string(path).expect("readable");
        for p in crate_paths(&code(&text)) {
            let Some(target) = resolve(&p, &files, &exports) else {
                continue; // a macro or a name this crate does not define
            };
            if target == *module || target.is_empty() {
                continue;
            }
            if layer(&target) > layer(module) {
                upward.push(format!(
                    "{} (layer {}) imports crate::{} (layer {})",
                    module.join("::"),
                    layer(module),
                    p.join("::"),
                    layer(&target)
                ));
            }
            edges.entry(module.clone()).or_default().insert(target);
        }
    }
    assert!(
        upward.is_empty(),
        "imports into a higher layer:\n{}",
        upward.join("\n")
    );
    // Cycles among files: depth-first search with colours.
    fn visit(
        n: &Vec<String>,
        edges: &BTreeMap<Vec<String>, BTreeSet<Vec<String>>>,
        state: &mut BTreeMap<Vec<String>, u8>,
        stack: &mut Vec<Vec<String>>,
    ) -> Option<Vec<Vec<String>>> {
        match state.get(n) {
            Some(2) => return None,
            Some(1) => {
                let at = stack.iter().position(|m| m == n).expect("on the stack");
                return Some(stack[at..].to_vec());
            }
            _ => {}
        }
        state.insert(n.clone(), 1);
        stack.push(n.clone());
        for m in edges.get(n).into_iter().flatten() {
            if let Some(cycle) = visit(m, edges, state, stack) {
                return Some(cycle);
            }
        }
        stack.pop();
        state.insert(n.clone(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for n in edges.keys() {
        let mut stack = Vec::new();
        if let Some(cycle) = visit(n, &edges, &mut state, &mut stack) {
            let names: Vec<String> = cycle.iter().map(|m| m.join("::")).collect();
            panic!("files import each other in a cycle: {}", names.join(" -> "));
        }
    }
    // The checker has power: it sees the edges it must see.
    let probe = vec!["bound".to_owned(), "probe".to_owned()];
    assert!(
        edges
            .get(&probe)
            .is_some_and(|e| e.contains(&vec!["bound".to_owned(), "scan".to_owned()])),
        "the probe's import of the scans was not seen: {:?}",
        edges.get(&probe)
    );
}

#[test]
fn the_path_parser_reads_groups_and_skips_comments() {
    let text = "use crate::{a::b as x, c};\n// use crate::zzz;\nfn f() { crate::d::e::f(); }";
    let paths = crate_paths(&code(text));
    let want: Vec<Vec<String>> = [vec!["a", "b"], vec!["c"], vec!["d", "e", "f"]]
        .iter()
        .map(|p| p.iter().map(|s| (*s).to_owned()).collect())
        .collect();
    assert_eq!(paths, want);
}
