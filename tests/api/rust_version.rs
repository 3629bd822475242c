//! The Rust versions docs/layout.md states ("Rust versions") are true: for each package and
//! feature set, the highest `rust-version` in its resolved graph (`cargo tree` over
//! `Cargo.lock`, this host's target) equals the table's, and the two manifests'
//! `rust-version` are their rows. A dependency update that needs a newer Rust fails here
//! until the table, the manifests and the README say so.

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A version as numbers, for ordering ("1.87.0" > "1.86").
fn numbers(v: &str) -> Vec<u64> {
    let mut n: Vec<u64> = v.split('.').map(|x| x.parse().unwrap_or(0)).collect();
    while n.last() == Some(&0) {
        n.pop();
    }
    n
}

/// `rust-version = "…"` of the manifest at `path`, if it states one.
fn rust_version(path: &Path) -> Option<String> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.lines().find_map(|line| {
        let rest = line.trim().strip_prefix("rust-version")?.trim_start();
        let value = rest.strip_prefix('=')?.trim();
        Some(value.trim_matches('"').to_string())
    })
}

/// The table's rows: (package, features, edges, version).
fn table() -> Vec<(String, Option<String>, String, String)> {
    let text = std::fs::read_to_string(root().join("docs/layout.md")).expect("docs/layout.md");
    let block = text
        .split("<!-- rust-versions -->")
        .nth(1)
        .and_then(|b| b.split("<!-- /rust-versions -->").next())
        .expect("docs/layout.md has a <!-- rust-versions --> block");
    block
        .lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| {
            let cells: Vec<&str> = l.split('|').map(str::trim).collect();
            let set = cells[1].trim_matches('`');
            let (package, features) = match set.split_once(" --features ") {
                Some((p, f)) => (p.to_string(), Some(f.to_string())),
                None => (set.to_string(), None),
            };
            let edges = cells[2].replace(' ', "");
            (package, features, edges, cells[3].to_string())
        })
        .collect()
}

/// The registry's unpacked copy of `name-version`'s manifest.
fn registry_manifest(name: &str, version: &str) -> PathBuf {
    let home = std::env::var_os("CARGO_HOME").map_or_else(
        || PathBuf::from(std::env::var_os("HOME").expect("HOME")).join(".cargo"),
        PathBuf::from,
    );
    let src = home.join("registry/src");
    std::fs::read_dir(&src)
        .unwrap_or_else(|e| panic!("{}: {e}", src.display()))
        .flatten()
        .map(|index| index.path().join(format!("{name}-{version}/Cargo.toml")))
        .find(|p| p.exists())
        .unwrap_or_else(|| panic!("{name} {version}: no manifest under {}", src.display()))
}

#[test]
fn the_stated_rust_versions_are_the_resolved_graphs() {
    let rows = table();
    assert!(
        rows.len() >= 6,
        "docs/layout.md's table has {} rows",
        rows.len()
    );
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let mut wrong = Vec::new();
    for (package, features, edges, stated) in &rows {
        let mut cmd = Command::new(&cargo);
        cmd.current_dir(root())
            .args([
                "tree", "--locked", "--prefix", "none", "--format", "{p}", "-p",
            ])
            .arg(package)
            .args(["-e", &format!("{edges},build")]);
        if let Some(f) = features {
            cmd.args(["--features", f]);
        }
        let out = cmd.output().expect("cargo tree runs");
        assert!(
            out.status.success(),
            "cargo tree -p {package} {features:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8_lossy(&out.stdout).into_owned();
        let mut needs: Option<(Vec<u64>, String)> = None;
        for line in text.lines() {
            let mut words = line.split_whitespace();
            let (Some(name), Some(version)) = (words.next(), words.next()) else {
                continue;
            };
            let Some(version) = version.strip_prefix('v') else {
                continue;
            };
            // A path package prints its folder: `name vX (/path)`; a proc macro `(proc-macro)`.
            let manifest = match words.next() {
                Some(path) if path.starts_with("(/") => {
                    PathBuf::from(path.trim_matches(|c| c == '(' || c == ')')).join("Cargo.toml")
                }
                _ => registry_manifest(name, version),
            };
            if let Some(rv) = rust_version(&manifest) {
                if needs.as_ref().is_none_or(|(n, _)| numbers(&rv) > *n) {
                    needs = Some((numbers(&rv), format!("{name} {version} ({rv})")));
                }
            }
        }
        let (needed, by) = needs.expect("some package states a rust-version");
        if needed != numbers(stated) {
            wrong.push(format!(
                "{package} {features:?} ({edges}): the table says {stated}, the graph needs {by}"
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    let first = &rows[0];
    let last = rows.last().unwrap();
    for ((package, _, _, stated), manifest) in [
        (first, "crates/torus-cull/Cargo.toml"),
        (last, "Cargo.toml"),
    ] {
        let declared = rust_version(&root().join(manifest)).expect("a rust-version");
        assert_eq!(
            numbers(&declared),
            numbers(stated),
            "{manifest} says rust-version {declared}; docs/layout.md's row for {package}: {stated}"
        );
    }
}
