//! The source layout shows the architecture: every module imports only
//! from itself and from the layers below its own, and no two files import
//! each other in a cycle (two files of one folder included).
//!
//! The layers, bottom first (`src/<folder>/` or `src/<file>.rs`); a module
//! may import from itself and from the modules of lower layers only:
//!
//! | layer | modules |
//! |---|---|
//! | 0 | `float` (the float trait), `rng` (the test support's seeded generator) |
//! | 1 | `error` (input errors), `rounding` (directed rounding, error bounds), `dd` (double-double numbers) |
//! | 2 | `math` (vectors, points, directions, rotations, placements) |
//! | 3 | `motion` (rigid motion, interval, swept arc) |
//! | 4 | `shape` (vertex sets, bounding balls, convex shapes, half-spaces) |
//! | 5 | `bound` (NEVQ, EVQ, one-sided rates, the probe) |
//! | 6 | `geometry` (closest points, predicates, GJK) |
//! | 7 | `mesh` (triangle meshes and their files) |
//! | 8 | `bvh` (ball trees) |
//! | 9 | `ca` (conservative advancement) |
//! | 10 | `scene` (many bodies: broad and narrow phase) |
//! | 11 | `chain` (linked bodies) |
//! | 12 | `bodies` (the built-in test bodies) |
//! | 13 | `reference` (the exact closed-form oracle) |
//! | 14 | `testkit` (hard-case generators, ground truth) |
//! | 15 | `features` (interop trait impls), `proofs` (documents only) |
//! | 16 | `lib` (the crate root: declarations and re-exports) |
//!
//! How it checks: every path in the code that starts with `crate::`,
//! `super::` or `self::` (comments, doc comments and string literals
//! stripped, so doc links and doctests do not count; a `use` group gives
//! one path an item) is made absolute: `super::` climbs one module from the
//! module the path stands in (from `src/ca/mesh/queue.rs` to `ca::mesh`,
//! from `src/ca/mesh/mod.rs` to `ca`, from an inline `mod tests` to its
//! file; `super::super::` two), `self::` stays there. A name the crate root
//! re-exports (`crate::Vec3`) is replaced by where `lib.rs` takes it from.
//! The path then names the file of its longest prefix that is a file's
//! module path (a name a `mod.rs` re-exports names that `mod.rs`, so a file
//! imports its siblings by their own paths, `super::queue::Pending`). A path
//! into a higher layer, or into another module of the same layer, fails the
//! test, and so does a cycle among the files, whatever folders they are in
//! (two files of one folder included).

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

const LAYERS: [(&str, u32); 21] = [
    ("float", 0),
    ("rng", 0),
    ("error", 1),
    ("rounding", 1),
    ("dd", 1),
    ("math", 2),
    ("motion", 3),
    ("shape", 4),
    ("bound", 5),
    ("geometry", 6),
    ("mesh", 7),
    ("bvh", 8),
    ("ca", 9),
    ("scene", 10),
    ("chain", 11),
    ("bodies", 12),
    ("reference", 13),
    ("testkit", 14),
    ("features", 15),
    ("proofs", 15),
    ("lib", 16),
];

/// A module path from the crate root (`["ca", "mesh", "queue"]`; `[]` is
/// the root).
type Module = Vec<String>;

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Every `.rs` file under `src/`, by its module path (`["bound", "probe"]`;
/// `mod.rs` names its folder, `lib.rs` the root `[]`).
fn files() -> BTreeMap<Module, PathBuf> {
    fn walk(dir: &Path, prefix: &[String], out: &mut BTreeMap<Module, PathBuf>) {
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
                if name != "mod" && !(prefix.is_empty() && name == "lib") {
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

fn is_ident(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

/// The code of a file without comments (line comments, doc comments and
/// block comments), without the contents of string literals (raw ones
/// too) and without character literals (a `'{'` opens no block).
fn code(text: &str) -> String {
    let mut out = Vec::with_capacity(text.len());
    let b = text.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let raw_hashes = (b[i] == b'r' && (i == 0 || !is_ident(b[i - 1])))
            .then(|| b[i + 1..].iter().take_while(|&&c| c == b'#').count())
            .filter(|&h| b.get(i + 1 + h) == Some(&b'"'));
        if b[i..].starts_with(b"//") {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i..].starts_with(b"/*") {
            while i < b.len() && !b[i..].starts_with(b"*/") {
                i += 1;
            }
            i += 2;
        } else if let Some(h) = raw_hashes {
            // `r#"..."#`: ends at a quote followed by as many hashes.
            let end: Vec<u8> = core::iter::once(b'"')
                .chain(core::iter::repeat_n(b'#', h))
                .collect();
            i += 2 + h;
            while i < b.len() && !b[i..].starts_with(&end) {
                i += 1;
            }
            out.extend_from_slice(b"\"\"");
            i += end.len();
        } else if b[i] == b'"' {
            out.push(b'"');
            i += 1;
            while i < b.len() && b[i] != b'"' {
                if b[i] == b'\\' {
                    i += 1;
                }
                i += 1;
            }
            out.push(b'"');
            i += 1;
        } else if b[i] == b'\'' {
            // A character literal (`'x'`, `'\n'`, `'é'`), or a lifetime.
            let close = match b.get(i + 1) {
                Some(b'\\') => b
                    .get(i + 3..)
                    .and_then(|s| s.iter().position(|&c| c == b'\''))
                    .map(|k| i + 3 + k),
                Some(&c) if c >= 0xF0 => Some(i + 5),
                Some(&c) if c >= 0xE0 => Some(i + 4),
                Some(&c) if c >= 0xC0 => Some(i + 3),
                Some(_) => Some(i + 2),
                None => None,
            };
            match close {
                Some(k) if b.get(k) == Some(&b'\'') => {
                    out.extend_from_slice(b"' '");
                    i = k + 1;
                }
                _ => {
                    out.push(b'\'');
                    i += 1;
                }
            }
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    String::from_utf8(out).expect("only whole characters are dropped")
}

/// One path read in the code: its segments as written (`super`, `self` and
/// `crate` included) and the module it stands in.
#[derive(Clone, Debug, PartialEq)]
struct Read {
    written: Vec<String>,
    within: Module,
}

/// A name a module binds with `use`: the module, the name (its rename if
/// any), and the path as written.
#[derive(Clone, Debug, PartialEq)]
struct Binding {
    module: Module,
    name: String,
    written: Vec<String>,
}

/// Every path in `code` (the code of the file of module `module`) that
/// starts with `crate::`, `super::` or `self::`, in `use` declarations and
/// in expressions alike, with the module each stands in (inline `mod name
/// { ... }` blocks tracked); and the names bound by `use` declarations at
/// a module's top level (block-local ones left out).
fn read(code: &str, module: &[String]) -> (Vec<Read>, Vec<Binding>) {
    let (mut paths, mut bindings) = (Vec::new(), Vec::new());
    let b = code.as_bytes();
    // Open blocks; an inline module's body is `Some(name)`.
    let mut blocks: Vec<Option<String>> = Vec::new();
    let within = |blocks: &[Option<String>]| {
        let mut m = module.to_vec();
        m.extend(blocks.iter().flatten().cloned());
        m
    };
    let keyword = |i: usize, word: &str| {
        b[i..].starts_with(word.as_bytes())
            && (i == 0 || !is_ident(b[i - 1]))
            && b.get(i + word.len()).is_some_and(|&c| !is_ident(c))
    };
    let mut i = 0;
    while i < b.len() {
        if keyword(i, "use") {
            let mut rest = &code[i + "use".len()..];
            let top_level = blocks.last().is_none_or(Option::is_some);
            for (written, name) in parse_tree(&mut rest, &[]) {
                let first = written.first().map(String::as_str);
                if matches!(first, Some("crate" | "super" | "self")) {
                    paths.push(Read {
                        written: written.clone(),
                        within: within(&blocks),
                    });
                }
                if let (true, Some(name)) = (top_level, name) {
                    bindings.push(Binding {
                        module: within(&blocks),
                        name,
                        written,
                    });
                }
            }
            i = code.len() - rest.len();
        } else if ["crate", "super", "self"]
            .iter()
            .any(|w| keyword(i, w) && b[i + w.len()..].starts_with(b"::"))
        {
            let mut rest = &code[i..];
            for (written, _) in parse_tree(&mut rest, &[]) {
                paths.push(Read {
                    written,
                    within: within(&blocks),
                });
            }
            i = code.len() - rest.len();
        } else if keyword(i, "mod") {
            let mut rest = &code[i + "mod".len()..];
            match ident(&mut rest) {
                Some(name) if rest.trim_start().starts_with('{') => {
                    blocks.push(Some(name));
                    let open = rest.find('{').expect("just seen");
                    i = code.len() - rest.len() + open + 1;
                }
                _ => i += "mod".len(),
            }
        } else {
            match b[i] {
                b'{' => blocks.push(None),
                b'}' => {
                    blocks.pop();
                }
                _ => {}
            }
            i += 1;
        }
    }
    (paths, bindings)
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

/// Parses a use tree (`a::b::{c, d::e as f, g::*}`) or a path, each path
/// with the name it binds: its last segment (the module for a trailing
/// `self`) or its rename; none for a glob.
fn parse_tree(rest: &mut &str, prefix: &[String]) -> Vec<(Vec<String>, Option<String>)> {
    let mut path = prefix.to_vec();
    loop {
        let s = rest.trim_start();
        if let Some(group) = s.strip_prefix('{') {
            *rest = group;
            let mut out = Vec::new();
            loop {
                out.extend(parse_tree(rest, &path));
                let s = rest.trim_start();
                let s = &s[s.find([',', '}']).unwrap_or(s.len())..];
                if let Some(next) = s.strip_prefix(',') {
                    *rest = next;
                    if let Some(end) = rest.trim_start().strip_prefix('}') {
                        *rest = end;
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
        if let Some(glob) = s.strip_prefix('*') {
            *rest = glob;
            return vec![(path, None)];
        }
        match ident(rest) {
            Some(id) => path.push(id),
            None => return vec![bound(path, rest)],
        }
        let s = rest.trim_start();
        if let Some(next) = s.strip_prefix("::") {
            *rest = next;
        } else {
            return vec![bound(path, rest)];
        }
    }
}

/// A parsed path with the name it binds (reading a rename `as x` off
/// `rest`).
fn bound(mut path: Vec<String>, rest: &mut &str) -> (Vec<String>, Option<String>) {
    let mut after = *rest;
    let rename = match ident(&mut after).as_deref() {
        Some("as") => ident(&mut after).inspect(|_| *rest = after),
        _ => None,
    };
    if path.last().is_some_and(|s| s == "self") {
        path.pop();
    }
    let name = rename.or_else(|| path.last().cloned());
    (path, name)
}

/// The absolute module path of `written`, read in module `within`; a path
/// that starts with a plain name is taken as relative to `within` (in a
/// `use`, a child module or an item; a crate's name resolves to nothing).
fn absolute(written: &[String], within: &[String]) -> Option<Module> {
    let mut out: Module = within.to_vec();
    let mut segments = written.iter().peekable();
    match segments.peek().map(|s| s.as_str()) {
        Some("crate") => {
            out.clear();
            segments.next();
        }
        Some("self") => {
            segments.next();
        }
        _ => {}
    }
    while segments.peek().is_some_and(|s| *s == "super") {
        out.pop()?;
        segments.next();
    }
    out.extend(segments.filter(|s| *s != "self").cloned());
    Some(out)
}

/// The file that defines module path `path`: the longest prefix that is a
/// file's module path, after every name a module binds with `use`
/// (`bindings`: (module, name) -> absolute path) is replaced by where it
/// comes from, so that a path through a re-export (`crate::Vec3`,
/// `crate::ca::AnyPair`, `super::MeshWorkspace`) names the file that
/// defines the item, not the `mod.rs` or `lib.rs` that re-exports it.
fn resolve(
    path: &[String],
    files: &BTreeMap<Module, String>,
    bindings: &BTreeMap<(Module, String), Module>,
) -> Module {
    let file_of = |path: &[String]| -> Module {
        (0..=path.len())
            .rev()
            .map(|n| path[..n].to_vec())
            .find(|p| files.contains_key(p))
            .expect("the root is a file")
    };
    let mut path = path.to_vec();
    // A chain of re-exports is short; the bound stops a `use` cycle.
    for _ in 0..32 {
        let file = file_of(&path);
        let Some(next) = path.get(file.len()) else {
            return file;
        };
        let Some(target) = bindings.get(&(file.clone(), next.clone())) else {
            return file;
        };
        let mut followed = target.clone();
        followed.extend_from_slice(&path[file.len() + 1..]);
        if followed == path {
            return file;
        }
        path = followed;
    }
    file_of(&path)
}

fn layer(module: &[String]) -> u32 {
    let top = module.first().map_or("lib", String::as_str);
    LAYERS
        .iter()
        .find(|(m, _)| *m == top)
        .map(|&(_, l)| l)
        .unwrap_or_else(|| panic!("module `{top}` has no layer in this test's table"))
}

fn name(module: &[String]) -> String {
    if module.is_empty() {
        "lib".to_owned()
    } else {
        module.join("::")
    }
}

/// The import graph of the files under `src`: for each file (by module
/// path), the files it imports, each with one path that imports it (as
/// written).
fn graph(src: &BTreeMap<Module, String>) -> BTreeMap<Module, BTreeMap<Module, String>> {
    let mut reads = Vec::new();
    let mut bindings = BTreeMap::new();
    for (module, text) in src {
        let (paths, bound) = read(&code(text), module);
        reads.extend(paths.into_iter().map(|p| (module.clone(), p)));
        // Every module's `use` bindings are followed (re-exports of the
        // root and of every `mod.rs` included): a file that imports an item
        // through its parent imports the item's own file.
        for b in bound {
            if let Some(target) = absolute(&b.written, &b.module) {
                bindings.insert((b.module, b.name), target);
            }
        }
    }
    let mut edges: BTreeMap<Module, BTreeMap<Module, String>> = BTreeMap::new();
    for (file, read) in reads {
        let Some(path) = absolute(&read.written, &read.within) else {
            continue; // `super` above the root: not this crate's path
        };
        let target = resolve(&path, src, &bindings);
        // The root holds no item a module imports (a name it does not
        // re-export, a macro, resolves to it).
        if target != file && !target.is_empty() {
            edges
                .entry(file)
                .or_default()
                .entry(target)
                .or_insert_with(|| read.written.join("::"));
        }
    }
    edges
}

/// The first cycle among the files of `edges` (a depth-first search with
/// colours), closed: its first file again at its end.
fn cycle(edges: &BTreeMap<Module, BTreeMap<Module, String>>) -> Option<Vec<Module>> {
    fn visit(
        n: &Module,
        edges: &BTreeMap<Module, BTreeMap<Module, String>>,
        state: &mut BTreeMap<Module, u8>,
        stack: &mut Vec<Module>,
    ) -> Option<Vec<Module>> {
        match state.get(n) {
            Some(2) => return None,
            Some(1) => {
                let at = stack.iter().position(|m| m == n).expect("on the stack");
                let mut cycle = stack[at..].to_vec();
                cycle.push(n.clone());
                return Some(cycle);
            }
            _ => {}
        }
        state.insert(n.clone(), 1);
        stack.push(n.clone());
        for m in edges.get(n).into_iter().flat_map(BTreeMap::keys) {
            if let Some(cycle) = visit(m, edges, state, stack) {
                return Some(cycle);
            }
        }
        stack.pop();
        state.insert(n.clone(), 2);
        None
    }
    let mut state = BTreeMap::new();
    edges
        .keys()
        .find_map(|n| visit(n, edges, &mut state, &mut Vec::new()))
}

/// A cycle as `a -> b (the path a imports b by) -> ... -> a`.
fn describe(cycle: &[Module], edges: &BTreeMap<Module, BTreeMap<Module, String>>) -> String {
    let mut out = name(&cycle[0]);
    for w in cycle.windows(2) {
        out += &format!(" -> {} (`{}`)", name(&w[1]), edges[&w[0]][&w[1]]);
    }
    out
}

fn module(path: &str) -> Module {
    path.split("::")
        .filter(|s| !s.is_empty())
        .map(str::to_owned)
        .collect()
}

#[test]
fn every_module_imports_only_downwards_and_no_files_form_a_cycle() {
    let src: BTreeMap<Module, String> = files()
        .into_iter()
        .map(|(m, path)| (m, fs::read_to_string(path).expect("readable")))
        .collect();
    let edges = graph(&src);
    let mut upward = Vec::new();
    for (file, targets) in &edges {
        for (target, written) in targets {
            let same_module = file.first() == target.first();
            if !same_module && layer(target) >= layer(file) {
                upward.push(format!(
                    "{} (layer {}) imports {} (layer {}) by `{}`",
                    name(file),
                    layer(file),
                    name(target),
                    layer(target),
                    written
                ));
            }
        }
    }
    assert!(
        upward.is_empty(),
        "imports into the same or a higher layer:\n{}",
        upward.join("\n")
    );
    if let Some(c) = cycle(&edges) {
        panic!(
            "files import each other in a cycle: {}",
            describe(&c, &edges)
        );
    }
    // The checker has power: it sees the edges it must see, through
    // `crate::`, `super::`, and the re-exports of the root and of `mod.rs`s.
    let sees = |from: &str, to: &str| {
        assert!(
            edges
                .get(&module(from))
                .is_some_and(|e| e.contains_key(&module(to))),
            "{from}'s import of {to} was not seen: {:?}",
            edges
                .get(&module(from))
                .map(|e| e.keys().collect::<Vec<_>>())
        );
    };
    sees("bound::probe", "bound::scan"); // crate::bound::scan
    sees("scene::narrow", "scene::query"); // super::query::Scene
    sees("ca::mesh::mesh_mesh", "ca::mesh::queue"); // super::queue::...
    sees("scene::query", "math::vec3"); // crate::Vec3, through lib.rs
    sees("ca::mesh::mesh_mesh", "ca::mesh::stats"); // super::TraversalStats, through mesh/mod.rs
    sees("scene::narrow", "ca::dispatch"); // crate::ca::AnyPair, through ca/mod.rs
}

/// The import graph of a crate made of `files` (module path, text).
fn graph_of(files: &[(&str, &str)]) -> BTreeMap<Module, BTreeMap<Module, String>> {
    let src = files
        .iter()
        .map(|(path, text)| (module(path), (*text).to_owned()))
        .collect();
    graph(&src)
}

#[test]
fn the_path_parser_reads_groups_renames_and_skips_comments() {
    let text = "use crate::{a::b as x, c::{self, d}, e::*};\n// use crate::zzz;\n\
                /* crate::yyy */ fn f() { crate::d::e::f(); let s = \"crate::www\"; }";
    let (paths, bindings) = read(&code(text), &module("m"));
    let written: Vec<String> = paths.iter().map(|p| p.written.join("::")).collect();
    assert_eq!(
        written,
        [
            "crate::a::b",
            "crate::c",
            "crate::c::d",
            "crate::e",
            "crate::d::e::f"
        ]
    );
    let bound: Vec<(String, String)> = bindings
        .iter()
        .map(|b| (b.name.clone(), b.written.join("::")))
        .collect();
    let want = [
        ("x", "crate::a::b"),
        ("c", "crate::c"),
        ("d", "crate::c::d"),
    ];
    assert_eq!(
        bound,
        want.map(|(n, w)| (n.to_owned(), w.to_owned())),
        "a glob binds no name"
    );
}

#[test]
fn super_and_self_are_resolved_from_the_module_they_stand_in() {
    let m = |s: &str| module(s);
    // From a file, a mod.rs, an inline module, and twice up.
    assert_eq!(
        absolute(&m("super::q::X"), &m("ca::mesh::p")),
        Some(m("ca::mesh::q::X"))
    );
    assert_eq!(absolute(&m("super::X"), &m("ca::mesh")), Some(m("ca::X")));
    assert_eq!(
        absolute(&m("self::q::X"), &m("ca::mesh")),
        Some(m("ca::mesh::q::X"))
    );
    assert_eq!(
        absolute(&m("super::super::X"), &m("ca::mesh::p::tests")),
        Some(m("ca::mesh::X"))
    );
    assert_eq!(absolute(&m("super::X"), &m("")), None);
    let (paths, _) = read(
        &code(
            "use super::a::{b, self};\nmod tests { use super::*; fn f() { super::super::g(); } }",
        ),
        &m("x::y"),
    );
    let read: Vec<(String, String)> = paths
        .iter()
        .map(|p| (p.written.join("::"), p.within.join("::")))
        .collect();
    let want = [
        ("super::a::b", "x::y"),
        ("super::a", "x::y"),
        ("super", "x::y::tests"),
        ("super::super::g", "x::y::tests"),
    ];
    assert_eq!(read, want.map(|(a, b)| (a.to_owned(), b.to_owned())));
}

#[test]
fn a_cycle_behind_a_parents_re_export_is_found() {
    // `a` imports `Thing` through `f`'s re-export, `b` (which defines it)
    // imports `a` directly: a cycle between `a` and `b`, not `a` and `f`.
    let files = [
        ("", "mod f;"),
        ("f", "mod a; mod b; pub use b::Thing;"),
        ("f::a", "use crate::f::Thing;\npub struct A;"),
        ("f::b", "pub struct Thing;\nuse super::a::A;"),
    ];
    let edges = graph_of(&files);
    let c = cycle(&edges).expect("a cycle");
    assert_eq!(
        describe(&c, &edges),
        "f::a -> f::b (`crate::f::Thing`) -> f::a (`super::a::A`)"
    );
}

#[test]
fn a_cycle_between_sibling_files_is_found() {
    // `a` and `b`, siblings in `f/`: a `use` one way, an expression path
    // the other.
    let files = [
        ("", "mod f;"),
        ("f", "mod a; mod b; pub use b::Thing;"),
        ("f::a", "use super::b::Thing;\npub fn other() {}"),
        ("f::b", "pub struct Thing;\nfn g() { super::a::other(); }"),
    ];
    let edges = graph_of(&files);
    let c = cycle(&edges).expect("a cycle");
    assert_eq!(
        describe(&c, &edges),
        "f::a -> f::b (`super::b::Thing`) -> f::a (`super::a::other`)"
    );
    // Out of an inline module, three levels up, to a name the root
    // re-exports.
    let files = [
        ("", "mod f; mod g; pub use g::Top;"),
        ("g", "use crate::f::a::A;\npub struct Top;"),
        (
            "f::a",
            "pub struct A;\nmod tests { fn t() { super::super::super::Top; } }",
        ),
    ];
    let edges = graph_of(&files);
    let c = cycle(&edges).expect("a cycle");
    assert_eq!(
        describe(&c, &edges),
        "f::a -> g (`super::super::super::Top`) -> f::a (`crate::f::a::A`)"
    );
    // Without a back edge: none; the inline `mod tests` of `b` importing
    // `super::*` is `b` itself, and `f`'s plain re-export is no edge.
    let files = [
        ("", "mod f;"),
        ("f", "mod a; mod b; pub use b::Thing;"),
        ("f::a", "use super::b::Thing;"),
        ("f::b", "pub struct Thing;\nmod tests { use super::*; }"),
    ];
    let edges = graph_of(&files);
    assert_eq!(cycle(&edges), None);
    assert_eq!(edges.len(), 1, "{edges:?}");
}
