//! Paths in the text exist, and names that are gone stay gone.

use super::*;

/// The folders a repository path may start with.
const PREFIXES: [&str; 9] = [
    "src/",
    "crates/",
    "tests/",
    "benches/",
    "docs/",
    "results/",
    "examples/",
    "workloads/",
    ".ci/",
];

/// Paths named on purpose that are not in the repository, each with why.
const ALLOWED: &[(&str, &str)] = &[
    // Placeholders: a name a command builds, or the reader fills in.
    (
        "results/<commit>",
        "a results file's name, built from the commit",
    ),
    ("results/<commit>.json", "placeholder"),
    ("results/<commit>-run.json", "placeholder"),
    (
        "results/<commit>-check-<shape>-<precision>.json",
        "placeholder",
    ),
    ("results/<commit>-family-time.json", "placeholder"),
    ("results/<commit>-bend-time.json", "placeholder"),
    ("results/<commit>-summary.json", "placeholder"),
    ("results/<commit><suffix>.json", "placeholder"),
    ("results/<short", "`results/<short commit>…`: placeholder"),
    ("results/<old>.json", "placeholder"),
    ("results/OLD.json", "placeholder"),
    ("results/NEW.json", "placeholder"),
    ("crates/torus-cull/src/cull/<name>.rs", "a new cull's file"),
    (
        "crates/torus-cull/src/gpu/wgsl/module/culls/<name>.wgsl",
        "a new cull's WGSL file",
    ),
    ("crates/torus-cull/src/<shape>/", "a new shape's folder"),
    (
        "crates/torus-cull/src/solids/<shape>.rs",
        "a new shape's Solid impl",
    ),
    (
        "src/check/shapes/<shape>/mod.rs",
        "a new shape's LabShape impl",
    ),
    ("src/oracle/<shape>.rs", "a new shape's oracle"),
    (
        "results/latest",
        "`results/latest….json`: what a build outside git writes",
    ),
    (
        "results/**/*.svg",
        "the charts git ignores: written, never committed",
    ),
    (
        "results/895821e-summary-bvh-*.svg",
        "charts `plot` writes, not committed",
    ),
    // Removed on purpose: results/README.md names each with the git show that restores it.
    (
        "results/def23bc-quick-time.json",
        "removed; restored by the git show beside it",
    ),
    (
        "results/052cf53-family-time.json",
        "removed; restored by the git show beside it",
    ),
    (
        "results/0edc3c1-dirty-f32-check.json",
        "removed; restored by the git show beside it",
    ),
    (
        "results/8b9959d-time.json",
        "removed; restored by the git show beside it",
    ),
    (
        "results/8b9959d-run.json",
        "removed; restored by the git show beside it",
    ),
    (
        "results/230696a-run.json",
        "removed; restored by the git show beside it",
    ),
    (
        "results/60bf307-bend.json",
        "removed; restored by the git show beside it",
    ),
    (
        "results/bbe3544-bend.json",
        "removed; restored by the git show beside it",
    ),
    (
        "results/0b97d73.json",
        "removed; restored by the git show beside it",
    ),
    (
        "results/f53cc7f.json",
        "removed (its summary stays); restored by the git show beside it",
    ),
    (
        "results/bb215a7-dirty-bvh-time.json",
        "removed (superseded by d62bb64's bench); restored by the git show beside it",
    ),
    (
        "results/bb215a7-dirty-bvh-time-repeat.json",
        "removed (superseded by d62bb64's bench); restored by the git show beside it",
    ),
    (
        "results/8a180e4.json",
        "removed (its summary stays); restored by the git show beside it",
    ),
    (
        "results/d2c851c.json",
        "removed (its summary stays); restored by the git show beside it",
    ),
    (
        "results/dea7bb4.json",
        "removed (its summary stays); restored by the git show beside it",
    ),
    (
        "results/d0e47f6.json",
        "removed (its summary stays); restored by the git show beside it",
    ),
    (
        "results/895821e.json",
        "removed (its summary stays); restored by the git show beside it",
    ),
    (
        "results/gpu-device-<UTC",
        "the folder benches/gpu_device.sh writes, named by the time of the run",
    ),
    (
        "src/<path>.rs",
        "a pattern in a doc comment: a module's file",
    ),
    (
        "src/<path>/mod.rs",
        "a pattern in a doc comment: a module's file",
    ),
];

/// Whether `path` exists under `base`; a `*` in its last part matches any run of
/// characters, and the pattern exists when some file matches it.
fn exists_under(base: &Path, path: &str) -> bool {
    let (dir, name) = path.rsplit_once('/').unwrap_or(("", path));
    if !name.contains('*') || dir.contains('*') {
        return base.join(path).exists();
    }
    let parts: Vec<&str> = name.split('*').collect();
    let Ok(entries) = fs::read_dir(base.join(dir)) else {
        return false;
    };
    entries.flatten().any(|e| {
        let n = e.file_name().to_string_lossy().into_owned();
        let (first, last) = (parts[0], parts[parts.len() - 1]);
        if !(n.starts_with(first) && n.ends_with(last) && n.len() >= first.len() + last.len()) {
            return false;
        }
        let mut rest = &n[first.len()..n.len() - last.len()];
        parts[1..parts.len() - 1]
            .iter()
            .all(|p| match rest.find(p) {
                Some(i) => {
                    rest = &rest[i + p.len()..];
                    true
                }
                None => false,
            })
    })
}

/// Names that no longer exist, wherever a comment or doc says them: the lab's old crate
/// name (`harness::…`, now `torus_cull_lab::…`) and design notes outside the repository
/// (`DESIGN.md`: the repository stands alone, its docs are under docs/).
const GONE: [&str; 2] = ["harness::", "DESIGN.md"];

/// A path with `{a,b}` groups, expanded (`d/{x,y}.rs`: `d/x.rs` and `d/y.rs`).
fn expand(path: &str) -> Vec<String> {
    let (Some(open), Some(close)) = (path.find('{'), path.find('}')) else {
        return vec![path.to_string()];
    };
    if close < open {
        return vec![path.to_string()];
    }
    path[open + 1..close]
        .split(',')
        .flat_map(|alt| {
            expand(&format!(
                "{}{}{}",
                &path[..open],
                alt.trim(),
                &path[close + 1..]
            ))
        })
        .collect()
}

/// Every repository-looking path in `text`, with its 1-based line.
fn named_paths(text: &str) -> Vec<(usize, String)> {
    let path_char = |c: char| c.is_alphanumeric() || "_-./<>{}*".contains(c);
    let mut out = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let chars: Vec<char> = line.chars().collect();
        let mut i = 0;
        while i < chars.len() {
            let before_ok = i == 0 || !(path_char(chars[i - 1]) || chars[i - 1] == ':');
            let rest: String = chars[i..].iter().take(12).collect();
            let prefix = PREFIXES
                .iter()
                .find(|p| rest.starts_with(*p))
                .filter(|_| before_ok);
            if let Some(p) = prefix {
                let mut j = i + p.chars().count();
                let mut braces = 0;
                while j < chars.len() && (path_char(chars[j]) || (braces > 0 && chars[j] == ',')) {
                    braces += i32::from(chars[j] == '{') - i32::from(chars[j] == '}');
                    j += 1;
                }
                let mut path: String = chars[i..j].iter().collect();
                while path.ends_with('.') && !path.ends_with("..") {
                    path.pop();
                }
                for (open, close) in [('<', '>'), ('{', '}')] {
                    if path.ends_with(close) && !path.contains(open) {
                        path.pop();
                    }
                }
                out.push((n + 1, path));
                i = j;
            } else {
                i += 1;
            }
        }
    }
    out
}

#[test]
fn named_paths_exist() {
    let r = root();
    let mut texts: Vec<(PathBuf, String)> = Vec::new();
    let mut docs = vec![r.join("README.md"), r.join("results/README.md")];
    files(&r.join("docs"), &[".md"], &mut docs);
    for d in docs {
        texts.push((d.clone(), fs::read_to_string(&d).unwrap()));
    }
    let mut code = Vec::new();
    for dir in ["src", "crates", "tests", "benches", "examples"] {
        files(&r.join(dir), &[".rs", ".wgsl"], &mut code);
    }
    code.push(r.join("build.rs"));
    for f in code.into_iter().filter(|f| f.exists()) {
        let comments = split(&fs::read_to_string(&f).unwrap()).1;
        texts.push((f, comments));
    }
    let library = r.join("crates/torus-cull");
    let mut stale = Vec::new();
    let mut used = BTreeSet::new();
    for (f, text) in &texts {
        for (line, path) in named_paths(text) {
            let exists = expand(&path).iter().all(|p| {
                exists_under(&r, p)
                // The library's own text may name its files from its folder.
                || (f.starts_with(&library) && exists_under(&library, p))
            });
            if exists {
                continue;
            }
            let here = format!("{}:{line}", rel(f));
            if let Some((_, _)) = ALLOWED.iter().find(|(p, _)| *p == path) {
                used.insert(path.clone());
                continue;
            }
            stale.push(format!("{here}: {path}"));
        }
    }
    for (f, text) in &texts {
        if f.starts_with(r.join("tests/api/layout")) {
            continue;
        }
        for (n, line) in text.lines().enumerate() {
            for gone in GONE.iter().filter(|g| line.contains(*g)) {
                stale.push(format!("{}:{}: {gone}", rel(f), n + 1));
            }
        }
    }
    let unused: Vec<_> = ALLOWED
        .iter()
        .filter(|(p, _)| !used.contains(*p))
        .map(|(p, _)| *p)
        .collect();
    eprintln!("layout: {} stale paths", stale.len());
    assert!(
        stale.is_empty(),
        "{} stale paths:\n{}",
        stale.len(),
        stale.join("\n")
    );
    assert!(
        unused.is_empty(),
        "allow-listed paths no longer named anywhere: {unused:?}"
    );
}
