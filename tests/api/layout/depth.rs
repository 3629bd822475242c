//! No circle at any depth: inside every folder, the modules side by side import one
//! another without a cycle (issue 57 item 4). The floors test sees top-level modules only;
//! `geometry/ray.rs` and `geometry/torus.rs` imported each other for months beneath it.
//!
//! Every file is a module (`a/b.rs` and `a/b/mod.rs` are `a::b`; inline `mod x { … }`
//! blocks count as their file). An import is every `crate::…`, `super::…` and `self::…`
//! path in the code and every `use child::…` of a module's own child, group braces
//! expanded, resolved segment by segment: a segment that names a module enters it, one that
//! a module's `use` brings in (at any visibility, aliases too) is followed to what that
//! `use` names, and anything else is an item of the module reached. An import from S of
//! an item defined in T, neither inside the other, is an arrow between the two children of
//! their nearest common folder that hold them; each folder's arrows must form no cycle.

use super::*;

/// A crate's modules: each file's module path and code.
struct Tree {
    /// Module path (`["geometry", "ray"]`) → (file, code with comments blanked).
    files: BTreeMap<Vec<String>, (PathBuf, String)>,
}

impl Tree {
    fn load(dir: &Path, root_file: &str, skip: Option<&str>) -> Tree {
        let mut all = Vec::new();
        files(dir, &[".rs"], &mut all);
        let mut out = BTreeMap::new();
        for f in all {
            let r = f.strip_prefix(dir).unwrap();
            let parts: Vec<String> = r
                .components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect();
            if skip.is_some_and(|s| parts[0] == s) {
                continue;
            }
            // Unit tests (`tests.rs`, `x_tests.rs`) check a module from outside, as an
            // integration test would: what they import is no arrow of the house.
            let stem = parts.last().unwrap().trim_end_matches(".rs");
            if stem == "tests" || stem.ends_with("_tests") {
                continue;
            }
            let mut path: Vec<String> = parts;
            let last = path.pop().unwrap();
            if path.is_empty() && last == root_file {
                // The crate root.
            } else if last != "mod.rs" {
                path.push(last.trim_end_matches(".rs").to_string());
            }
            let code = without_inline_tests(&split(&fs::read_to_string(&f).unwrap()).0);
            out.insert(path, (f, code));
        }
        Tree { files: out }
    }

    fn is_module(&self, m: &[String]) -> bool {
        self.files.contains_key(m)
    }

    /// Where `path` (absolute segments) leads: the module defining its item. `depth` guards
    /// against a `use` that names itself.
    fn resolve(&self, path: &[String], depth: usize) -> Vec<String> {
        let mut cur: Vec<String> = Vec::new();
        for (i, seg) in path.iter().enumerate() {
            let mut next = cur.clone();
            next.push(seg.clone());
            if self.is_module(&next) {
                cur = next;
                continue;
            }
            if depth < 16
                && let Some(target) = self.uses(&cur).get(seg)
            {
                let mut full = target.clone();
                full.extend(path[i + 1..].iter().cloned());
                return self.resolve(&full, depth + 1);
            }
            return cur;
        }
        cur
    }

    /// The names a module's `use` statements bring in, each with the absolute path it names.
    fn uses(&self, module: &[String]) -> BTreeMap<String, Vec<String>> {
        let mut out = BTreeMap::new();
        let Some((_, code)) = self.files.get(module) else {
            return out;
        };
        for stmt in use_statements(code) {
            for (path, name) in expand_tree(&stmt.tree) {
                if let Some(abs) = self.absolute(module, &path, stmt.inline_depth)
                    && let Some(name) = name
                {
                    out.insert(name, abs);
                }
            }
        }
        out
    }

    /// A path written in `module` (inside `inline` inline modules) made absolute, if it is
    /// this crate's: `crate::`, `super::`, `self::` or a child module of `module`.
    fn absolute(&self, module: &[String], path: &[String], inline: usize) -> Option<Vec<String>> {
        let first = path.first()?;
        match first.as_str() {
            "crate" => Some(path[1..].to_vec()),
            "self" => {
                let mut m = module.to_vec();
                m.extend(path[1..].iter().cloned());
                Some(m)
            }
            "super" => {
                let supers = path.iter().take_while(|s| *s == "super").count();
                // The first supers leave inline modules, which are the file's own.
                let out_of_file = supers.saturating_sub(inline);
                if out_of_file > module.len() {
                    return None;
                }
                let mut m = module[..module.len() - out_of_file].to_vec();
                m.extend(path[supers..].iter().cloned());
                Some(m)
            }
            child => {
                let mut m = module.to_vec();
                m.push(child.to_string());
                self.is_module(&m).then(|| {
                    let mut m = module.to_vec();
                    m.extend(path.iter().cloned());
                    m
                })
            }
        }
    }
}

/// One `use` statement: its tree's text and how many inline modules enclose it.
struct UseStmt {
    tree: String,
    inline_depth: usize,
    line: usize,
    /// Its byte span in the code, `use` to `;`.
    span: (usize, usize),
}

/// The code with its inline `mod tests { … }` blocks blanked (newlines kept): unit tests,
/// as [`Tree::load`] leaves out their files.
fn without_inline_tests(code: &str) -> String {
    let mut bytes = code.as_bytes().to_vec();
    for (open, close) in inline_mods(code) {
        let head = code[..open].trim_end();
        if head.ends_with("mod tests") {
            for b in &mut bytes[open..=close] {
                if *b != b'\n' {
                    *b = b' ';
                }
            }
        }
    }
    String::from_utf8_lossy(&bytes).into_owned()
}

/// Where each inline `mod name {` block of the code opens and closes (byte offsets).
fn inline_mods(code: &str) -> Vec<(usize, usize)> {
    let b = code.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while let Some(k) = code[i..].find("mod ") {
        let at = i + k;
        i = at + 4;
        if at > 0 && (b[at - 1].is_ascii_alphanumeric() || b[at - 1] == b'_') {
            continue;
        }
        let rest = &code[at + 4..];
        let name_len = rest
            .find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(rest.len());
        let after = rest[name_len..].trim_start();
        if name_len == 0 || !after.starts_with('{') {
            continue;
        }
        let open = at + 4 + name_len + (rest[name_len..].len() - after.len());
        let mut depth = 0;
        for (j, ch) in code[open..].char_indices() {
            match ch {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        out.push((open, open + j));
                        break;
                    }
                }
                _ => {}
            }
        }
    }
    out
}

/// Every `use …;` of the code (at any nesting), its tree text after `use`.
fn use_statements(code: &str) -> Vec<UseStmt> {
    let mods = inline_mods(code);
    let b = code.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while let Some(k) = code[i..].find("use ") {
        let at = i + k;
        i = at + 4;
        if at > 0 && (b[at - 1].is_ascii_alphanumeric() || b[at - 1] == b'_') {
            continue;
        }
        let Some(end) = code[at..].find(';') else {
            break;
        };
        // Whitespace collapsed, `x as y` marked `x@y`, then the spaces dropped.
        let words: Vec<&str> = code[at + 4..at + end].split_whitespace().collect();
        let tree = words.join(" ").replace(" as ", "@").replace(' ', "");
        let inline_depth = mods.iter().filter(|(s, e)| *s < at && at < *e).count();
        let line = code[..at].matches('\n').count() + 1;
        out.push(UseStmt {
            tree,
            inline_depth,
            line,
            span: (at, at + end),
        });
    }
    out
}

/// A use tree (`a::b::{c,d::e@f,self}`: spaces removed, `as` marked `@`) as paths, each with the name
/// it binds (`None` for a glob).
fn expand_tree(tree: &str) -> Vec<(Vec<String>, Option<String>)> {
    let tree = tree.trim_start_matches("::");
    // The prefix before a top-level `{`, if any.
    if let Some(open) = tree.find('{')
        && tree.ends_with('}')
    {
        let prefix: Vec<String> = tree[..open]
            .trim_end_matches("::")
            .split("::")
            .filter(|s| !s.is_empty())
            .map(str::to_string)
            .collect();
        let inner = &tree[open + 1..tree.len() - 1];
        let mut parts = Vec::new();
        let (mut depth, mut start) = (0, 0);
        for (j, ch) in inner.char_indices() {
            match ch {
                '{' => depth += 1,
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    parts.push(&inner[start..j]);
                    start = j + 1;
                }
                _ => {}
            }
        }
        parts.push(&inner[start..]);
        let mut out = Vec::new();
        for part in parts.into_iter().filter(|p| !p.is_empty()) {
            for (mut path, name) in expand_tree(part) {
                if path.first().map(String::as_str) == Some("self") {
                    // `a::{self}` binds `a`.
                    path.remove(0);
                    let name = name.or_else(|| prefix.last().cloned());
                    let mut full = prefix.clone();
                    full.extend(path);
                    out.push((full, name));
                } else {
                    let mut full = prefix.clone();
                    full.extend(path);
                    out.push((full, name));
                }
            }
        }
        return out;
    }
    let (path, alias) = match tree.split_once('@') {
        Some((p, a)) => (p, Some(a.to_string())),
        None => (tree, None),
    };
    let segs: Vec<String> = path.split("::").map(str::to_string).collect();
    if segs.last().map(String::as_str) == Some("*") {
        return vec![(segs[..segs.len() - 1].to_vec(), None)];
    }
    let name = alias.or_else(|| segs.last().cloned());
    vec![(segs, name)]
}

/// Every `crate::`, `super::` and `self::` path in the code outside `use` statements
/// (those are read whole by [`use_statements`]), as segments, with its line and its
/// inline depth.
fn inline_paths(code: &str) -> Vec<(usize, Vec<String>, usize)> {
    let mods = inline_mods(code);
    let b: Vec<char> = code.chars().collect();
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    let mut out = Vec::new();
    let mut i = 0;
    let mut line = 1;
    let mut byte = 0;
    while i < b.len() {
        if b[i] == '\n' {
            line += 1;
        }
        let starts = ["crate::", "super::", "self::"]
            .iter()
            .find(|p| b[i..].iter().take(p.len()).copied().eq(p.chars()));
        let before_ok = i == 0 || !(ident(b[i - 1]) || b[i - 1] == ':' || b[i - 1] == '$');
        if let (Some(_), true) = (starts, before_ok) {
            let mut segs = Vec::new();
            let mut j = i;
            loop {
                let s = j;
                while j < b.len() && ident(b[j]) {
                    j += 1;
                }
                if s == j {
                    break;
                }
                segs.push(b[s..j].iter().collect::<String>());
                if b.get(j) == Some(&':') && b.get(j + 1) == Some(&':') {
                    j += 2;
                } else {
                    break;
                }
            }
            let depth = mods.iter().filter(|(s, e)| *s < byte && byte < *e).count();
            out.push((line, segs, depth));
            for ch in &b[i..j] {
                byte += ch.len_utf8();
            }
            i = j;
            continue;
        }
        byte += b[i].len_utf8();
        i += 1;
    }
    out
}

/// Whether `a` is `b` or inside it.
fn within(a: &[String], b: &[String]) -> bool {
    a.len() >= b.len() && a[..b.len()] == *b
}

/// The cycles among sibling modules of one crate, each named with one import per arrow.
fn cycles(tree: &Tree) -> (usize, Vec<String>) {
    // Per folder: arrows between its children, each with a file:line that makes it.
    let mut arrows: BTreeMap<Vec<String>, BTreeMap<String, BTreeSet<String>>> = BTreeMap::new();
    let mut witness: BTreeMap<(Vec<String>, String, String), String> = BTreeMap::new();
    let mut count = 0;
    for (module, (file, code)) in &tree.files {
        let mut imports: Vec<(usize, Vec<String>)> = Vec::new();
        for stmt in use_statements(code) {
            for (path, _) in expand_tree(&stmt.tree) {
                if let Some(abs) = tree.absolute(module, &path, stmt.inline_depth) {
                    imports.push((stmt.line, abs));
                }
            }
        }
        // The code with its `use` statements blanked (newlines kept): they were read whole.
        let mut rest = code.clone().into_bytes();
        for stmt in use_statements(code) {
            for b in &mut rest[stmt.span.0..stmt.span.1] {
                if *b != b'\n' {
                    *b = b' ';
                }
            }
        }
        let rest = String::from_utf8_lossy(&rest).into_owned();
        for (line, segs, depth) in inline_paths(&rest) {
            if let Some(abs) = tree.absolute(module, &segs, depth) {
                imports.push((line, abs));
            }
        }
        for (line, abs) in imports {
            let target = tree.resolve(&abs, 0);
            if within(module, &target) || within(&target, module) {
                continue;
            }
            count += 1;
            let common = module
                .iter()
                .zip(&target)
                .take_while(|(a, b)| a == b)
                .count();
            let folder = module[..common].to_vec();
            let (from, to) = (module[common].clone(), target[common].clone());
            arrows
                .entry(folder.clone())
                .or_default()
                .entry(from.clone())
                .or_default()
                .insert(to.clone());
            witness
                .entry((folder, from, to))
                .or_insert_with(|| format!("{}:{line}", rel(file)));
        }
    }
    let mut problems = Vec::new();
    for (folder, edges) in &arrows {
        for scc in components(edges) {
            if scc.len() > 1 {
                let how: Vec<String> = witness
                    .iter()
                    .filter(|((f, a, b), _)| f == folder && scc.contains(a) && scc.contains(b))
                    .map(|((_, a, b), at)| format!("{a} → {b} ({at})"))
                    .collect();
                problems.push(format!(
                    "a cycle in `{}` between {}: {}",
                    if folder.is_empty() {
                        "the crate root".to_string()
                    } else {
                        folder.join("/")
                    },
                    scc.join(", "),
                    how.join("; ")
                ));
            }
        }
    }
    (count, problems)
}

#[test]
fn no_circle_at_any_depth() {
    let mut problems = Vec::new();
    let mut total = 0;
    for krate in &CRATES {
        // The command's files live in the lab's folder `cli/`: they are its crate, not the lab's.
        let skip = (krate.dir == "src").then_some("cli");
        let tree = Tree::load(&root().join(krate.dir), krate.root_file, skip);
        let (count, found) = cycles(&tree);
        assert!(
            count > 20,
            "{}: only {count} imports between modules read: the reader is broken",
            krate.name
        );
        total += count;
        problems.extend(found.into_iter().map(|p| format!("{}: {p}", krate.name)));
    }
    eprintln!(
        "layout: {total} imports between modules, {} cycles at any depth",
        problems.len()
    );
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The reader itself: a planted circle between two siblings two folders deep is found,
/// through a re-export and a `super::` path; without it, none.
#[test]
fn a_circle_deep_in_a_folder_is_found() {
    let module = |p: &[&str]| p.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let file = |code: &str| (PathBuf::from("x.rs"), code.to_string());
    let mut files = BTreeMap::new();
    files.insert(module(&[]), file("mod a;"));
    files.insert(module(&["a"]), file("mod deep; pub use deep::Thing;"));
    files.insert(
        module(&["a", "deep"]),
        file("mod one; mod two; pub use one::Thing;"),
    );
    files.insert(
        module(&["a", "deep", "one"]),
        file("use super::two::Other; pub struct Thing;"),
    );
    files.insert(
        module(&["a", "deep", "two"]),
        file("pub struct Other; fn f() -> crate::a::Thing { todo!() }"),
    );
    let tree = Tree { files };
    let (count, found) = cycles(&tree);
    assert_eq!(count, 2, "{found:?}");
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(
        found[0].contains("a/deep") && found[0].contains("one, two"),
        "{found:?}"
    );
    let mut files = tree.files;
    files.insert(
        module(&["a", "deep", "two"]),
        file("pub struct Other; fn f() {}"),
    );
    let (_, found) = cycles(&Tree { files });
    assert!(found.is_empty(), "{found:?}");
}
