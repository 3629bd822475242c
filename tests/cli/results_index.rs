//! `results/README.md` indexes the committed evidence: every results JSON committed under
//! `results/` is linked there, every file linked there exists, and no SVG is committed
//! (`torus-cull plot` redraws the charts from the JSON; `.gitignore` keeps them out).
//!
//! The committed results are held to a budget (issue 53): at most 30 MB in all, no file
//! over 2 MB, every JSON compact (one line). A full bench commits its summary
//! (`torus-cull summarize`); the full file's restore line goes in the index's "Removed files".
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

/// The budget of the tracked `results/`: the tree travels to a device machine whole
/// (docs/gpu.md: 64 MiB), and every bench adds to it.
const RESULTS_BUDGET_BYTES: u64 = 30_000_000;
/// No single tracked results file over this: a full bench's records go in the history, its
/// summary in the tree.
const RESULTS_FILE_MAX_BYTES: u64 = 2_000_000;

/// What breaks the budget, given (path, size) of each tracked file: one line per file over
/// [`RESULTS_FILE_MAX_BYTES`], and one for the total over [`RESULTS_BUDGET_BYTES`].
fn budget_breaches(sizes: &[(String, u64)]) -> Vec<String> {
    let mut out: Vec<String> = sizes
        .iter()
        .filter(|(_, n)| *n > RESULTS_FILE_MAX_BYTES)
        .map(|(f, n)| format!("results/{f}: {n} bytes, over {RESULTS_FILE_MAX_BYTES}"))
        .collect();
    let total: u64 = sizes.iter().map(|(_, n)| n).sum();
    if total > RESULTS_BUDGET_BYTES {
        out.push(format!(
            "tracked results/: {total} bytes in {} files, over {RESULTS_BUDGET_BYTES}",
            sizes.len()
        ));
    }
    out
}

#[test]
fn tracked_results_stay_within_their_budget_and_compact() {
    let sizes: Vec<(String, u64)> = committed_files()
        .into_iter()
        .map(|f| {
            let path = root().join("results").join(&f);
            let n = std::fs::metadata(&path)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
                .len();
            (f, n)
        })
        .collect();
    let breaches = budget_breaches(&sizes);
    assert!(
        breaches.is_empty(),
        "results/ over its budget (summarize a full bench, move the rest to \"Removed \
         files\" in results/README.md with its git show line):\n{}",
        breaches.join("\n")
    );
    let pretty: Vec<&String> = sizes
        .iter()
        .map(|(f, _)| f)
        .filter(|f| f.ends_with(".json"))
        .filter(|f| {
            let text = std::fs::read(root().join("results").join(f)).unwrap();
            text.iter().filter(|&&b| b == b'\n').count() > 1
        })
        .collect();
    assert!(
        pretty.is_empty(),
        "results JSON not compact (python3 .ci/results-compact.py write FILE): {pretty:?}"
    );
}

#[test]
fn the_budget_names_each_file_over_it_and_the_total() {
    let ok = [("a.json".to_string(), RESULTS_FILE_MAX_BYTES)];
    assert!(budget_breaches(&ok).is_empty());
    let big = [("a.json".to_string(), RESULTS_FILE_MAX_BYTES + 1)];
    assert_eq!(budget_breaches(&big).len(), 1);
    assert!(budget_breaches(&big)[0].contains("results/a.json"));
    let many: Vec<(String, u64)> = (0..16)
        .map(|i| (format!("f{i}.json"), RESULTS_FILE_MAX_BYTES))
        .collect();
    let got = budget_breaches(&many);
    assert_eq!(got.len(), 1, "{got:?}");
    assert!(got[0].contains("16 files"), "{got:?}");
}
