//! `results/README.md` indexes the committed evidence: every results JSON committed under
//! `results/` is linked there, every file linked there exists, and no SVG is committed
//! (`torus-cull plot` redraws the charts from the JSON; `.gitignore` keeps them out).
//!
//! The committed files are `git ls-files results`; where git or the repository is not
//! there (a source tarball), every file under `results/` is taken as committed.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Paths under `results/`, relative to it, with `/` separators.
fn committed_files() -> BTreeSet<String> {
    let git = Command::new("git")
        .args(["ls-files", "-z", "--", "results"])
        .current_dir(root())
        .output();
    match git {
        Ok(o) if o.status.success() && !o.stdout.is_empty() => o
            .stdout
            .split(|&b| b == 0)
            .filter(|p| !p.is_empty())
            .map(|p| {
                let p = String::from_utf8_lossy(p);
                p.strip_prefix("results/").unwrap_or(&p).to_string()
            })
            .collect(),
        _ => {
            let mut out = BTreeSet::new();
            walk(&root().join("results"), "", &mut out);
            out
        }
    }
}

fn walk(dir: &Path, prefix: &str, out: &mut BTreeSet<String>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let name = format!("{prefix}{}", e.file_name().to_string_lossy());
        if e.path().is_dir() {
            walk(&e.path(), &format!("{name}/"), out);
        } else {
            out.insert(name);
        }
    }
}

/// The `.json` targets of the index's markdown links, `[text](target)`, relative to
/// `results/`. Removed files are named in code spans, not linked, so they are not listed.
fn linked_json(index: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut rest = index;
    while let Some(at) = rest.find("](") {
        rest = &rest[at + 2..];
        let Some(end) = rest.find(')') else { break };
        let target = rest[..end].split('#').next().unwrap_or_default();
        if target.ends_with(".json") && !target.contains("://") {
            out.insert(target.trim_start_matches("./").to_string());
        }
        rest = &rest[end..];
    }
    out
}

#[test]
fn the_index_lists_every_committed_json_and_nothing_else() {
    let index_path = root().join("results/README.md");
    let index = std::fs::read_to_string(&index_path).expect("results/README.md");
    let linked = linked_json(&index);
    let committed = committed_files();
    assert!(
        committed.contains("README.md"),
        "results/README.md is not committed"
    );

    // Each rule: the files that break it, and what to say of them.
    let none_of = |bad: Vec<&String>, what: &str| assert!(bad.is_empty(), "{what}: {bad:?}");
    none_of(
        committed
            .iter()
            .filter(|f| f.ends_with(".json") && !linked.contains(*f))
            .collect(),
        "committed under results/ but not linked in results/README.md",
    );
    none_of(
        linked
            .iter()
            .filter(|f| !root().join("results").join(f).is_file())
            .collect(),
        "linked in results/README.md but no such file under results/",
    );
    none_of(
        committed
            .iter()
            .filter(|f| f.to_ascii_lowercase().ends_with(".svg"))
            .collect(),
        "SVGs committed under results/ (torus-cull plot redraws them; git rm --cached them)",
    );
}

#[test]
fn links_are_read_as_the_index_writes_them() {
    let text = "| [a.json](a.json) | x |\n[docs](../docs/results.md#x) `gone.json`\n\
                [b](sub/b.json#meta) [c](https://example.org/c.json)";
    let got: Vec<_> = linked_json(text).into_iter().collect();
    assert_eq!(got, ["a.json", "sub/b.json"]);
}
