//! Every test a proof names exists: each lemma in `proofs/` says which tests
//! check it, and a renamed or deleted test must not leave a proof pointing
//! at nothing.
//!
//! Read from every `proofs/*.md`, in backticks: file paths (`tests/x.rs`,
//! `src/.../x.rs`, `fuzz/fuzz_targets/x.rs`, `python/tests/x.py`) must exist;
//! `file::name` must name a function in that file; other paths
//! (`module::tests::name`) and bare snake-case names of at least four words
//! must name a function (Rust's `fn` or Python's `def`), module or file of
//! the repository. `{a,b}` alternatives are expanded.

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

/// Every `.rs` and `.py` file of the repository's own code (not build
/// output).
fn sources() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = fs::read_dir(dir) else {
            return;
        };
        for e in entries.flatten() {
            let p = e.path();
            let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
            if p.is_dir() {
                if name != "target" && name != "corpus" && !name.starts_with('.') {
                    walk(&p, out);
                }
            } else if name.ends_with(".rs") || name.ends_with(".py") {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    for d in [
        "src",
        "tests",
        "fuzz",
        "examples",
        "benches",
        "compare",
        "ci-nostd",
        "motion-bound-parry",
        "python",
    ] {
        walk(&root().join(d), &mut out);
    }
    out
}

/// `a_{x,y}_b` -> `a_x_b`, `a_y_b` (every group, left to right).
fn expand(s: &str) -> Vec<String> {
    match (s.find('{'), s.find('}')) {
        (Some(i), Some(j)) if i < j => s[i + 1..j]
            .split(',')
            .flat_map(|alt| expand(&format!("{}{}{}", &s[..i], alt.trim(), &s[j + 1..])))
            .collect(),
        _ => vec![s.to_owned()],
    }
}

/// `tests/x.rs::name` -> (`tests/x.rs`, `name`): a Rust or Python file's
/// path, ended by `.rs` or `.py` and then nothing or `::`; no file
/// otherwise (`python/motion_bound.pyi` is not a `.py` file).
fn split_file(item: &str) -> (Option<&str>, &str) {
    for ext in [".rs", ".py"] {
        let mut from = 0;
        while let Some(i) = item[from..].find(ext).map(|i| i + from) {
            let end = i + ext.len();
            let rest = &item[end..];
            if rest.is_empty() || rest.starts_with("::") {
                return (Some(&item[..end]), rest.trim_start_matches("::"));
            }
            from = end;
        }
    }
    (None, item)
}

fn is_snake(s: &str) -> bool {
    !s.is_empty()
        && s.chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
}

#[test]
fn every_test_a_proof_names_exists() {
    let files = sources();
    let texts: Vec<(PathBuf, String)> = files
        .iter()
        .map(|p| (p.clone(), fs::read_to_string(p).unwrap_or_default()))
        .collect();
    let defines = |name: &str| {
        let stems = files
            .iter()
            .any(|p| p.file_stem().and_then(|s| s.to_str()) == Some(name));
        stems
            || texts.iter().any(|(_, t)| {
                t.contains(&format!("fn {name}("))
                    || t.contains(&format!("fn {name}<"))
                    || t.contains(&format!("mod {name}"))
                    || t.contains(&format!("def {name}("))
            })
    };
    let mut checked = BTreeSet::new();
    let mut missing = Vec::new();
    let mut proofs: Vec<PathBuf> = fs::read_dir(root().join("proofs"))
        .expect("proofs/")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    proofs.sort();
    for proof in &proofs {
        let text = fs::read_to_string(proof).expect("readable");
        let name = proof.file_name().and_then(|n| n.to_str()).unwrap_or("?");
        for (k, token) in text.split('`').enumerate() {
            if k % 2 == 0 || token.contains(' ') || token.is_empty() {
                continue; // outside backticks, or a formula
            }
            for item in expand(token) {
                let item = item.trim_end_matches("()").to_owned();
                let (file, rest) = split_file(&item);
                if let Some(file) = file {
                    if !(file.starts_with("tests/")
                        || file.starts_with("src/")
                        || file.starts_with("fuzz/")
                        || file.starts_with("examples/")
                        || file.starts_with("motion-bound-parry/")
                        || file.starts_with("python/"))
                    {
                        continue;
                    }
                    checked.insert(item.clone());
                    let path = root().join(file);
                    let Ok(body) = fs::read_to_string(&path) else {
                        missing.push(format!("{name}: `{item}`: no file {file}"));
                        continue;
                    };
                    let last = rest.rsplit("::").next().unwrap_or("");
                    if is_snake(last)
                        && last != "tests"
                        && !body.contains(&format!("fn {last}("))
                        && !body.contains(&format!("fn {last}<"))
                        && !body.contains(&format!("def {last}("))
                    {
                        missing.push(format!("{name}: `{item}`: no fn {last} in {file}"));
                    }
                    continue;
                }
                let segments: Vec<&str> = rest.split("::").collect();
                let last = *segments.last().unwrap_or(&"");
                let words = last.split('_').count();
                let path_like = segments.len() > 1 && segments.iter().all(|s| is_snake(s));
                if !(path_like || (is_snake(last) && words >= 4)) {
                    continue;
                }
                checked.insert(item.clone());
                if !defines(last) {
                    missing.push(format!("{name}: `{item}`: nothing named {last}"));
                }
            }
        }
    }
    println!(
        "{} names checked in {} proof files",
        checked.len(),
        proofs.len()
    );
    assert!(
        checked.len() > 40,
        "the reader found too few names ({}): it has no power",
        checked.len()
    );
    assert!(
        missing.is_empty(),
        "proofs name tests that do not exist:\n{}",
        missing.join("\n")
    );
}

#[test]
fn braces_expand_to_every_alternative() {
    assert_eq!(
        expand("t_{f32,f64}_{a,b}"),
        ["t_f32_a", "t_f32_b", "t_f64_a", "t_f64_b"]
    );
    assert_eq!(expand("plain"), ["plain"]);
}

#[test]
fn file_paths_end_at_their_extension() {
    assert_eq!(split_file("tests/x.rs::a_b"), (Some("tests/x.rs"), "a_b"));
    assert_eq!(
        split_file("python/tests/t.py"),
        (Some("python/tests/t.py"), "")
    );
    assert_eq!(
        split_file("python/motion_bound.pyi"),
        (None, "python/motion_bound.pyi")
    );
    assert_eq!(split_file("ca::past_contact"), (None, "ca::past_contact"));
}
