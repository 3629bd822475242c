//! The repository's layout, checked against its own text (issue 37 items 6 and 7).
//!
//! * Imports point down: every `crate::…` path in the code (in `use` statements and inline)
//!   of each top-level module of the library (`crates/torus-cull/src/`), the lab
//!   (`src/lib.rs`) and the command (`src/cli/main.rs`) names a module on a lower floor of
//!   the order written in `docs/layout.md` (its "Floors" block). The crate root is the top
//!   floor, a facade: a module that names an item through it (`crate::Torus` rather than
//!   `crate::geometry::Torus`) imports upward. Fails with each offending file:line, and
//!   with every cycle between top-level modules.
//! * Paths in the text exist: every repository path (`src/…`, `crates/…`, `tests/…`,
//!   `docs/…`, …) named in the docs, in Rust comments and in WGSL comments names a file or
//!   folder of the repository, unless it is on the short allow-list below.
//!
//! Plain Rust over the source text: comments and string literals are blanked before the
//! paths are read, so a path in a doc comment is text (checked by the second test), not
//! an import.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every file under `dir` whose name ends in one of `exts`, sorted, skipping `target/` and
/// hidden folders other than `.ci`.
fn files(dir: &Path, exts: &[&str], out: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<_> = entries.flatten().map(|e| e.path()).collect();
    entries.sort();
    for p in entries {
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        if p.is_dir() {
            if name == "target" || (name.starts_with('.') && name != ".ci") {
                continue;
            }
            files(&p, exts, out);
        } else if exts.iter().any(|e| name.ends_with(e)) {
            out.push(p);
        }
    }
}

fn rel(p: &Path) -> String {
    p.strip_prefix(root())
        .unwrap_or(p)
        .to_string_lossy()
        .replace('\\', "/")
}

/// Rust (or WGSL) source split in two, each the same length with the same newlines: the
/// code with comments and string/char literals blanked, and the comments alone.
fn split(src: &str) -> (String, String) {
    let c: Vec<char> = src.chars().collect();
    let (mut code, mut comments) = (String::new(), String::new());
    let mut i = 0;
    let push = |code: &mut String, comments: &mut String, ch: char, is_comment: bool| {
        let blank = if ch == '\n' { '\n' } else { ' ' };
        code.push(if is_comment { blank } else { ch });
        comments.push(if is_comment { ch } else { blank });
    };
    let blank_both = |code: &mut String, comments: &mut String, ch: char| {
        let b = if ch == '\n' { '\n' } else { ' ' };
        code.push(b);
        comments.push(b);
    };
    while i < c.len() {
        let at = |k: usize| c.get(i + k).copied().unwrap_or('\0');
        if at(0) == '/' && at(1) == '/' {
            while i < c.len() && c[i] != '\n' {
                push(&mut code, &mut comments, c[i], true);
                i += 1;
            }
        } else if at(0) == '/' && at(1) == '*' {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    push(&mut code, &mut comments, '/', true);
                    push(&mut code, &mut comments, '*', true);
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    push(&mut code, &mut comments, '*', true);
                    push(&mut code, &mut comments, '/', true);
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    push(&mut code, &mut comments, c[i], true);
                    i += 1;
                }
            }
        } else if at(0) == 'r'
            && (at(1) == '"' || (at(1) == '#' && (at(2) == '"' || at(2) == '#')))
            && (i == 0 || !(c[i - 1].is_alphanumeric() || c[i - 1] == '_'))
        {
            // A raw string: r"…", r#"…"#.
            let mut j = i + 1;
            let mut hashes = 0;
            while c.get(j) == Some(&'#') {
                hashes += 1;
                j += 1;
            }
            for &ch in &c[i..=j.min(c.len() - 1)] {
                blank_both(&mut code, &mut comments, ch);
            }
            i = j + 1;
            while i < c.len() {
                if c[i] == '"' && (1..=hashes).all(|h| c.get(i + h) == Some(&'#')) {
                    for _ in 0..=hashes {
                        blank_both(&mut code, &mut comments, ' ');
                    }
                    i += hashes + 1;
                    break;
                }
                blank_both(&mut code, &mut comments, c[i]);
                i += 1;
            }
        } else if at(0) == '"' {
            blank_both(&mut code, &mut comments, '"');
            i += 1;
            while i < c.len() && c[i] != '"' {
                if c[i] == '\\' {
                    blank_both(&mut code, &mut comments, c[i]);
                    i += 1;
                }
                if i < c.len() {
                    blank_both(&mut code, &mut comments, c[i]);
                    i += 1;
                }
            }
            if i < c.len() {
                blank_both(&mut code, &mut comments, '"');
                i += 1;
            }
        } else if at(0) == '\'' && (at(1) == '\\' || at(2) == '\'') {
            // A char literal ('x', '\n', '\u{..}'); a lifetime ('a) is code.
            blank_both(&mut code, &mut comments, '\'');
            i += 1;
            if c.get(i) == Some(&'\\') {
                blank_both(&mut code, &mut comments, '\\');
                i += 1;
            }
            while i < c.len() && c[i] != '\'' {
                blank_both(&mut code, &mut comments, c[i]);
                i += 1;
            }
            if i < c.len() {
                blank_both(&mut code, &mut comments, '\'');
                i += 1;
            }
        } else {
            push(&mut code, &mut comments, c[i], false);
            i += 1;
        }
    }
    (code, comments)
}

fn is_ident(ch: char) -> bool {
    ch.is_alphanumeric() || ch == '_'
}

/// One crate root: the folder its modules live in, the root file (the facade), and the
/// name its floors carry in docs/layout.md.
struct CrateRoot {
    name: &'static str,
    dir: &'static str,
    root_file: &'static str,
}

const CRATES: [CrateRoot; 3] = [
    CrateRoot {
        name: "torus-cull",
        dir: "crates/torus-cull/src",
        root_file: "lib.rs",
    },
    CrateRoot {
        name: "torus-cull-lab",
        dir: "src",
        root_file: "lib.rs",
    },
    CrateRoot {
        name: "torus-cull (the command)",
        dir: "src/cli",
        root_file: "main.rs",
    },
];

/// The floors of docs/layout.md: in its `<!-- floors -->` block, one line per crate,
/// `<crate name>: <floor> <floor> … <root file>`, ground floor first, each floor one
/// module or several joined by commas (modules on one floor import none of each other).
fn floors() -> BTreeMap<String, Vec<Vec<String>>> {
    let doc = fs::read_to_string(root().join("docs/layout.md")).unwrap();
    let start = doc
        .find("<!-- floors -->")
        .expect("docs/layout.md has a <!-- floors --> block");
    let block = &doc[start..];
    let block = &block[..block
        .find("<!-- /floors -->")
        .expect("the floors block ends")];
    let mut out = BTreeMap::new();
    for line in block.lines() {
        let line = line.trim();
        let Some((name, mods)) = line.split_once(": ") else {
            continue;
        };
        if CRATES.iter().any(|c| c.name == name) {
            let floors = mods
                .split_whitespace()
                .map(|f| {
                    f.split(',')
                        .filter(|m| !m.is_empty())
                        .map(str::to_string)
                        .collect()
                })
                .collect();
            out.insert(name.to_string(), floors);
        }
    }
    out
}

/// The top-level modules a root file declares (`mod x;`, `pub mod x;`, `#[cfg(..)] pub mod x;`).
fn declared_modules(root_code: &str) -> Vec<String> {
    let mut mods = Vec::new();
    for line in root_code.lines() {
        let t = line.trim();
        let t = t.strip_prefix("pub ").unwrap_or(t);
        if let Some(name) = t.strip_prefix("mod ").and_then(|r| r.strip_suffix(';')) {
            mods.push(name.trim().to_string());
        }
    }
    mods
}

/// The top-level module a file of the crate belongs to (`None` for the root file itself).
fn top_module(krate: &CrateRoot, file: &Path, modules: &[String]) -> Option<String> {
    let r = file.strip_prefix(root().join(krate.dir)).ok()?;
    let first = r
        .components()
        .next()?
        .as_os_str()
        .to_string_lossy()
        .into_owned();
    let name = first.strip_suffix(".rs").unwrap_or(&first).to_string();
    modules.contains(&name).then_some(name)
}

/// Every `crate::x` of the code, with its 1-based line: `x` the first segment, or each
/// first segment of a `crate::{a::…, b}` group; `x!` for a macro.
fn crate_paths(code: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let b: Vec<char> = code.chars().collect();
    let line_of = |pos: usize| b[..pos].iter().filter(|&&c| c == '\n').count() + 1;
    let mut i = 0;
    while i + 7 <= b.len() {
        let is_start = b[i..i + 7].iter().collect::<String>() == "crate::"
            && (i == 0 || !(is_ident(b[i - 1]) || b[i - 1] == '$'));
        if !is_start {
            i += 1;
            continue;
        }
        let mut j = i + 7;
        if b.get(j) == Some(&'{') {
            // A group: the first segment of each top-level item.
            let mut depth = 0;
            let mut expect = true;
            while j < b.len() {
                match b[j] {
                    '{' => {
                        depth += 1;
                        if depth > 1 {
                            expect = false;
                        }
                    }
                    '}' => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                    }
                    ',' if depth == 1 => expect = true,
                    ch if expect && depth == 1 && is_ident(ch) => {
                        let s = j;
                        while j < b.len() && is_ident(b[j]) {
                            j += 1;
                        }
                        out.push((line_of(s), b[s..j].iter().collect()));
                        expect = false;
                        continue;
                    }
                    _ => {}
                }
                j += 1;
            }
        } else {
            let s = j;
            while j < b.len() && is_ident(b[j]) {
                j += 1;
            }
            let mut name: String = b[s..j].iter().collect();
            if b.get(j) == Some(&'!') {
                name.push('!');
            }
            if !name.is_empty() {
                out.push((line_of(i), name));
            }
        }
        i = j.max(i + 1);
    }
    out
}

/// What the root file re-exports from its modules (`pub use geometry::{Ray, Torus};`):
/// each name with the module it lives in.
fn reexports(root_code: &str, modules: &[String]) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    for stmt in root_code.split(';') {
        let t = stmt.trim();
        let Some(i) = t.find("use ") else { continue };
        let before = t[..i].trim_end();
        if !(before.ends_with("pub") || before.ends_with("pub(crate)")) {
            continue;
        }
        let path = t[i + 4..].trim();
        let path = path.strip_prefix("crate::").unwrap_or(path);
        let Some((first, rest)) = path.split_once("::") else {
            continue;
        };
        if !modules.iter().any(|m| m == first) {
            continue;
        }
        for item in rest.replace(['{', '}'], ",").split(',') {
            let item = item.trim();
            let name = match item.split_once(" as ") {
                Some((_, alias)) => alias.trim(),
                None => item.rsplit("::").next().unwrap_or(item),
            };
            if !name.is_empty() && name != "self" {
                out.insert(name.to_string(), first.to_string());
            }
        }
    }
    out
}

/// The macros a file exports at the crate root (`#[macro_export] macro_rules! name`).
fn exported_macros(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut exported = false;
    for line in code.lines() {
        let t = line.trim();
        if t.starts_with("#[macro_export]") {
            exported = true;
        } else if let Some(rest) = t.strip_prefix("macro_rules!") {
            if exported {
                out.push(rest.trim().trim_end_matches('{').trim().to_string());
            }
            exported = false;
        }
    }
    out
}

#[test]
fn imports_point_down() {
    let floors = floors();
    let mut problems = Vec::new();
    let (mut upward, mut cycles_found) = (0, 0);
    for krate in &CRATES {
        let dir = root().join(krate.dir);
        let root_code = split(&fs::read_to_string(dir.join(krate.root_file)).unwrap()).0;
        let modules = declared_modules(&root_code);
        let order = floors
            .get(krate.name)
            .unwrap_or_else(|| panic!("docs/layout.md's floors name no `{}:` line", krate.name));
        // The order places every module once, and the root file last.
        let mut placed: Vec<String> = modules.clone();
        placed.push(krate.root_file.to_string());
        let listed: Vec<&String> = order.iter().flatten().collect();
        let (a, b): (BTreeSet<_>, BTreeSet<_>) =
            (placed.iter().collect(), listed.iter().copied().collect());
        assert!(
            a == b && listed.len() == b.len(),
            "docs/layout.md's floors for {} must place each top-level module once: {b:?} vs {a:?}",
            krate.name
        );
        assert_eq!(
            order.last(),
            Some(&vec![krate.root_file.to_string()]),
            "{}: the root file is the top floor, alone",
            krate.name
        );
        let floor = |m: &str| order.iter().position(|f| f.iter().any(|o| o == m)).unwrap();
        let reexports = reexports(&root_code, &modules);

        let mut sources = Vec::new();
        files(&dir, &[".rs"], &mut sources);
        let sources: Vec<(PathBuf, String, String)> = sources
            .into_iter()
            .filter_map(|f| {
                let m = top_module(krate, &f, &modules)?;
                let code = split(&fs::read_to_string(&f).unwrap()).0;
                Some((f, m, code))
            })
            .collect();
        let mut macro_home = BTreeMap::new();
        for (_, m, code) in &sources {
            for mac in exported_macros(code) {
                macro_home.insert(format!("{mac}!"), m.clone());
            }
        }
        for mac in exported_macros(&root_code) {
            macro_home.insert(format!("{mac}!"), krate.root_file.to_string());
        }

        let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (f, m, code) in &sources {
            for (line, name) in crate_paths(code) {
                let target = if let Some(home) = macro_home.get(&name) {
                    home.clone()
                } else if modules.contains(&name) {
                    name.clone()
                } else if let Some(home) = reexports.get(&name) {
                    // Named through the facade, defined below it: the import is of its home.
                    home.clone()
                } else {
                    krate.root_file.to_string()
                };
                if &target == m {
                    continue;
                }
                edges.entry(m.clone()).or_default().insert(target.clone());
                if floor(&target) >= floor(m) {
                    upward += 1;
                    problems.push(format!(
                        "{}:{line}: `crate::{name}` imports {target} from {m}, not below it",
                        rel(f)
                    ));
                }
            }
        }
        // Cycles: strongly connected components of more than one module.
        for scc in components(&edges) {
            if scc.len() > 1 {
                cycles_found += 1;
                problems.push(format!(
                    "{}: a cycle between {}",
                    krate.name,
                    scc.join(", ")
                ));
            }
        }
    }
    eprintln!("layout: {upward} upward imports, {cycles_found} cycles");
    assert!(
        problems.is_empty(),
        "{upward} upward imports, {cycles_found} cycles (floors: docs/layout.md):\n{}",
        problems.join("\n")
    );
}

/// Tarjan's strongly connected components.
fn components(edges: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    struct State<'a> {
        edges: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on: BTreeSet<&'a str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a str) {
        let n = s.index.len();
        s.index.insert(v, n);
        s.low.insert(v, n);
        s.stack.push(v);
        s.on.insert(v);
        if let Some(ws) = s.edges.get(v) {
            for w in ws {
                let w = w.as_str();
                if !s.index.contains_key(w) {
                    visit(s, w);
                    let lw = s.low[w];
                    let lv = s.low.get_mut(v).unwrap();
                    *lv = (*lv).min(lw);
                } else if s.on.contains(w) {
                    let iw = s.index[w];
                    let lv = s.low.get_mut(v).unwrap();
                    *lv = (*lv).min(iw);
                }
            }
        }
        if s.low[v] == s.index[v] {
            let mut scc = Vec::new();
            while let Some(w) = s.stack.pop() {
                s.on.remove(w);
                scc.push(w.to_string());
                if w == v {
                    break;
                }
            }
            scc.sort();
            s.out.push(scc);
        }
    }
    let mut s = State {
        edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on: BTreeSet::new(),
        out: Vec::new(),
    };
    let nodes: BTreeSet<&str> = edges
        .iter()
        .flat_map(|(k, vs)| std::iter::once(k.as_str()).chain(vs.iter().map(String::as_str)))
        .collect();
    for v in nodes {
        if !s.index.contains_key(v) {
            visit(&mut s, v);
        }
    }
    s.out
}

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
        if f.ends_with("tests/api/layout.rs") {
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
