//! The library's package stands alone: the project's pages ship in it (its `docs/` holds a
//! link to each root page), no file of the package names a `docs/*.md` it lacks, and the
//! licence texts the manifest's `license` names are in it.

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn pages(dir: &Path) -> BTreeSet<String> {
    fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".md"))
        .collect()
}

/// Every text file of the package's folder, following the pages' links.
fn package_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap().flatten() {
        let p = entry.path();
        let name = entry.file_name().to_string_lossy().into_owned();
        if p.is_dir() {
            if name != "target" && !name.starts_with('.') {
                package_files(&p, out);
            }
        } else if [".rs", ".md", ".toml", ".wgsl"]
            .iter()
            .any(|e| name.ends_with(e))
        {
            out.push(p);
        }
    }
}

/// The page names `text` refers to: `docs/` and a page's name anywhere, and in a page,
/// its links to a sibling page.
fn named_pages(text: &str, is_page: bool) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut grab = |marker: &str| {
        for (i, _) in text.match_indices(marker) {
            let rest = &text[i + marker.len()..];
            let name: String = rest
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == '-')
                .collect();
            if !name.is_empty() && rest[name.len()..].starts_with(".md") {
                out.insert(format!("{name}.md"));
            }
        }
    };
    grab("docs/");
    if is_page {
        grab("](");
    }
    out
}

#[test]
fn every_page_ships_in_the_library_package_as_a_link() {
    let shipped_dir = root().join("crates/torus-cull/docs");
    let shipped = pages(&shipped_dir);
    assert_eq!(
        shipped,
        pages(&root().join("docs")),
        "crates/torus-cull/docs/ must link every docs/*.md (a symbolic link to ../../../docs/ and the page's name)"
    );
    for page in &shipped {
        let link = shipped_dir.join(page);
        let target = fs::read_link(&link).unwrap_or_else(|e| panic!("{}: {e}", link.display()));
        assert_eq!(
            target,
            Path::new("../../../docs").join(page),
            "{}",
            link.display()
        );
    }
}

#[test]
fn no_file_of_the_package_names_a_page_it_lacks() {
    let krate = root().join("crates/torus-cull");
    let shipped = pages(&krate.join("docs"));
    let mut files = Vec::new();
    package_files(&krate, &mut files);
    assert!(files.len() > 50, "{} files", files.len());
    let mut missing = Vec::new();
    for file in &files {
        let text = fs::read_to_string(file).unwrap();
        let is_page = file.parent() == Some(krate.join("docs").as_path());
        for page in named_pages(&text, is_page) {
            if !shipped.contains(&page) {
                missing.push(format!("{}: names {page}", file.display()));
            }
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n"));
}

#[test]
fn the_licences_the_manifest_names_are_in_the_package() {
    let manifest = fs::read_to_string(root().join("crates/torus-cull/Cargo.toml")).unwrap();
    assert!(manifest.contains(r#"license = "MIT OR Apache-2.0""#));
    for name in ["LICENSE-MIT", "LICENSE-APACHE"] {
        let at_root = fs::read_to_string(root().join(name)).expect(name);
        let in_package = fs::read_to_string(root().join("crates/torus-cull").join(name))
            .unwrap_or_else(|e| panic!("crates/torus-cull/{name}: {e}"));
        assert_eq!(at_root, in_package, "{name}: the package's copy differs");
        assert!(
            at_root.len() > 1000,
            "{name} is too short to be the licence"
        );
    }
}
