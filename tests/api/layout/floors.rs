//! Imports point down: the floors of docs/layout.md between top-level modules.

use super::*;

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
