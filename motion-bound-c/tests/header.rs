//! The committed header against the sources, without cbindgen (whose install
//! costs about four minutes in CI): the functions `src/` exports are exactly
//! those `include/motion_bound.h` declares, each documented on both sides.
//! CI also regenerates the header with cbindgen and diffs it when cbindgen is
//! installed (`.ci/run`).

use std::collections::BTreeSet;
use std::path::Path;

/// Every `pub (unsafe) extern "C" fn` name in `src/`, with whether a doc
/// comment precedes it (attributes between are skipped).
fn exported() -> Vec<(String, bool)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).expect("src/ is readable") {
        let text = std::fs::read_to_string(entry.expect("an entry").path()).expect("a source");
        let lines: Vec<&str> = text.lines().collect();
        for (i, line) in lines.iter().enumerate() {
            let l = line.trim_start();
            let rest = l
                .strip_prefix("pub unsafe extern \"C\" fn ")
                .or_else(|| l.strip_prefix("pub extern \"C\" fn "));
            let Some(rest) = rest else { continue };
            let name: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            let mut j = i;
            while j > 0 && lines[j - 1].trim_start().starts_with("#[") {
                j -= 1;
            }
            let documented = j > 0 && lines[j - 1].trim_start().starts_with("///");
            out.push((name, documented));
        }
    }
    out
}

/// Every function the header declares (`<type> name(`), with whether a doc
/// comment (`*/`) ends just before its declaration.
fn declared() -> Vec<(String, bool)> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("include/motion_bound.h");
    let text = std::fs::read_to_string(path).expect("include/motion_bound.h is readable");
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        if line.starts_with(' ') || line.starts_with('#') || line.starts_with('}') {
            continue;
        }
        let Some(open) = line.find('(') else { continue };
        let head = &line[..open];
        if head.contains("typedef") {
            continue;
        }
        let name: String = head
            .chars()
            .rev()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect::<String>()
            .chars()
            .rev()
            .collect();
        if name.starts_with("mb_") {
            let documented = i > 0 && lines[i - 1].trim_end().ends_with("*/");
            out.push((name, documented));
        }
    }
    out
}

#[test]
fn header_declares_exactly_the_exported_functions() {
    let src = exported();
    let hdr = declared();
    assert!(
        src.len() >= 30,
        "found only {} exported functions in src/",
        src.len()
    );
    let a: BTreeSet<&str> = src.iter().map(|(n, _)| n.as_str()).collect();
    let b: BTreeSet<&str> = hdr.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(a.len(), src.len(), "a function exported twice");
    assert_eq!(b.len(), hdr.len(), "a function declared twice");
    let missing: Vec<_> = a.difference(&b).collect();
    let stale: Vec<_> = b.difference(&a).collect();
    assert!(
        missing.is_empty() && stale.is_empty(),
        "include/motion_bound.h is out of date: not declared {missing:?}, no longer exported \
         {stale:?}; regenerate it (motion-bound-c/cbindgen.toml says how)"
    );
}

#[test]
fn every_exported_function_is_documented() {
    let undocumented: Vec<_> = exported()
        .into_iter()
        .chain(declared())
        .filter(|(_, d)| !d)
        .map(|(n, _)| n)
        .collect();
    assert!(undocumented.is_empty(), "undocumented: {undocumented:?}");
}
