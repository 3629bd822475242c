//! The repository's layout, checked against its own text (issue 37 items 6 and 7; issue 57
//! item 4: no circle at any depth).
//!
//! * Imports point down: every `crate::…` path in the code (in `use` statements and inline)
//!   of each top-level module of the library (`crates/torus-cull/src/`), the lab
//!   (`src/lib.rs`) and the command (`src/cli/main.rs`) names a module on a lower floor of
//!   the order written in `docs/layout.md` (its "Floors" block). The crate root is the top
//!   floor, a facade: a module that names an item through it (`crate::Torus` rather than
//!   `crate::geometry::Torus`) imports upward. Fails with each offending file:line, and
//!   with every cycle between top-level modules.
//! * No circle at any depth (`depth.rs`): inside every folder of both crates, the modules
//!   side by side import one another without a cycle, the imports read from `crate::…`,
//!   `super::…`, `self::…` and a parent's `use child::…`, each resolved through the
//!   re-exports to the module that defines the item.
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

mod depth;
mod floors;
mod paths;

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
