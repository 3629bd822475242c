// Records what the lab's binaries were built from, for the results' `meta`: the compiler, and
// the git commit and whether the sources differed from it. Taken here, at build time,
// because a results file describes the build that made it, not whichever repository the
// command happens to run in.
use std::path::{Path, PathBuf};
use std::process::Command;

/// The files the binaries are built from: what `dirty` looks at, and what reruns this
/// script when it changes.
const SOURCES: [&str; 6] = [
    "src",
    "crates",
    "benches",
    "build.rs",
    "Cargo.toml",
    "Cargo.lock",
];

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let version = Command::new(rustc)
        .arg("--version")
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .map(|s| s.trim().to_string())
        .unwrap_or_else(|| "unknown".into());
    println!("cargo:rustc-env=TORUS_CULL_RUSTC={version}");
    println!("cargo:rerun-if-env-changed=RUSTC");

    let manifest_dir = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").expect("set by cargo"));
    let git = |args: &[&str]| {
        Command::new("git")
            .arg("-C")
            .arg(&manifest_dir)
            .args(args)
            .output()
            .ok()
            .filter(|o| o.status.success())
            .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
    };
    let commit = git(&["rev-parse", "--short", "HEAD"]);
    // --no-optional-locks: never touch the index, so this script does not make itself stale.
    let mut status = vec![
        "--no-optional-locks",
        "status",
        "--porcelain",
        "--untracked-files=no",
        "--",
    ];
    status.extend(SOURCES);
    let dirty = commit.is_some() && git(&status).is_some_and(|s| !s.is_empty());
    println!(
        "cargo:rustc-env=TORUS_CULL_GIT_COMMIT={}",
        commit.as_deref().unwrap_or("")
    );
    println!("cargo:rustc-env=TORUS_CULL_GIT_DIRTY={dirty}");

    for source in SOURCES {
        println!("cargo:rerun-if-changed={source}");
    }
    // HEAD moves on checkout, commit and reset. Watch only files that exist: cargo reruns
    // a script on every build when a watched path is missing.
    let git_path = |args: &[&str]| git(args).map(|p| absolute(&manifest_dir, &p));
    let mut watched = Vec::new();
    if let Some(git_dir) = git_path(&["rev-parse", "--git-dir"]) {
        watched.push(git_dir.join("HEAD"));
        watched.push(git_dir.join("logs").join("HEAD"));
    }
    if let Some(common) = git_path(&["rev-parse", "--git-common-dir"]) {
        if let Some(branch) = git(&["symbolic-ref", "-q", "HEAD"]) {
            watched.push(common.join(branch));
        }
        watched.push(common.join("packed-refs"));
    }
    for path in watched.into_iter().filter(|p| p.exists()) {
        println!("cargo:rerun-if-changed={}", path.display());
    }
}

fn absolute(base: &Path, path: &str) -> PathBuf {
    let p = Path::new(path);
    if p.is_absolute() {
        p.to_path_buf()
    } else {
        base.join(p)
    }
}
